//! Formal lists of function calls: one binder for user and standard
//! functions, so both refuse the same mistakes the same way.

use crate::checked::errors;

const ADD2: &str = "FUNCTION Add2 : INT\nVAR_INPUT a, b : INT; END_VAR\nVAR_OUTPUT c : INT; END_VAR\n    LD a\n    ADD b\n    ST Add2\n    ST c\nEND_FUNCTION\n";

fn program(call: &str) -> String {
    format!("{ADD2}PROGRAM P\nVAR x, y : INT; END_VAR\n{call}\n    ST x\nEND_PROGRAM\n")
}

#[test]
fn a_parameter_given_twice_is_an_error_for_user_and_standard_functions() {
    // The user function: the second `a` (line 11, column 26).
    let e = errors(&program("    Add2(a := 1, b := 2, a := 3)"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(
        (e[0].0.as_str(), e[0].1, e[0].2),
        ("IL0112", 11, 26),
        "{e:?}"
    );
    assert_eq!(e[0].3, "parameter `a` is given twice");
    // An output given twice too.
    let e = errors(&program("    Add2(a := 1, b := 2, c => y, c => x)"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].3, "parameter `c` is given twice");
    // A standard function: the same message from the same loop.
    let e = errors(&program("    LIMIT(MN := 0, IN := x, MN := 1, MX := 9)"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(
        (e[0].0.as_str(), e[0].1, e[0].2),
        ("IL0112", 11, 29),
        "{e:?}"
    );
    assert_eq!(e[0].3, "parameter `MN` is given twice");
}

#[test]
fn unknown_names_are_reported_each_and_known_ones_still_checked() {
    let e = errors(&program("    Add2(a := 1, q := 2, b := TRUE, r => y)"));
    let got: Vec<(&str, &str)> = e.iter().map(|x| (x.0.as_str(), x.3.as_str())).collect();
    assert!(got.contains(&("IL0112", "Add2 has no input `q`")), "{e:?}");
    assert!(got.contains(&("IL0112", "Add2 has no output `r`")), "{e:?}");
    // `b := TRUE` is still checked against INT.
    assert!(got.iter().any(|(c, _)| *c == "IL0106"), "{e:?}");
    let e = errors(&program("    LIMIT(MN := 0, IN := x, MAX := 9)"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].3
            .starts_with("LIMIT has no parameter `MAX` (it has MN, IN, MX)"),
        "{e:?}"
    );
    let e = errors(&program("    LIMIT(MN := 0, IN := x)"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].3, "LIMIT needs parameter `MX`");
}

#[test]
fn en_eno_and_outputs_bind_as_before() {
    let src = program("    Add2(EN := TRUE, a := 1, b := 2, c => y, ENO => z)")
        .replace("x, y : INT;", "x, y : INT; z : BOOL;");
    assert_eq!(errors(&src), []);
}
