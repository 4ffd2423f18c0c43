//! `textDocument/codeAction`: the checker's quick fixes, applied as an
//! editor applies them, give a program that checks.

use super::*;

/// `text` with a workspace edit's changes to `uri` applied (single-line
/// ranges over ASCII text, as here).
fn apply(text: &str, uri: &str, action: &Value) -> String {
    let mut edits: Vec<&Value> = action["edit"]["changes"][uri]
        .as_array()
        .unwrap()
        .iter()
        .collect();
    edits.sort_by_key(|e| {
        let s = &e["range"]["start"];
        std::cmp::Reverse((s["line"].as_u64(), s["character"].as_u64()))
    });
    let mut lines: Vec<String> = text.split('\n').map(str::to_string).collect();
    for e in edits {
        let (a, b) = (&e["range"]["start"], &e["range"]["end"]);
        let n = a["line"].as_u64().unwrap() as usize;
        assert_eq!(a["line"], b["line"]);
        let (x, y) = (
            a["character"].as_u64().unwrap() as usize,
            b["character"].as_u64().unwrap() as usize,
        );
        let l = &lines[n];
        lines[n] = format!("{}{}{}", &l[..x], e["newText"].as_str().unwrap(), &l[y..]);
    }
    lines.join("\n")
}

#[test]
fn quick_fixes_rename_convert_and_write_durations() {
    let dir = temp_dir("actions");
    let path = dir.join("m.il");
    let m = uri(&path);
    let text = "PROGRAM Main\nVAR\n    count : INT;\n    big : DINT;\n    flag : BOOL;\n    t : TON;\nEND_VAR\n    LD flg\n    JMPC skp\n    LD big\nL1: ST count\n    LD T#5s\n    ST t.PT\nskip:\nEND_PROGRAM\n";
    let mut c = Client::start(&[]);
    let init = c.initialize(&dir, json!({}));
    assert_eq!(init["capabilities"]["codeActionProvider"], json!(true));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    let diags = c.diagnostics_for(&m);
    assert!(diags.len() >= 3, "{diags:?}");
    let actions_at = |c: &mut Client, line: u64| {
        c.result(
            "textDocument/codeAction",
            json!({"textDocument": {"uri": m},
                   "range": {"start": {"line": line, "character": 0}, "end": {"line": line, "character": 40}},
                   "context": {"diagnostics": []}}),
        )
    };
    let titles = |v: &Value| -> Vec<String> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|a| a["title"].as_str().unwrap().to_string())
            .collect()
    };
    let a = actions_at(&mut c, 7);
    assert_eq!(titles(&a), ["Change to `flag`"], "{a}");
    assert_eq!(a[0]["kind"], json!("quickfix"));
    assert!(apply(text, &m, &a[0]).contains("    LD flag\n"));
    let a = actions_at(&mut c, 8);
    assert_eq!(titles(&a), ["Change to `skip`"], "{a}");
    // DINT into INT: the conversion goes after the label, the ST below it.
    let a = actions_at(&mut c, 10);
    assert_eq!(
        titles(&a),
        ["Convert the current result with `DINT_TO_INT`"],
        "{a}"
    );
    let fixed = apply(text, &m, &a[0]);
    assert!(
        fixed.contains("    LD big\nL1: DINT_TO_INT\n    ST count\n"),
        "{fixed}"
    );
    // Every fix applied: the program checks.
    let mut all = text.to_string();
    for line in [10u64, 8, 7] {
        let a = actions_at(&mut c, line);
        all = apply(&all, &m, &a[0]);
    }
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": m, "version": 2}, "contentChanges": [{"text": all}]}),
    );
    // Only the warning that `L1` is never jumped to is left.
    let left = c.diagnostics_for(&m);
    assert!(
        left.iter().all(|d| d["code"] == json!("IL0120")),
        "{left:?}\n{all}"
    );
    // A duration without its `T#` (a syntax error, alone then).
    let broken = all.replace("LD T#5s", "LD 5s");
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": m, "version": 3}, "contentChanges": [{"text": broken}]}),
    );
    assert_eq!(
        c.diagnostics_for(&m).len(),
        1,
        "a syntax error stops the check"
    );
    let a = actions_at(&mut c, 12);
    assert_eq!(titles(&a), ["Write `T#5s`"], "{a}");
    assert_eq!(apply(&broken, &m, &a[0]), all);
    c.finish();
}

#[test]
fn a_positional_call_converts_to_the_formal_form() {
    let dir = temp_dir("formal");
    let path = dir.join("m.il");
    let m = uri(&path);
    let text = "FUNCTION_BLOCK Fb\nVAR_INPUT\n    a : INT;\n    b : BOOL;\nEND_VAR\nVAR_OUTPUT q : BOOL; END_VAR\n    LD b\n    ST q\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR\n    t1 : TON;\n    f : Fb;\n    go : BOOL;\n    v : ARRAY[1..2] OF INT;\nEND_VAR\n    CAL t1(go, T#5s)\n    LD t1.Q\n    CALC f(v[1], t1.Q)\n    CAL t1(IN := go)\nEND_PROGRAM\n";
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    assert_eq!(c.diagnostics_for(&m), Vec::<Value>::new());
    let at = |c: &mut Client, line: u64| {
        c.result(
            "textDocument/codeAction",
            json!({"textDocument": {"uri": m},
                   "range": {"start": {"line": line, "character": 6}, "end": {"line": line, "character": 6}},
                   "context": {"diagnostics": []}}),
        )
    };
    let a = at(&mut c, 16);
    assert_eq!(a[0]["title"], json!("Convert to the formal form"), "{a}");
    assert_eq!(a[0]["kind"], json!("refactor.rewrite"));
    assert!(apply(text, &m, &a[0]).contains("    CAL t1(IN := go, PT := T#5s)\n"));
    let a = at(&mut c, 18);
    let out = apply(text, &m, &a[0]);
    assert!(out.contains("    CALC f(a := v[1], b := t1.Q)\n"), "{out}");
    // Already formal: nothing to offer.
    assert_eq!(at(&mut c, 19), json!([]));
    // The converted text checks as before (opened in a folder of its own:
    // another program).
    let n = uri(&temp_dir("formal-out").join("n.il"));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": n, "languageId": "il", "version": 1, "text": out}}),
    );
    assert_eq!(c.diagnostics_for(&n), Vec::<Value>::new());
    c.finish();
}
