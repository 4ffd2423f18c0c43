//! `ilc lsp` driven as an editor drives it: a client in the test speaks
//! JSON-RPC with Content-Length framing to the built `ilc lsp` over its
//! stdin/stdout and checks the answers.

use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::Receiver;
use std::time::Duration;

use serde_json::{Value, json};

/// Programs per folder.
mod calls;
mod code_actions;
mod consistency;
mod dialect;
mod folders;
mod formatting;
mod imports;
mod moved_lines;
mod semantic;
mod table;

const LIB: &str = "\
FUNCTION_BLOCK Motor
VAR_INPUT
    start : BOOL;
END_VAR
VAR_OUTPUT
    run : BOOL;
END_VAR
VAR
    t1 : TON;
END_VAR
    LD start
    ST t1.IN
    CAL t1(PT := T#5s)
    LD t1.Q
    ST run
END_FUNCTION_BLOCK
";

/// `ST ok` stores an INT into a BOOL: one error, fixed by storing into `count`.
const MAIN: &str = "\
PROGRAM main
VAR
    m : Motor;
    tp : TP;
    go AT %IX0.0 : BOOL;
    count : INT := 5;
    ok : BOOL;
END_VAR
    LD go
    JMPC skip
    LD (* ä😀 *) count
    ADD 1
    ST ok
skip:
    CAL m(start := go)
    LD m.run
    ST ok
END_PROGRAM
";

/// Waits for an answer are bounded so that a broken server fails the test
/// instead of hanging it (this measures nothing).
const PATIENCE: Duration = Duration::from_secs(120);

struct Client {
    child: Child,
    stdin: ChildStdin,
    incoming: Receiver<Value>,
    next_id: i64,
    /// Notifications received while waiting for a response.
    notes: Vec<Value>,
}

impl Client {
    fn start(env: &[(&str, &str)]) -> Client {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_ilc"));
        cmd.arg("lsp")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        for (k, v) in env {
            cmd.env(k, v);
        }
        let mut child = cmd.spawn().expect("start ilc lsp");
        let stdin = child.stdin.take().unwrap();
        let incoming = il_testkit::framed::reader(child.stdout.take().unwrap());
        Client {
            child,
            stdin,
            incoming,
            next_id: 0,
            notes: Vec::new(),
        }
    }

    fn send(&mut self, msg: &Value) {
        il_testkit::framed::send(&mut self.stdin, msg).unwrap();
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// The whole response (`result` or `error`).
    fn request(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let m = self.incoming.recv_timeout(PATIENCE).expect("a response");
            if m["id"] == json!(id) && m.get("method").is_none() {
                return m;
            }
            self.notes.push(m);
        }
    }

    fn result(&mut self, method: &str, params: Value) -> Value {
        let r = self.request(method, params);
        assert!(r.get("error").is_none(), "{method}: {r}");
        r["result"].clone()
    }

    /// The next diagnostics published for `uri`.
    fn diagnostics_for(&mut self, uri: &str) -> Vec<Value> {
        if let Some(k) = self.notes.iter().position(|n| {
            n["method"] == "textDocument/publishDiagnostics" && n["params"]["uri"] == uri
        }) {
            let n = self.notes.remove(k);
            return n["params"]["diagnostics"].as_array().unwrap().clone();
        }
        loop {
            let m = self.incoming.recv_timeout(PATIENCE).expect("diagnostics");
            if m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri {
                return m["params"]["diagnostics"].as_array().unwrap().clone();
            }
            self.notes.push(m);
        }
    }

    fn initialize(&mut self, root: &Path, options: Value) -> Value {
        self.initialize_with(root, options, json!({}))
    }

    fn initialize_with(&mut self, root: &Path, options: Value, caps: Value) -> Value {
        let r = self.result(
            "initialize",
            json!({"processId": null, "rootUri": uri(root), "capabilities": caps,
                   "initializationOptions": options}),
        );
        self.notify("initialized", json!({}));
        r
    }

    fn finish(self) {
        self.finish_with_log();
    }

    /// Shut the server down; what it wrote to stderr (its log).
    fn finish_with_log(mut self) -> String {
        let r = self.request("shutdown", Value::Null);
        assert_eq!(r["result"], Value::Null, "{r}");
        self.notify("exit", Value::Null);
        let mut log = String::new();
        if let Some(mut e) = self.child.stderr.take() {
            let _ = std::io::Read::read_to_string(&mut e, &mut log);
        }
        let status = self.child.wait().unwrap();
        assert!(status.success(), "{status}");
        log
    }
}

fn uri(p: &Path) -> String {
    format!("file://{}", p.display())
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ilc-lsp-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn pos(uri: &str, line: usize, character: usize) -> Value {
    json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
}

/// The 0-based line of the first line of `text` containing `needle`, and
/// the UTF-16 column of `needle` in it (plus `by` characters).
fn find(text: &str, needle: &str, by: usize) -> (usize, usize) {
    for (n, line) in text.lines().enumerate() {
        if let Some(k) = line.find(needle) {
            return (n, line[..k].encode_utf16().count() + by);
        }
    }
    panic!("`{needle}` not in the text");
}

fn at(uri: &str, text: &str, needle: &str, by: usize) -> Value {
    let (l, c) = find(text, needle, by);
    pos(uri, l, c)
}

fn labels(items: &Value) -> Vec<String> {
    let list = items.get("items").unwrap_or(items);
    list.as_array()
        .map(|a| {
            a.iter()
                .map(|i| i["label"].as_str().unwrap().to_string())
                .collect()
        })
        .unwrap_or_default()
}

fn hover_text(v: &Value) -> String {
    v["contents"]["value"].as_str().unwrap_or("").to_string()
}

#[test]
fn an_editor_session() {
    let dir = temp_dir("session");
    std::fs::write(dir.join("lib.il"), LIB).unwrap();
    std::fs::write(dir.join("main.il"), MAIN).unwrap();
    let lib = uri(&dir.join("lib.il"));
    let main = uri(&dir.join("main.il"));

    let mut c = Client::start(&[]);
    let init = c.initialize_with(
        &dir,
        json!({}),
        json!({"workspace": {"inlayHint": {"refreshSupport": true}}}),
    );
    let caps = &init["capabilities"];
    for cap in [
        "hoverProvider",
        "definitionProvider",
        "referencesProvider",
        "renameProvider",
        "documentSymbolProvider",
        "workspaceSymbolProvider",
        "completionProvider",
        "inlayHintProvider",
    ] {
        assert!(caps.get(cap).is_some(), "{cap} in {caps}");
    }
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": main, "languageId": "il", "version": 1, "text": MAIN}}),
    );

    // The diagnostics are those of `ilc check lib.il main.il`: same codes,
    // same messages (the LSP message adds the label, notes and help).
    let diags = c.diagnostics_for(&main);
    let check = Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(["check", "--message-format", "json"])
        .arg(dir.join("lib.il"))
        .arg(dir.join("main.il"))
        .output()
        .unwrap();
    let expected: Vec<Value> = String::from_utf8(check.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert!(!expected.is_empty(), "the example has an error");
    assert_eq!(diags.len(), expected.len(), "{diags:?}");
    for (d, e) in diags.iter().zip(&expected) {
        assert_eq!(d["code"], e["code"]);
        assert!(
            d["message"]
                .as_str()
                .unwrap()
                .starts_with(e["message"].as_str().unwrap())
        );
        assert_eq!(d["range"]["start"]["line"], e["line"].as_u64().unwrap() - 1);
        assert_eq!(d["severity"], if e["severity"] == "error" { 1 } else { 2 });
    }
    assert!(c.diagnostics_for(&lib).is_empty(), "the library is fine");

    // The fix: store into `count`. The diagnostics are cleared.
    let fixed = MAIN.replacen("    ST ok\nskip:", "    ST count\nskip:", 1);
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": main, "version": 2}, "contentChanges": [{"text": fixed}]}),
    );
    assert_eq!(c.diagnostics_for(&main), Vec::<Value>::new());
    let text = fixed.as_str();

    // Hover: the CR before and after an instruction.
    let h = c.result("textDocument/hover", at(&main, text, "ADD", 1));
    assert_eq!(hover_text(&h), "CR before: `INT`\n\nCR after: `INT`", "{h}");
    let h = c.result("textDocument/hover", at(&main, text, "JMPC", 1));
    assert!(hover_text(&h).contains("CR before: `BOOL`"), "{h}");
    // At the label the paths disagree (BOOL from the JMPC, INT falling through).
    let h = c.result("textDocument/hover", at(&main, text, "skip:", 1));
    let t = hover_text(&h);
    assert!(
        t.contains("BOOL from line 10") && t.contains("INT from line 13"),
        "{t}"
    );
    // A variable: its declaration, with section, address and initial value.
    let h = c.result("textDocument/hover", at(&main, text, "LD go", 4));
    let t = hover_text(&h);
    assert!(
        t.contains("go AT %IX0.0 : BOOL;") && t.contains("VAR"),
        "{t}"
    );
    assert!(t.contains("address: `%IX0.0`"), "{t}");
    // After a comment holding characters outside the BMP: UTF-16 columns.
    let h = c.result("textDocument/hover", at(&main, text, "*) count", 5));
    assert!(hover_text(&h).contains("count : INT := 5;"), "{h}");
    // A standard function block: its interface from il_std::signature.
    let h = c.result("textDocument/hover", at(&main, text, ": TP", 3));
    let t = hover_text(&h);
    assert!(
        t.contains("standard function block `TP`") && t.contains("PT : TIME"),
        "{t}"
    );
    // A member of a user FB instance.
    let h = c.result("textDocument/hover", at(&main, text, "m.run", 3));
    assert!(hover_text(&h).contains("run : BOOL;"), "{h}");

    // Definition: a member of an FB in the other file, a label.
    let d = c.result("textDocument/definition", at(&main, text, "m.run", 3));
    assert_eq!(d["uri"], lib);
    assert_eq!(d["range"]["start"]["line"], find(LIB, "run : BOOL", 0).0);
    let d = c.result("textDocument/definition", at(&main, text, "JMPC skip", 6));
    assert_eq!(d["uri"], main);
    assert_eq!(d["range"]["start"]["line"], find(text, "skip:", 0).0);
    let d = c.result("textDocument/definition", at(&main, text, ": Motor", 3));
    assert_eq!(
        (d["uri"].clone(), d["range"]["start"]["line"].clone()),
        (json!(lib), json!(0))
    );

    // References: the declaration and the two uses of `count`.
    let r = c.result(
        "textDocument/references",
        json!({"textDocument": {"uri": main}, "position": at(&main, text, "count :", 1)["position"],
               "context": {"includeDeclaration": true}}),
    );
    let mut lines: Vec<u64> = r
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["range"]["start"]["line"].as_u64().unwrap())
        .collect();
    lines.sort();
    assert_eq!(lines, vec![5, 10, 12], "{r}");
    // `run` of Motor, used in main.il: both files.
    let r = c.result(
        "textDocument/references",
        json!({"textDocument": {"uri": lib}, "position": at(&lib, LIB, "run : BOOL", 1)["position"],
               "context": {"includeDeclaration": false}}),
    );
    let files: Vec<&str> = r
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["uri"].as_str().unwrap())
        .collect();
    assert!(
        files.contains(&lib.as_str()) && files.contains(&main.as_str()),
        "{r}"
    );

    // Rename a variable: every use, and only those.
    let e = c.result(
        "textDocument/rename",
        json!({"textDocument": {"uri": main}, "position": at(&main, text, "count :", 1)["position"],
               "newName": "total"}),
    );
    let edits = e["changes"][&main].as_array().unwrap();
    assert_eq!(edits.len(), 3, "{e}");
    assert!(edits.iter().all(|t| t["newText"] == "total"));
    let bad = c.request(
        "textDocument/rename",
        json!({"textDocument": {"uri": main}, "position": at(&main, text, "count :", 1)["position"],
               "newName": "not a name"}),
    );
    assert!(bad.get("error").is_some(), "{bad}");
    // Rename a label.
    let e = c.result(
        "textDocument/rename",
        json!({"textDocument": {"uri": main}, "position": at(&main, text, "skip:", 1)["position"],
               "newName": "done"}),
    );
    assert_eq!(e["changes"][&main].as_array().unwrap().len(), 2, "{e}");

    // Document symbols: the POU, its sections and variables, its labels.
    let s = c.result(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": main}}),
    );
    let pou = &s[0];
    assert_eq!(pou["name"], "main");
    let children = pou["children"].as_array().unwrap();
    let var = children
        .iter()
        .find(|c| c["name"] == "VAR")
        .expect("the VAR section");
    let names: Vec<&str> = var["children"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["m", "tp", "go", "count", "ok"]);
    assert!(children.iter().any(|c| c["name"] == "skip"), "{s}");
    // Workspace symbols, across files.
    let w = c.result("workspace/symbol", json!({"query": "mot"}));
    assert!(
        w.as_array()
            .unwrap()
            .iter()
            .any(|s| s["name"] == "Motor" && s["location"]["uri"] == lib),
        "{w}"
    );

    // Completion.
    let items = labels(&c.result("textDocument/completion", at(&main, text, "JMPC skip", 5)));
    assert_eq!(items, ["skip"], "labels after JMPC");
    let items = labels(&c.result("textDocument/completion", at(&main, text, "m.run", 2)));
    assert!(
        items.contains(&"run".into()) && items.contains(&"start".into()),
        "{items:?}"
    );
    assert!(
        !items.contains(&"t1".into()),
        "a block's own VAR is not a member: {items:?}"
    );
    let items = labels(&c.result("textDocument/completion", at(&main, text, "LD go", 1)));
    assert!(
        items.contains(&"LD".into())
            && items.contains(&"JMPCN".into())
            && items.contains(&"LIMIT".into()),
        "operators: {items:?}"
    );
    let items = labels(&c.result("textDocument/completion", at(&main, text, "CAL m", 4)));
    assert!(
        items.contains(&"m".into())
            && items.contains(&"tp".into())
            && !items.contains(&"count".into()),
        "instances: {items:?}"
    );
    let items = c.result("textDocument/completion", at(&main, text, "CAL m(", 6));
    assert!(
        labels(&items).contains(&"start".into()),
        "formal parameters: {items}"
    );
    assert!(labels(&items).contains(&"run".into()));
    let items = labels(&c.result("textDocument/completion", at(&main, text, "LD m.run", 3)));
    assert!(
        items.contains(&"count".into()) && items.contains(&"go".into()),
        "variables: {items:?}"
    );

    // Inlay hints: the CR type at the end of each instruction line.
    let end = text.lines().count();
    let range = json!({"start": {"line": 0, "character": 0}, "end": {"line": end, "character": 0}});
    let hints = c.result(
        "textDocument/inlayHint",
        json!({"textDocument": {"uri": main}, "range": range}),
    );
    let add_line = find(text, "ADD", 0).0;
    let add = hints
        .as_array()
        .unwrap()
        .iter()
        .find(|h| h["position"]["line"] == add_line)
        .expect("a hint on the ADD line");
    assert_eq!(add["label"], "CR: INT");
    assert_eq!(add["position"]["character"], "    ADD 1".len());
    // Turned off by the client setting.
    c.notify(
        "workspace/didChangeConfiguration",
        json!({"settings": {"ilc": {"inlayHints": {"crType": false}}}}),
    );
    let hints = c.result(
        "textDocument/inlayHint",
        json!({"textDocument": {"uri": main}, "range": range}),
    );
    assert_eq!(hints, json!([]));
    // The client was asked to fetch the hints again.
    assert!(
        c.notes
            .iter()
            .any(|m| m["method"] == "workspace/inlayHint/refresh"),
        "{:?}",
        c.notes
    );

    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn inlay_hints_can_be_off_from_the_start() {
    let dir = temp_dir("nohints");
    let main = uri(&dir.join("main.il"));
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({"inlayHints": {"crType": false}}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": main, "languageId": "il", "version": 1, "text": MAIN}}),
    );
    let range = json!({"start": {"line": 0, "character": 0}, "end": {"line": 40, "character": 0}});
    let hints = c.result(
        "textDocument/inlayHint",
        json!({"textDocument": {"uri": main}, "range": range}),
    );
    assert_eq!(hints, json!([]));
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_requests_do_not_kill_the_server() {
    let dir = temp_dir("hostile");
    let main = uri(&dir.join("main.il"));
    let mut c = Client::start(&[("ILC_LSP_TEST_PANIC", "1")]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": main, "languageId": "il", "version": 1, "text": MAIN}}),
    );
    // Positions past the end of the text and of a line are clamped.
    for (l, ch) in [
        (99_999, 0),
        (0, 99_999),
        (u32::MAX as usize, u32::MAX as usize),
        (10, 9),
    ] {
        for m in [
            "textDocument/hover",
            "textDocument/definition",
            "textDocument/completion",
            "textDocument/prepareRename",
        ] {
            let r = c.request(m, pos(&main, l, ch));
            assert!(r.get("error").is_none(), "{m} at {l}:{ch}: {r}");
        }
    }
    // Garbage parameters: an error response.
    let r = c.request(
        "textDocument/hover",
        json!({"textDocument": 5, "position": "here"}),
    );
    assert_eq!(r["error"]["code"], -32602, "{r}");
    // A document the server does not know.
    let r = c.result("textDocument/hover", pos("file:///nowhere/x.il", 1, 1));
    assert_eq!(r, Value::Null);
    // A panic in a handler: an error response, and the server goes on.
    let r = c.request("ilc/testPanic", json!({}));
    assert_eq!(r["error"]["code"], -32603, "{r}");
    // An edit that is not IL at all, then a request: still answered.
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": main, "version": 2}, "contentChanges": [{"text": "\u{0}((((*{ END_VAR :="}]}),
    );
    let r = c.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": main}}),
    );
    assert!(r.get("error").is_none(), "{r}");
    let h = c.result("textDocument/hover", at(&main, MAIN, "ADD", 1));
    assert_eq!(h, Value::Null, "the text is not IL any more: {h}");
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn hover_on_a_standard_function() {
    let dir = temp_dir("stdfn");
    let main = uri(&dir.join("f.il"));
    let text = "PROGRAM p\nVAR\n    x : INT;\nEND_VAR\n    LD x\n    LIMIT 0, 100\n    ST x\nEND_PROGRAM\n";
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": main, "languageId": "il", "version": 1, "text": text}}),
    );
    assert_eq!(c.diagnostics_for(&main), Vec::<Value>::new());
    let h = c.result("textDocument/hover", at(&main, text, "LIMIT", 2));
    let t = hover_text(&h);
    assert!(
        t.contains("FUNCTION LIMIT(MN : ") && t.contains("standard function"),
        "{t}"
    );
    // Formal parameter names of a standard function inside its call list.
    let edited = text.replace("LIMIT 0, 100", "LIMIT(");
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": main, "version": 2}, "contentChanges": [{"text": edited}]}),
    );
    let items = c.result("textDocument/completion", at(&main, &edited, "LIMIT(", 6));
    let names = labels(&items);
    assert!(
        names.contains(&"MN".into()) && names.contains(&"MX".into()),
        "{items}"
    );
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A workspace file in Windows-1251 (Russian comments): read as
/// Windows-1252 with a warning when no encoding is set, as Windows-1251
/// without one when the initialization option names it.
#[test]
fn workspace_files_are_read_in_the_encoding_of_the_options() {
    let src: &[u8] = b"(* \xCF\xF3\xF1\xEA *)\nPROGRAM Nasos\nVAR pusk : BOOL; END_VAR\n    LD pusk\n    ST pusk\nEND_PROGRAM\n";
    for (options, warned) in [
        (json!({}), true),
        (json!({"encoding": "windows-1251"}), false),
    ] {
        let dir = temp_dir(if warned { "enc-guess" } else { "enc-1251" });
        std::fs::write(dir.join("nasos.il"), src).unwrap();
        let nasos = uri(&dir.join("nasos.il"));
        let mut c = Client::start(&[]);
        c.initialize(&dir, options);
        let d = c.diagnostics_for(&nasos);
        if warned {
            assert_eq!(d.len(), 1, "{d:?}");
            assert_eq!(d[0]["code"], "IL0039");
            assert_eq!(d[0]["severity"], 2);
            assert_eq!(d[0]["range"]["start"], json!({"line": 0, "character": 3}));
        } else {
            assert_eq!(d, Vec::<Value>::new());
        }
        c.finish();
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// The CR shown at a label and at a user FUNCTION called as an operator,
/// before and after an edit of another POU (whose check alone is redone:
/// the hover reads the CR steps the server kept of the others).
#[test]
fn hover_shows_the_cr_at_labels_and_function_calls_after_edits() {
    let dir = temp_dir("cr-hover");
    let main = uri(&dir.join("f.il"));
    let text = "FUNCTION Twice : INT\nVAR_INPUT v : INT; END_VAR\n    LD v\n    MUL 2\n    ST Twice\nEND_FUNCTION\n\nPROGRAM p\nVAR x : INT; b : BOOL; END_VAR\n    LD x\n    Twice\n    ST x\nagain:\n    LD b\n    JMPC again\nEND_PROGRAM\n";
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": main, "languageId": "il", "version": 1, "text": text}}),
    );
    assert_eq!(c.diagnostics_for(&main), Vec::<Value>::new());
    let check = |c: &mut Client| {
        let call = hover_text(&c.result("textDocument/hover", at(&main, text, "    Twice", 5)));
        assert!(
            call.contains("CR before: `INT`, CR after (its result): `INT`"),
            "{call}"
        );
        let label = hover_text(&c.result("textDocument/hover", at(&main, text, "again:", 1)));
        assert!(label.contains("CR at this label"), "{label}");
    };
    check(&mut c);
    // `MUL 2` -> `MUL 3` inside the FUNCTION, sent as a range.
    let (line, col) = find(text, "MUL 2", 4);
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": main, "version": 2}, "contentChanges": [{"range": {"start": {"line": line, "character": col}, "end": {"line": line, "character": col + 1}}, "text": "3"}]}),
    );
    check(&mut c);
    let symbols = c.result(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": main}}),
    );
    assert_eq!(symbols.as_array().map(Vec::len), Some(2), "{symbols}");
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
