//! The 3rd-edition and vendor forms accepted by default, and refused one by
//! one under `Standard::Iec2003` with an error that names the form.

use crate::checked::{errors, errors_std};
use il_codegen::Standard;

/// A program with a pragma in every place a comment may stand.
const PRAGMAS: &str = "{attribute 'qualified_only'}
{attribute 'hide'} PROGRAM p {before declarations}
VAR {in a block}
    x {after a name} : INT; {after a declaration}
    {on its own line}
    y : INT := 3 {before the semicolon};
END_VAR
{on its own line in the body}
    LD y {after an instruction}
    {a pragma
     over two lines}
    ADD 1 (* a comment *) {and a pragma}
    ST x
END_PROGRAM
{after the POU}
";

#[test]
fn pragmas_are_ignored_wherever_a_comment_may_stand() {
    assert_eq!(errors(PRAGMAS), []);
}

#[test]
fn pragmas_are_refused_under_iec2003_one_by_one() {
    let e = errors_std(PRAGMAS, Standard::Iec2003);
    assert_eq!(e.len(), 13, "{e:#?}");
    assert!(e.iter().all(|(code, ..)| code == "IL0301"), "{e:#?}");
    assert_eq!(
        e[0],
        (
            "IL0301".to_string(),
            1,
            1,
            "pragmas `{ ... }` are a 3rd-edition feature".to_string()
        )
    );
    let lines: Vec<usize> = e.iter().map(|e| e.1).collect();
    assert_eq!(lines, [1, 2, 2, 3, 4, 4, 5, 6, 8, 9, 10, 12, 15]);
}

#[test]
fn an_unterminated_pragma_is_an_error_at_its_start() {
    // Like an unclosed comment it swallows the rest of the file, END_PROGRAM too.
    let e = errors("PROGRAM p\n    LD 1 {never closed\n    ST x\nEND_PROGRAM\n");
    assert_eq!(e.len(), 2, "{e:#?}");
    assert_eq!(e[1].0, "IL0014");
    assert_eq!(
        e[0],
        (
            "IL0025".to_string(),
            2,
            10,
            "this pragma is never closed".to_string()
        )
    );
}

/// Every place a value meets a wider type (the FB and FUNCTION are used below).
const WIDENING: &str = "FUNCTION twice : DINT
VAR_INPUT a : DINT; END_VAR
VAR_OUTPUT wide : LINT; END_VAR
    LD a
    ADD a
    ST twice
    ST wide
END_FUNCTION
FUNCTION_BLOCK acc
VAR_INPUT inc : LREAL; END_VAR
VAR_OUTPUT total : REAL; END_VAR
    LD total
END_FUNCTION_BLOCK
PROGRAM p
VAR
    s : SINT := -3;
    i : INT;
    d : DINT := INT#7;
    l : LINT;
    us : USINT;
    ui : UINT;
    b : BOOL;
    w : WORD;
    r : REAL;
    lr : LREAL;
    t : TIME;
    lt : LTIME;
    f : acc;
END_VAR
    LD s
    ST i
    ST d
    ADD i
    ST l
    LD us
    ST i
    LD b
    OR w
    ST w
    LD i
    ST r
    LD r
    ST lr
    LD d
    GT s
    ST b
    LD t
    ST lt
    LD s
    twice
    ST l
    twice(a := i, wide => l)
    ST d
    CAL f(inc := r, total => lr)
    LD ui
    ST f.inc
    LD INT#5
    ST d
    LD d
    ADD INT#5
    ST d
END_PROGRAM
";

#[test]
fn widening_is_implicit_everywhere_a_value_meets_a_wider_type() {
    assert_eq!(errors(WIDENING), []);
}

#[test]
fn widening_is_refused_under_iec2003_one_by_one() {
    let e = errors_std(WIDENING, Standard::Iec2003);
    assert!(e.iter().all(|e| e.0 == "IL0302"), "{e:#?}");
    let msgs: Vec<(usize, &str)> = e.iter().map(|e| (e.1, e.3.as_str())).collect();
    let lines: Vec<usize> = e.iter().map(|e| e.1).collect();
    assert_eq!(
        lines,
        [
            7, 18, 31, 32, 33, 34, 36, 38, 41, 43, 45, 48, 50, 51, 52, 54, 54, 56, 58, 60
        ],
        "{msgs:#?}"
    );
    for m in [
        (
            31,
            "implicit conversion SINT → INT is a 3rd-edition feature",
        ),
        (
            18,
            "implicit conversion INT → DINT is a 3rd-edition feature",
        ),
        (
            34,
            "implicit conversion INT → LINT is a 3rd-edition feature",
        ),
        (
            38,
            "implicit conversion BOOL → WORD is a 3rd-edition feature",
        ),
        (
            48,
            "implicit conversion TIME → LTIME is a 3rd-edition feature",
        ),
        (
            56,
            "implicit conversion UINT → LREAL is a 3rd-edition feature",
        ),
    ] {
        assert!(msgs.contains(&m), "{m:?} in {msgs:#?}");
    }
}

fn body(lines: &str) -> Vec<(String, usize, usize, String)> {
    errors(&format!(
        "PROGRAM p\nVAR s : SINT; i : INT; d : DINT; u : UINT; w : WORD; by : BYTE; r : REAL; lr : LREAL; END_VAR\n{lines}\nEND_PROGRAM\n"
    ))
}

#[test]
fn narrowing_and_lossy_conversions_stay_errors_that_name_the_function() {
    let e = body("    LD d\n    ST i");
    assert_eq!(e.len(), 1, "{e:#?}");
    assert_eq!(e[0].0, "IL0106");
    assert_eq!(
        e[0].3,
        "`i` is INT, but the current result is DINT; narrowing is never implicit: convert with DINT_TO_INT"
    );
    // Not in the table: signed into unsigned, integer into bit string, DINT into REAL.
    for (src, msg) in [
        (
            "    LD i\n    ST u",
            "`u` is UINT, but the current result is INT",
        ),
        (
            "    LD by\n    ST i",
            "`i` is INT, but the current result is BYTE",
        ),
        (
            "    LD d\n    ST r",
            "`r` is REAL, but the current result is DINT",
        ),
        (
            "    LD lr\n    ST r",
            "`r` is REAL, but the current result is LREAL; narrowing is never implicit: convert with LREAL_TO_REAL",
        ),
    ] {
        let e = body(src);
        assert_eq!(e.len(), 1, "{src}: {e:#?}");
        assert_eq!((e[0].0.as_str(), e[0].3.as_str()), ("IL0106", msg), "{src}");
    }
    // At an operator, neither side widens into the other.
    let e = body("    LD i\n    ADD u\n    ST i");
    assert_eq!(e[0].0, "IL0106", "{e:#?}");
    assert!(e[0].3.starts_with("ADD of INT and UINT"), "{e:#?}");
}

#[test]
fn at_a_label_the_cr_type_must_still_agree_exactly() {
    let e = body("    LD i\n    GT 0\n    JMPC l\n    LD s\n    JMP m\nl:  LD i\nm:  ST d");
    assert!(e.iter().any(|e| e.0 == "IL0109"), "{e:#?}");
}

#[test]
fn the_wider_type_is_the_crs_after_an_operator() {
    // SINT + INT gives INT: storing it into a SINT is narrowing.
    let e = body("    LD s\n    ADD i\n    ST s");
    assert_eq!(e.len(), 1, "{e:#?}");
    assert!(e[0].3.contains("convert with INT_TO_SINT"), "{e:#?}");
}
