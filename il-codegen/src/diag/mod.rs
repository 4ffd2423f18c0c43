//! Diagnostics: what every stage reports, and the source text they point into.
//!
//! Stages collect [`Diagnostic`]s instead of stopping at the first; the front
//! ends render them (`render` for terminals and build scripts, `to_json` for
//! editors, `render_short` for `compile_error!` inside `il!`).

use crate::ast::Span;

pub mod codes;
mod did_you_mean;
#[cfg(feature = "json")]
mod json;
pub mod render;
pub(crate) mod text;

pub use did_you_mean::suggest;
#[cfg(feature = "build")]
pub use render::render;
pub use render::render_short;

/// One diagnostic as one line of JSON, for editors (`ilc check
/// --message-format json`):
///
/// ```json
/// {"file":"a.il","line":12,"column":5,"end_line":12,"end_column":7,
///  "severity":"error","code":"IL0003","message":"...","label":"...",
///  "secondary":[{"line":3,"column":1,"end_line":3,"end_column":4,"label":"..."}],
///  "notes":["..."],"help":"..."|null,"rendered":"error[IL0003]: ..."}
/// ```
///
/// Lines and columns are 1-based; columns count characters (Unicode scalar
/// values), not bytes; `end_*` is the position just after the span;
/// `rendered` is [`render()`]'s report of it, without colours.
#[cfg(all(feature = "build", feature = "json"))]
pub fn to_json(file: &SourceFile, d: &Diagnostic) -> String {
    json::object(file, d, &render(file, std::slice::from_ref(d), false))
}

/// A source file and its line table.
#[derive(Clone, Debug)]
pub struct SourceFile {
    /// The name shown in messages (a path as the user gave it).
    pub name: String,
    /// The whole text.
    pub text: String,
    /// Byte offset of each line's start: `u32`, as spans, and sized from a
    /// count of the line breaks, so 4 bytes a line (for a program of short
    /// lines a looser table costs about as much as the text).
    line_starts: Vec<u32>,
    /// Characters before each `CHAR_BLOCK`-byte block of the text: a column
    /// is then counted from the nearest block, not from the line start, so
    /// many diagnostics on one long line stay linear in total.
    block_chars: Vec<u32>,
    /// What reading the file from its bytes reported ([`crate::read`]: an
    /// encoding guessed, bytes invalid in its encoding), in positions of
    /// `text`: the pipeline adds them to the file's diagnostics, so every
    /// front end shows them with the rest.
    pub read_diagnostics: Vec<Diagnostic>,
}

/// Bytes per entry of [`SourceFile::block_chars`].
const CHAR_BLOCK: usize = 256;

/// Whether a byte starts a character (is not a UTF-8 continuation byte).
fn starts_char(b: u8) -> bool {
    b & 0xC0 != 0x80
}

impl SourceFile {
    /// A file from its name and text (builds the line table).
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> Self {
        let text = text.into();
        // A count of the line breaks sizes the line table exactly; then one
        // pass over the bytes fills both tables: a byte loop finds the line
        // ends of short lines faster than a string searcher restarted at
        // each (about 180 instructions a line).
        let lines = text.bytes().filter(|&b| b == b'\n').count();
        let mut line_starts = Vec::with_capacity(lines + 1);
        line_starts.push(0);
        let mut block_chars = Vec::with_capacity(text.len() / CHAR_BLOCK + 1);
        let mut n = 0u32;
        for (k, block) in text.as_bytes().chunks(CHAR_BLOCK).enumerate() {
            block_chars.push(n);
            n += block.iter().filter(|&&b| starts_char(b)).count() as u32;
            let base = k * CHAR_BLOCK + 1;
            for (i, &b) in block.iter().enumerate() {
                if b == b'\n' {
                    // Offsets past 4 GiB, as spans, saturate.
                    line_starts.push(u32::try_from(base + i).unwrap_or(u32::MAX));
                }
            }
        }
        SourceFile {
            name: name.into(),
            text,
            line_starts,
            block_chars,
            read_diagnostics: Vec::new(),
        }
    }

