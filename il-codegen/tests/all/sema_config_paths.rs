//! VAR_ACCESS paths through array elements and members of structures
//! (Ed.2 2.7.1 `symbolic_variable`), and VAR_CONFIG, which names whole
//! variables only (Ed.2 B.1.7 `instance_specific_init`).

use crate::checked::errors;

const PROG: &str = "TYPE Pt : STRUCT x : INT; y : ARRAY[1..3] OF INT; END_STRUCT; END_TYPE
FUNCTION_BLOCK F
VAR_INPUT IN : INT; END_VAR
VAR_OUTPUT Q : BOOL; END_VAR
    LD IN
    GT 0
    ST Q
END_FUNCTION_BLOCK
PROGRAM P
VAR a : ARRAY[0..3] OF INT; m : ARRAY[1..2, 1..3] OF INT; fbs : ARRAY[1..2] OF F;
    t : ARRAY[1..2] OF TON; p : Pt; END_VAR
VAR CONSTANT k : ARRAY[1..2] OF INT := [1, 2]; END_VAR
    LD a[0]
    ST a[1]
END_PROGRAM
";

/// `PROG` (16 lines) and a configuration; `tail` starts at line 21, so its
/// first declaration after the block keyword is on line 22.
fn config(tail: &str) -> String {
    format!(
        "{PROG}CONFIGURATION C\nVAR_GLOBAL g : Pt; h : ARRAY[1..4] OF INT; s : INT; END_VAR\nRESOURCE RES1 ON PLC\nPROGRAM P1 : P;\nEND_RESOURCE\n{tail}\nEND_CONFIGURATION\n"
    )
}

#[test]
fn paths_through_elements_and_members_are_accepted() {
    let src = config(
        "VAR_ACCESS
a2 : RES1.P1.a[2] : INT READ_WRITE;
m23 : RES1.P1.m[2, 3] : INT;
q1 : RES1.P1.fbs[1].Q : BOOL;
in2 : RES1.P1.fbs[2].IN : INT READ_WRITE;
tq : RES1.P1.t[2].Q : BOOL;
tpt : RES1.P1.t[1].PT : TIME READ_WRITE;
px : RES1.P1.p.x : INT READ_WRITE;
py : RES1.P1.p.y[3] : INT;
gx : g.x : INT READ_WRITE;
gy : g.y[1] : INT;
h3 : h[3] : INT READ_WRITE;
rh : RES1.h[-0 + 4] : INT;
k1 : RES1.P1.k[1] : INT;
END_VAR",
    );
    // Subscripts of a configuration path are constant expressions.
    assert_eq!(errors(&src), []);
    let with = |sub: &str| src.replace("RES1.h[-0 + 4]", &format!("RES1.h[{sub}]"));
    for sub in ["4", "7 MOD 3 + 3", "-(-4)", "(1 + 1) * 2", "9 / 2", "16#4"] {
        assert_eq!(errors(&with(sub)), [], "{sub}");
    }
    // Refused: out of bounds once folded, a division by zero, a variable.
    for (sub, msg) in [
        ("10 / 2 * 2", "outside"),
        ("4 MOD 0", "divides by zero"),
        ("1 / (2 - 2)", "divides by zero"),
        ("k + 1", "must be a constant"),
    ] {
        let e = errors(&with(sub));
        assert_eq!(e.len(), 1, "{sub}: {e:?}");
        assert!(e[0].3.contains(msg), "{sub}: {e:?}");
    }
}

