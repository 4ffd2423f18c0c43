//! Rendering diagnostics for people: rustc-like reports (via `annotate-snippets`)
//! for terminals and build scripts, and a compact form for `compile_error!`.
//!
//! Every function here accepts any span, including spans past the end of the
//! text, reversed spans, empty spans and spans that cut a UTF-8 character:
//! they are clamped, never a panic.

use std::borrow::Cow;
use std::fmt::Write as _;

#[cfg(feature = "build")]
use annotate_snippets::{AnnotationKind, Group, Level, Renderer, Snippet};

#[cfg(feature = "build")]
use super::text::{ceil_char, floor_char};
use super::text::{clamp_span, display_span, unsafe_char};
use super::{Diagnostic, Severity, SourceFile};
#[cfg(feature = "build")]
use crate::ast::Span;

/// The byte range of the lines that `lo..hi` touches (without the final line
/// break). From the line table, so that many diagnostics on one long line do
/// not each scan it.
#[cfg_attr(not(feature = "build"), allow(dead_code))] // only rustc-style rendering uses it
fn line_range(file: &SourceFile, lo: usize, hi: usize) -> (usize, usize) {
    let text = file.text.as_str();
    let start = file.line_start(file.line_of(lo as u32));
    let mut end = file.line_end(file.line_of(hi as u32));
    // A CRLF line is shown without its CR.
    if end > hi && text.as_bytes()[end - 1] == b'\r' {
        end -= 1;
    }
    (start, end)
}

/// Lines longer than this (in bytes) are shown as a window around the spans.
#[cfg_attr(not(feature = "build"), allow(dead_code))] // only rustc-style rendering uses it
const LONG_LINE: usize = 480;
/// Bytes shown on each side of the spans in such a window.
#[cfg_attr(not(feature = "build"), allow(dead_code))] // only rustc-style rendering uses it
const CONTEXT: usize = 80;

/// `s` on one line: every character that could start a line or reorder text written as an escape (`\n`, `\t`,
/// `\u{202e}`), so that text quoted from a file (a name holding
/// `\nerror[IL0000]: fake`) can never forge a line of the report. No
/// message, label, note or help is meant to span lines.
pub fn one_line(s: &str) -> Cow<'_, str> {
    if !s.chars().any(unsafe_char) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if unsafe_char(c) => {
                let _ = write!(out, "\\u{{{:x}}}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    Cow::Owned(out)
}

/// The source lines as shown: control characters other than tab, line
/// breaks and the CR of a CRLF become U+FFFD (a lone CR or an escape
/// sequence would redraw the terminal line). Returns the text and a map
/// from byte offsets in `src` to offsets in it.
fn shown_source(src: &str) -> (Cow<'_, str>, Vec<(usize, usize)>) {
    let bad = |k: usize, c: char| {
        unsafe_char(c) && c != '\t' && c != '\n' && !(c == '\r' && src[k + 1..].starts_with('\n'))
    };
    if !src.char_indices().any(|(k, c)| bad(k, c)) {
        return (Cow::Borrowed(src), Vec::new());
    }
    let mut out = String::with_capacity(src.len() + 8);
    // (offset in src after a replaced char, bytes added so far)
    let mut shifts = Vec::new();
    for (k, c) in src.char_indices() {
        if bad(k, c) {
            out.push('\u{FFFD}');
            shifts.push((k + c.len_utf8(), out.len() - (k + c.len_utf8())));
        } else {
            out.push(c);
        }
    }
    (Cow::Owned(out), shifts)
}

/// Offset `o` of the original source in [`shown_source`]'s text.
#[cfg_attr(not(feature = "build"), allow(dead_code))] // only rustc-style rendering uses it
fn shifted(shifts: &[(usize, usize)], o: usize) -> usize {
    let i = shifts.partition_point(|(at, _)| *at <= o);
    if i == 0 { o } else { o + shifts[i - 1].1 }
}

#[cfg_attr(not(feature = "build"), allow(dead_code))] // only rustc-style rendering uses it
fn ordered<'d>(text: &str, diags: &'d [Diagnostic]) -> Vec<&'d Diagnostic> {
    let mut v: Vec<&'d Diagnostic> = diags.iter().collect();
    // Stable: equal positions keep the order in which the stages reported them.
    v.sort_by_key(|d| clamp_span(text, d.span));
    v
}

