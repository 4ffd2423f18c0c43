//! The initialization option `dialect`: `.il` documents are M221 /
//! TwidoSuite listings, checked as `ilc check --dialect m221` checks them.

use super::*;

#[test]
fn m221_listings_are_checked_with_the_dialect_option() {
    let dir = temp_dir("dialect-m221");
    let text = "LD %I0.0\nST %Q0.0\n\nBLK %TM0\nLD %I0.1\nIN\nEND_BLK\n";
    std::fs::write(dir.join("main.il"), text).unwrap();
    let main = uri(&dir.join("main.il"));
    // As IEC IL the listing is no program; as an M221 listing its one
    // problem is the timer without configuration, on its line.
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({"dialect": "m221"}));
    let d = c.diagnostics_for(&main);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "IL0436");
    assert_eq!(
        d[0]["range"]["start"],
        json!({"line": 3, "character": 4}),
        "{d:?}"
    );
    c.finish();
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    let d = c.diagnostics_for(&main);
    assert!(d.iter().all(|x| x["code"] != "IL0436"), "{d:?}");
    assert!(!d.is_empty());
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn hover_definition_references_in_an_m221_listing() {
    let dir = temp_dir("dialect-m221-hover");
    let text = "LD %I0.0\nOR %M0\nST %M0\n\nLD %M0\nST %Q0.0\n";
    std::fs::write(dir.join("main.il"), text).unwrap();
    let main = uri(&dir.join("main.il"));
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({"dialect": "m221"}));
    let d = c.diagnostics_for(&main);
    assert!(d.is_empty(), "{d:?}");
    // An object: its declaration as the import wrote it, over the operand alone.
    let h = c.result("textDocument/hover", at(&main, text, "%Q0.0", 1));
    assert!(hover_text(&h).contains("Q0_0 AT %QX0.0 : BOOL"), "{h}");
    assert_eq!(
        h["range"]["start"],
        json!({"line": 5, "character": 3}),
        "{h}"
    );
    // The operator: the current result.
    let h = c.result("textDocument/hover", at(&main, text, "LD %M0", 0));
    assert!(hover_text(&h).contains("CR before"), "{h}");
    // The listing declares nothing: an object's definition is its first use,
    // and its references are every use, each once, from any of them.
    let def = c.result("textDocument/definition", at(&main, text, "LD %M0", 4));
    assert_eq!(
        def["range"]["start"],
        json!({"line": 1, "character": 3}),
        "{def}"
    );
    let starts = |v: &Value| -> Vec<(u64, u64)> {
        (v.as_array().unwrap().iter())
            .map(|x| {
                let s = &x["range"]["start"];
                (
                    s["line"].as_u64().unwrap(),
                    s["character"].as_u64().unwrap(),
                )
            })
            .collect()
    };
    for from in ["OR %M0", "ST %M0", "LD %M0"] {
        let mut p = at(&main, text, from, 4);
        p["context"] = json!({"includeDeclaration": true});
        let refs = c.result("textDocument/references", p);
        assert_eq!(
            starts(&refs),
            [(1, 3), (2, 3), (4, 3)],
            "from {from}: {refs}"
        );
        let hl = c.result("textDocument/documentHighlight", at(&main, text, from, 4));
        assert_eq!(starts(&hl), [(1, 3), (2, 3), (4, 3)], "from {from}: {hl}");
    }
    // `%M0` is an address, not a name the listing could be renamed by.
    let mut p = at(&main, text, "ST %M0", 4);
    p["newName"] = json!("Pump");
    let r = c.request("textDocument/rename", p);
    let e = r["error"]["message"].as_str().unwrap_or_default();
    assert!(e.contains("`%M0` is how this file writes `M0`"), "{r}");
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
