//! `textDocument/formatting` and `rangeFormatting`: one edit per changed
//! line, the edits give what `ilc fmt` writes, a range edits its lines
//! only, and a file with syntax errors gets no edits.

use super::*;

/// The text after applying `edits` (each replaces whole lines' contents).
fn apply(text: &str, edits: &Value) -> String {
    let mut lines: Vec<String> = text.split('\n').map(str::to_string).collect();
    for e in edits.as_array().unwrap() {
        let (a, b) = (&e["range"]["start"], &e["range"]["end"]);
        assert_eq!(a["line"], b["line"], "one line per edit: {e}");
        assert_eq!(a["character"], json!(0), "{e}");
        let n = a["line"].as_u64().unwrap() as usize;
        assert_eq!(
            b["character"].as_u64().unwrap() as usize,
            lines[n].chars().count()
        );
        lines[n] = e["newText"].as_str().unwrap().to_string();
    }
    lines.join("\n")
}

#[test]
fn formatting_edits_the_lines_that_change() {
    let dir = temp_dir("fmt");
    let path = dir.join("m.il");
    let m = uri(&path);
    let text = "PROGRAM Main\nVAR\n  x:INT;\n  long_name : BOOL;\nEND_VAR\n ld x\n   add 1\nst x\nEND_PROGRAM\n";
    let mut c = Client::start(&[]);
    let init = c.initialize(&dir, json!({}));
    assert_eq!(
        init["capabilities"]["documentFormattingProvider"],
        json!(true)
    );
    assert_eq!(
        init["capabilities"]["documentRangeFormattingProvider"],
        json!(true)
    );
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    let _ = c.diagnostics_for(&m);
    let opts = json!({"tabSize": 4, "insertSpaces": true});
    let edits = c.result(
        "textDocument/formatting",
        json!({"textDocument": {"uri": m}, "options": opts}),
    );
    let want = "PROGRAM Main\nVAR\n    x         : INT;\n    long_name : BOOL;\nEND_VAR\n    LD  x\n    ADD 1\n    ST  x\nEND_PROGRAM\n";
    assert_eq!(apply(text, &edits), want, "{edits}");
    // Lines 5 and 6 only: the declarations stay as they are.
    let edits = c.result(
        "textDocument/rangeFormatting",
        json!({"textDocument": {"uri": m}, "options": opts,
               "range": {"start": {"line": 5, "character": 0}, "end": {"line": 6, "character": 3}}}),
    );
    assert_eq!(edits.as_array().unwrap().len(), 2, "{edits}");
    assert!(apply(text, &edits).contains("  x:INT;\n"));
    assert!(apply(text, &edits).contains("    LD  x\n    ADD 1\nst x"));
    // A syntax error: no edits (the diagnostics say why).
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": m, "version": 2},
               "contentChanges": [{"text": "PROGRAM Main\n ld (\nEND_PROGRAM\n"}]}),
    );
    let _ = c.diagnostics_for(&m);
    let edits = c.result(
        "textDocument/formatting",
        json!({"textDocument": {"uri": m}, "options": opts}),
    );
    assert_eq!(edits, Value::Null);
    c.finish();
}
