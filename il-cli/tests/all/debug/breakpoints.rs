//! Breakpoints: verified, moved to the next instruction line, refused with
//! a reason; conditions, hit counts, log points and function breakpoints.

use serde_json::json;

use super::{Dap, MOTOR, temp_file, var};

const COUNT: &str = "\
PROGRAM Count
VAR count : INT; END_VAR
    LD   count
    ADD  1
    ST   count
END_PROGRAM
";

#[test]
fn lines_are_verified_moved_or_refused() {
    let mut d = Dap::start();
    d.launch(json!({"program": MOTOR, "pou": "Motor", "cycles": 1}));
    let bps = d.breakpoints(
        MOTOR,
        json!([{"line": 13}, {"line": 24}, {"line": 1}, {"line": 19}, {"line": 9999}]),
    );
    assert_eq!(
        (bps[0]["verified"].as_bool(), bps[0]["line"].as_u64()),
        (Some(true), Some(14)),
        "{bps:?}"
    );
    assert!(
        bps[0]["message"]
            .as_str()
            .unwrap()
            .contains("moved from line 13")
    );
    assert_eq!(bps[1]["verified"], false, "{bps:?}");
    assert!(
        bps[1]["message"]
            .as_str()
            .unwrap()
            .contains("holds no instruction")
    );
    assert_eq!(bps[2]["line"], 14);
    assert_eq!(
        (bps[3]["verified"].as_bool(), bps[3]["line"].as_u64()),
        (Some(true), Some(19))
    );
    assert_eq!(bps[4]["verified"], false);
    // Another file is not part of the launched program.
    let other = temp_file("other", COUNT);
    let bps = d.breakpoints(&other, json!([{"line": 3}]));
    assert_eq!(bps[0]["verified"], false);
    assert!(
        bps[0]["message"]
            .as_str()
            .unwrap()
            .contains("is not a file of the launched program")
    );
    // A hit count that is no count is refused.
    let bps = d.breakpoints(MOTOR, json!([{"line": 14, "hitCondition": "often"}]));
    assert_eq!(bps[0]["verified"], false);
    let f = d.ok(
        "setFunctionBreakpoints",
        json!({"breakpoints": [{"name": "motor"}, {"name": "Motr"}]}),
    );
    assert_eq!(f["breakpoints"][0]["verified"], true);
    assert_eq!(f["breakpoints"][0]["line"], 14);
    assert_eq!(f["breakpoints"][1]["verified"], false);
    assert!(
        f["breakpoints"][1]["message"]
            .as_str()
            .unwrap()
            .contains("did you mean `Motor`")
    );
    d.ok("configurationDone", json!({}));
    assert_eq!(d.stopped()["reason"], "function breakpoint");
    assert_eq!(d.top().1, 14);
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}

#[test]
fn conditions_hit_counts_and_log_points() {
    let path = temp_file("count", COUNT);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 10}));
    let bps = d.breakpoints(
        &path,
        json!([
            {"line": 3, "condition": "count > 5"},
            {"line": 4, "hitCondition": "3"},
            {"line": 5, "logMessage": "count is {count}"},
        ]),
    );
    assert!(bps.iter().all(|b| b["verified"] == true), "{bps:?}");
    d.ok("configurationDone", json!({}));
    // The hit count: the third time line 4 runs (scan 3).
    d.stopped();
    let (frame, line, _) = d.top();
    assert_eq!(line, 4);
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "scan").0, "3");
    // Only the hit count breakpoint goes on: remove it.
    d.breakpoints(&path, json!([{"line": 3, "condition": "count > 5"}, {"line": 5, "logMessage": "count is {count}"}]));
    d.ok("continue", json!({"threadId": 1}));
    d.stopped();
    let (frame, line, _) = d.top();
    assert_eq!(line, 3);
    assert_eq!(d.eval(frame, "count")["result"], "6");
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "scan").0, "7");
    d.breakpoints(&path, json!([]));
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    // The log point printed once per scan, never stopping (before the line
    // runs: `ST count` has not stored this scan's count yet).
    let logs: Vec<String> = d
        .events
        .iter()
        .filter(|e| e["event"] == "output" && e["body"]["category"] == "console")
        .map(|e| e["body"]["output"].as_str().unwrap().trim().to_string())
        .collect();
    // Scans 1 to 6; scan 7 stopped on line 3, and then the log point was removed.
    let want: Vec<String> = (0..6).map(|n| format!("count is {n}")).collect();
    assert_eq!(logs, want);
    d.finish();
}
