//! Bare instruction lists (`ilc check --snippet`): the standard's Table 51
//! compiles as the body of a PROGRAM named after the file, and every place
//! points into the file as written.

use il_codegen::diag::{Diagnostic, SourceFile};

const TABLE51: &str = "START: LD %IX1       (* PUSH BUTTON *)\n       ANDN %MX5      (* NOT INHIBITED *)\n       ST %QX2        (* FAN ON *)\n";

fn check(name: &str, text: &str) -> (SourceFile, Vec<Diagnostic>) {
    let f = SourceFile::new(name, text);
    let d = il_codegen::Program::new()
        .snippet(f.clone())
        .check()
        .into_diagnostics();
    (f, d.into_iter().next().unwrap())
}

#[test]
fn table_51_compiles_as_a_program_named_after_the_file() {
    let f = SourceFile::new("plc/table51.il", TABLE51);
    let checked = il_codegen::Program::new().snippet(f).check();
    assert!(!checked.has_errors(), "{}", checked.render(false));
    // The one warning (START is never jumped to) is on line 1 of the file.
    let d = &checked.diagnostics()[0];
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code, "IL0120");
    assert_eq!(d[0].span.lo, 0);
    let ir = checked.ir().unwrap();
    assert_eq!(ir[0].pous[0].name, "table51");
    let text = &checked.files(Default::default()).unwrap()[0];
    assert!(text.contains("pub struct table51"), "{text}");
    // The IL lines in the comments are the file's.
    assert!(text.contains("// 1: START: LD %IX1"), "{text}");
    assert!(text.contains("// 3: ST %QX2"), "{text}");
}

#[test]
fn names_without_declarations_are_listed_in_one_error() {
    let src = "    LD start\n    ANDN stop\n    ST motor\n    LD %IX0.0\n    ST motor\n    CAL t\n";
    let (f, d) = check("s2.il", src);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code, "IL0036");
    assert_eq!(
        d[0].message,
        "a bare instruction list has no declarations; these names need one: `start`, `stop`, `motor`, `t`"
    );
    assert_eq!(f.line_col(d[0].span.lo), (1, 8));
    let others: Vec<(usize, usize)> = d[0]
        .secondary
        .iter()
        .map(|(s, _)| f.line_col(s.lo))
        .collect();
    assert_eq!(others, [(2, 10), (3, 8), (6, 9)]);
}

#[test]
fn a_file_with_a_pou_is_no_snippet_and_errors_keep_their_lines() {
    let (f, d) = check(
        "p.il",
        "(* a program *)\nPROGRAM P\n    LD %IX0.0\nEND_PROGRAM\n",
    );
    let e: Vec<&Diagnostic> = d.iter().filter(|d| d.code == "IL0036").collect();
    assert_eq!(e.len(), 1, "{d:?}");
    assert!(e[0].message.ends_with("but this file declares a PROGRAM"));
    assert_eq!(f.line_col(e[0].span.lo), (2, 1));
    // A type error on line 2 of a snippet is reported on line 2.
    let (f, d) = check("t.il", "LD %IX0.0\nADD 1\nST %QX0.0\n");
    assert!(!d.is_empty());
    assert!(d.iter().all(|d| d.code != "IL0036"), "{d:?}");
    assert_eq!(f.line_col(d[0].span.lo).0, 2, "{d:?}");
}
