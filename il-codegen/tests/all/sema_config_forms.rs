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

#[test]
fn partly_specified_addresses_only_where_a_program_or_block_binds_them() {
    let fb = |decl: &str| {
        format!("FUNCTION_BLOCK B\n{decl}\n    LD TRUE\n    ST q\nEND_FUNCTION_BLOCK\n")
    };
    for ok in [
        "VAR x AT %I* : BOOL; q : BOOL; END_VAR",
        "VAR x AT %IW* : INT; q : BOOL; END_VAR",
        "VAR x AT %M* : LREAL; q : BOOL; END_VAR",
        "VAR_INPUT x AT %I* : BOOL; END_VAR\nVAR_OUTPUT q AT %Q* : BOOL; END_VAR",
    ] {
        assert_eq!(errors(&fb(ok)), [], "{ok}");
    }
    let cases = [
        (
            "VAR q : BOOL; END_VAR\nVAR_TEMP x AT %I* : BOOL; END_VAR",
            "a partly specified address `%I*` cannot be used in VAR_TEMP (it lives for one call): declare it in the VAR of a PROGRAM or FUNCTION_BLOCK",
        ),
        (
            "VAR q : BOOL; x AT %IW* : BOOL; END_VAR",
            "`%IW*` has a size that BOOL does not have; write `%I*` or the matching size letter",
        ),
        (
            "VAR q : BOOL; x AT %QX* : INT; END_VAR",
            "`%QX*` has a size that INT does not have; write `%Q*` or the matching size letter",
        ),
    ];
    for (decl, want) in cases {
        let (code, _, msg) = only(&fb(decl));
        assert_eq!((code.as_str(), msg.as_str()), ("IL0128", want), "{decl}");
    }
    let f = "FUNCTION F : BOOL\nVAR x AT %I* : BOOL; END_VAR\n    LD x\n    ST F\nEND_FUNCTION\n";
    let (code, line, msg) = only(f);
    assert_eq!((code.as_str(), line), ("IL0128", 2));
    assert!(msg.contains("cannot be used in a FUNCTION"), "{msg}");
    let g = "CONFIGURATION C\nVAR_GLOBAL x AT %I* : BOOL; END_VAR\nEND_CONFIGURATION\n";
    let (code, _, msg) = only(g);
    assert_eq!(code, "IL0128");
    assert!(
        msg.starts_with("a VAR_GLOBAL needs a full address, not `%I*`"),
        "{msg}"
    );
}

const IO: &str = "FUNCTION_BLOCK L\nVAR s AT %I* : BOOL; w AT %QW* : WORD; plain : INT; END_VAR\nVAR CONSTANT k : INT := 2; END_VAR\n    LD s\n    ST s\nEND_FUNCTION_BLOCK\nPROGRAM M\nVAR l : L; n : INT; t : TON; END_VAR\nVAR_TEMP tmp : INT; END_VAR\n    CAL l\nEND_PROGRAM\n";

/// `IO` and a configuration with resource `R` running `M` as `m`, then
/// `tail` (its first line is 17, so a declaration after the block keyword is 18).
fn io_config(tail: &str) -> String {
    format!(
        "{IO}CONFIGURATION C\nVAR_GLOBAL g : INT; loc AT %MW0 : INT; END_VAR\nRESOURCE R ON PLC\nPROGRAM m : M;\nEND_RESOURCE\n{tail}\nEND_CONFIGURATION\n"
    )
}

#[test]
fn var_config_and_var_access_accepted() {
    let src = io_config(
        "VAR_CONFIG\nR.m.l.s AT %IX1.1 : BOOL;\nR.m.l.w AT %QW3 : WORD := 16#FF;\nR.m.n : INT := 4;\nEND_VAR\nVAR_ACCESS\na : R.m.n : INT READ_WRITE;\nb : g : INT;\nc : R.m.l.plain : INT READ_ONLY;\nEND_VAR",
    );
    assert_eq!(errors(&src), []);
}

