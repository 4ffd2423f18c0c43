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
    // A literal longer than the other string still compares.
    assert_eq!(
        prog(d, "LD a\nEQ 'abcdefgh'\nST x\nLD 'abcdefgh'\nLT a\nST x"),
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

#[test]
fn nested_initialisers_and_subrange_arrays() {
    let decl = |d: &str| {
        codes(&format!(
            "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; D : INT (5..9); \
             H : STRUCT p : ARRAY[1..2] OF Pt; d : ARRAY[1..2] OF D; END_STRUCT; END_TYPE\n\
             PROGRAM Main\nVAR {d} END_VAR\nLD 1\nEND_PROGRAM\n"
        ))
    };
    let ok = Vec::<String>::new();
    assert_eq!(
        decl("a : ARRAY[1..2] OF Pt := [(x := 1), (x := 2, y := 3)];"),
        ok
    );
    assert_eq!(
        decl("a : ARRAY[1..4] OF Pt := [2((y := 1)), (x := 2)];"),
        ok
    );
    assert_eq!(decl("h : H := (p := [(x := 1)], d := [5, 9]);"), ok);
    assert_eq!(
        decl("hs : ARRAY[1..2] OF H := [(d := [6]), (p := [(y := 2)])];"),
        ok
    );
    assert_eq!(decl("a : ARRAY[1..2] OF INT (0..3) := [3, 0];"), ok);
    // Refused: an element outside the element subrange, a field the
    // structure does not have, a structure for a number, too many elements.
    assert_eq!(decl("a : ARRAY[1..2] OF D := [5, 4];"), ["IL0127"]);
    assert_eq!(decl("a : ARRAY[1..2] OF INT (0..3) := [4];"), ["IL0127"]);
    assert_eq!(decl("h : H := (d := [10]);"), ["IL0127"]);
    assert_eq!(decl("a : ARRAY[1..2] OF Pt := [(z := 1)];"), ["IL0112"]);
    assert_eq!(decl("a : ARRAY[1..2] OF INT := [(x := 1)];"), ["IL0127"]);
    assert_eq!(decl("a : ARRAY[1..2] OF Pt := [3((x := 1))];"), ["IL0127"]);
    // A store of a literal outside the element subrange is refused, a
    // variable's is checked at run time.
    let body = |b: &str| {
        codes(&format!(
            "TYPE D : INT (5..9); END_TYPE\nPROGRAM Main\nVAR a : ARRAY[1..2] OF D; i : INT; END_VAR\n{b}\nEND_PROGRAM\n"
        ))
    };
    assert_eq!(body("LD 9\nST a[i]\nLD i\nST a[1]"), ok);
    assert_eq!(body("LD 4\nST a[i]"), ["IL0116"]);
}

#[test]
fn subscript_expressions() {
    let body = |b: &str| {
        errors(&format!(
            "PROGRAM Main\nVAR a : ARRAY[1..4] OF INT; m : ARRAY[1..2, 0..3] OF INT; \
             i : INT; u : ULINT; w : UINT; r : REAL; x : INT; END_VAR\n{b}\nEND_PROGRAM\n"
        ))
    };
    let ok = Vec::<(String, String, u32)>::new();
    assert_eq!(body("LD a[i + 1]\nST a[i-1]\nLD m[2 * i - 1, u]\nST x"), ok);
    assert_eq!(
        body("LD a[(i + 1) * 2]\nST a[-1 + i]\nLD a[2 * 2]\nST a[1+1]"),
        ok
    );
    // `/ MOD`, unary minus, parentheses; INT and UINT meet at DINT.
    assert_eq!(
        body("LD a[3 MOD 2 + 3]\nST a[i / 2]\nST a[-i + 5]\nST a[-(i - 5)]\nST a[i MOD w]"),
        ok
    );
    assert_eq!(
        body("LD 1\nST a[i * i * i - 3 + w]\nST a[(i + 1) mod 4 + 1]"),
        ok
    );
    // Refused: a literal expression outside the bounds (folded), a REAL in
    // the expression, a dangling operator, a constant division by zero,
    // INT with ULINT (no integer type holds both), negated unsigned
    // integers, a literal that does not fit the expression's type.
    let e = body("LD a[2 * 3]\nST x");
    assert_eq!((e[0].0.as_str(), e[0].2), ("IL0125", 3), "{e:?}");
    assert!(
        e[0].1.contains("subscript 6 is outside the bounds 1..4"),
        "{e:?}"
    );
    let e = body("LD a[i + r]\nST x");
    assert_eq!((e[0].0.as_str(), e[0].2), ("IL0125", 3), "{e:?}");
    assert!(e[0].1.contains("must be an integer, not REAL"), "{e:?}");
    let e = body("LD a[i +]\nST x");
    assert!(!e.is_empty() && e.iter().all(|d| d.2 == 3), "{e:?}");
    for (b, msg) in [
        ("LD a[i / 0]", "`i / 0` divides by zero"),
        ("LD a[i MOD (1 - 1)]", "`i MOD (1 - 1)` divides by zero"),
        (
            "LD a[i + u]",
            "no integer type holds both INT and ULINT in `i + u`; convert one side (ULINT_TO_LINT)",
        ),
        ("LD a[-w]", "`-w` negates an unsigned integer (UINT)"),
        (
            "LD a[i + 40000]",
            "in a subscript of type INT: 40000 does not fit in INT",
        ),
    ] {
        let e = body(&format!("{b}\nST x"));
        assert_eq!(e.len(), 1, "{b}: {e:?}");
        assert_eq!((e[0].0.as_str(), e[0].2), ("IL0125", 3), "{b}: {e:?}");
        assert!(e[0].1.contains(msg), "{b}: {e:?}");
    }
}

#[test]
fn a_block_holding_itself_is_reported_at_the_instance_declaration() {
    let src = "FUNCTION_BLOCK Loop\nVAR\n    n : INT;\n    inner : Loop;\nEND_VAR\nLD n\nST n\nEND_FUNCTION_BLOCK\n";
    let e = errors(src);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].0.as_str(), e[0].2), ("IL0117", 4), "{e:?}");
    assert!(e[0].1.contains("Loop → Loop"), "{e:?}");
    // Through another block and an array: each at its own declaration.
    let src = "FUNCTION_BLOCK A\nVAR b : B; END_VAR\nLD 1\nEND_FUNCTION_BLOCK\n\
               FUNCTION_BLOCK B\nVAR x : INT;\n    many : ARRAY[1..2] OF A;\nEND_VAR\nLD 1\nEND_FUNCTION_BLOCK\n";
    let mut e = errors(src);
    e.sort_by_key(|d| d.2);
    let got: Vec<(&str, u32)> = e.iter().map(|d| (d.0.as_str(), d.2)).collect();
    assert_eq!(got, [("IL0117", 2), ("IL0117", 7)], "{e:?}");
    // A block holding another (no cycle) is fine; a FUNCTION calling itself
    // is still reported at the call.
    let ok = "FUNCTION_BLOCK A\nVAR t : TON; END_VAR\nLD 1\nEND_FUNCTION_BLOCK\n\
              FUNCTION_BLOCK B\nVAR a : A; END_VAR\nLD 1\nEND_FUNCTION_BLOCK\n";
    assert_eq!(errors(ok), []);
    let f = "FUNCTION F : INT\nVAR_INPUT x : INT; END_VAR\nLD x\nF\nST F\nEND_FUNCTION\n";
    let e = errors(f);
    assert_eq!((e[0].0.as_str(), e[0].2), ("IL0117", 4), "{e:?}");
}

