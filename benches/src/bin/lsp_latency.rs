//! `lsp_latency [ILC] [--fbs N] [--lines L] [--edits E] [--full] [--new-line] [--times]`:
//! the language server's latency as an editor sees it, on one generated
//! file of N FUNCTION_BLOCKs of L lines (default 500 x 200: 100 000 lines).
//! Starts `ILC lsp` (default `target/release/ilc`), opens the file, then
//! edits one line in the middle POU E times, alternately making and fixing
//! an error (so every edit changes the published diagnostics), and times
//! each edit from `didChange` to its `publishDiagnostics`; then times E
//! hovers on an instruction. Prints the medians and the spread, and the
//! machine's load.
//!
//! Each edit is sent as the range it replaces (incremental sync, as editors
//! do when the server asks for it); `--full` sends the whole text instead.
//! `--new-line` makes each error a line of its own, inserted and deleted
//! again (edits that change the number of lines).
//! `--times` prints the medians of where the server says its time went
//! (`ILC_LSP_TIMES`: parse, check, index, ...).

use serde_json::{Value, json};
use std::io::BufReader;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn program(fbs: usize, lines: usize) -> String {
    let mut s = String::with_capacity(fbs * lines * 16);
    for p in 0..fbs {
        s.push_str(&format!(
            "FUNCTION_BLOCK Fb{p}\nVAR_INPUT a, b : BOOL; x : INT; END_VAR\nVAR_OUTPUT q : BOOL; y : INT; END_VAR\nVAR t : TON; END_VAR\n"
        ));
        let body = lines.saturating_sub(5);
        for i in 0..body {
            s.push_str(match i % 8 {
                0 => "    LD   a\n",
                1 => "    AND  b\n",
                2 => "    ST   q\n",
                3 => "    LD   x\n",
                4 => "    ADD  1\n",
                5 => "    ST   y\n",
                6 => "    LD   q\n",
                _ => "    ST   t.IN\n",
            });
        }
        s.push_str("END_FUNCTION_BLOCK\n");
    }
    s
}

struct Server {
    stdin: std::process::ChildStdin,
    out: BufReader<std::process::ChildStdout>,
    next: i64,
}

impl Server {
    fn send(&mut self, v: &Value) {
        il_testkit::framed::send(&mut self.stdin, v).unwrap();
    }
    fn read(&mut self) -> Value {
        il_testkit::framed::read(&mut self.out).expect("the server closed its output")
    }
    fn request(&mut self, method: &str, params: Value) -> Value {
        self.next += 1;
        let id = self.next;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let v = self.read();
            if v["id"] == json!(id) {
                return v;
            }
        }
    }
    fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }
    fn diagnostics(&mut self, uri: &str) -> usize {
        loop {
            let v = self.read();
            if v["method"] == json!("textDocument/publishDiagnostics")
                && v["params"]["uri"] == json!(uri)
            {
                return v["params"]["diagnostics"].as_array().map_or(0, Vec::len);
            }
        }
    }
}