    /// Characters in `text[..offset]` (offset clamped to the text).
    fn chars_before(&self, offset: usize) -> usize {
        let offset = offset.min(self.text.len());
        // The text's end in a text of whole blocks has no entry of its own:
        // count it from the last block (a base of 0 there would underflow
        // the column at the end of a 4096-byte file).
        let block = (offset / CHAR_BLOCK).min(self.block_chars.len().saturating_sub(1));
        let base = self.block_chars.get(block).copied().unwrap_or(0) as usize;
        let rest = &self.text.as_bytes()[block * CHAR_BLOCK..offset];
        base + rest.iter().filter(|&&b| starts_char(b)).count()
    }

    /// The 1-based line of a byte offset (what `line_col` gives, without
    /// counting the column's characters).
    pub fn line_of(&self, offset: u32) -> usize {
        self.line_of_near(offset, 0)
    }

    /// [`Self::line_of`], looking first at the 1-based line `near` (see
    /// [`Self::line_col_near`]).
    pub fn line_of_near(&self, offset: u32, near: usize) -> usize {
        let offset = (offset as usize).min(self.text.len());
        self.line_index(offset, near) + 1
    }

    /// The 0-based line holding `offset` (at most the text's length): line
    /// `near - 1` or `near` when it is one of them, else a binary search.
    fn line_index(&self, offset: usize, near: usize) -> usize {
        let starts = &self.line_starts;
        for l in [near.saturating_sub(1), near] {
            let Some(&lo) = starts.get(l) else {
                break;
            };
            if lo as usize <= offset && starts.get(l + 1).is_none_or(|&hi| offset < hi as usize) {
                return l;
            }
        }
        starts.partition_point(|&s| s as usize <= offset) - 1
    }

    /// 1-based line and 1-based column (in characters) of a byte offset.
    pub fn line_col(&self, offset: u32) -> (usize, usize) {
        self.line_col_near(offset, 0)
    }

    /// [`Self::line_col`], looking first at the 1-based line `near` and the
    /// one after it: a walk over a body asks for each instruction's line
    /// in order, and searching the whole table each time would be about a
    /// tenth of the check's own work.
    pub fn line_col_near(&self, offset: u32, near: usize) -> (usize, usize) {
        let offset = (offset as usize).min(self.text.len());
        let line = self.line_index(offset, near);
        let start = self.line_starts[line] as usize;
        // Most columns are a few bytes from the line start: count those
        // directly; far ones from the nearest block (long lines stay linear).
        crate::step_counter::add(1 + (offset - start.min(offset)).min(CHAR_BLOCK) as u64);
        let col = match self.text.as_bytes().get(start..offset) {
            Some(rest) if rest.len() <= CHAR_BLOCK => {
                rest.iter().filter(|&&b| starts_char(b)).count()
            }
            _ => self.chars_before(offset) - self.chars_before(start),
        };
        (line + 1, col + 1)
    }

    /// The byte offset where a 1-based line starts (the text's end past the
    /// last line).
    pub fn line_start(&self, line: usize) -> usize {
        self.line_starts
            .get(line.wrapping_sub(1))
            .map_or(self.text.len(), |&s| s as usize)
    }

    /// The byte offset where a 1-based line ends, before its `\n`.
    pub fn line_end(&self, line: usize) -> usize {
        self.line_starts
            .get(line)
            .map_or(self.text.len(), |&next| (next as usize).saturating_sub(1))
    }

    /// The text of a 1-based line, without its line break.
    pub fn line_text(&self, line: usize) -> &str {
        if line == 0 || line > self.line_starts.len() {
            return "";
        }
        self.text
            .get(self.line_start(line)..self.line_end(line))
            .unwrap_or("")
            .trim_end_matches('\r')
    }

    /// The source text of a span ("" if the span is not on char boundaries).
    pub fn snippet(&self, span: Span) -> &str {
        self.text.get(span.range()).unwrap_or("")
    }
}

/// How bad a [`Diagnostic`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// The input is refused: no code is generated.
    Error,
    /// Code is generated, but something looks wrong.
    Warning,
}