/// Deferred parentheses save the outer CR in a slot per depth and type: a
/// saved value is read at its `)`, before the next group of that depth
/// starts, so sequential groups share one `__save_N` (a 100k-line POU had
/// one local per group, 11,000 of them).
#[test]
fn parentheses_share_a_save_slot_per_depth_and_type() {
    let src = "PROGRAM P\nVAR a, b, c : INT; r : REAL; END_VAR\n\
        LD a\nADD( b\nMUL( c\nSUB 1\n)\n)\nST a\n\
        LD b\nADD( c\nMUL( a\n)\n)\nST b\n\
        LD r\nMUL( r\nADD 1.0\n)\nST r\n\
        LD c\nSUB( a\n)\nST c\nEND_PROGRAM\n";
    let f = SourceFile::new("t.il", src);
    let checked = il_codegen::Program::new().il(f).check();
    assert!(!checked.has_errors(), "{:?}", checked.diagnostics());
    let pou = &checked.ir().unwrap()[0].pous[0];
    // INT at depth 0, INT at depth 1, REAL at depth 0: three slots for five groups.
    assert_eq!(pou.save_types.len(), 3, "{:?}", pou.save_types);
    let slots: Vec<u32> = pou
        .body
        .iter()
        .filter_map(|s| match &s.op {
            il_codegen::ir::Op::Save { slot, .. } => Some(*slot),
            _ => None,
        })
        .collect();
    assert_eq!(slots, [0, 1, 0, 1, 2, 0]);
}

/// The place table keeps a place without subscripts once (`LD a`, `ST a`,
/// `AND fb.Q` twice), and a place with subscripts once per use.
#[test]
fn place_table_shares_places_without_subscripts() {
    let src = "PROGRAM P\nVAR a, b : BOOL; t : TON; arr : ARRAY[0..3] OF BOOL; i : INT; END_VAR\n\
        LD a\nAND t.Q\nST a\nLD t.Q\nAND arr[i]\nOR arr[i]\nST b\nLD a\nST b\nEND_PROGRAM\n";
    let checked = il_codegen::Program::new()
        .il(SourceFile::new("t.il", src))
        .check();
    assert!(!checked.has_errors(), "{:?}", checked.diagnostics());
    let pou = &checked.ir().unwrap()[0].pous[0];
    // a, t.Q, b, and arr[i] twice (its subscript `i` is one more).
    let names: Vec<String> = pou
        .places
        .iter()
        .map(|p| format!("{:?}{}", p.root, p.path.len()))
        .collect();
    assert_eq!(pou.places.len(), 6, "{names:?}");
}
