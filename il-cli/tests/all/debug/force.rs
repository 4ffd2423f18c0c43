//! Forcing pins values across scans until released; a scan breakpoint; the
//! flow of the current results; the process image scope.

use serde_json::json;

use super::{Dap, temp_file, var};

const IO: &str = "\
PROGRAM Io
VAR count : INT; lamp AT %QX0.0 : BOOL; END_VAR
    LD   count
    ADD  1
    ST   count
    LD   %IX0.1
    ST   lamp
END_PROGRAM
";

#[test]
fn forced_values_hold_until_released_and_flow_shows_each_line() {
    let path = temp_file("force", IO);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 5, "force": {"count": "100"}}));
    let f = d.ok(
        "setFunctionBreakpoints",
        json!({"breakpoints": [{"name": "scan 3"}, {"name": "scan 0"}]}),
    );
    assert_eq!(f["breakpoints"][0]["verified"], true);
    assert_eq!(f["breakpoints"][1]["verified"], false);
    d.ok("configurationDone", json!({}));
    let stop = d.stopped();
    assert_eq!(stop["reason"], "function breakpoint");
    let (frame, line, _) = d.top();
    assert_eq!(line, 3);
    // Scans 1 and 2 stored 101, and the force wrote 100 back after each.
    assert_eq!(d.eval(frame, "count")["result"], "100");
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "scan").0, "3");
    assert_eq!(d.ok("flow", json!({}))["lines"], json!([]));
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    assert_eq!(d.top().1, 5);
    let flow = d.ok("flow", json!({}));
    assert_eq!(flow["scan"], 3);
    assert_eq!(
        super::without_source(&flow["lines"]),
        json!([{"pou": "Io", "line": 3, "cr": "100 : INT"}, {"pou": "Io", "line": 4, "cr": "101 : INT"}])
    );
    assert_eq!(flow["lines"][0]["source"]["name"], "force.il");
    // Force an input, release count.
    let r = d.ok("force", json!({"expression": "%IX0.1", "value": "TRUE"}));
    assert_eq!(r["forced"].as_array().unwrap().len(), 2);
    let r = d.ok("force", json!({"expression": "count"}));
    assert_eq!(
        r["forced"],
        json!([{"expression": "%IX0.1", "value": "TRUE"}])
    );
    assert!(
        !d.refused("force", json!({"expression": "nothing", "value": "1"}))
            .is_empty()
    );
    d.ok(
        "setFunctionBreakpoints",
        json!({"breakpoints": [{"name": "scan 5"}]}),
    );
    d.ok("continue", json!({"threadId": 1}));
    d.stopped();
    let (frame, _, _) = d.top();
    // Released in scan 3: 101 stays, scan 4 adds one.
    assert_eq!(d.eval(frame, "count")["result"], "102");
    let image = d.scope(frame, "Process image");
    assert_eq!(var(&image, "%IX0.1"), ("TRUE", "BOOL"));
    // Scan 4 copied the forced input to the lamp.
    assert_eq!(d.eval(frame, "lamp")["result"], "TRUE");
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}
