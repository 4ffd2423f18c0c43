//! `textDocument/semanticTokens/full`: names coloured by what the checker
//! resolved them to.

use super::*;

/// The decoded tokens: (line, column, text, type, modifiers).
fn decode(
    text: &str,
    legend: &Value,
    data: &Value,
) -> Vec<(u64, u64, String, String, Vec<String>)> {
    let types: Vec<&str> = legend["tokenTypes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_str().unwrap())
        .collect();
    let mods: Vec<&str> = legend["tokenModifiers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_str().unwrap())
        .collect();
    let lines: Vec<&str> = text.lines().collect();
    let d: Vec<u64> = data
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect();
    let (mut line, mut col) = (0, 0);
    d.chunks(5)
        .map(|t| {
            if t[0] > 0 {
                col = 0;
            }
            line += t[0];
            col += t[1];
            let word: String = lines[line as usize]
                .chars()
                .skip(col as usize)
                .take(t[2] as usize)
                .collect();
            let m = (0..mods.len())
                .filter(|i| t[4] & (1 << i) != 0)
                .map(|i| mods[i].to_string())
                .collect();
            (line, col, word, types[t[3] as usize].to_string(), m)
        })
        .collect()
}

#[test]
fn names_are_coloured_by_what_they_name() {
    let dir = temp_dir("semantic");
    let path = dir.join("m.il");
    let m = uri(&path);
    let text = "TYPE Mode : (Idle, Run); END_TYPE\n\
FUNCTION Twice : INT\nVAR_INPUT x : INT; END_VAR\n    LD x\n    MUL 2\n    ST Twice\nEND_FUNCTION\n\
PROGRAM Main\nVAR\n    t1 : TON;\n    n : INT;\n    mode : Mode;\nEND_VAR\n\
    LD n\n    Twice\n    ST n\n    LD Mode#Run\n    ST mode\n    CAL t1(IN := TRUE, PT := T#1s)\n    LD t1.Q\n    JMPC done\n    LD n\n    ABS\n    ST n\ndone:\nEND_PROGRAM\n";
    let mut c = Client::start(&[]);
    let init = c.initialize(&dir, json!({}));
    let legend = init["capabilities"]["semanticTokensProvider"]["legend"].clone();
    assert!(legend.is_object(), "{init}");
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    assert_eq!(c.diagnostics_for(&m), Vec::<Value>::new());
    let r = c.result(
        "textDocument/semanticTokens/full",
        json!({"textDocument": {"uri": m}}),
    );
    let toks = decode(text, &legend, &r["data"]);
    let kind_of = |word: &str, line: u64| -> (String, Vec<String>) {
        toks.iter()
            .find(|t| t.2 == word && t.0 == line)
            .map(|t| (t.3.clone(), t.4.clone()))
            .unwrap_or_else(|| panic!("no token `{word}` on line {line}: {toks:?}"))
    };
    let decl = vec!["declaration".to_string()];
    assert_eq!(kind_of("Mode", 0), ("type".into(), decl.clone()));
    assert_eq!(kind_of("Run", 0).0, "enumMember");
    assert_eq!(kind_of("Twice", 1), ("function".into(), decl.clone()));
    assert_eq!(kind_of("x", 2).0, "parameter");
    assert_eq!(kind_of("t1", 9), ("instance".into(), decl.clone()));
    assert_eq!(
        kind_of("TON", 9),
        ("class".into(), vec!["defaultLibrary".to_string()])
    );
    // A user FUNCTION as an operator, an enumeration value, an instance, a
    // member of a standard block, a jump target and its label.
    assert_eq!(kind_of("Twice", 14), ("function".into(), vec![]));
    assert_eq!(kind_of("Run", 16).0, "enumMember");
    assert_eq!(kind_of("t1", 18), ("instance".into(), vec![]));
    assert_eq!(kind_of("Q", 19).0, "property");
    assert_eq!(kind_of("done", 20).0, "label");
    assert_eq!(kind_of("done", 24), ("label".into(), decl));
    assert_eq!(kind_of("n", 13).0, "variable");
    c.finish();
}
