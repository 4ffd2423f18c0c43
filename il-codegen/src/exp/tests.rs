//! The import's own unit tests (through the public API: `tests/all/exp.rs`).

use super::*;

fn import(text: &str) -> Import {
    Import::new(SourceFile::new("t.EXP", text))
}

#[test]
fn objects_and_their_headers() {
    let i = import(
        "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @PATH := '\\/K14' *)\nFUNCTION f : INT\nVAR_INPUT a : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD a\nST f\nEND_FUNCTION\n\nLIBRARY\nStandard.lib 1.1.1\nEND_LIBRARY\n",
    );
    let o = i.objects();
    assert_eq!(o.len(), 2);
    assert_eq!(o[0].kind, ObjectKind::Pou(PouKind::Function));
    assert_eq!(o[0].name, "f");
    assert_eq!(o[0].path, "\\/K14");
    assert_eq!(o[0].language, Language::Il);
    assert_eq!(o[1].kind, ObjectKind::Skipped("a library reference"));
    assert_eq!(o[1].name, "Standard.lib 1.1.1");
    assert!(i.diagnostics.is_empty(), "{:?}", i.diagnostics);
    assert!(i.il.text.contains("FUNCTION f : INT"), "{}", i.il.text);
    assert!(!i.il.text.contains("@END_DECLARATION"));
}

#[test]
fn st_bodies_are_interfaces() {
    let i = import(
        "FUNCTION_BLOCK fb\nVAR_INPUT a : INT; END_VAR\nVAR t : BLINK; END_VAR\n(* @END_DECLARATION := '0' *)\nIF a > 1 THEN a := 2; END_IF;\nEND_FUNCTION_BLOCK\n",
    );
    assert_eq!(i.objects()[0].language, Language::St);
    assert_eq!(i.diagnostics.len(), 1);
    assert_eq!(i.diagnostics[0].code, codes::NOT_IL);
    assert!(
        i.il.text.starts_with("{extern} FUNCTION_BLOCK fb"),
        "{}",
        i.il.text
    );
    assert!(!i.il.text.contains("BLINK"), "{}", i.il.text);
    assert!(!i.il.text.contains("IF a"), "{}", i.il.text);
}
