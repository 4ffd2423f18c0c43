//! The LSP's programs: the documents of one folder are one program.

use super::*;

/// A workspace with two crates' `plc/` folders, each with its own `PROGRAM
/// Main` and FUNCTION `Scale`: each folder is one program, so neither is a
/// duplicate of the other, and names resolve within their own folder.
#[test]
fn each_folder_is_a_program_of_its_own() {
    let dir = temp_dir("folders");
    let (a, b) = (dir.join("a/plc"), dir.join("b/plc"));
    std::fs::create_dir_all(&a).unwrap();
    std::fs::create_dir_all(&b).unwrap();
    let scale = |k: i32| {
        format!(
            "FUNCTION Scale : INT\nVAR_INPUT x : INT; END_VAR\n    LD x\n    MUL {k}\n    ST Scale\nEND_FUNCTION\n"
        )
    };
    let main = "PROGRAM Main\nVAR v : INT; END_VAR\n    LD v\n    Scale\n    ST v\nEND_PROGRAM\n";
    std::fs::write(a.join("scale.il"), scale(2)).unwrap();
    std::fs::write(b.join("scale.il"), scale(3)).unwrap();
    std::fs::write(b.join("main.il"), main).unwrap();
    let a_main = uri(&a.join("main.il"));
    let b_scale = uri(&b.join("scale.il"));
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": a_main, "languageId": "il", "version": 1, "text": main}}),
    );
    assert_eq!(c.diagnostics_for(&a_main), Vec::<Value>::new());
    assert_eq!(c.diagnostics_for(&b_scale), Vec::<Value>::new());
    // `Scale` in a/plc/main.il is a/plc's.
    let d = c.result("textDocument/definition", at(&a_main, main, "Scale", 1));
    assert_eq!(d["uri"], uri(&a.join("scale.il")), "{d}");
    // Both show up among the workspace symbols, each in its folder.
    let s = c.result("workspace/symbol", json!({"query": "Scale"}));
    let mut files: Vec<String> = s
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["name"] == "Scale")
        .map(|s| s["location"]["uri"].as_str().unwrap().to_string())
        .collect();
    files.sort();
    assert_eq!(files, [uri(&a.join("scale.il")), b_scale.clone()]);
    // A duplicate within one folder is still one.
    std::fs::write(a.join("more.il"), scale(4)).unwrap();
    let more = uri(&a.join("more.il"));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": more, "languageId": "il", "version": 1, "text": scale(4)}}),
    );
    let dup = c.diagnostics_for(&more);
    assert!(
        dup.iter()
            .any(|d| d["message"].as_str().unwrap().contains("Scale")),
        "{dup:?}"
    );
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
