//! Names and nesting that pass the parser but cannot become Rust: each is
//! refused with a code and a place.

use il_codegen::diag::SourceFile;

/// The errors of compiling `src`: code, line, column, message.
fn errors(src: &str) -> Vec<(String, usize, usize, String)> {
    let f = SourceFile::new("t.il", src);
    match il_codegen::compile(&f, Default::default()) {
        Ok(_) => Vec::new(),
        Err(d) => d
            .iter()
            .filter(|d| d.is_error())
            .map(|d| {
                let (l, c) = f.line_col(d.span.lo);
                (d.code.to_string(), l, c, d.message.clone())
            })
            .collect(),
    }
}

/// `_` was accepted as a POU, variable or enumeration value name and became
/// `__invalid_1` in the Rust.
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
            e.iter().any(|(c, l, k, m)| c == "IL0126"
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
