//! Programs of several files, loaded as `ilc run` loads them: a folder of
//! CODESYS exports in Windows-1251 (launch `encoding`), breakpoints per
//! file, each frame in the file of its POU; and the client's numbering of
//! lines and columns from 0 (`linesStartAt1: false`).

use std::path::{Path, PathBuf};

use serde_json::{Value, json};

use super::{Dap, MOTOR, var};

/// Cyrillic and ASCII in Windows-1251 (А..я are 0xC0..0xFF there).
fn cp1251(s: &str) -> Vec<u8> {
    s.chars()
        .map(|c| match c as u32 {
            0..=0x7f => c as u8,
            x @ 0x410..=0x44f => (x - 0x410 + 0xc0) as u8,
            _ => panic!("not in this test's Windows-1251 subset: {c}"),
        })
        .collect()
}

/// A fresh folder with these files written in Windows-1251.
fn folder(tag: &str, files: &[(&str, &str)]) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ilc-debug-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    for (name, text) in files {
        std::fs::write(d.join(name), cp1251(text)).unwrap();
    }
    d
}

const COUNTER: &str = "\
(* Счётчик пусков *)
FUNCTION_BLOCK Counter
VAR_INPUT up : BOOL; END_VAR
VAR_OUTPUT n : INT; END_VAR
    LD   n
    ADD  1
    ST   n
END_FUNCTION_BLOCK
";

const MAIN: &str = "\
(* Насосная станция *)
PROGRAM Main
VAR c : Counter; total : INT; msg : STRING[20]; END_VAR
    LD   'Насос'
    ST   msg
    CAL  c(up := TRUE)
    LD   c.n
    ST   total
END_PROGRAM
";

fn name(frame: &Value) -> &str {
    frame["source"]["name"].as_str().unwrap_or("")
}