impl Severity {
    /// `"error"` / `"warning"`, as rendered and in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// A change to the source that resolves a diagnostic: edits that replace
/// each span's text (an empty span inserts).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fix {
    /// What it does, as a command: "Change to `count`".
    pub title: String,
    /// The edits, in the order of their spans, none overlapping.
    pub edits: Vec<(Span, String)>,
}

/// One message about one place in the source.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Stable code, `IL0001` ...; see [`codes`].
    pub code: &'static str,
    /// Error or warning.
    pub severity: Severity,
    /// What is wrong, in a PLC engineer's words.
    pub message: String,
    /// Where.
    pub span: Span,
    /// Text under the caret (short; may be empty).
    pub label: String,
    /// Other places that explain this one (e.g. the other path into a label).
    pub secondary: Vec<(Span, String)>,
    /// `= note: ...` lines.
    pub notes: Vec<String>,
    /// `= help: ...` (a suggestion).
    pub help: Option<String>,
    /// Changes to the source that resolve it, as an editor offers them
    /// (quick fixes): the help of a "did you mean", a conversion to insert.
    pub fixes: Vec<Fix>,
    /// For `IL0032` only: how many diagnostics (and errors) it stands for.
    cut: (usize, usize),
}

impl Diagnostic {
    /// An error with a code, a place and a message (no label, notes or help).
    pub fn error(code: &'static str, span: Span, message: impl Into<String>) -> Self {
        Diagnostic {
            code,
            severity: Severity::Error,
            message: message.into(),
            span,
            label: String::new(),
            secondary: Vec::new(),
            notes: Vec::new(),
            help: None,
            fixes: Vec::new(),
            cut: (0, 0),
        }
    }
    /// A warning with a code, a place and a message.
    pub fn warning(code: &'static str, span: Span, message: impl Into<String>) -> Self {
        Diagnostic {
            severity: Severity::Warning,
            ..Self::error(code, span, message)
        }
    }

    /// A source that a feature left out of this build reads: one error at
    /// the file's start, saying `file` is `what` and which il-macros
    /// feature reads it (`il!` builds the compiler without them).
    #[cfg_attr(all(feature = "plcopen", feature = "exp"), allow(dead_code))]
    pub(crate) fn not_built(
        code: &'static str,
        file: &SourceFile,
        what: &str,
        label: &str,
        feature: &str,
    ) -> Self {
        let first = file.text.chars().next().map_or(0, char::len_utf8);
        Diagnostic::error(
            code,
            Span::new(0, first),
            format!("`{}` is {what}, and this build of the IL compiler cannot read it", file.name),
        )
        .with_label(label)
        .with_note(format!(
            "turn on the `{feature}` feature: `il-macros = {{ version = \"0.1\", features = [\"{feature}\"] }}` (il-codegen has it by default)"
        ))
    }

    /// With the text under the caret.
    pub fn with_label(mut self, label: impl Into<String>) -> Self {
        self.label = label.into();
        self
    }
    /// With another place and its label.
    pub fn with_secondary(mut self, span: Span, label: impl Into<String>) -> Self {
        self.secondary.push((span, label.into()));
        self
    }
    /// With a `= note:` line.
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }
    /// With a `= help:` suggestion.
    pub fn with_help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into());
        self
    }
    /// "did you mean `name`?": the help, and the fix that writes `name`
    /// at `span` (the misspelled name).
    pub fn did_you_mean(&mut self, span: Span, name: &str) -> &mut Self {
        self.help = Some(format!("did you mean `{name}`?"));
        self.fixes.push(Fix {
            title: format!("Change to `{name}`"),
            edits: vec![(span, name.to_string())],
        });
        self
    }
    /// In-place forms of the builders, for diagnostics already pushed.
    pub fn add_secondary(&mut self, span: Span, label: impl Into<String>) -> &mut Self {
        self.secondary.push((span, label.into()));
        self
    }
    /// Replace the text under the caret.
    pub fn set_label(&mut self, label: impl Into<String>) -> &mut Self {
        self.label = label.into();
        self
    }
    /// Replace the suggestion.
    pub fn set_help(&mut self, help: impl Into<String>) -> &mut Self {
        self.help = Some(help.into());
        self
    }
    /// Add a `= note:` line.
    pub fn add_note(&mut self, note: impl Into<String>) -> &mut Self {
        self.notes.push(note.into());
        self
    }
    /// Whether it is an error (refuses the input) rather than a warning.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// The most diagnostics kept for one file: beyond this a file is usually not
