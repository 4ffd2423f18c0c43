//! The server's diagnostics are `ilc check`'s: after each edit of a random
//! sequence (characters and lines deleted, IL words and broken syntax
//! inserted), what the server last published for the document equals what
//! `ilc check --message-format json` says of the same text (code, line,
//! column, message): the server parses again only the POUs an edit
//! touches, and applies the edits the editor sends (incremental sync).

use super::*;

/// (code, line, column, message), 1-based, columns in characters.
type Key = (String, u64, u64, String);

fn from_lsp(text: &str, d: &Value) -> Key {
    let line = d["range"]["start"]["line"].as_u64().unwrap();
    let utf16 = d["range"]["start"]["character"].as_u64().unwrap() as usize;
    // UTF-16 units to characters on that line.
    let l = text.split('\n').nth(line as usize).unwrap_or("");
    let (mut units, mut chars) = (0, 0);
    for c in l.chars() {
        if units >= utf16 {
            break;
        }
        units += c.len_utf16();
        chars += 1;
    }
    let message = d["message"]
        .as_str()
        .unwrap()
        .lines()
        .next()
        .unwrap_or("")
        .to_string();
    (
        d["code"].as_str().unwrap_or("").to_string(),
        line + 1,
        chars as u64 + 1,
        message,
    )
}

/// The LSP position of byte `off` of `text`.
fn lsp_pos(text: &str, off: usize) -> Value {
    let line = text[..off].matches('\n').count();
    let start = text[..off].rfind('\n').map_or(0, |i| i + 1);
    let character: usize = text[start..off].chars().map(char::len_utf16).sum();
    json!({"line": line, "character": character})
}

fn from_check(dir: &Path, text: &str) -> Vec<Key> {
    let path = dir.join("check.il");
    std::fs::write(&path, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(["check", "--message-format", "json"])
        .arg(&path)
        .output()
        .unwrap();
    let mut keys: Vec<Key> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .filter_map(|l| serde_json::from_str::<Value>(l).ok())
        .filter(|d| d.get("code").is_some())
        .map(|d| {
            (
                d["code"].as_str().unwrap().to_string(),
                d["line"].as_u64().unwrap(),
                d["column"].as_u64().unwrap(),
                d["message"].as_str().unwrap().to_string(),
            )
        })
        .collect();
    keys.sort();
    keys
}

#[test]
fn after_random_edits_the_server_says_what_ilc_check_says() {
    let dir = temp_dir("consistency");
    let path = dir.join("m.il");
    let m = uri(&path);
    let mut text = format!("{LIB}{MAIN}");
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    let mut shown: Vec<Key> = c
        .diagnostics_for(&m)
        .iter()
        .map(|d| from_lsp(&text, d))
        .collect();
    let inserts = [
        "x",
        " ",
        "\n",
        "LD ",
        "1",
        "    ST ok\n",
        "(*",
        "*)",
        ":",
        ";",
        "END_VAR\n",
        "    ADD count\n",
        "    JMP skip\n",
        "T#5s",
        "'",
        "ä",
        "(",
        ")",
        "VAR\n",
        "    LD m.run\n",
    ];
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut rand = |n: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % n as u64) as usize
    };
    let other = temp_dir("consistency-check");
    for version in 2..42 {
        // A char boundary at or before `i`.
        let floor = |t: &str, mut i: usize| {
            while !t.is_char_boundary(i) {
                i -= 1;
            }
            i
        };
        let at = floor(&text, rand(text.len() + 1));
        // The edits go as an editor with incremental sync sends them: the
        // range replaced (line, UTF-16 column) and its new text.
        let change = match rand(3) {
            0 => {
                let end = floor(&text, (at + 1 + rand(6)).min(text.len()));
                let range = json!({"start": lsp_pos(&text, at), "end": lsp_pos(&text, end)});
                text.replace_range(at..end, "");
                json!({"range": range, "text": ""})
            }
            1 => {
                let new = inserts[rand(inserts.len())];
                let range = json!({"start": lsp_pos(&text, at), "end": lsp_pos(&text, at)});
                text.insert_str(at, new);
                json!({"range": range, "text": new})
            }
            _ => {
                // Undo towards the original now and then, so that the
                // sequence also passes through programs without errors.
                text = format!("{LIB}{MAIN}");
                json!({"text": text})
            }
        };
        c.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": m, "version": version}, "contentChanges": [change]}),
        );
        // A request after the change: its answer comes after the change's
        // diagnostics, if it published any (only changed ones are).
        c.result(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": m}}),
        );
        let published: Vec<Value> = c
            .notes
            .iter()
            .filter(|n| {
                n["method"] == "textDocument/publishDiagnostics" && n["params"]["uri"] == json!(m)
            })
            .cloned()
            .collect();
        c.notes.clear();
        if let Some(last) = published.last() {
            shown = last["params"]["diagnostics"]
                .as_array()
                .unwrap()
                .iter()
                .map(|d| from_lsp(&text, d))
                .collect();
        }
        shown.sort();
        assert_eq!(
            shown,
            from_check(&other, &text),
            "after edit {version}:\n{text}"
        );
    }
    c.finish();
}