fn stats(name: &str, mut v: Vec<Duration>) {
    v.sort();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!(
        "{name}: median {:.1} ms (min {:.1}, max {:.1}, n = {})",
        ms(v[v.len() / 2]),
        ms(v[0]),
        ms(v[v.len() - 1]),
        v.len()
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let opt = |k: &str, d: usize| {
        args.iter()
            .position(|a| a == k)
            .and_then(|i| args.get(i + 1))
            .and_then(|v| v.parse().ok())
            .unwrap_or(d)
    };
    let (fbs, lines, edits) = (opt("--fbs", 500), opt("--lines", 200), opt("--edits", 20));
    let ilc = args
        .first()
        .filter(|a| !a.starts_with("--"))
        .cloned()
        .unwrap_or_else(|| "target/release/ilc".into());
    let dir = std::env::temp_dir().join(format!("il-lsp-latency-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("big.il");
    let text = program(fbs, lines);
    let uri = format!("file://{}", path.display());
    let full = args.iter().any(|a| a == "--full");
    let new_line = args.iter().any(|a| a == "--new-line");
    let times = args.iter().any(|a| a == "--times");
    let mut child = Command::new(&ilc)
        .arg("lsp")
        .env("ILC_LSP_TIMES", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(if times { Stdio::piped() } else { Stdio::null() })
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start `{ilc} lsp`: {e}"));
    let log = child.stderr.take().map(|e| {
        std::thread::spawn(move || {
            std::io::BufRead::lines(BufReader::new(e))
                .map_while(Result::ok)
                .collect::<Vec<String>>()
        })
    });
    let mut s = Server {
        stdin: child.stdin.take().unwrap(),
        out: BufReader::new(child.stdout.take().unwrap()),
        next: 0,
    };
    s.request(
        "initialize",
        json!({"processId": null, "rootUri": format!("file://{}", dir.display()), "capabilities": {}}),
    );
    s.notify("initialized", json!({}));
    let t = Instant::now();
    s.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "il", "version": 1, "text": text}}),
    );
    assert_eq!(s.diagnostics(&uri), 0);
    println!(
        "{} lines ({fbs} FBs of {lines}): open to first diagnostics {:.0} ms",
        text.lines().count(),
        t.elapsed().as_secs_f64() * 1e3
    );
    // The `ADD  1` of the middle POU's first rung group.
    let mid = text
        .find(&format!("FUNCTION_BLOCK Fb{}\n", fbs / 2))
        .unwrap();
    let at = mid + text[mid..].find("    ADD  1\n").unwrap();
    let line = text[..at].lines().count() as u64;
    let mut spent = Vec::new();
    for i in 0..edits {
        // `ADD  1` <-> `ADD  nosuch`: column 9 of the line; or a line
        // `ADD  nosuch` inserted before it and deleted.
        let pos = |l: u64, c: u64| json!({"line": l, "character": c});
        let (new, range, put) = match (new_line, i % 2 == 0) {
            (false, true) => (
                format!("{}    ADD  nosuch\n{}", &text[..at], &text[at + 11..]),
                (pos(line, 9), pos(line, 10)),
                "nosuch",
            ),
            (false, false) => (text.clone(), (pos(line, 9), pos(line, 15)), "1"),
            (true, true) => (
                format!("{}    ADD  nosuch\n{}", &text[..at], &text[at..]),
                (pos(line, 0), pos(line, 0)),
                "    ADD  nosuch\n",
            ),
            (true, false) => (text.clone(), (pos(line, 0), pos(line + 1, 0)), ""),
        };
        let change = if full {
            json!({"text": new})
        } else {
            json!({"range": {"start": range.0, "end": range.1}, "text": put})
        };
        let t = Instant::now();
        s.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": i + 2}, "contentChanges": [change]}),
        );
        let n = s.diagnostics(&uri);
        spent.push(t.elapsed());
        assert_eq!(n, usize::from(i % 2 == 0));
    }
    stats("edit inside one POU to fresh diagnostics", spent);
    let mut times = Vec::new();
    for _ in 0..edits {
        let t = Instant::now();
        let r = s.request(
            "textDocument/hover",
            json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": 6}}),
        );
        times.push(t.elapsed());
        assert!(r["result"].is_object(), "{r}");
    }
    stats("hover", times);
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "load: {}",
        load.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );
    // The server's memory: what it holds between edits (VmRSS) and at most.
    let status =
        std::fs::read_to_string(format!("/proc/{}/status", child.id())).unwrap_or_default();
    let mem: Vec<String> = status
        .lines()
        .filter(|l| l.starts_with("VmRSS") || l.starts_with("VmHWM"))
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();
    if !mem.is_empty() {
        println!("server memory: {}", mem.join(", "));
    }
    s.request("shutdown", Value::Null);
    s.notify("exit", Value::Null);
    let _ = child.wait();
    if let Some(log) = log {
        server_times(&log.join().unwrap_or_default(), edits);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The medians of the server's own times of the last `edits` checks (its
/// lines `ilc lsp: times: parse 1.0 check 2.0 ... ms`).
fn server_times(log: &[String], edits: usize) {
    let rows: Vec<Vec<(String, f64)>> = log
        .iter()
        .filter_map(|l| l.strip_prefix("ilc lsp: times: "))
        .map(|l| {
            let w: Vec<&str> = l.trim_end_matches(" ms").split_whitespace().collect();
            w.chunks(2)
                .filter_map(|p| Some((p[0].to_string(), p.get(1)?.parse().ok()?)))
                .collect()
        })
        .collect();
    let last = &rows[rows.len().saturating_sub(edits)..];
    let Some(first) = last.first() else {
        println!("the server printed no times");
        return;
    };
    let medians: Vec<String> = (0..first.len())
        .map(|k| {
            let mut v: Vec<f64> = last.iter().filter_map(|r| Some(r.get(k)?.1)).collect();
            v.sort_by(f64::total_cmp);
            format!("{} {:.1}", first[k].0, v[v.len() / 2])
        })
        .collect();
    println!(
        "inside the server, per edit (median ms): {}",
        medians.join(", ")
    );
}
