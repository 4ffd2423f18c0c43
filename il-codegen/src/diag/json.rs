//! Diagnostics as JSON for editors: one object per diagnostic, written by
//! hand (no serde).
//!
//! ```json
//! {"file":"a.il","line":12,"column":5,"end_line":12,"end_column":7,
//!  "severity":"error","code":"IL0003","message":"...","label":"...",
//!  "secondary":[{"line":3,"column":1,"end_line":3,"end_column":4,"label":"..."}],
//!  "notes":["..."],"help":"..."|null,"rendered":"error[IL0003]: ..."}
//! ```
//!
//! Lines and columns are 1-based; columns count characters (Unicode scalar
//! values), not bytes; `end_*` is the position just after the span.

use std::fmt::Write as _;

use super::render::{display_span, render};
use super::{Diagnostic, SourceFile};
use crate::ast::Span;

/// Append `s` to `out` as a JSON string literal (with the quotes).
pub fn write_json_string(out: &mut String, s: &str) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            // Other C0 controls, DEL, and the two separators JavaScript chokes on.
            c if (c as u32) < 0x20 || c == '\u{7f}' || c == '\u{2028}' || c == '\u{2029}' => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

fn positions(out: &mut String, file: &SourceFile, span: Span) {
    let (lo, hi) = display_span(&file.text, span);
    let (line, column) = file.line_col(lo as u32);
    let (end_line, end_column) = file.line_col(hi as u32);
    let _ = write!(
        out,
        "\"line\":{line},\"column\":{column},\"end_line\":{end_line},\"end_column\":{end_column}"
    );
}

/// One diagnostic as one line of JSON (no line break inside or at the end).
pub fn to_json(file: &SourceFile, d: &Diagnostic) -> String {
    let mut out = String::with_capacity(256);
    out.push_str("{\"file\":");
    write_json_string(&mut out, &file.name);
    out.push(',');
    positions(&mut out, file, d.span);
    out.push_str(",\"severity\":");
    write_json_string(&mut out, d.severity.as_str());
    out.push_str(",\"code\":");
    write_json_string(&mut out, d.code);
    out.push_str(",\"message\":");
    write_json_string(&mut out, &d.message);
    out.push_str(",\"label\":");
    write_json_string(&mut out, &d.label);
    out.push_str(",\"secondary\":[");
    for (i, (span, label)) in d.secondary.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push('{');
        positions(&mut out, file, *span);
        out.push_str(",\"label\":");
        write_json_string(&mut out, label);
        out.push('}');
    }
    out.push_str("],\"notes\":[");
    for (i, note) in d.notes.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        write_json_string(&mut out, note);
    }
    out.push_str("],\"help\":");
    match &d.help {
        Some(h) => write_json_string(&mut out, h),
        None => out.push_str("null"),
    }
    out.push_str(",\"rendered\":");
    write_json_string(&mut out, &render(file, std::slice::from_ref(d), false));
    out.push('}');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    use il_testkit::json::{J, get, parse};

    #[test]
    fn escaping() {
        let mut s = String::new();
        write_json_string(&mut s, "a\"b\\c\nd\te\r\u{1}\u{1f}\u{7f}é\u{2028}");
        assert_eq!(s, r#""a\"b\\c\nd\te\r\u0001\u001f\u007fé\u2028""#);
        let all: String = (0u32..0x300).filter_map(char::from_u32).collect();
        let mut s = String::new();
        write_json_string(&mut s, &all);
        assert_eq!(parse(&s), J::Str(all));
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
        let j = to_json(&f, &d);
        assert!(!j.contains('\n'));
        let v = parse(&j);
        assert_eq!(get(&v, "file"), &J::Str("dir\\a \"b\".il".into()));
        assert_eq!(get(&v, "line"), &J::Num(2.0));
        assert_eq!(get(&v, "column"), &J::Num(3.0));
        assert_eq!(get(&v, "end_line"), &J::Num(2.0));
        assert_eq!(get(&v, "end_column"), &J::Num(5.0));
        assert_eq!(get(&v, "severity"), &J::Str("error".into()));
        assert_eq!(get(&v, "code"), &J::Str("IL0003".into()));
        assert_eq!(get(&v, "label"), &J::Str("here \"quoted\"".into()));
        assert_eq!(
            get(&v, "notes"),
            &J::Arr(vec![J::Str("n1".into()), J::Str("n2\tx".into())])
        );
        assert_eq!(get(&v, "help"), &J::Null);
        let J::Arr(sec) = get(&v, "secondary") else {
            panic!()
        };
        assert_eq!(get(&sec[0], "line"), &J::Num(1.0));
        assert_eq!(get(&sec[0], "label"), &J::Str("in this program".into()));
        let J::Str(r) = get(&v, "rendered") else {
            panic!()
        };
        assert_eq!(r, &render(&f, &[d], false));
        assert!(r.starts_with("error[IL0003]"));
    }

    #[test]
    fn help_and_odd_spans() {
        let f = SourceFile::new("x.il", "é");
        let d = Diagnostic::warning("IL0100", Span::new(1, 99), "w").with_help("h");
        let v = parse(&to_json(&f, &d));
        assert_eq!(get(&v, "help"), &J::Str("h".into()));
        assert_eq!(get(&v, "severity"), &J::Str("warning".into()));
        assert_eq!(get(&v, "column"), &J::Num(1.0));
        assert_eq!(get(&v, "end_column"), &J::Num(2.0));
    }
}
