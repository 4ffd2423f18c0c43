//! A user FUNCTION's frame shows its result; `nextScan` goes to the next
//! scan's first line; `realTime` paces the scans by the wall clock.

use serde_json::json;

use super::{Dap, temp_file, var};

const SRC: &str = "\
FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
    LD   x
    MUL  2
    ST   Twice
END_FUNCTION
PROGRAM Main
VAR n : INT := 5; q : INT; END_VAR
    LD   n
    Twice
    ST   q
END_PROGRAM
";

#[test]
fn a_function_frame_shows_its_result_and_next_scan_moves_on() {
    let path = temp_file("twice", SRC);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 3}));
    d.breakpoints(&path, json!([{"line": 5}]));
    d.ok("configurationDone", json!({}));
    d.stopped();
    let st = d.ok("stackTrace", json!({"threadId": 1}));
    assert_eq!(st["stackFrames"][0]["name"], "Twice");
    assert_eq!(st["stackFrames"][1]["name"], "Main");
    assert_eq!(st["stackFrames"][1]["line"], 10);
    let result = d.scope(1, "Result");
    assert_eq!(var(&result, "Twice"), ("0", "INT"));
    let cr = d.scope(1, "Current result");
    assert_eq!(var(&cr, "CR"), ("10", "INT"));
    assert_eq!(d.eval(1, "x")["result"], "5");
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    // Back in Main after the call's line: the result stored.
    let (_, line, name) = d.top();
    assert_eq!((line, name.as_str()), (11, "Main"));
    assert_eq!(d.scope(1, "Current result")[0].1, "10");
    d.breakpoints(&path, json!([]));
    d.ok("nextScan", json!({"threadId": 1}));
    d.stopped();
    let (frame, line, _) = d.top();
    assert_eq!(line, 9);
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "scan").0, "2");
    assert_eq!(d.eval(frame, "q")["result"], "10");
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}

#[test]
fn real_time_paces_the_scans() {
    let path = temp_file("paced", SRC);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 3, "cycleTime": "100ms", "realTime": true}));
    let t = std::time::Instant::now();
    d.ok("configurationDone", json!({}));
    d.event("terminated");
    assert!(
        t.elapsed() >= std::time::Duration::from_millis(250),
        "{:?}",
        t.elapsed()
    );
    d.finish();
}