/// Render diagnostics the way rustc does (`error[IL0003]: ...`, ` --> file:line:col`,
/// the source lines with carets and labels, `= note:` and `= help:`), sorted by
/// position, each followed by an empty line. `color` adds ANSI styles.
#[cfg(feature = "build")]
pub fn render(file: &SourceFile, diags: &[Diagnostic], color: bool) -> String {
    let renderer = if color {
        Renderer::styled()
    } else {
        Renderer::plain()
    };
    let mut out = String::new();
    for d in ordered(&file.text, diags) {
        out.push_str(&render_one(&renderer, file, d));
        out.push_str("\n\n");
    }
    out
}

#[cfg(feature = "build")]
fn render_one(renderer: &Renderer, file: &SourceFile, d: &Diagnostic) -> String {
    let text = file.text.as_str();
    let level = match d.severity {
        Severity::Error => Level::ERROR,
        Severity::Warning => Level::WARNING,
    };
    let fix = |span: Span| display_span(text, span);
    let primary = fix(d.span);
    let secondary: Vec<((usize, usize), &str)> = d
        .secondary
        .iter()
        .map(|(s, l)| (fix(*s), l.as_str()))
        .collect();

    // Hand annotate-snippets only the lines the spans touch (plus what lies
    // between them; it folds long unannotated stretches), not the whole file.
    let lo = secondary.iter().map(|s| s.0.0).fold(primary.0, usize::min);
    let hi = secondary.iter().map(|s| s.0.1).fold(primary.1, usize::max);
    let (mut start, mut end) = line_range(file, lo, hi);
    let first_line = file.line_of(start as u32);
    // A long line (machine-written XML, a damaged file) is shown as a window
    // around the spans, with the position given apart: annotate-snippets
    // measures the whole line for every report, which on one line with many
    // reports is quadratic.
    let window = end - start > LONG_LINE && first_line == file.line_of(hi as u32);
    let (line_lo, line_hi) = (start, end);
    if window {
        start = floor_char(text, lo.saturating_sub(CONTEXT).max(start));
        end = ceil_char(text, (hi + CONTEXT).min(end).min(start + 2 * LONG_LINE));
    }
    let raw = &text[start..end];
    let (shown_raw, shifts) = shown_source(raw);
    let (before, after) = match window {
        true => (
            if start > line_lo { "..." } else { "" },
            if end < line_hi { "..." } else { "" },
        ),
        false => ("", ""),
    };
    let source: Cow<'_, str> = if window {
        Cow::Owned(format!("{before}{shown_raw}{after}"))
    } else {
        shown_raw
    };
    let shift = before.len();
    // Spans that run past `end` (a span over a final line break) are cut there.
    let rel = |(a, b): (usize, usize)| {
        let a = a.saturating_sub(start).min(raw.len());
        let b = b.saturating_sub(start).min(raw.len());
        shifted(&shifts, a) + shift..shifted(&shifts, b) + shift
    };
    // Everything quoted from the user goes through one_line.
    let label = one_line(&d.label);
    let path = one_line(&file.name);
    let message = one_line(&d.message);
    let secondary_labels: Vec<Cow<'_, str>> = secondary.iter().map(|(_, l)| one_line(l)).collect();
    let notes: Vec<Cow<'_, str>> = d.notes.iter().map(|n| one_line(n)).collect();
    let help = d.help.as_deref().map(one_line);
    let mut primary_ann = AnnotationKind::Primary.span(rel(primary));
    if !label.is_empty() {
        primary_ann = primary_ann.label(label.as_ref());
    }
    let mut snippet = Snippet::source(source.as_ref())
        .line_start(first_line)
        .path(path.as_ref())
        .fold(true)
        .annotation(primary_ann);
    for ((span, _), label) in secondary.iter().zip(&secondary_labels) {
        let mut ann = AnnotationKind::Context.span(rel(*span));
        if !label.is_empty() {
            ann = ann.label(label.as_ref());
        }
        snippet = snippet.annotation(ann);
    }
    let mut group: Group<'_> = level
        .primary_title(message.as_ref())
        .id(d.code)
        .element(snippet);
    for note in &notes {
        group = group.element(Level::NOTE.message(note.as_ref()));
    }
    if let Some(help) = &help {
        group = group.element(Level::HELP.message(help.as_ref()));
    }
    let out = renderer.render(&[group]);
    if !window {
        return out;
    }
    // annotate-snippets gave the column inside the window: name the real one.
    let shown = source[..rel(primary).start].chars().count() + 1;
    let (line, col) = file.line_col(primary.0 as u32);
    out.replacen(
        &format!("{path}:{line}:{shown}"),
        &format!("{path}:{line}:{col}"),
        1,
    )
}

