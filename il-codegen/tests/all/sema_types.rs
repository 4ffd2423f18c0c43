//! Errors around user types, direct addresses and FB nesting.

use il_codegen::diag::SourceFile;

fn codes(src: &str) -> Vec<(String, String)> {
    let f = SourceFile::new("t.il", src);
    match il_codegen::compile(&f, Default::default()) {
        Ok(_) => Vec::new(),
        Err(d) => d
            .iter()
            .filter(|d| d.is_error())
            .map(|d| (d.code.to_string(), d.message.clone()))
            .collect(),
    }
}

const TYPES: &str =
    "TYPE C : (Red, Green); P : INT (0..10); S : STRUCT a : INT; END_STRUCT; END_TYPE\n";

#[test]
fn user_type_errors() {
    let fb = |body: &str| {
        codes(&format!(
            "{TYPES}FUNCTION_BLOCK F\nVAR c : C; p : P; s : S; i : INT; END_VAR\n{body}\nEND_FUNCTION_BLOCK\n"
        ))
    };
    assert_eq!(fb("LD C#Green\nST c"), []);
    assert_eq!(fb("LD C#Blue\nST c")[0].0, "IL0101");
    assert_eq!(
        fb("LD 11\nST p")[0].0,
        "IL0116",
        "constant outside the subrange"
    );
    assert_eq!(fb("LD 10\nST p\nLD s.a\nST i"), []);
    assert_eq!(fb("LD s.b\nST i")[0].0, "IL0112");
    assert_eq!(
        fb("LD c\nADD c\nST c")[0].0,
        "IL0107",
        "no arithmetic on enumerations"
    );
    assert_eq!(fb("LD i\nST c")[0].0, "IL0106");
}

#[test]
fn self_containing_types_and_blocks_are_refused() {
    let e = codes("TYPE S : STRUCT a : INT; next : S; END_STRUCT; END_TYPE\n");
    assert!(e.iter().any(|(c, _)| c == "IL0117"), "{e:?}");
    let e =
        codes("FUNCTION_BLOCK Loop\nVAR inner : Loop; END_VAR\nCAL inner\nEND_FUNCTION_BLOCK\n");
    assert!(
        e.iter().any(|(c, m)| c == "IL0117" && m.contains("Loop")),
        "{e:?}"
    );
}

#[test]
fn address_errors() {
    let fb = |decl: &str, body: &str| {
        codes(&format!(
            "PROGRAM P\nVAR {decl} END_VAR\n{body}\nEND_PROGRAM\n"
        ))
    };
    assert_eq!(
        fb("x AT %IX0.0 : INT;", "LD x\nST x")[0].0,
        "IL0128",
        "an INT at a bit address"
    );
    assert_eq!(
        fb("x AT %IX0.9 : BOOL;", "LD x\nST x")[0].0,
        "IL0128",
        "bit 9"
    );
    assert_eq!(
        fb("x : BOOL;", "LD x\nST %IX0.0")[0].0,
        "IL0111",
        "inputs are the host's"
    );
    assert_eq!(
        fb("x : BOOL;", "LD %IB5000\nST x")[0].0,
        "IL0128",
        "outside the image"
    );
    assert_eq!(fb("w AT %QW1 : WORD;", "LD 16#FF\nST w"), []);
}
