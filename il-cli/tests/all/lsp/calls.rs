//! Calls in the editor: signature help (operator, formal and FB calls, user
//! and standard), hover on a user FUNCTION used as an operator, and go to
//! definition on members of standard and user function blocks.

use super::*;

const TEXT: &str = "FUNCTION Scale : INT\nVAR_INPUT\n    x : INT;\n    k : INT;\nEND_VAR\n    LD x\n    MUL k\n    ST Scale\nEND_FUNCTION\n\
FUNCTION_BLOCK Pump\nVAR_INPUT\n    go : BOOL;\nEND_VAR\nVAR_OUTPUT\n    running : BOOL;\nEND_VAR\n    LD go\n    ST running\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR\n    n : INT;\n    t1 : TON;\n    c : CTU;\n    p : Pump;\nEND_VAR\n    LD n\n    Scale 3\n    LIMIT 0, 100\n    ST n\n    CAL t1(IN := TRUE, PT := T#1s)\n    LD c.CV\n    CAL p(go := t1.Q)\n    LD p.running\n    ST t1.IN\nEND_PROGRAM\n";

fn line_col(needle: &str, by: usize) -> (u64, u64) {
    let (l, c) = find(TEXT, needle, by);
    (l as u64, c as u64)
}

#[test]
fn signature_help_hover_and_definitions_of_calls() {
    let dir = temp_dir("calls");
    let path = dir.join("m.il");
    let m = uri(&path);
    let mut c = Client::start(&[]);
    let init = c.initialize(&dir, json!({}));
    assert!(
        init["capabilities"]["signatureHelpProvider"].is_object(),
        "{init}"
    );
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": TEXT}}),
    );
    assert_eq!(c.diagnostics_for(&m), Vec::<Value>::new());
    let sig_at = |c: &mut Client, needle: &str, by: usize| {
        let (l, ch) = line_col(needle, by);
        c.result(
            "textDocument/signatureHelp",
            json!({"textDocument": {"uri": m}, "position": {"line": l, "character": ch}}),
        )
    };
    // A user FUNCTION as an operator: the CR is `x`, the operand `k`.
    let h = sig_at(&mut c, "Scale 3", 7);
    assert_eq!(
        h["signatures"][0]["label"],
        json!("Scale(x : INT, k : INT)"),
        "{h}"
    );
    assert_eq!(h["activeParameter"], json!(1));
    assert!(
        h["signatures"][0]["documentation"]
            .as_str()
            .unwrap()
            .contains("current result is its first input `x`")
    );
    // A standard one, after the comma: MX.
    let h = sig_at(&mut c, "LIMIT 0, 100", 10);
    assert!(
        h["signatures"][0]["label"]
            .as_str()
            .unwrap()
            .starts_with("LIMIT(MN : "),
        "{h}"
    );
    assert_eq!(h["activeParameter"], json!(2));
    // An FB call: by the formal name being written.
    let h = sig_at(&mut c, "PT := T#1s", 3);
    assert_eq!(
        h["signatures"][0]["label"],
        json!("t1 : TON(IN : BOOL, PT : TIME)"),
        "{h}"
    );
    assert_eq!(h["activeParameter"], json!(1));
    let h = sig_at(&mut c, "go := t1.Q", 2);
    assert_eq!(
        h["signatures"][0]["label"],
        json!("p : Pump(go : BOOL)"),
        "{h}"
    );
    // No call: no help.
    assert_eq!(sig_at(&mut c, "LD n", 4), Value::Null);

    // Hover on the FUNCTION as an operator: inputs, result, the CR.
    let (l, ch) = line_col("Scale 3", 2);
    let h = c.result(
        "textDocument/hover",
        json!({"textDocument": {"uri": m}, "position": {"line": l, "character": ch}}),
    );
    let v = h["contents"]["value"].as_str().unwrap();
    assert!(
        v.contains("FUNCTION Scale : INT\nVAR_INPUT\n    x : INT;\n    k : INT;\nEND_VAR"),
        "{v}"
    );
    assert!(
        v.contains("CR before: `INT`, CR after (its result): `INT`"),
        "{v}"
    );

    // Definition of a standard block's member: its rendered declaration.
    let (l, ch) = line_col("c.CV", 3);
    let d = c.result(
        "textDocument/definition",
        json!({"textDocument": {"uri": m}, "position": {"line": l, "character": ch}}),
    );
    let file = d["uri"]
        .as_str()
        .unwrap()
        .strip_prefix("file://")
        .unwrap()
        .to_string();
    assert!(file.ends_with("/CTU.il"), "{d}");
    let rendered = std::fs::read_to_string(&file).unwrap();
    let line = rendered
        .lines()
        .nth(d["range"]["start"]["line"].as_u64().unwrap() as usize)
        .unwrap();
    assert_eq!(line.trim(), "CV : INT;", "{rendered}");
    // ... and of a user block's member: its declaration.
    let (l, ch) = line_col("p.running", 3);
    let d = c.result(
        "textDocument/definition",
        json!({"textDocument": {"uri": m}, "position": {"line": l, "character": ch}}),
    );
    assert_eq!(
        d["range"]["start"],
        json!({"line": 14, "character": 4}),
        "{d}"
    );
    c.finish();
}
