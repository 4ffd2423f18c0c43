//! Navigation from the checker's resolution table: names the server's
//! former index of its own did not resolve, and document highlight.

use super::*;

#[test]
fn enumeration_values_types_and_externals() {
    let dir = temp_dir("table");
    let path = dir.join("m.il");
    let m = uri(&path);
    let text = "TYPE Mode : (Idle, Run); END_TYPE\n\
TYPE Alias : Mode; END_TYPE\n\
FUNCTION_BLOCK Fb\nVAR_EXTERNAL g : INT; END_VAR\nVAR m : Alias; END_VAR\n\
    LD Mode#Run\n    ST m\n    LD Idle\n    ST m\n    LD g\n    ADD 1\n    ST g\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR_EXTERNAL g : INT; END_VAR\nVAR f : Fb; END_VAR\n    CAL f\nEND_PROGRAM\n\
CONFIGURATION C\nVAR_GLOBAL g : INT; END_VAR\nRESOURCE R ON PLC\nPROGRAM p : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n";
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    assert_eq!(c.diagnostics_for(&m), Vec::<Value>::new());
    let line_of = |v: &Value| v["range"]["start"]["line"].as_u64().unwrap();
    // An enumeration value, typed or bare: its declaration.
    let d = c.result("textDocument/definition", at(&m, text, "#Run", 2));
    assert_eq!(
        (line_of(&d), d["range"]["start"]["character"].clone()),
        (0, json!(19)),
        "{d}"
    );
    let d = c.result("textDocument/definition", at(&m, text, "LD Idle", 4));
    assert_eq!(
        (line_of(&d), d["range"]["start"]["character"].clone()),
        (0, json!(13)),
        "{d}"
    );
    let h = c.result("textDocument/hover", at(&m, text, "LD Idle", 4));
    assert!(
        hover_text(&h).contains("value of the enumeration `Mode`"),
        "{h}"
    );
    // A TYPE named by another TYPE: a reference of it.
    let r = c.result(
        "textDocument/references",
        json!({"textDocument": {"uri": m}, "position": at(&m, text, "Mode :", 1)["position"],
               "context": {"includeDeclaration": false}}),
    );
    let mut lines: Vec<u64> = r.as_array().unwrap().iter().map(line_of).collect();
    lines.sort();
    assert_eq!(lines, [1, 5], "{r}");
    // Highlight: the uses of `g` in its FB (the external, not the global).
    let hl = c.result(
        "textDocument/documentHighlight",
        json!({"textDocument": {"uri": m}, "position": at(&m, text, "LD g", 3)["position"]}),
    );
    let mut lines: Vec<u64> = hl.as_array().unwrap().iter().map(line_of).collect();
    lines.sort();
    assert_eq!(lines, [3, 9, 11], "{hl}");
    // A program instance's type.
    let d = c.result("textDocument/definition", at(&m, text, ": Main", 2));
    assert_eq!(line_of(&d), 13, "{d}");
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
