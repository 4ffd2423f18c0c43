//! Every declaration is checked once, whether anything uses it or not
//! (issue 29, item 4): a defect in a TYPE, a STRUCT field, an initial value
//! or a block's variables is reported at the declaration, exactly once,
//! when nothing uses it and when many things do.

use crate::checked::errors;
use il_codegen::diag::SourceFile;

type Error = (&'static str, usize, usize, &'static str);

fn owned(e: &[Error]) -> Vec<(String, usize, usize, String)> {
    e.iter()
        .map(|(c, l, col, m)| (c.to_string(), *l, *col, m.to_string()))
        .collect()
}

/// A program that uses nothing of `types` (lines 2.. of the file).
fn unused(types: &str) -> String {
    format!(
        "TYPE\n{types}\nEND_TYPE\nPROGRAM Main\nVAR x : INT; END_VAR\nLD 1\nST x\nEND_PROGRAM\n"
    )
}

/// The same types, with `name` used everywhere a type can be: twice in a
/// PROGRAM, in a FUNCTION_BLOCK, through an alias, a STRUCT field, an array
/// and a global (the uses after the defect's line).
fn used(types: &str, name: &str) -> String {
    format!(
        "TYPE\n{types}\nAgain : {name}; Holder : STRUCT h1, h2 : {name}; END_STRUCT; \
         Row : ARRAY[1..2] OF {name};\nEND_TYPE\n\
         PROGRAM Main\nVAR x : INT; v1, v2 : {name}; v3 : Again; h : Holder; r : Row; END_VAR\n\
         LD 1\nST x\nEND_PROGRAM\n\
         FUNCTION_BLOCK Fb\nVAR v : {name}; END_VAR\nLD 1\nEND_FUNCTION_BLOCK\n\
         CONFIGURATION C\nVAR_GLOBAL g : {name}; END_VAR\nRESOURCE R ON PLC\nEND_RESOURCE\nEND_CONFIGURATION\n"
    )
}

/// `types` (from line 2) gives exactly `want`, unused and used as `name`.
fn once(types: &str, name: &str, want: &[Error]) {
    let want = owned(want);
    assert_eq!(errors(&unused(types)), want, "unused:\n{types}");
    assert_eq!(errors(&used(types, name)), want, "used:\n{types}");
}

/// [`once`] for a function block type: used as instances (not in a STRUCT,
/// not as a global).
fn once_instance(types: &str, name: &str, want: &[Error]) {
    let want = owned(want);
    assert_eq!(errors(&unused(types)), want, "unused:\n{types}");
    let used = format!(
        "TYPE\n{types}\nAgain : {name}; Row : ARRAY[1..2] OF {name};\nEND_TYPE\n\
         PROGRAM Main\nVAR x : INT; v1, v2 : {name}; v3 : Again; r : Row; END_VAR\n\
         LD 1\nST x\nEND_PROGRAM\n\
         FUNCTION_BLOCK Fb\nVAR v : {name}; END_VAR\nLD 1\nEND_FUNCTION_BLOCK\n"
    );
    assert_eq!(errors(&used), want, "used:\n{types}");
}

#[test]
fn subranges_are_checked_at_their_declaration() {
    once(
        "R : LINT (16..-16);",
        "R",
        &[(
            "IL0127",
            2,
            11,
            "the subrange 16..-16 is empty: its lower limit is above its upper limit",
        )],
    );
    once(
        "O : SINT (0..300);",
        "O",
        &[(
            "IL0127",
            2,
            14,
            "the subrange limit 300 is outside SINT (-128..127)",
        )],
    );
    once(
        "O : USINT (-1..3);",
        "O",
        &[(
            "IL0127",
            2,
            12,
            "the subrange limit -1 is outside USINT (0..255)",
        )],
    );
    once(
        "I : INT (0..10) := 20;",
        "I",
        &[("IL0127", 2, 20, "20 is outside the subrange 0..10")],
    );
    // Subranges are of integer types (Ed.2 2.3.3.1), not bit strings.
    once(
        "W : WORD (0..16);",
        "W",
        &[(
            "IL0127",
            2,
            5,
            "a subrange needs an integer base type, not the bit string WORD",
        )],
    );
    once(
        "F : REAL (0..1);",
        "F",
        &[(
            "IL0127",
            2,
            5,
            "a subrange needs an integer base type, not `REAL`",
        )],
    );
    // A subrange of a subrange names an elementary base; an alias of a
    // subrange inherits its limits, and its own initial value must fit them.
    once(
        "I : INT (0..10);\nSub : I (0..5);",
        "Sub",
        &[(
            "IL0127",
            3,
            7,
            "a subrange needs an integer base type, not `I`",
        )],
    );
    once(
        "I : INT (0..10);\nI2 : I := 50;",
        "I2",
        &[("IL0127", 3, 11, "50 is outside the subrange 0..10")],
    );
    once(
        "I : INT (0..10) := 5;\nI2 : I;\nI3 : I2 := 11;",
        "I3",
        &[("IL0127", 4, 12, "11 is outside the subrange 0..10")],
    );
}