/// One self-contained message for `compile_error!` (inside `il!`, and in the
/// file build.rs writes in place of a failed program), where rustc can only
/// point at the whole string literal. It has the layout of [`render`], the
/// one of rustc, `ilc` and build.rs: the code and the message, the IL
/// position on an arrow line, the source line with a caret line under the
/// span, the notes and the help. rustc prints it after `error: `, so editors'
/// rustc problem matchers read the `-->` line as the error's place.
///
/// ```text
/// IL0003: expected an operand after `LD`
///   --> plc/motor.il:12:5
///    |
/// 12 |     LD
///    |     ^^ operand missing here
///    = help: write `LD x` ...
/// ```
pub fn render_short(file: &SourceFile, d: &Diagnostic) -> String {
    render_short_in(file, d, None)
}

/// Where the IL of an `il!` string literal starts in the Rust file.
#[derive(Clone, Debug, PartialEq)]
pub struct RustPlace {
    /// As rustc names it in its messages (`src/main.rs`).
    pub file: String,
    /// 1-based.
    pub line: usize,
    /// 1-based, in characters: the column of the IL's first character.
    pub column: usize,
}

impl RustPlace {
    /// The place of IL line `line`, column `col` (both 1-based): the
    /// literal's later lines start at column 1 of the Rust file. (Exact for
    /// raw strings; an escape earlier on the line of a `"..."` string
    /// moves it.)
    pub fn of(&self, line: usize, col: usize) -> (usize, usize) {
        let column = if line == 1 {
            self.column + col - 1
        } else {
            col
        };
        (self.line + line - 1, column)
    }
}

/// [`render_short`] for IL inside a Rust file: the arrow names the Rust
/// file, line and column of the error, so that editors' rustc problem
/// matchers (which read the line after `error:`) put it on the IL's line
/// itself; the gutter numbers Rust lines, and a note gives the IL's own
/// line and column. Without a place, the arrow says the IL line only.
pub fn render_short_in(file: &SourceFile, d: &Diagnostic, place: Option<&RustPlace>) -> String {
    let text = file.text.as_str();
    let (lo_shown, hi) = display_span(text, d.span);
    let (line, col) = file.line_col(lo_shown as u32);
    let mut out = String::new();
    if d.severity == Severity::Warning {
        out.push_str("warning ");
    }
    let (num, at, il_place) = match place {
        Some(p) => {
            let (l, c) = p.of(line, col);
            (
                l.to_string(),
                format!("{}:{l}:{c}", one_line(&p.file)),
                Some(format!("IL line {line}, column {col} of the il! input")),
            )
        }
        None => (
            line.to_string(),
            format!("{}:{line}:{col}", one_line(&file.name)),
            None,
        ),
    };
    let pad = " ".repeat(num.len());
    out.push_str(&format!(
        "{}: {}\n{pad}--> {at}\n",
        d.code,
        one_line(&d.message)
    ));

    let src_line = file.line_text(line);
    // The caret line copies tabs so that it lines up under the source line.
    let prefix: String = src_line
        .chars()
        .take(col - 1)
        .map(|c| if c == '\t' { '\t' } else { ' ' })
        .collect();
    let on_line = src_line.chars().count().saturating_sub(col - 1);
    let span_chars = text[lo_shown..hi.max(lo_shown)]
        .chars()
        .take_while(|&c| c != '\n')
        .count();
    let carets = "^".repeat(span_chars.min(on_line).max(1));
    let shown = shown_source(src_line).0;
    let sep = if shown.is_empty() { "" } else { " " };
    out.push_str(&format!(
        "{pad} |\n{num} |{sep}{shown}\n{pad} | {prefix}{carets}"
    ));
    if !d.label.is_empty() {
        out.push(' ');
        out.push_str(&one_line(&d.label));
    }
    out.push('\n');
    for (span, label) in &d.secondary {
        let (l, c) = file.line_col(span.lo);
        let (l, c) = place.map_or((l, c), |p| p.of(l, c));
        let label = one_line(label);
        out.push_str(&format!("{pad} = note: {label} (line {l}, column {c})\n"));
    }
    for note in il_place.iter().chain(&d.notes) {
        let note = one_line(note);
        out.push_str(&format!("{pad} = note: {note}\n"));
    }
    if let Some(help) = &d.help {
        let help = one_line(help);
        out.push_str(&format!("{pad} = help: {help}\n"));
    }
    out.truncate(out.trim_end().len());
    out
}

