//! The documentation a declaration carries in the IL: the comment lines just
//! above a POU (`(* A motor starter ... *)`), and the comment after a
//! variable's `;` on its line (`start : BOOL; (* push button *)`). The
//! checker records them in the IR ([`crate::ir::Var::doc`],
//! [`crate::ir::CheckedPou::doc`]) so that generated items carry the
//! engineer's words as Rust docs.
//!
//! Read from the lines of the source, not from the lexer, which skips
//! comments: only a whole comment at the end of a declaration line, or
//! lines that hold nothing but comments, count; anything else gives none.

use crate::ast::Span;
use crate::diag::SourceFile;

/// At most this many lines above a POU are read for its comment.
const MAX_LINES: usize = 40;

/// The comment after the declaration at `span` on its line, if the line
/// ends with one: `x : INT; (* counts starts *)` gives `counts starts`.
pub(crate) fn trailing(file: &SourceFile, span: Span) -> Option<String> {
    let line = file.line_text(file.line_of(span.lo)).trim_end();
    let (code, inner) = if let Some(body) = line.strip_suffix("*)") {
        let open = body.rfind("(*")?;
        (&body[..open], &body[open + 2..])
    } else {
        let open = line.find("//")?;
        (&line[..open], &line[open + 2..])
    };
    // The comment must follow the declaration's `;` directly (not a
    // string's `//`, not a second comment).
    (code.trim_end().ends_with(';') && !inner.contains("*)"))
        .then(|| tidy(&[inner]))
        .flatten()
}

/// The comment on the lines just above `span`'s line (pragma lines such as
/// `{extern}` in between are passed over), if those lines hold only
/// comments: one `(* ... *)` over several lines, or several one-line ones.
pub(crate) fn leading(file: &SourceFile, span: Span) -> Option<String> {
    let mut line = file.line_of(span.lo);
    let mut lines: Vec<&str> = Vec::new();
    let mut open = false;
    while line > 1 && lines.len() < MAX_LINES {
        line -= 1;
        let t = file.line_text(line).trim();
        if !open && lines.is_empty() && t.starts_with('{') && t.ends_with('}') {
            continue;
        }
        if open {
            // Inside a comment that ends further down: until its `(*`.
            if let Some(rest) = t.strip_prefix("(*") {
                lines.push(rest);
                open = false;
            } else if t.contains("(*") || t.contains("*)") {
                return None;
            } else {
                lines.push(t);
            }
        } else if let Some(body) = t.strip_suffix("*)") {
            if let Some(one) = body.strip_prefix("(*") {
                lines.push(one);
            } else {
                open = true;
                lines.push(body);
            }
        } else if let Some(rest) = t.strip_prefix("//") {
            lines.push(rest);
        } else {
            break;
        }
    }
    if open {
        return None;
    }
    lines.reverse();
    tidy(&lines)
}

/// The lines trimmed, those that are only decoration (`*****`, `-----`)
/// dropped; `None` when nothing is left.
fn tidy(lines: &[&str]) -> Option<String> {
    let kept: Vec<&str> = lines
        .iter()
        .map(|l| l.trim().trim_matches('*').trim())
        .filter(|l| l.chars().any(char::is_alphanumeric))
        .collect();
    (!kept.is_empty()).then(|| kept.join("\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(text: &str, word: &str) -> (SourceFile, Span) {
        let lo = text.find(word).expect("word");
        (
            SourceFile::new("t.il", text),
            Span::new(lo, lo + word.len()),
        )
    }

    #[test]
    fn a_trailing_comment_is_the_variables() {
        let (f, s) = at(
            "VAR\n  n : INT := 1; (* counts; starts *)\nEND_VAR\n",
            "n :",
        );
        assert_eq!(trailing(&f, s).as_deref(), Some("counts; starts"));
        let (f, s) = at("VAR\n  n : INT; // line comment\nEND_VAR\n", "n :");
        assert_eq!(trailing(&f, s).as_deref(), Some("line comment"));
        for text in [
            "VAR\n  n : INT;\nEND_VAR\n",
            "VAR\n  n : INT (* not after ; *)\nEND_VAR\n",
            "VAR\n  n : INT; (* open\n*)\nEND_VAR\n",
            "VAR\n  n : INT; (* a *) x (* b *)\nEND_VAR\n",
            "VAR\n  n : INT; (* ***** *)\nEND_VAR\n",
            "VAR\n  n : STRING := 'http://x';\nEND_VAR\n",
        ] {
            let (f, s) = at(text, "n :");
            assert_eq!(trailing(&f, s), None, "{text}");
        }
    }

    #[test]
    fn the_comment_lines_above_a_pou_are_its() {
        let text = "(* not this one *)\n\n(*****\n * A motor starter\n * with seal-in.\n *****)\n{extern}\nFUNCTION_BLOCK M\nEND_FUNCTION_BLOCK\n";
        let (f, s) = at(text, "M\n");
        assert_eq!(
            leading(&f, s).as_deref(),
            Some("A motor starter\nwith seal-in.")
        );
        let (f, s) = at("(* one *)\n// two\nPROGRAM P\nEND_PROGRAM\n", "P\n");
        assert_eq!(leading(&f, s).as_deref(), Some("one\ntwo"));
        for text in [
            "PROGRAM P\nEND_PROGRAM\n",
            "END_TYPE\nPROGRAM P\nEND_PROGRAM\n",
            "x *)\nPROGRAM P\nEND_PROGRAM\n",
        ] {
            let (f, s) = at(text, "P\n");
            assert_eq!(leading(&f, s), None, "{text}");
        }
    }
}