#[test]
fn a_bit_string_subrange_is_refused_in_a_variable_too() {
    let e = errors("PROGRAM Main\nVAR w : DWORD (0..5); END_VAR\nLD 1\nEND_PROGRAM\n");
    assert_eq!(
        e,
        owned(&[(
            "IL0127",
            2,
            9,
            "a subrange needs an integer base type, not the bit string DWORD",
        )])
    );
}

#[test]
fn enumerations_are_checked_at_their_declaration() {
    once(
        "E : (A, B, A);",
        "E",
        &[("IL0104", 2, 12, "`A` appears twice in `E`")],
    );
    once(
        "E : (A, B) := C;",
        "E",
        &[("IL0127", 2, 15, "`C` is not a value of E (A, B)")],
    );
    once(
        "E : (A, B := 2.5);",
        "E",
        &[(
            "IL0127",
            2,
            14,
            "an enumeration value must be a (64-bit) integer",
        )],
    );
}

#[test]
fn arrays_are_checked_at_their_declaration() {
    once(
        "A : ARRAY[5..1] OF INT;",
        "A",
        &[("IL0125", 2, 11, "array bounds 5..1 are empty")],
    );
    once(
        "A : ARRAY[1..n] OF INT;",
        "A",
        &[("IL0121", 2, 14, "array bounds must be integer literals")],
    );
    // The element count of extreme bounds is counted without overflow.
    once(
        "A : ARRAY[-9223372036854775808..9223372036854775807] OF INT;",
        "A",
        &[("IL0125", 2, 5, "array too large (over 16 million elements)")],
    );
    once(
        "A : ARRAY[1..2] OF INT := [1, 2, 3];",
        "A",
        &[(
            "IL0127",
            2,
            27,
            "3 initial values for an array of 2 elements",
        )],
    );
    once(
        "A : ARRAY[1..2] OF SINT (0..9) := [1, 10];",
        "A",
        &[("IL0127", 2, 39, "10 is outside the subrange 0..9")],
    );
}

#[test]
fn structures_and_their_initialisers_are_checked_at_their_declaration() {
    const S: &str = "S : STRUCT a : INT; b : SINT (0..10); END_STRUCT;\n";
    once(
        "T : STRUCT a : INT := 'x'; END_STRUCT;",
        "T",
        &[(
            "IL0127",
            2,
            23,
            "expected a value of type INT, found a string literal",
        )],
    );
    once(
        "T : STRUCT b : SINT (0..10) := 11; END_STRUCT;",
        "T",
        &[("IL0127", 2, 32, "11 is outside the subrange 0..10")],
    );
    once(
        &format!("{S}T : S := (c := 1);"),
        "T",
        &[("IL0112", 3, 11, "S has no field `c`")],
    );
    once(
        &format!("{S}T : S := (a := TRUE);"),
        "T",
        &[(
            "IL0127",
            3,
            16,
            "expected a value of type INT, found a BOOL literal",
        )],
    );
    once(
        &format!("{S}T : S := (b := 11);"),
        "T",
        &[("IL0127", 3, 16, "11 is outside the subrange 0..10")],
    );
    once(
        &format!("{S}T : ARRAY[1..2] OF S := [(a := 1), (z := 2)];"),
        "T",
        &[("IL0112", 3, 37, "S has no field `z`")],
    );
    // A field of a type whose initial value is wrong: reported at the type.
    once(
        "I : INT (0..10) := 20;\nT : STRUCT i : I; END_STRUCT;",
        "T",
        &[("IL0127", 2, 20, "20 is outside the subrange 0..10")],
    );
}

#[test]
fn a_type_defined_in_terms_of_itself_is_reported_once() {
    once(
        "T1 : T2;\nT2 : T1;",
        "T1",
        &[("IL0117", 3, 6, "type `T1` is defined in terms of itself")],
    );
    once(
        "T : ARRAY[1..2] OF T;",
        "T",
        &[("IL0117", 2, 20, "type `T` is defined in terms of itself")],
    );
}

#[test]
fn a_type_declared_twice_still_has_its_own_errors_reported() {
    let e = errors(&unused("T : INT;\nT : SINT (0..300);"));
    assert_eq!(
        e,
        owned(&[
            ("IL0104", 3, 1, "`T` is already the name of a type or POU"),
            (
                "IL0127",
                3,
                14,
                "the subrange limit 300 is outside SINT (-128..127)"
            ),
        ])
    );
}