#[cfg(all(test, feature = "build"))]
mod tests {
    use super::*;

    fn file(text: &str) -> SourceFile {
        SourceFile::new("t.il", text)
    }

    #[test]
    fn plain_error_has_rustc_shape() {
        let f = file("PROGRAM p\n    LD\nEND_PROGRAM\n");
        let d = Diagnostic::error(
            "IL0003",
            Span::new(14, 16),
            "expected an operand after `LD`",
        )
        .with_label("operand missing")
        .with_note("every LD loads one operand")
        .with_help("write `LD x`");
        let r = render(&f, &[d], false);
        assert!(
            r.starts_with("error[IL0003]: expected an operand after `LD`\n"),
            "{r}"
        );
        assert!(r.contains(" --> t.il:2:5\n"), "{r}");
        assert!(r.contains("2 |     LD\n"), "{r}");
        assert!(r.contains("^^ operand missing"), "{r}");
        assert!(r.contains("= note: every LD loads one operand"), "{r}");
        assert!(r.contains("= help: write `LD x`"), "{r}");
        assert!(!r.contains('\x1b'));
        assert!(r.ends_with("\n\n"));
    }

    #[test]
    fn color_adds_escapes_only_when_asked() {
        let f = file("LD x\n");
        let d = Diagnostic::warning("IL0100", Span::new(3, 4), "unused");
        assert!(render(&f, std::slice::from_ref(&d), true).contains('\x1b'));
        let plain = render(&f, &[d], false);
        assert!(plain.starts_with("warning[IL0100]: unused"), "{plain}");
    }

    #[test]
    fn sorted_by_position() {
        let f = file("a\nb\nc\n");
        let d1 = Diagnostic::error("IL0001", Span::new(4, 5), "third line");
        let d2 = Diagnostic::error("IL0002", Span::new(0, 1), "first line");
        let r = render(&f, &[d1, d2], false);
        assert!(r.find("first line").unwrap() < r.find("third line").unwrap());
    }

    #[test]
    fn odd_spans_do_not_panic() {
        for text in [
            "",
            "\n",
            "x",
            "x\n",
            "x\r\n",
            "é\n\t\u{0}\u{1b}[31m",
            "\n\n\n",
            "a\u{301}b",
        ] {
            let f = file(text);
            for lo in 0..text.len() as u32 + 3 {
                for hi in 0..text.len() as u32 + 3 {
                    let d = Diagnostic::error("IL0001", Span { lo, hi }, "m")
                        .with_label("l")
                        .with_secondary(Span { lo: hi, hi: lo }, "s");
                    let _ = render(&f, std::slice::from_ref(&d), false);
                    let _ = render(&f, std::slice::from_ref(&d), true);
                    let _ = render_short(&f, &d);
                }
            }
        }
    }

