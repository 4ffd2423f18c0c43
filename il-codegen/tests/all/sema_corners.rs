//! The standard's corners (docs/semantics.md; IL-SEMANTICS.md "Values and
//! calls"): what the checker accepts and refuses for strings of several
//! lengths, ANY-typed standard functions on derived types, nested
//! initialisers, subscript expressions and self-containing blocks.

use il_codegen::diag::SourceFile;

/// (code, message, line) of every error.
fn errors(src: &str) -> Vec<(String, String, u32)> {
    let f = SourceFile::new("t.il", src);
    let lines = f.clone();
    il_codegen::Program::new().il(f).check().diagnostics()[0]
        .iter()
        .filter(|d| d.is_error())
        .map(|d| {
            let line = lines.line_of(d.span.lo) as u32;
            (d.code.to_string(), d.message.clone(), line)
        })
        .collect()
}

fn codes(src: &str) -> Vec<String> {
    errors(src).into_iter().map(|e| e.0).collect()
}

const TYPES: &str = "TYPE C : (Red, Green, Blue); P : INT (0..10); S : STRUCT a : INT; END_STRUCT; \
                     A : ARRAY[1..2] OF INT; END_TYPE\n";

fn prog(decls: &str, body: &str) -> Vec<String> {
    codes(&format!(
        "{TYPES}FUNCTION_BLOCK Take\nVAR_INPUT s4 : STRING[4]; END_VAR\nVAR_OUTPUT o : STRING; END_VAR\n\
         VAR_IN_OUT io : STRING[4]; END_VAR\nLD s4\nST o\nEND_FUNCTION_BLOCK\n\
         PROGRAM Main\nVAR {decls} END_VAR\n{body}\nEND_PROGRAM\n"
    ))
}

#[test]
fn strings_of_any_length_are_one_type() {
    let d = "a : STRING[4]; b : STRING; w : WSTRING[4]; x : BOOL; t : Take; i : INT;";
    assert_eq!(prog(d, "LD a\nST b\nLD b\nST a"), Vec::<String>::new());
    assert_eq!(
        prog(d, "LD a\nEQ b\nST x\nLD b\nGT a\nST x"),
        Vec::<String>::new()
    );
    assert_eq!(
        prog(d, "CAL t(s4 := b, o => a, io := a)"),
        Vec::<String>::new()
    );
    assert_eq!(prog(d, "LD b\nST t.s4"), Vec::<String>::new());
    assert_eq!(
        prog(d, "LD TRUE\nSEL a, b\nST a\nLD a\nCONCAT b\nST a"),
        Vec::<String>::new()
    );
    assert_eq!(
        prog(d, "LD a\nEQ b, a\nST x\nLD a\nMAX b\nST b"),
        Vec::<String>::new()
    );
    // Refused: another kind of string, a number, a VAR_IN_OUT of another
    // length (it is a reference), a literal longer than the capacity.
    assert_eq!(prog(d, "LD a\nST w"), ["IL0106"]);
    assert_eq!(prog(d, "LD w\nEQ a\nST x"), ["IL0106"]);
    assert_eq!(prog(d, "LD a\nST i"), ["IL0106"]);
    assert_eq!(prog(d, "CAL t(io := b)"), ["IL0130"]);
    assert_eq!(prog(d, "LD 'abcde'\nST a"), ["IL0116"]);
}

#[test]
fn any_typed_functions_take_derived_types() {
    let d = "c : C; c2 : C; p : P; s : S; s2 : S; a : A; a2 : A; x : BOOL; k : INT; t : Take; \
             ts : ARRAY[1..2] OF Take;";
    let ok = Vec::<String>::new();
    assert_eq!(
        prog(d, "LD x\nSEL c, c2\nST c\nLD k\nMUX c, c2, C#Red\nST c"),
        ok
    );
    assert_eq!(prog(d, "LD c\nMOVE\nST c\nLD c\nEQ c2, c\nST x"), ok);
    assert_eq!(
        prog(
            d,
            "LD x\nSEL s, s2\nST s\nLD k\nMUX a, a2\nST a\nLD a\nMOVE\nST a2"
        ),
        ok
    );
    assert_eq!(
        prog(
            d,
            "LD p\nMAX 3\nST p\nLD p\nLIMIT p, 9\nST p\nLD p\nGT 1, 0\nST x"
        ),
        ok
    );
    // Refused: enumerations are not ordered, structures and arrays are not
    // elementary, two different types, FB instances are not values.
    assert_eq!(prog(d, "LD c\nGT c2, c\nST x"), ["IL0106"]);
    assert_eq!(prog(d, "LD c\nMAX c2\nST c"), ["IL0106"]);
    assert_eq!(prog(d, "LD s\nMIN s2\nST s"), ["IL0106"]);
    assert_eq!(prog(d, "LD s\nEQ s2, s\nST x"), ["IL0106"]);
    assert_eq!(prog(d, "LD x\nSEL c, s\nST c"), ["IL0106"]);
    assert_eq!(prog(d, "LD x\nSEL ts, ts\nST x"), ["IL0106"]);
}
