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

fn bits(lines: &str) -> Vec<(String, usize, usize, String)> {
    bits_std(lines, Standard::default())
}

fn bits_std(lines: &str, std: Standard) -> Vec<(String, usize, usize, String)> {
    errors_std(
        &format!(
            "PROGRAM p\nVAR b : BOOL; by : BYTE; w : WORD; d : DINT; s : SINT; lw : LWORD; r : REAL; t : TON; a : ARRAY[0..3] OF WORD; sub : INT(0..100); END_VAR\n{lines}\nEND_PROGRAM\n"
        ),
        std,
    )
}

#[test]
fn partial_access_is_accepted_as_operand_and_target() {
    for src in [
        "    LD w.15\n    AND d.%X31\n    ST b",
        "    LD b\n    ST w.0\n    STN by.%X7\n    S lw.63\n    R s.7",
        "    LD w.%B1\n    ST by",
        "    LD lw.%D1\n    ST lw.%D0\n    LD lw.%W3\n    ST w",
        "    LD t.ET\n    LD a[2].3\n    ST a[1].%X0",
        "    LD by\n    ST w.%B0\n    ST d.%B3",
        "    LD 1\n    ST w.3\n    LD 16#FF\n    ST d.%B2",
    ] {
        assert_eq!(bits(src), [], "{src}");
    }
}

#[test]
fn a_part_beyond_the_width_is_an_error_at_its_line() {
    let cases = [
        (
            "    LD w.16\n    ST b",
            "`w.16`: bit 16 is beyond WORD, which has bits 0..15 (16 bits)",
        ),
        (
            "    LD b\n    ST by.%X8",
            "`by.%X8`: bit 8 is beyond BYTE, which has bits 0..7 (8 bits)",
        ),
        (
            "    LD d.%B4\n    ST by",
            "`d.%B4`: byte 4 is beyond DINT, which has bytes 0..3 (32 bits)",
        ),
        (
            "    LD w.%D0\n    ST d",
            "`w.%D0`: WORD has no double words (16 bits)",
        ),
        (
            "    LD lw.%W4\n    ST w",
            "`lw.%W4`: word 4 is beyond LWORD, which has words 0..3 (64 bits)",
        ),
        (
            "    LD r.0\n    ST b",
            "`r.0`: partial access needs a bit string or an integer, not REAL",
        ),
        (
            "    LD b.0\n    ST b",
            "`b.0`: partial access needs a bit string or an integer, not BOOL",
        ),
        (
            "    LD b\n    ST sub.0",
            "`sub` is a subrange: its parts cannot be written",
        ),
    ];
    for (src, msg) in cases {
        let e = bits(src);
        assert_eq!(e.len(), 1, "{src}: {e:#?}");
        // The line of the access (the second line when the first loads b).
        let line = if src.starts_with("    LD b\n") { 4 } else { 3 };
        assert_eq!(
            (e[0].0.as_str(), e[0].1, e[0].3.as_str()),
            ("IL0135", line, msg),
            "{src}"
        );
    }
    // A part has the type of its size, checked (and widened) like any value.
    assert_eq!(bits("    LD w.%B0\n    ST w"), [], "BYTE into WORD widens");
    let e = bits("    LD w.%B0\n    ST s");
    assert_eq!(
        e[0].3, "`s` is SINT, but the current result is BYTE",
        "{e:#?}"
    );
}

#[test]
fn partial_access_is_refused_under_iec2003() {
    let e = bits_std("    LD w.3\n    ST d.%X0", Standard::Iec2003);
    let msgs: Vec<(&str, usize, &str)> = e
        .iter()
        .map(|e| (e.0.as_str(), e.1, e.3.as_str()))
        .collect();
    assert_eq!(
        msgs,
        [
            ("IL0303", 3, "partial access `w.3` is a 3rd-edition feature"),
            (
                "IL0303",
                4,
                "partial access `d.%X0` is a 3rd-edition feature"
            ),
        ]
    );
}

#[test]
fn a_part_cannot_be_bound_to_a_var_in_out() {
    let e = errors(
        "FUNCTION_BLOCK f\nVAR_IN_OUT x : BOOL; END_VAR\n    LD x\nEND_FUNCTION_BLOCK\nPROGRAM p\nVAR w : WORD; i : f; END_VAR\n    CAL i(x := w.3)\nEND_PROGRAM\n",
    );
    assert_eq!(e.len(), 1, "{e:#?}");
    assert_eq!((e[0].0.as_str(), e[0].1), ("IL0130", 7));
}

#[test]
fn standard_functions_take_their_widest_argument_type() {
    for src in [
        "    LIMIT(MN := s, IN := i, MX := 100)\n    ST i",
        "    LD d\n    MAX i, s\n    ST d",
        "    LD s\n    MIN i\n    ST i",
        "    LD r\n    ADD i\n    ST r",
        "    SEL(G := TRUE, IN0 := s, IN1 := d)\n    ST d",
    ] {
        assert_eq!(body(src), [], "{src}");
    }
    // The result has the wider type: storing it narrower is the usual error.
    let e = body("    LIMIT(MN := s, IN := d, MX := 100)\n    ST i");
    assert_eq!(e.len(), 1, "{e:#?}");
    assert!(e[0].3.ends_with("convert with DINT_TO_INT"), "{e:#?}");
    // Neither widens into the other: still one type needed.
    let e = body("    LD i\n    MAX u\n    ST i");
    assert_eq!(e.len(), 1, "{e:#?}");
    assert_eq!(e[0].0, "IL0106");
    assert!(
        e[0].3
            .starts_with("MAX needs arguments of one type; found INT and UINT"),
        "{e:#?}"
    );
    // Under the 2nd edition each widened argument is named.
    let e = errors_std(
        "PROGRAM p\nVAR s : SINT; i : INT; END_VAR\n    LIMIT(MN := s, IN := i, MX := 100)\n    ST i\nEND_PROGRAM\n",
        Standard::Iec2003,
    );
    assert_eq!(e.len(), 1, "{e:#?}");
    assert_eq!(
        (e[0].0.as_str(), e[0].3.as_str()),
        (
            "IL0302",
            "implicit conversion SINT → INT is a 3rd-edition feature"
        )
    );
}

/// `AT %I*` in VAR_INPUT / VAR_OUTPUT: a vendor placement (Ed.2 2.4.1.1
/// allows it only in VAR), accepted by default, refused under the 2nd
/// edition; in VAR it is accepted by both.
#[test]
fn partly_specified_interface_variables_are_refused_under_iec2003() {
    let fb = |decl: &str| {
        format!("FUNCTION_BLOCK B\n{decl}\n    LD TRUE\n    ST q\nEND_FUNCTION_BLOCK\n")
    };
    let interface = fb("VAR_INPUT x AT %I* : BOOL; END_VAR\nVAR_OUTPUT q AT %QX* : BOOL; END_VAR");
    assert_eq!(errors(&interface), []);
    let e = errors_std(&interface, Standard::Iec2003);
    let msgs: Vec<(&str, usize, &str)> = e
        .iter()
        .map(|e| (e.0.as_str(), e.1, e.3.as_str()))
        .collect();
    assert_eq!(
        msgs,
        [
            (
                "IL0304",
                2,
                "a partly specified address `%I*` in VAR_INPUT is a vendor form"
            ),
            (
                "IL0304",
                3,
                "a partly specified address `%QX*` in VAR_OUTPUT is a vendor form"
            ),
        ]
    );
    let var = fb("VAR x AT %I* : BOOL; q AT %Q* : BOOL; END_VAR");
    assert_eq!(errors_std(&var, Standard::Iec2003), []);
}