/// A path may end at an input or output of a standard FB instance.
#[test]
fn paths_into_standard_blocks_are_accepted() {
    let src = io_config(
        "VAR_CONFIG\nR.m.t.PT : TIME := T#1s;\nEND_VAR\nVAR_ACCESS\nq : R.m.t.Q : BOOL;\net : R.m.t.et : TIME;\npt : R.m.t.PT : TIME READ_WRITE;\nEND_VAR",
    );
    assert_eq!(errors(&src), []);
    let e = errors(&io_config(
        "VAR_CONFIG\nR.m.t.PT : TIME := T#1s;\nR.m.t.pt : TIME := T#2s;\nEND_VAR",
    ));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].3, "VAR_CONFIG already configures `R.m.t.pt`");
    let e = errors(&io_config("VAR_ACCESS\nq : R.m.t.Q : TIME;\nEND_VAR"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(
        e[0].3,
        "the access path `q` is declared TIME, but what it names is BOOL"
    );
}

#[test]
fn var_config_refuses_what_does_not_fit() {
    let cases = [
        (
            "R.x.n : INT := 1;",
            "IL0131",
            "there is no program instance `x` here",
        ),
        (
            "R.m.nn : INT := 1;",
            "IL0131",
            "PROGRAM `M` has no variable `nn`",
        ),
        (
            "R.m.n.x : INT := 1;",
            "IL0131",
            "`n` is INT, which has no members",
        ),
        (
            "R.m.t.PT.x : TIME := T#1s;",
            "IL0131",
            "`PT` is TIME, which has no members",
        ),
        (
            "R.m.t.PX : TIME := T#1s;",
            "IL0131",
            "the standard block TON has no input or output `PX`",
        ),
        (
            "R.m.t.PT : INT := 1;",
            "IL0131",
            "`R.m.t.PT` is TIME, not INT",
        ),
        (
            "R.m.t.Q AT %QX0.0 : BOOL;",
            "IL0131",
            "`R.m.t.Q` is not declared `AT %I*`",
        ),
        (
            "R.m.tmp : INT := 1;",
            "IL0131",
            "`tmp` of M is a VAR_TEMP, which is not part of the instance",
        ),
        (
            "R.m : INT := 1;",
            "IL0131",
            "`R.m` names a program instance: add the variable",
        ),
        ("R.m.n : DINT := 1;", "IL0131", "`R.m.n` is INT, not DINT"),
        (
            "R.m.n AT %MW2 : INT;",
            "IL0131",
            "`R.m.n` is not declared `AT %I*`, `%Q*` or `%M*`: VAR_CONFIG gives an address only to a partly specified variable",
        ),
        (
            "R.m.l.s AT %QX0.0 : BOOL;",
            "IL0131",
            "`R.m.l.s` is declared `AT %I*`, so its address must be in the same area, not %QX0.0",
        ),
        (
            "R.m.l.s AT %I* : BOOL;",
            "IL0131",
            "VAR_CONFIG must give the full address (`%IX0.1`, `%QW2`)",
        ),
        (
            "R.m.l.w AT %QX0.0 : WORD;",
            "IL0128",
            "`%QX0.0` is a bit (BOOL); it cannot hold WORD",
        ),
        (
            "R.m.n : INT := TRUE;",
            "IL0127",
            "expected a value of type INT",
        ),
    ];
    for (decl, code, want) in cases {
        let e = errors(&io_config(&format!("VAR_CONFIG\n{decl}\nEND_VAR")));
        assert_eq!(e.len(), 1, "{decl}: {e:?}");
        assert_eq!((e[0].0.as_str(), e[0].1), (code, 18), "{decl}: {e:?}");
        assert!(e[0].3.starts_with(want), "{decl}: {}", e[0].3);
    }
    let e = errors(&io_config(
        "VAR_CONFIG\nR.m.n : INT := 1;\nR.M.N : INT := 2;\nEND_VAR",
    ));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(
        (e[0].0.as_str(), e[0].3.as_str()),
        ("IL0104", "VAR_CONFIG already configures `R.M.N`")
    );
}

#[test]
fn var_access_refuses_what_does_not_fit() {
    let cases = [
        (
            "a : R.m.n : DINT;",
            "IL0131",
            "the access path `a` is declared DINT, but what it names is INT",
        ),
        (
            "a : nope : INT;",
            "IL0131",
            "configuration `C` has no global `nope`",
        ),
        (
            "a : loc : INT;",
            "IL0131",
            "the global `loc` is at %MW0 in the process image",
        ),
        (
            "a : R.m.l.k : INT READ_WRITE;",
            "IL0111",
            "`a` names a CONSTANT: it can only be READ_ONLY",
        ),
        (
            "a : Q.m.n : INT;",
            "IL0131",
            "configuration `C` has no resource or global `Q`",
        ),
    ];
    for (decl, code, want) in cases {
        let e = errors(&io_config(&format!("VAR_ACCESS\n{decl}\nEND_VAR")));
        assert_eq!(e.len(), 1, "{decl}: {e:?}");
        assert_eq!((e[0].0.as_str(), e[0].1), (code, 18), "{decl}: {e:?}");
        assert!(e[0].3.starts_with(want), "{decl}: {}", e[0].3);
    }
    let e = errors(&io_config(
        "VAR_ACCESS\na : g : INT;\nA : g : INT;\nEND_VAR",
    ));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].3, "access path `A` is declared twice");
}

#[test]
fn var_config_and_var_access_belong_to_the_configuration() {
    let src = format!(
        "{IO}CONFIGURATION C\nRESOURCE R ON PLC\nPROGRAM m : M;\nVAR_CONFIG R.m.n : INT := 1; END_VAR\nEND_RESOURCE\nEND_CONFIGURATION\n"
    );
    let e = errors(&src);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(
        e[0].3,
        "VAR_CONFIG and VAR_ACCESS belong in the CONFIGURATION, not in a RESOURCE"
    );
}
