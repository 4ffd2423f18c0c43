//! The help a new user gets on common first mistakes: the hint names what
//! they most likely meant, spelled as they wrote it.

use il_codegen::diag::{Diagnostic, SourceFile};

fn check(files: &[(&str, &str)]) -> Vec<Vec<Diagnostic>> {
    files
        .iter()
        .fold(il_codegen::Program::new(), |p, (n, t)| {
            p.il(SourceFile::new(*n, *t))
        })
        .check()
        .into_diagnostics()
}

fn helps(src: &str) -> Vec<(String, String)> {
    check(&[("t.il", src)])[0]
        .iter()
        .map(|d| (d.code.to_string(), d.help.clone().unwrap_or_default()))
        .collect()
}

#[test]
fn a_duration_without_t_sharp_suggests_it() {
    let h = helps(
        "PROGRAM P\nVAR t : TIME; END_VAR\n    LD 5s\n    ST t\n    LD 1h_30m\n    ST t\n    LD 5x\n    ST t\nEND_PROGRAM\n",
    );
    assert_eq!(
        h[0],
        ("IL0018".into(), "a duration is written `T#5s`".into())
    );
    assert_eq!(h[1].1, "a duration is written `T#1h_30m`");
    assert_eq!(
        h[2],
        ("IL0018".into(), String::new()),
        "`5x` is no duration"
    );
}

#[test]
fn a_number_stored_into_a_bool_suggests_a_comparison_first() {
    let h = helps(
        "PROGRAM P\nVAR b : BOOL; n : INT; END_VAR\n    LD n\n    ADD 10\n    ST b\nEND_PROGRAM\n",
    );
    assert_eq!(h.len(), 1);
    assert_eq!(h[0].0, "IL0106");
    assert!(
        h[0].1
            .starts_with("to test the value, compare it first (`GT 0`"),
        "{}",
        h[0].1
    );
    assert!(h[0].1.ends_with("`INT_TO_BOOL`"), "{}", h[0].1);
    // Between numbers, the conversion alone.
    let h = helps("PROGRAM P\nVAR r : REAL; n : INT; END_VAR\n    LD n\n    ST r\nEND_PROGRAM\n");
    assert_eq!(h[0].1, "convert with `INT_TO_REAL`");
}

#[test]
fn a_label_suggestion_is_spelled_as_declared() {
    let h = helps(
        "PROGRAM P\nVAR b : BOOL; END_VAR\n    LD b\n    JMPC fulll\n    RET\nFull:\n    LD b\nEND_PROGRAM\n",
    );
    assert_eq!(h[0], ("IL0102".into(), "did you mean `Full`?".into()));
}

#[test]
fn a_duplicate_pou_name_does_not_hide_the_errors_in_its_body() {
    let a = "FUNCTION_BLOCK M\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_FUNCTION_BLOCK\n";
    let b = "FUNCTION_BLOCK M\nVAR x : INT; b : BOOL; END_VAR\n    LD x\n    ST b\nEND_FUNCTION_BLOCK\n";
    let d = check(&[("a.il", a), ("b.il", b)]);
    assert!(d[0].is_empty(), "{:?}", d[0]);
    let codes: Vec<(&str, u32)> = d[1].iter().map(|d| (d.code, d.span.lo)).collect();
    assert_eq!(codes.len(), 2, "{:?}", d[1]);
    assert_eq!(codes[0].0, "IL0104");
    assert_eq!(codes[1].0, "IL0106", "the duplicate's own body is checked");
    assert_eq!(codes[1].1 as usize, b.find("ST b").unwrap());
}

#[test]
fn one_input_functions_given_an_operand_say_the_cr_is_the_argument() {
    let src = "PROGRAM P\nVAR x, y : INT; END_VAR\n    ABS y\n    ST x\n    LD x\n    ABS y\n    ST x\nEND_PROGRAM\n";
    let d = &check(&[("t.il", src)])[0];
    assert_eq!(d.len(), 2, "{d:?}");
    assert_eq!(d[0].code, "IL0108");
    assert_eq!(
        d[0].help.as_deref(),
        Some(
            "ABS takes one argument, the current result, not its operand: write `LD y`, then `ABS` alone"
        )
    );
    assert_eq!(d[1].code, "IL0115");
    assert!(
        d[1].message
            .starts_with("ABS takes 1 argument, the current result;"),
        "{}",
        d[1].message
    );
}

#[test]
fn a_label_no_path_leaves_a_value_at_is_worded_as_what_happened() {
    let src = "FUNCTION_BLOCK F\nVAR t : TON; b : BOOL; END_VAR\n    CAL t\n    JMP l\nl:\n    ST b\nEND_FUNCTION_BLOCK\n";
    let d = &check(&[("t.il", src)])[0];
    let e: Vec<&Diagnostic> = d.iter().filter(|d| d.is_error()).collect();
    assert_eq!(e.len(), 1, "{d:?}");
    assert_eq!(e[0].code, "IL0109");
    assert_eq!(
        e[0].message,
        "the current result is undefined at `l`: no path into it leaves a value"
    );
}

#[test]
fn st_calls_and_reserved_words_get_one_clear_error() {
    let src = "FUNCTION_BLOCK F\nVAR_INPUT a, b : INT; END_VAR\n    LD a\n    ST b\nEND_FUNCTION_BLOCK\nPROGRAM P\nVAR fb : F; END_VAR\n    fb(10, 20);\nEND_PROGRAM\n";
    let d = &check(&[("t.il", src)])[0];
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code, "IL0009");
    assert!(d[0].message.contains("`fb(10, 20);`"), "{}", d[0].message);
    let d = &check(&[(
        "t.il",
        "PROGRAM P\nVAR x : INT; on : BOOL; END_VAR\n    LD x\n    ST x\nEND_PROGRAM\n",
    )])[0];
    assert_eq!(d.len(), 1, "{d:?}");
    assert!(
        d[0].notes
            .iter()
            .any(|n| n.starts_with("`on` is a reserved keyword")),
        "{:?}",
        d[0]
    );
}

#[test]
fn an_fb_parameter_named_twice_is_an_error_at_the_second() {
    // An output read twice is fine: `Q => x, NOT Q => y`.
    let src = "PROGRAM P\nVAR t : TON; x, y : BOOL; END_VAR\n    CAL t(IN := TRUE, PT := T#1s, in := FALSE, Q => x, NOT Q => y, PT := T#2s)\nEND_PROGRAM\n";
    let d = &check(&[("t.il", src)])[0];
    let got: Vec<(&str, usize, &str)> = d
        .iter()
        .map(|d| (d.code, d.span.lo as usize, d.message.as_str()))
        .collect();
    assert_eq!(
        got,
        [
            (
                "IL0112",
                src.find("in :=").unwrap(),
                "parameter `in` is given twice"
            ),
            (
                "IL0112",
                src.rfind("PT :=").unwrap(),
                "parameter `PT` is given twice"
            ),
        ]
    );
}