    #[test]
    fn eof_span_points_at_end_of_last_line() {
        let f = file("PROGRAM p\n  LD x\n");
        let d = Diagnostic::error("IL0002", Span::new(17, 17), "expected `END_PROGRAM`");
        let r = render(&f, std::slice::from_ref(&d), false);
        assert!(r.contains(" --> t.il:2:7"), "{r}");
        let s = render_short(&f, &d);
        assert!(s.contains("\n --> t.il:2:7\n"), "{s}");
    }

    #[test]
    fn short_form() {
        let f = file("PROGRAM p\n\tLD\nEND_PROGRAM\n");
        let d = Diagnostic::error(
            "IL0003",
            Span::new(11, 13),
            "expected an operand after `LD`",
        )
        .with_label("here")
        .with_help("write `LD x`");
        let s = render_short(&f, &d);
        assert_eq!(
            s,
            "IL0003: expected an operand after `LD`\n --> t.il:2:2\n  |\n2 | \tLD\n  | \t^^ here\n  = help: write `LD x`"
        );
    }

    /// A name quoted from a file holding a line break, a lone CR, an escape
    /// sequence or a bidi override: no renderer starts a line with it.
    #[test]
    fn quoted_text_cannot_forge_a_line() {
        let evil = "x\nerror[IL0000]: fake\r\u{1b}[2K\u{85}\u{2028}\u{202e}y";
        let f = SourceFile::new(format!("a{evil}.il"), "PROGRAM p\n    LD x\nEND_PROGRAM\n");
        let d = Diagnostic::error("IL0003", Span::new(14, 18), format!("unknown `{evil}`"))
            .with_label(evil)
            .with_secondary(Span::new(0, 7), evil)
            .with_note(evil)
            .with_help(evil);
        let forged = |out: &str| {
            out.lines()
                .any(|l| l.trim_start().starts_with("error[IL0000]") || l.starts_with("IL0000"))
        };
        for out in [
            render(&f, std::slice::from_ref(&d), false),
            render(&f, std::slice::from_ref(&d), true),
            render_short(&f, &d),
        ] {
            assert!(!forged(&out), "{out}");
            assert!(
                !out.chars()
                    .any(|c| c == '\r' || c == '\u{85}' || c == '\u{2028}' || c == '\u{202e}'),
                "{out:?}"
            );
            // ESC only in the styles of the coloured render, never from the text.
            assert!(!out.contains("\u{1b}[2K"), "{out:?}");
        }
        let plain = render(&f, std::slice::from_ref(&d), false);
        assert!(
            plain.contains(r"unknown `x\nerror[IL0000]: fake\r\u{1b}[2K\u{85}\u{2028}\u{202e}y`"),
            "{plain}"
        );
        assert!(plain.contains(r" --> ax\nerror[IL0000]"), "{plain}");
    }

    /// Control characters in the source line itself are shown as U+FFFD and
    /// the carets stay under the span; a CRLF file is shown unchanged.
    #[test]
    fn control_characters_in_the_source_are_neutralised() {
        let f = file("PROGRAM p\n  \u{1b}[31m\r LD qq\nEND_PROGRAM\n");
        let lo = f.text.find("qq").unwrap();
        let d =
            Diagnostic::error("IL0004", Span::new(lo, lo + 2), "unknown `qq`").with_label("here");
        let r = render(&f, std::slice::from_ref(&d), false);
        assert!(!r.contains('\u{1b}') && !r.contains('\r'), "{r:?}");
        let line = r
            .lines()
            .find(|l| l.contains("LD qq"))
            .expect("source line");
        let carets = r.lines().find(|l| l.contains("^^")).expect("carets");
        let col = |s: &str, pat: &str| s[..s.find(pat).unwrap()].chars().count();
        assert_eq!(col(line, "qq"), col(carets, "^^"), "{r}");
        let crlf = file("PROGRAM p\r\n  LD qq\r\nEND_PROGRAM\r\n");
        let lo = crlf.text.find("qq").unwrap();
        let d = Diagnostic::error("IL0004", Span::new(lo, lo + 2), "unknown `qq`");
        assert!(!render(&crlf, &[d], false).contains('\u{FFFD}'));
    }
}
