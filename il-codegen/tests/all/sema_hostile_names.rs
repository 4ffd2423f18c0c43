//! Names and nesting that pass the parser but cannot become Rust: each is
//! refused with a code and a place.

use crate::checked::errors;

/// `_` was accepted as a POU, variable or enumeration value name and became
/// `__invalid_1` in the Rust. The lexer refuses it (IL0033, a front-end
/// code: no stage reports another's).
#[test]
fn underscore_alone_is_not_an_identifier() {
    let cases: &[(&str, usize, usize)] = &[
        (
            "PROGRAM _\nVAR x : INT; END_VAR\n LD x\n ST x\nEND_PROGRAM\n",
            1,
            9,
        ),
        (
            "PROGRAM P\nVAR _ : INT; END_VAR\n LD 1\n ST _\nEND_PROGRAM\n",
            2,
            5,
        ),
        (
            "PROGRAM P\nVAR x, __ : INT; END_VAR\n LD x\n ST x\nEND_PROGRAM\n",
            2,
            8,
        ),
        (
            "TYPE C : (Red, _); END_TYPE\nPROGRAM P\nVAR c : C; END_VAR\n LD c\n ST c\nEND_PROGRAM\n",
            1,
            16,
        ),
        (
            "TYPE S : STRUCT _ : INT; END_STRUCT; END_TYPE\nPROGRAM P\nVAR s : S; END_VAR\nEND_PROGRAM\n",
            1,
            17,
        ),
        (
            "FUNCTION_BLOCK _\nVAR x : INT; END_VAR\n LD x\n ST x\nEND_FUNCTION_BLOCK\n",
            1,
            16,
        ),
        (
            "PROGRAM P\nVAR x : INT; END_VAR\n_: LD x\n ST x\nEND_PROGRAM\n",
            3,
            1,
        ),
    ];
    for (src, line, col) in cases {
        let e = errors(src);
        assert!(
            e.iter().any(|(c, l, k, m)| c == "IL0033"
                && l == line
                && k == col
                && m.contains("letter or a digit")),
            "{src}\n{e:?}"
        );
    }
    // `_` inside a name is fine; `_x` and `x_1` are IEC identifiers.
    assert_eq!(
        errors("PROGRAM _P\nVAR _x, x_1 : INT; END_VAR\n LD _x\n ST x_1\nEND_PROGRAM\n"),
        []
    );
}

/// Enumeration values and STRUCT fields were not checked for `__` and a
/// trailing `_`, which the generated code reserves.
#[test]
fn enum_values_and_struct_fields_are_identifiers_too() {
    let e = errors("TYPE C : (Red, a__b); S : STRUCT x_ : INT; END_STRUCT; END_TYPE\n");
    assert!(
        e.iter()
            .any(|(c, l, k, _)| c == "IL0126" && *l == 1 && *k == 16),
        "{e:?}"
    );
    assert!(
        e.iter()
            .any(|(c, l, k, _)| c == "IL0126" && *l == 1 && *k == 34),
        "{e:?}"
    );
}

/// A chain of `n` FUNCTION_BLOCKs, each holding the next (through a
/// one-element array when `arrays`), under a PROGRAM.
fn fb_chain(n: usize, arrays: bool) -> String {
    let mut s = String::new();
    for k in 1..=n {
        let inner = match (k < n, arrays) {
            (false, _) => String::new(),
            (true, false) => format!("inner : F{};", k + 1),
            (true, true) => format!("inner : ARRAY[0..0] OF F{};", k + 1),
        };
        s.push_str(&format!(
            "FUNCTION_BLOCK F{k}\nVAR x : INT; {inner} END_VAR\n LD x\n ST x\nEND_FUNCTION_BLOCK\n"
        ));
    }
    s + "PROGRAM Main\nVAR top : F1; END_VAR\n CAL top\nEND_PROGRAM\n"
}

/// A chain of `n` STRUCTs, each holding the next, under a PROGRAM.
fn struct_chain(n: usize) -> String {
    let mut s = String::from("TYPE\n");
    for k in 1..=n {
        let inner = if k < n {
            format!(" inner : S{};", k + 1)
        } else {
            String::new()
        };
        s.push_str(&format!("S{k} : STRUCT x : INT;{inner} END_STRUCT;\n"));
    }
    s + "END_TYPE\nPROGRAM Main\nVAR s : S1; y : INT; END_VAR\n LD s.x\n ST y\nEND_PROGRAM\n"
}

