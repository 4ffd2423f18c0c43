//! Diagnostics as JSON (`super::to_json`, which documents the fields): one
//! object per diagnostic, on one line, written by serde_json.

use std::io;

use serde::Serialize;
use serde_json::ser::{CharEscape, CompactFormatter, Formatter, Serializer};

use super::text::{display_span, unsafe_char};
use super::{Diagnostic, SourceFile};
use crate::ast::Span;

/// One diagnostic, in the order of the fields of the JSON object.
#[derive(Serialize)]
struct Object<'a> {
    file: &'a str,
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
    severity: &'static str,
    code: &'static str,
    message: &'a str,
    label: &'a str,
    secondary: Vec<Secondary<'a>>,
    notes: &'a [String],
    help: Option<&'a str>,
    rendered: &'a str,
}

/// A secondary span and its label.
#[derive(Serialize)]
struct Secondary<'a> {
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
    label: &'a str,
}

/// Start and end (line, column) of a span as shown.
fn positions(file: &SourceFile, span: Span) -> [(usize, usize); 2] {
    let (lo, hi) = display_span(&file.text, span);
    [file.line_col(lo as u32), file.line_col(hi as u32)]
}

/// serde_json's compact form, with every character that must not reach a
/// terminal ([`unsafe_char`]: controls, DEL, line separators, bidi
/// controls) written as `\uXXXX`, so that a JSON line shown in a log can
/// neither break nor reorder it. Besides `"` and `\`, serde_json itself
/// escapes only C0 controls, two of them as `\b` and `\f`: written as
/// `\u0008` and `\u000c` here, as every other control.
struct Escaping;

impl Formatter for Escaping {
    fn write_string_fragment<W: ?Sized + io::Write>(
        &mut self,
        out: &mut W,
        fragment: &str,
    ) -> io::Result<()> {
        let mut from = 0;
        for (i, c) in fragment.char_indices().filter(|&(_, c)| unsafe_char(c)) {
            out.write_all(&fragment.as_bytes()[from..i])?;
            // All of them are below U+FFFF: one `\uXXXX` each.
            write!(out, "\\u{:04x}", u32::from(c))?;
            from = i + c.len_utf8();
        }
        out.write_all(&fragment.as_bytes()[from..])
    }

    fn write_char_escape<W: ?Sized + io::Write>(
        &mut self,
        out: &mut W,
        escape: CharEscape,
    ) -> io::Result<()> {
        match escape {
            CharEscape::Backspace => out.write_all(b"\\u0008"),
            CharEscape::FormFeed => out.write_all(b"\\u000c"),
            _ => CompactFormatter.write_char_escape(out, escape),
        }
    }
}

/// `value` as one line of JSON.
fn write(value: &impl Serialize) -> String {
    let mut out = Vec::with_capacity(256);
    value
        .serialize(&mut Serializer::with_formatter(&mut out, Escaping))
        .expect("writing to a Vec does not fail, and every value here serialises");
    String::from_utf8(out).expect("serde_json writes UTF-8")
}

/// One diagnostic as one line of JSON (no line break inside or at the
/// end), with `rendered` (its rustc-style report) as the last field.
pub(super) fn object(file: &SourceFile, d: &Diagnostic, rendered: &str) -> String {
    let [(line, column), (end_line, end_column)] = positions(file, d.span);
    let secondary = d
        .secondary
        .iter()
        .map(|(span, label)| {
            let [(line, column), (end_line, end_column)] = positions(file, *span);
            Secondary {
                line,
                column,
                end_line,
                end_column,
                label,
            }
        })
        .collect();
    write(&Object {
        file: &file.name,
        line,
        column,
        end_line,
        end_column,
        severity: d.severity.as_str(),
        code: d.code,
        message: &d.message,
        label: &d.label,
        secondary,
        notes: &d.notes,
        help: d.help.as_deref(),
        rendered,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    use il_testkit::json::{get, parse};

    #[test]
    fn escaping() {
        let s = write(&"a\"b\\c\nd\te\r\u{1}\u{8}\u{c}\u{1f}\u{7f}é\u{85}\u{2028}\u{202e}/");
        assert_eq!(
            s,
            r#""a\"b\\c\nd\te\r\u0001\u0008\u000c\u001f\u007fé\u0085\u2028\u202e/""#
        );
        let all: String = (0u32..0x3000).filter_map(char::from_u32).collect();
        assert_eq!(parse(&write(&all)), all.as_str());
    }

    #[test]
    fn object_fields() {
        let f = SourceFile::new("dir\\a \"b\".il", "PROGRAM p\n  LD\nEND_PROGRAM\n");
        let d = Diagnostic::error(
            "IL0003",
            Span::new(12, 14),
            "expected an operand after `LD`",
        )
        .with_label("here \"quoted\"")
        .with_secondary(Span::new(0, 7), "in this program")
        .with_note("n1")
        .with_note("n2\tx");
        let j = object(&f, &d, "error[IL0003]: ...\n");
        assert!(!j.contains('\n'));
        let v = parse(&j);
        assert_eq!(get(&v, "file"), "dir\\a \"b\".il");
        assert_eq!(get(&v, "line"), 2);
        assert_eq!(get(&v, "column"), 3);
        assert_eq!(get(&v, "end_line"), 2);
        assert_eq!(get(&v, "end_column"), 5);
        assert_eq!(get(&v, "severity"), "error");
        assert_eq!(get(&v, "code"), "IL0003");
        assert_eq!(get(&v, "label"), "here \"quoted\"");
        assert_eq!(get(&v, "notes"), &serde_json::json!(["n1", "n2\tx"]));
        assert!(get(&v, "help").is_null());
        let sec = &get(&v, "secondary")[0];
        assert_eq!(get(sec, "line"), 1);
        assert_eq!(get(sec, "label"), "in this program");
        assert_eq!(get(&v, "rendered"), "error[IL0003]: ...\n");
        // The fields in their documented order.
        let at = |k: &str| j.find(&format!("\"{k}\":")).unwrap();
        let keys = [
            "file",
            "line",
            "column",
            "end_line",
            "end_column",
            "severity",
            "code",
            "message",
            "label",
            "secondary",
            "notes",
            "help",
            "rendered",
        ];
        assert!(keys.windows(2).all(|k| at(k[0]) < at(k[1])), "{j}");
    }

    #[test]
    fn help_and_odd_spans() {
        let f = SourceFile::new("x.il", "é");
        let d = Diagnostic::warning("IL0100", Span::new(1, 99), "w").with_help("h");
        let v = parse(&object(&f, &d, ""));
        assert_eq!(get(&v, "help"), "h");
        assert_eq!(get(&v, "severity"), "warning");
        assert_eq!(get(&v, "column"), 1);
        assert_eq!(get(&v, "end_column"), 2);
    }
}