/// IL at all, and rendering every message would cost more than it tells.
pub const MAX_PER_FILE: usize = 200;

/// Keep the first [`MAX_PER_FILE`] diagnostics of one file (sorted by
/// position) and replace the rest with one `IL0032` that counts them; an
/// error stays an error so that a cut list never turns a failed check into
/// a passed one.
pub fn limit(diags: &mut Vec<Diagnostic>) {
    let too_many = codes::TOO_MANY;
    if diags.len() <= MAX_PER_FILE && !diags.iter().any(|d| d.code == too_many) {
        return;
    }
    // An earlier stage's count is carried over, so limiting twice counts once.
    let (mut cut, mut cut_errors, mut at) = (0usize, 0usize, None);
    diags.retain(|d| {
        if d.code != too_many {
            return true;
        }
        cut += d.cut.0;
        cut_errors += d.cut.1;
        at = Some(d.span);
        false
    });
    if diags.len() > MAX_PER_FILE {
        let rest = diags.split_off(MAX_PER_FILE);
        at = Some(rest[0].span);
        cut += rest.len();
        cut_errors += rest.iter().filter(|d| d.is_error()).count();
    }
    let Some(at) = at else { return };
    diags.push(Diagnostic::not_shown(at, cut, cut_errors));
}

impl Diagnostic {
    /// `cut` diagnostics (`cut_errors` of them errors) from `at` on are
    /// not shown: what [`limit`] leaves at the end of a cut list, and what
    /// a stage that stops keeping diagnostics early reports instead of
    /// them (it carries the counts, which [`limit`] adds up).
    pub(crate) fn not_shown(at: Span, cut: usize, cut_errors: usize) -> Diagnostic {
        let message = format!(
            "{cut} more diagnostics in this file are not shown ({cut_errors} of them errors)"
        );
        let mut d = if cut_errors > 0 {
            Diagnostic::error(codes::TOO_MANY, at, message)
        } else {
            Diagnostic::warning(codes::TOO_MANY, at, message)
        }
        .with_help(format!(
            "only the first {MAX_PER_FILE} are listed; fix those first"
        ));
        d.cut = (cut, cut_errors);
        d
    }
}

/// True when any diagnostic is an error.
pub fn has_errors(diags: &[Diagnostic]) -> bool {
    diags.iter().any(Diagnostic::is_error)
}

#[cfg(all(test, feature = "build", feature = "json"))]
mod json_tests {
    use super::*;
    use il_testkit::json::{get, parse};

    /// `rendered` is the plain report; text quoted from a file (a line
    /// break, a lone CR, an escape sequence, a bidi override) stays escaped
    /// and the object on one line.
    #[test]
    fn rendered_is_the_report_and_quoted_text_stays_escaped() {
        let evil = "x\nerror[IL0000]: fake\r\u{1b}[2K\u{85}\u{2028}\u{202e}y";
        let f = SourceFile::new(format!("a{evil}.il"), "PROGRAM p\n    LD x\nEND_PROGRAM\n");
        let d = Diagnostic::error("IL0003", Span::new(14, 18), format!("unknown `{evil}`"))
            .with_label(evil)
            .with_secondary(Span::new(0, 7), evil)
            .with_note(evil)
            .with_help(evil);
        let j = to_json(&f, &d);
        assert!(
            !j.chars()
                .any(|c| c.is_control() || c == '\u{2028}' || c == '\u{202e}'),
            "{j:?}"
        );
        assert!(
            j.contains(r"x\nerror[IL0000]: fake\r\u001b[2K\u0085\u2028\u202ey"),
            "{j}"
        );
        let v = parse(&j);
        let rendered = render(&f, std::slice::from_ref(&d), false);
        assert_eq!(get(&v, "rendered"), rendered.as_str());
    }
}
