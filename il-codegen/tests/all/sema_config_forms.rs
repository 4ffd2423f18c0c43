//! Configuration forms: VAR_IN_OUT of a PROGRAM bound by the configuration,
//! TASK inputs from globals and addresses, and what is refused about them.

use crate::checked::errors;

const PROG: &str = "PROGRAM P\nVAR_IN_OUT io : DINT; END_VAR\nVAR_EXTERNAL e : DINT; END_VAR\n    LD io\n    ADD 1\n    ST io\n    ST e\nEND_PROGRAM\n";

/// `PROG` and a configuration (line 9 on) with `globals` and `body`.
fn config(globals: &str, body: &str) -> String {
    format!(
        "{PROG}CONFIGURATION C\nVAR_GLOBAL e : DINT; g, h : DINT; k AT %MD4 : DINT; b : BOOL; t : TIME; {globals} END_VAR\n{body}\nEND_CONFIGURATION\n"
    )
}

fn only(src: &str) -> (String, usize, String) {
    let e = errors(src);
    assert_eq!(e.len(), 1, "{e:?}");
    (e[0].0.clone(), e[0].1, e[0].3.clone())
}

#[test]
fn a_bound_program_in_out_and_task_sources_are_accepted() {
    let src = config(
        "",
        "TASK a (INTERVAL := t, PRIORITY := 1);\nTASK s (SINGLE := b);\nTASK i (SINGLE := %IX0.0);\nTASK l (SINGLE := TRUE);\nPROGRAM p1 WITH a : P (io := g);\nPROGRAM p2 WITH i : P (io := h);",
    );
    assert_eq!(errors(&src), []);
}

#[test]
fn a_program_in_out_must_be_bound_to_a_plain_global_of_its_type() {
    let (code, line, msg) = only(&config("", "PROGRAM p1 : P;"));
    assert_eq!((code.as_str(), line), ("IL0130", 11));
    assert_eq!(
        msg,
        "program `P` has the VAR_IN_OUT `io` : DINT, which instance `p1` does not bind"
    );
    let (code, _, msg) = only(&config("", "PROGRAM p1 : P (io := 5);"));
    assert_eq!(code, "IL0130");
    assert!(
        msg.contains("bind it to a global variable, not a value"),
        "{msg}"
    );
    let (_, _, msg) = only(&config("s : INT;", "PROGRAM p1 : P (io := s);"));
    assert!(msg.contains("is DINT, the global `s` is INT"), "{msg}");
    let (_, _, msg) = only(&config("", "PROGRAM p1 : P (io := k);"));
    assert!(msg.contains("at %MD4 in the process image"), "{msg}");
    let (_, _, msg) = only(&config("", "PROGRAM p1 : P (io := e);"));
    assert!(
        msg.contains("also uses the global `e` as VAR_EXTERNAL"),
        "{msg}"
    );
    let (code, _, msg) = only(&config("", "PROGRAM p1 : P (io := nope);"));
    assert_eq!(code, "IL0129");
    assert!(msg.contains("has no global `nope`"), "{msg}");
    let src = format!(
        "{PROG}CONFIGURATION C\nVAR_GLOBAL e : DINT; END_VAR\nVAR_GLOBAL CONSTANT c : DINT := 1; END_VAR\nPROGRAM p1 : P (io := c);\nEND_CONFIGURATION\n"
    );
    let (_, _, msg) = only(&src);
    assert!(
        msg.contains("CONSTANT and cannot be passed by reference"),
        "{msg}"
    );
}

#[test]
fn two_in_outs_cannot_share_one_global() {
    let src = "PROGRAM Q\nVAR_IN_OUT x, y : INT; END_VAR\n    LD x\n    ST y\nEND_PROGRAM\nCONFIGURATION C\nVAR_GLOBAL g : INT; END_VAR\nPROGRAM q : Q (x := g, y := g);\nEND_CONFIGURATION\n";
    let (code, line, msg) = only(src);
    assert_eq!((code.as_str(), line), ("IL0130", 8));
    assert_eq!(msg, "the global `g` is already bound to the VAR_IN_OUT `x`");
}

#[test]
fn task_sources_of_the_wrong_kind_are_refused() {
    let cases = [
        (
            "TASK a (INTERVAL := b);",
            "INTERVAL needs a TIME global; `b` is BOOL",
        ),
        (
            "TASK a (INTERVAL := %MD1);",
            "INTERVAL needs a TIME, and a direct address holds no TIME: use a TIME global",
        ),
        (
            "TASK a (INTERVAL := 10);",
            "INTERVAL must be a non-negative TIME literal such as T#10ms, or a TIME global",
        ),
        (
            "TASK a (SINGLE := g);",
            "SINGLE needs a BOOL global; `g` is DINT",
        ),
        (
            "TASK a (SINGLE := %IW2);",
            "`%IW2` is a word (WORD, INT, UINT); it cannot hold BOOL",
        ),
        (
            "TASK a (SINGLE := 1);",
            "SINGLE must be a BOOL global, a bit address (%IX0.0) or TRUE/FALSE",
        ),
    ];
    for (task, want) in cases {
        let (code, line, msg) = only(&config("", &format!("{task}\nPROGRAM p1 : P (io := g);")));
        assert!(code == "IL0131" || code == "IL0128", "{task}: {code}");
        assert_eq!((line, msg.as_str()), (11, want), "{task}");
    }
}
