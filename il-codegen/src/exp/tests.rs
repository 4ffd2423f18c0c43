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

#[test]
fn sfc_bodies_and_visualisations() {
    let i = import(
        "(* @NESTEDCOMMENTS := 'Yes' *)\nPROGRAM Seq\nVAR_OUTPUT q : BOOL; END_VAR\n(* @END_DECLARATION := '0' *)\nINITIAL_STEP Init:\nEND_STEP\nACTION Init_active:\nq := TRUE;\nEND_ACTION\nTRANSITION FROM Init TO Init := TRUE;\nEND_TRANSITION\nEND_PROGRAM\n\n(* @NESTEDCOMMENTS := 'Yes' *)\n(* @PATH := '' *)\nVISUALISATION PLC_VISU _VISU_TYPES : 1,1\n_BG_BMP : ''\nEND_VISUALISATION\n",
    );
    let o = i.objects();
    assert_eq!(o.len(), 2, "{o:?}");
    assert_eq!(o[0].language, Language::Sfc);
    assert_eq!(o[1].kind, ObjectKind::Skipped("a visualisation"));
    assert_eq!(o[1].name, "PLC_VISU");
    let codes: Vec<&str> = i.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, [codes::NOT_IL]);
}

#[test]
fn the_body_language_is_read_from_what_only_st_has() {
    let body = |b: &str| {
        let text = format!(
            "FUNCTION_BLOCK fb\nVAR_INPUT a : INT; END_VAR\nVAR x : INT; END_VAR\n(* @END_DECLARATION := '0' *)\n{b}\nEND_FUNCTION_BLOCK\n"
        );
        import(&text).objects()[0].language
    };
    // IL that starts with a user function used as an operator, with a
    // call's `:=` in parentheses, with a label, or empty.
    assert_eq!(body("Twice 3\nST x"), Language::Il);
    assert_eq!(
        body("CAL t(IN := TRUE,\n  PT := T#1s)\nLD t.Q\nST x"),
        Language::Il
    );
    assert_eq!(body("start: LD a (* x := 1; *)\nST x"), Language::Il);
    assert_eq!(body("LD 'a;b'\nST x"), Language::Il);
    assert_eq!(body(""), Language::Il);
    // ST: an assignment, a statement's `;`, a control keyword, even when
    // the first word is spelt like an IL operator.
    assert_eq!(body("x := a;"), Language::St);
    assert_eq!(body("S := TRUE;"), Language::St);
    assert_eq!(body("Twice(a);"), Language::St);
    assert_eq!(body("IF a > 1 THEN\n x := 2\nEND_IF"), Language::St);
    assert_eq!(body("LD := 1"), Language::St);
}

#[test]
fn a_block_of_a_referenced_library_is_named_with_its_library() {
    let text = "(* @NESTEDCOMMENTS := 'Yes' *)\nPROGRAM PLC_PRG\nVAR b : BLINK; q : BOOL; END_VAR\n(* @END_DECLARATION := '0' *)\nCAL b(ENABLE := TRUE)\nLD b.OUT\nST q\nEND_PROGRAM\n\nLIBRARY\nUtil.lib 18.5.10 14:14:28\n(* @LIBRARYSYMFILEINFO := '0' *)\nNumOfPOUs: 2\nBLINK: 2048\nHYSTERESIS: 2048\nNumOfGVLs: 1\nGlobale_Variablen: 0\nEND_LIBRARY\n";
    let c = crate::Program::new()
        .source(SourceFile::new("t.EXP", text))
        .check();
    let d = c.diagnostics()[0]
        .iter()
        .find(|d| d.code == "IL0105")
        .unwrap_or_else(|| panic!("{:?}", c.diagnostics()));
    assert!(
        d.notes.iter().any(|n| n.starts_with(
            "`BLINK` is a POU of the library `Util.lib`, which this project references"
        )),
        "{:?}",
        d.notes
    );
    // A global list's name is no POU of the library.
    assert!(!d.notes.iter().any(|n| n.contains("Globale_Variablen")));
}

#[test]
fn a_called_program_is_a_block_with_one_global_instance() {
    // Without a task configuration, PLC_PRG calls Aux, and Aux calls no one.
    let text = "PROGRAM Aux\nVAR_OUTPUT n : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD n\nADD 1\nST n\nEND_PROGRAM\nACTION Reset:\nLD 0\nST n\nEND_ACTION\n\nPROGRAM PLC_PRG\nVAR k : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nCAL Aux\nLD Aux.n\nST k\nCAL Aux.Reset\nEND_PROGRAM\n";
    let c = crate::Program::new()
        .source(SourceFile::new("t.EXP", text))
        .check();
    assert!(c.diagnostics()[0].is_empty(), "{:?}", c.diagnostics());
    let crate::Input::Exp(i) = &c.inputs()[0] else {
        panic!("an export")
    };
    let il = &i.il.text;
    assert!(il.contains("FUNCTION_BLOCK Aux\n"), "{il}");
    assert!(il.contains("END_FUNCTION_BLOCK\n"), "{il}");
    assert!(il.contains("CAL Aux(Reset := TRUE)"), "{il}");
    assert!(il.contains("VAR_GLOBAL\n\tAux : Aux;\nEND_VAR"), "{il}");
    assert!(il.contains("PROGRAM PLC_PRG : PLC_PRG;"), "{il}");
    // No task runs Aux: it runs where it is called, with no Aux_RUN.
    assert!(!il.contains("Aux_RUN"), "{il}");
}