#[test]
fn function_block_instance_initialisers_are_checked_unused() {
    once_instance(
        "T : TON := (XX := T#1s);",
        "T",
        &[("IL0112", 2, 13, "TON has no input `XX`")],
    );
    once_instance(
        "T : TON := (PT := 5);",
        "T",
        &[(
            "IL0127",
            2,
            19,
            "expected a value of type TIME, found the integer literal 5",
        )],
    );
    // In a block nothing calls or holds.
    let e = errors(
        "FUNCTION_BLOCK Unused\nVAR t : TON := (PT := 5); c : INT (0..5) := 7; END_VAR\n\
         LD 1\nEND_FUNCTION_BLOCK\n",
    );
    assert_eq!(
        e,
        owned(&[
            (
                "IL0127",
                2,
                23,
                "expected a value of type TIME, found the integer literal 5"
            ),
            ("IL0127", 2, 45, "7 is outside the subrange 0..5"),
        ])
    );
}

#[test]
fn initial_values_of_unused_variables_are_checked() {
    let e = errors(
        "FUNCTION Fn : INT\nVAR_INPUT i : SINT := 300; END_VAR\nLD 1\nST Fn\nEND_FUNCTION\n\
         CONFIGURATION C\nVAR_GLOBAL g : BOOL := 2; END_VAR\nRESOURCE R ON PLC\nEND_RESOURCE\nEND_CONFIGURATION\n",
    );
    assert_eq!(
        e,
        owned(&[
            ("IL0127", 2, 23, "300 does not fit in SINT (-128..127)"),
            ("IL0127", 7, 24, "2 is not a BOOL (only 0 and 1 are)"),
        ])
    );
}

#[test]
fn valid_unused_declarations_give_no_diagnostic() {
    let types = "\
        L : LINT (-9223372036854775808..9223372036854775807);\n\
        U : ULINT (0..18446744073709551615) := 18446744073709551615;\n\
        One : SINT (-5..-5);\n\
        I : INT (0..10) := 5; I2 : I; I3 : I2 := 7;\n\
        E : (A, B := 5, C) := B;\n\
        Arr : ARRAY[-2..2, 1..3] OF I := [15(4)];\n\
        Fwd : STRUCT later : Later := (v := 3); e : E := C; END_STRUCT;\n\
        Later : STRUCT v : I; END_STRUCT;\n\
        Tmr : TON := (PT := T#1s);\n\
        Str : STRING[4] := 'abcd';";
    let f = SourceFile::new("t.il", unused(types));
    let checked = il_codegen::Program::new().il(f).check();
    assert_eq!(checked.diagnostics()[0], [], "{types}");
    assert_eq!(errors(&used(types, "I3")), []);
}

#[test]
fn named_types_give_their_initial_values_through_aliases() {
    let src = "TYPE I : INT (0..10) := 5; J : I; K : J; E : (A, B) := E#B; F : E; END_TYPE\n\
               PROGRAM Main\nVAR k : K; f : F; END_VAR\nLD k\nST k\nEND_PROGRAM\n";
    let file = SourceFile::new("t.il", src);
    let checked = il_codegen::Program::new().il(file).check();
    assert!(!checked.has_errors(), "{}", checked.render(false));
    let program = &checked.ir().expect("no errors")[0];
    let vars = &program.pous[0].vars;
    let init = |n: &str| {
        let v = vars.iter().find(|v| v.name == n).expect("declared");
        format!("{:?}", v.init)
    };
    assert!(init("k").contains("Int(5"), "{}", init("k"));
    assert!(init("f").contains("\"B\""), "{}", init("f"));
    // The enumeration's default (for its Rust `Default`) is the one given.
    let default = program.types.iter().find_map(|t| match t {
        il_codegen::ir::TypeDef::Enum { default, .. } => Some(*default),
        _ => None,
    });
    assert_eq!(default, Some(1));
}

#[test]
fn a_long_chain_of_aliases_resolves_once() {
    // Each alias names the next; resolved in order, not again per use (a
    // chain used to be cut at 32 with a false "defined in terms of itself").
    let n = 20_000;
    let mut types = String::new();
    for i in 0..n {
        types.push_str(&format!("T{i} : T{};\n", i + 1));
    }
    types.push_str(&format!("T{n} : INT (0..9) := 3;"));
    assert_eq!(errors(&used(&types, "T0")), []);
}

#[test]
fn an_error_in_a_type_of_another_file_is_reported_in_that_file_once() {
    let types = SourceFile::new(
        "types.il",
        "TYPE\n  O : SINT (0..300);\nEND_TYPE\n".to_string(),
    );
    let user = SourceFile::new(
        "main.il",
        "PROGRAM Main\nVAR a, b : O; END_VAR\nLD 1\nEND_PROGRAM\n".to_string(),
    );
    let checked = il_codegen::Program::new()
        .il(types.clone())
        .il(user)
        .check();
    let d = checked.diagnostics();
    let at: Vec<(usize, usize, String)> = d[0]
        .iter()
        .map(|d| {
            let (l, c) = types.line_col(d.span.lo);
            (l, c, d.message.clone())
        })
        .collect();
    assert_eq!(
        at,
        [(
            2,
            16,
            "the subrange limit 300 is outside SINT (-128..127)".to_string()
        )]
    );
    assert_eq!(d[1], []);
}