#[test]
fn access_paths_refuse_what_does_not_fit() {
    // (declaration, code, column, message start)
    let cases = [
        (
            "x : RES1.P1.a[4] : INT;",
            "IL0125",
            15,
            "subscript 4 is outside the bounds 0..3",
        ),
        (
            "x : RES1.P1.m[1, 0] : INT;",
            "IL0125",
            18,
            "subscript 0 is outside the bounds 1..3",
        ),
        (
            "x : h[-1] : INT;",
            "IL0125",
            7,
            "subscript -1 is outside the bounds 1..4",
        ),
        (
            "x : RES1.P1.fbs[3].Q : BOOL;",
            "IL0125",
            17,
            "subscript 3 is outside the bounds 1..2",
        ),
        (
            "x : RES1.P1.a[s] : INT;",
            "IL0131",
            15,
            "a subscript of a configuration path must be a constant",
        ),
        (
            "x : RES1.P1.a[1, 2] : INT;",
            "IL0125",
            14,
            "2 subscripts for an array of 1 dimensions",
        ),
        (
            "x : RES1.P1.a.x : INT;",
            "IL0131",
            15,
            "`a` is ARRAY[0..3] OF INT, which has no members",
        ),
        ("x : g[1] : INT;", "IL0125", 6, "`g` is Pt, not an array"),
        (
            "x : g.xx : INT;",
            "IL0131",
            7,
            "the structure Pt has no member `xx`",
        ),
        (
            "x : RES1.P1.fbs[1].R : BOOL;",
            "IL0131",
            20,
            "FUNCTION_BLOCK `F` has no variable `R`",
        ),
        (
            "x : RES1.P1.t[1].Z : BOOL;",
            "IL0131",
            18,
            "the standard block TON has no input or output `Z`",
        ),
        (
            "x : RES1.P1.a[1].3 : BOOL;",
            "IL0131",
            18,
            "a partial access (`.3`, `.%X3`) is not part of a configuration path",
        ),
        (
            "x : RES1.P1.p.y[2] : DINT;",
            "IL0131",
            22,
            "the access path `x` is declared DINT, but what it names is INT",
        ),
        (
            "x : RES1.P1.k[1] : INT READ_WRITE;",
            "IL0111",
            1,
            "`x` names a CONSTANT: it can only be READ_ONLY",
        ),
        (
            "x : RES1.nope.a[1] : INT;",
            "IL0131",
            10,
            "resource `RES1` has no program instance or global `nope`",
        ),
        (
            "x : gg.x : INT;",
            "IL0131",
            5,
            "configuration `C` has no resource or global `gg`",
        ),
    ];
    for (decl, code, col, want) in cases {
        let e = errors(&config(&format!("VAR_ACCESS\n{decl}\nEND_VAR")));
        assert_eq!(e.len(), 1, "{decl}: {e:?}");
        assert_eq!(
            (e[0].0.as_str(), e[0].1, e[0].2),
            (code, 22, col),
            "{decl}: {e:?}"
        );
        assert!(e[0].3.starts_with(want), "{decl}: {}", e[0].3);
    }
}

#[test]
fn a_wrong_member_name_gets_a_suggestion() {
    let f = il_codegen::diag::SourceFile::new(
        "t.il",
        config("VAR_ACCESS\nx : g.yy[1] : INT;\nEND_VAR"),
    );
    let checked = il_codegen::Program::new().il(f).check();
    let d = &checked.diagnostics()[0];
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].help.as_deref(), Some("did you mean `y`?"));
}

/// Ed.2 B.1.7: `instance_specific_init ::= resource_name '.' program_name
/// '.' {fb_name '.'} variable_name ...`: no subscripts, no members of
/// structures.
#[test]
fn var_config_names_whole_variables_only() {
    let cases = [
        (
            "RES1.P1.a[1] : INT := 3;",
            10,
            "VAR_CONFIG names a whole variable of a program or FB instance (Ed.2 2.7.1: `Res.Prog.fb.x`), not an array element",
        ),
        (
            "RES1.P1.p.x : INT := 3;",
            11,
            "VAR_CONFIG names a whole variable of a program or FB instance (Ed.2 2.7.1: `Res.Prog.fb.x`), not the member `x` of a structure",
        ),
        (
            "RES1.P1.fbs[1].IN : INT := 3;",
            12,
            "VAR_CONFIG names a whole variable of a program or FB instance (Ed.2 2.7.1: `Res.Prog.fb.x`), not an array element",
        ),
    ];
    for (decl, col, want) in cases {
        let e = errors(&config(&format!("VAR_CONFIG\n{decl}\nEND_VAR")));
        assert_eq!(e.len(), 1, "{decl}: {e:?}");
        assert_eq!(
            (e[0].0.as_str(), e[0].1, e[0].2),
            ("IL0131", 22, col),
            "{decl}: {e:?}"
        );
        assert!(e[0].3.starts_with(want), "{decl}: {}", e[0].3);
    }
    // The whole array and the whole structure are configured.
    let src = config(
        "VAR_CONFIG\nRES1.P1.a : ARRAY[0..3] OF INT := [1, 2, 3, 4];\nRES1.P1.p : Pt := (x := 2);\nEND_VAR",
    );
    assert_eq!(errors(&src), []);
}