/// 130 nested FUNCTION_BLOCKs passed the checker and failed in rustc
/// ("reached the recursion limit finding the struct tail"), and 200 nested
/// STRUCTs too. The deepest accepted nesting (tests/plc/deep_nesting.il,
/// compiled by rustc in the tests crate) is 120 levels; one more is IL0133,
/// reported once, at the outermost type that is too deep.
#[test]
fn nesting_deeper_than_rustc_compiles_is_refused() {
    // Main + 118 FBs + the INT of the last: 120 levels.
    assert_eq!(errors(&fb_chain(118, false)), []);
    let e = errors(&fb_chain(119, false));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].0.as_str(), e[0].1), ("IL0133", 119 * 5 + 1), "{e:?}");
    assert!(
        e[0].3.contains("121 levels") && e[0].3.contains("at most 120"),
        "{e:?}"
    );
    let e = errors(&fb_chain(130, false));
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].3.contains("`F11`"),
        "reported where the chain gets too deep: {e:?}"
    );
    // Each array dimension is a level: rustc's drop check goes through them.
    assert_eq!(errors(&fb_chain(59, true)), []);
    assert_eq!(errors(&fb_chain(60, true))[0].0, "IL0133");
    assert_eq!(errors(&struct_chain(118)), []);
    let e = errors(&struct_chain(200));
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].0 == "IL0133" && e[0].3.contains("STRUCT `S81`"),
        "{e:?}"
    );
}

/// Arrays over 64 KiB are kept on the heap as FB/PROGRAM variables, and
/// refused (IL0134) wherever they would be a value on the stack.
#[test]
fn arrays_too_large_for_the_stack_are_refused_where_they_would_be_on_it() {
    let big = "ARRAY[0..8192] OF LREAL"; // 65,544 bytes
    let small = "ARRAY[0..8191] OF LREAL"; // 65,536 bytes: not large
    let refused = |src: &str, line: usize, col: usize| {
        let e = errors(src);
        assert!(
            e.iter()
                .any(|(c, l, k, _)| c == "IL0134" && *l == line && *k == col),
            "{src}\n{e:?}"
        );
    };
    // Accepted: variables of a PROGRAM or FUNCTION_BLOCK, used element-wise.
    let ok = format!(
        "FUNCTION_BLOCK F\nVAR_INPUT a : {big}; END_VAR\nVAR_OUTPUT b : {big}; END_VAR\nVAR c : {big}; x : LREAL; END_VAR\n LD a[1]\n ST b[2]\n ST c[3]\nEND_FUNCTION_BLOCK\n\
         PROGRAM P\nVAR f : F; g : ARRAY[0..9999] OF F; END_VAR\n LD f.b[2]\n ST f.a[1]\nEND_PROGRAM\n"
    );
    assert_eq!(errors(&ok), []);
    // As a whole: through the CR, as an argument.
    refused(
        &format!("PROGRAM P\nVAR a, b : {big}; END_VAR\n LD a\n ST b\nEND_PROGRAM\n"),
        3,
        5,
    );
    let copy = format!("PROGRAM P\nVAR a, b : {small}; END_VAR\n LD a\n ST b\nEND_PROGRAM\n");
    assert_eq!(errors(&copy), [], "64 KiB exactly is still copied by value");
    refused(
        &format!(
            "FUNCTION_BLOCK F\nVAR_INPUT a : {big}; END_VAR\nEND_FUNCTION_BLOCK\n\
             PROGRAM P\nVAR f : F; a : {big}; END_VAR\n CAL f(a := a)\nEND_PROGRAM\n"
        ),
        6,
        13,
    );
    // On the stack: FUNCTION variables and results, VAR_TEMP, VAR_IN_OUT.
    refused(
        &format!("FUNCTION G : INT\nVAR a : {big}; END_VAR\n LD 1\n ST G\nEND_FUNCTION\n"),
        2,
        5,
    );
    refused(
        &format!("FUNCTION G : INT\nVAR_INPUT a : {big}; END_VAR\n LD 1\n ST G\nEND_FUNCTION\n"),
        2,
        11,
    );
    refused(
        &format!("FUNCTION G : {big}\nVAR_INPUT i : INT; END_VAR\nEND_FUNCTION\n"),
        1,
        14,
    );
    refused(
        &format!("PROGRAM P\nVAR_TEMP t : {big}; END_VAR\nEND_PROGRAM\n"),
        2,
        10,
    );
    refused(
        &format!("FUNCTION_BLOCK F\nVAR_IN_OUT io : {big}; END_VAR\nEND_FUNCTION_BLOCK\n"),
        2,
        12,
    );
    // A STRUCT is a value; a global is not supported on the heap yet.
    refused(
        &format!("TYPE S : STRUCT a : {big}; END_STRUCT; END_TYPE\n"),
        1,
        17,
    );
    refused(
        &format!(
            "PROGRAM P\nVAR x : INT; END_VAR\n LD x\n ST x\nEND_PROGRAM\n\
             CONFIGURATION C\nVAR_GLOBAL g : {big}; END_VAR\nPROGRAM p : P;\nEND_CONFIGURATION\n"
        ),
        7,
        12,
    );
    // Only the first dimension goes to the heap: its rows must fit.
    refused(
        "PROGRAM P\nVAR a : ARRAY[0..1, 0..8192] OF LREAL; END_VAR\nEND_PROGRAM\n",
        2,
        5,
    );
    assert_eq!(
        errors("PROGRAM P\nVAR a : ARRAY[0..999, 0..1999] OF LREAL; END_VAR\nEND_PROGRAM\n"),
        []
    );
}
