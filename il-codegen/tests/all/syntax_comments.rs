//! Comments do not nest (issue 29, item 5): the text after the first `*)`
//! of `(* outer (* inner *) still comment? *)` is read as IL, and its
//! errors are replaced by one that says where the comment ended, with the
//! inner `(*` marked. A comment that holds a `(*` and whose rest reads as
//! IL is accepted.

use crate::syntax_common::*;

const MESSAGE: &str = "the comment ended at this `*)`: comments do not nest";

/// The one diagnostic of `src` (parse only): IL0038 at `close` (line,
/// column), its inner `(*` at `inner`.
fn nested_at(src: &str, close: (usize, usize), inner: (usize, usize)) {
    let f = SourceFile::new("t.il", src);
    let (_, d) = parse(&f);
    assert_eq!(d.len(), 1, "{src}\n{}", show(&f, &d));
    let d = &d[0];
    assert_eq!(
        (d.code, f.line_col(d.span.lo), d.message.as_str()),
        ("IL0038", close, MESSAGE),
        "{src}"
    );
    assert_eq!(d.span.hi - d.span.lo, 2, "the span is the `*)`");
    assert_eq!(d.label, "the comment ends here");
    let (at, label) = &d.secondary[0];
    assert_eq!(f.line_col(at.lo), inner, "{src}");
    assert_eq!(
        label,
        "this `(*` does not open a comment inside the comment"
    );
    assert_eq!(
        d.notes,
        ["the text after this `*)` is read as IL, not as comment"]
    );
}

const MAIN: &str = "PROGRAM Main\nVAR x : INT; END_VAR\nLD 1\nST x\nEND_PROGRAM\n";

#[test]
fn outside_a_pou() {
    nested_at(
        &format!("(* outer (* inner *) still comment? *)\n{MAIN}"),
        (1, 19),
        (1, 10),
    );
    nested_at(&format!("{MAIN}(* a (* b *) c *)\n"), (6, 11), (6, 6));
}

#[test]
fn in_a_body() {
    nested_at(
        "PROGRAM Main\nVAR x : INT; END_VAR\nLD 1 (* outer (* inner *) still comment *)\nST x\nEND_PROGRAM\n",
        (3, 24),
        (3, 15),
    );
    nested_at(
        "PROGRAM Main\nVAR x : INT; END_VAR\n(* a (* b *) c *) LD 1\nST x\nEND_PROGRAM\n",
        (3, 11),
        (3, 6),
    );
    // Code commented out with its own comments: the first `*)` is the
    // inner one's, and what follows it is code up to the stray `*)`.
    nested_at(
        "PROGRAM Main\nVAR x : INT; END_VAR\n(* disabled:\nLD 2 (* old *)\nST x\n*)\nLD 1\nST x\nEND_PROGRAM\n",
        (4, 13),
        (4, 6),
    );
}

#[test]
fn in_declarations() {
    nested_at(
        "PROGRAM Main\nVAR x : INT; (* outer (* inner *) still comment *) y : INT; END_VAR\nLD 1\nST x\nEND_PROGRAM\n",
        (2, 32),
        (2, 23),
    );
    nested_at(
        &format!("TYPE (* a (* b *) c *) T : INT; END_TYPE\n{MAIN}"),
        (1, 16),
        (1, 11),
    );
    nested_at(
        "PROGRAM Main (* a (* b *) c *)\nVAR x : INT; END_VAR\nLD 1\nST x\nEND_PROGRAM\n",
        (1, 24),
        (1, 19),
    );
    nested_at(
        "CONFIGURATION C\nVAR_GLOBAL g : INT; (* a (* b *) c *) END_VAR\n\
         RESOURCE R ON PLC\nEND_RESOURCE\nEND_CONFIGURATION\n",
        (2, 31),
        (2, 26),
    );
}

#[test]
fn each_nested_comment_once_and_other_errors_kept() {
    let src = "PROGRAM Main\nVAR x : INT; END_VAR\nLD 1 (* a (* b *) c d e *)\nST x (* fine (* this *)\n\
               LD 2 (* d (* e *) f *)\nST x\nLD\nEND_PROGRAM\n";
    let e: Vec<(&str, usize, usize)> = errs(src).into_iter().map(|e| (e.0, e.1, e.2)).collect();
    assert_eq!(
        e,
        [("IL0038", 3, 16), ("IL0038", 5, 16), ("IL0003", 7, 1)],
        "{src}"
    );
    // Instructions outside a POU after the comment are still reported.
    let src = format!("(* a (* b *) c *)\nLD x\nST y\n{MAIN}");
    let e: Vec<(&str, usize, usize)> = errs(&src).into_iter().map(|e| (e.0, e.1, e.2)).collect();
    assert_eq!(e, [("IL0038", 1, 11), ("IL0011", 2, 1)], "{src}");
}

#[test]
fn a_comment_whose_rest_reads_as_il_is_accepted() {
    for src in [
        format!("(* just (* one *)\n{MAIN}"),
        format!("(* (* (* *)\n{MAIN}"),
        "PROGRAM Main\nVAR x : INT; (* see (* here *) END_VAR\nLD 1 (* a (* b *)\nST x\nEND_PROGRAM\n"
            .to_string(),
        // Balanced only much later: the rest is read, and it is fine.
        format!("(* note (* x *)\n{MAIN}(* later *)\n"),
    ] {
        ok(&src);
        let f = SourceFile::new("t.il", src.clone());
        let checked = il_codegen::Program::new().il(f).check();
        assert!(!checked.has_errors(), "{src}");
    }
}

#[test]
fn the_checker_errors_of_the_rest_of_the_line_are_named_too() {
    // The rest of the line (`(*` and `*)` never balance) parses, as a call
    // of a function `c`; the checker's error becomes the comment's.
    let src = "PROGRAM Main\nVAR x : INT; END_VAR\nLD 1\nST x\n(* a (* b *) c\nEND_PROGRAM\n";
    let e = crate::checked::errors(src);
    assert_eq!(
        e,
        [("IL0038".to_string(), 5, 11, MESSAGE.to_string())],
        "{src}"
    );
}

#[test]
fn an_unclosed_comment_with_a_comment_inside_is_never_closed() {
    let src = format!("{MAIN}(* a (* b\nLD x\n");
    let e: Vec<(&str, usize, usize)> = errs(&src).into_iter().map(|e| (e.0, e.1, e.2)).collect();
    assert_eq!(e, [("IL0002", 6, 1)], "{src}");
}