#[test]
fn a_folder_of_exports_in_windows_1251_stops_in_each_file() {
    // `ё` is not in the subset above: the counter's comment says it otherwise.
    let counter = COUNTER.replace('ё', "е");
    let dir = folder("exp", &[("counter.exp", &counter), ("main.exp", MAIN)]);
    let (main, count) = (dir.join("main.exp"), dir.join("counter.exp"));
    let s = |p: &Path| p.display().to_string();
    let mut d = Dap::start();
    d.launch(json!({"program": s(&dir), "encoding": "windows-1251", "cycles": 2}));
    // Each file's breakpoints, set by its path, on its own lines.
    let a = d.breakpoints(&s(&main), json!([{"line": 6}]));
    let b = d.breakpoints(&s(&count), json!([{"line": 4}]));
    assert_eq!(
        (a[0]["verified"].as_bool(), a[0]["line"].as_u64()),
        (Some(true), Some(6))
    );
    // A declaration line moves to the first instruction of that file.
    assert_eq!(
        (b[0]["verified"].as_bool(), b[0]["line"].as_u64()),
        (Some(true), Some(5))
    );
    // Setting the counter's again leaves main's in place.
    let b = d.breakpoints(&s(&count), json!([{"line": 6}]));
    assert_eq!(b[0]["line"], 6);
    d.ok("configurationDone", json!({}));

    d.stopped();
    let st = d.ok("stackTrace", json!({"threadId": 1}));
    let top = &st["stackFrames"][0];
    assert_eq!(
        (name(top), top["line"].as_u64()),
        ("main.exp", Some(6)),
        "{st}"
    );
    // The literal was read in Windows-1251.
    assert_eq!(d.eval(1, "msg")["result"], "'Насос'");

    d.ok("continue", json!({"threadId": 1}));
    d.stopped();
    let st = d.ok("stackTrace", json!({"threadId": 1}));
    let frames = st["stackFrames"].as_array().unwrap();
    let seen: Vec<(&str, u64, &str)> = frames
        .iter()
        .map(|f| {
            (
                name(f),
                f["line"].as_u64().unwrap(),
                f["name"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        seen,
        [
            ("counter.exp", 6, "Main.c (Counter)"),
            ("main.exp", 6, "Main")
        ]
    );
    assert!(
        frames[0]["source"]["path"]
            .as_str()
            .unwrap()
            .ends_with("counter.exp")
    );
    // Clearing main's breakpoints leaves the counter's: scan 2 stops there.
    d.breakpoints(&s(&main), json!([]));
    d.ok("continue", json!({"threadId": 1}));
    d.stopped();
    assert_eq!(d.top().1, 6);
    let cr = d.scope(1, "Current result");
    assert_eq!(var(&cr, "scan").0, "2");
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

/// `program` as a list of files; their encoding from `ilc --encoding`.
#[test]
fn a_list_of_files_in_the_commands_encoding() {
    let counter = COUNTER.replace('ё', "е");
    let dir = folder("list", &[("counter.exp", &counter), ("main.exp", MAIN)]);
    let (main, count) = (dir.join("main.exp"), dir.join("counter.exp"));
    let s = |p: &Path| p.display().to_string();
    let mut d = Dap::start_with(&["--encoding", "windows-1251"]);
    d.launch(json!({"program": [s(&count), s(&main)], "cycles": 1}));
    let b = d.breakpoints(&s(&count), json!([{"line": 7}]));
    assert_eq!(b[0]["verified"], true);
    d.ok("configurationDone", json!({}));
    d.stopped();
    let st = d.ok("stackTrace", json!({"threadId": 1}));
    assert_eq!(name(&st["stackFrames"][0]), "counter.exp");
    assert_eq!(d.eval(2, "msg")["result"], "'Насос'");
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
    // A list that is not of paths is the launch's error.
    let mut d = Dap::start();
    d.ok("initialize", json!({"adapterID": "ilc"}));
    let e = d.refused("launch", json!({"program": [s(&main), 3]}));
    assert!(e.contains("`program`"), "{e}");
    d.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

/// The OWEN project of the corpus: 95 exports in Windows-1251, launched as
/// its folder, read in the launch's `encoding` (no IL0039 warning that
/// the files are not UTF-8), and run through.
#[test]
fn the_owen_export_folder_runs_in_its_encoding() {
    let dir = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/corpus/exp/kaapyth0n_OWEN"
    );
    if !Path::new(dir).exists() {
        eprintln!("../shared/corpus not found: the OWEN launch test is skipped");
        return;
    }
    let output = |d: &Dap| -> String {
        d.events
            .iter()
            .filter(|e| e["event"] == "output")
            .map(|e| e["body"]["output"].as_str().unwrap_or("").to_string())
            .collect()
    };
    let mut d = Dap::start();
    d.launch(json!({"program": dir, "encoding": "windows-1251", "cycles": 2}));
    d.ok("configurationDone", json!({}));
    assert_eq!(d.event("exited")["body"]["exitCode"], 0);
    d.event("terminated");
    let text = output(&d);
    assert!(!text.contains("IL0039"), "{text}");
    d.finish();
    // Without it the files are read as Windows-1252, with the warning.
    let mut d = Dap::start();
    d.launch(json!({"program": dir, "cycles": 1}));
    assert!(output(&d).contains("IL0039"), "{}", output(&d));
    d.finish();
    // A bad encoding is the launch's error.
    let mut d = Dap::start();
    d.ok("initialize", json!({"adapterID": "ilc"}));
    let e = d.refused("launch", json!({"program": dir, "encoding": "klingon"}));
    assert!(e.contains("`encoding`") && e.contains("klingon"), "{e}");
    d.finish();
}

#[test]
fn lines_and_columns_from_0_when_the_client_counts_so() {
    let mut d = Dap::start();
    d.ok(
        "initialize",
        json!({"adapterID": "x", "linesStartAt1": false, "columnsStartAt1": false}),
    );
    d.ok(
        "launch",
        json!({"program": MOTOR, "pou": "Motor", "cycles": 6, "set": ["start=TRUE@3"]}),
    );
    d.event("initialized");
    // `ADD 1` is line 22 of the file, 21 from 0; `END_VAR` (12 from 0)
    // moves to `LD start` (13 from 0), and the message says it so.
    let bps = d.breakpoints(MOTOR, json!([{"line": 21}, {"line": 12}]));
    assert_eq!(
        (bps[0]["verified"].as_bool(), bps[0]["line"].as_u64()),
        (Some(true), Some(21))
    );
    assert_eq!(bps[1]["line"], 13);
    assert_eq!(
        bps[1]["message"],
        "moved from line 12: it holds no instruction"
    );
    let f = d.ok(
        "setFunctionBreakpoints",
        json!({"breakpoints": [{"name": "Motor"}]}),
    );
    assert_eq!(f["breakpoints"][0]["line"], 13);
    d.ok("setFunctionBreakpoints", json!({"breakpoints": []}));
    d.breakpoints(MOTOR, json!([{"line": 21}]));
    d.ok("configurationDone", json!({}));
    d.stopped();
    let st = d.ok("stackTrace", json!({"threadId": 1}));
    let top = &st["stackFrames"][0];
    assert_eq!(
        (top["line"].as_u64(), top["column"].as_u64()),
        (Some(21), Some(0))
    );
    let cr = d.scope(1, "Current result");
    assert_eq!(var(&cr, "CR"), ("0", "INT"));
    assert_eq!(var(&cr, "scan").0, "3");
    // The flow and its message about the CAL count from 0 too: `CLK edge`
    // is line 18 of the file.
    let flow = d.ok("flow", json!({}));
    let lines = flow["lines"].as_array().unwrap();
    let clk = lines.iter().find(|l| l["line"] == 17).expect("line 17 ran");
    assert_eq!(clk["cr"], "undefined (after CAL on line 17)");
    assert_eq!(lines[0]["line"], 13);
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    assert_eq!(d.top().1, 22);
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}
