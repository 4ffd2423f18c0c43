//! Runtime faults stop as exceptions at their line; a scan that never ends
//! is paused; a program that does not compile ends the session with its
//! diagnostics; bad launch arguments are error responses.

use serde_json::json;

use super::{Dap, MOTOR, temp_file, var};

#[test]
fn division_by_zero_stops_as_an_exception_at_its_line() {
    let src = "PROGRAM D\nVAR n : INT; z : INT; END_VAR\n    LD   7\n    DIV  z\n    ST   n\nEND_PROGRAM\n";
    let path = temp_file("div", src);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 2}));
    d.ok("setExceptionBreakpoints", json!({"filters": ["faults"]}));
    d.ok("configurationDone", json!({}));
    let stop = d.stopped();
    assert_eq!(stop["reason"], "exception", "{stop}");
    assert!(
        stop["text"].as_str().unwrap().contains("DivisionByZero"),
        "{stop}"
    );
    let (frame, line, _) = d.top();
    assert_eq!(line, 4);
    let info = d.ok("exceptionInfo", json!({"threadId": 1}));
    assert!(info["description"].as_str().unwrap().contains("line 4"));
    // The CR after the faulting DIV is the generated code's 0.
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "CR"), ("0", "INT"));
    d.ok("setExceptionBreakpoints", json!({"filters": []}));
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}

#[test]
fn an_endless_jmp_loop_is_paused_and_disconnected() {
    let src = "PROGRAM L\nVAR n : DINT; END_VAR\nagain:\n    LD   n\n    ADD  1\n    ST   n\n    JMP  again\nEND_PROGRAM\n";
    let path = temp_file("loop", src);
    let mut d = Dap::start();
    d.launch(json!({"program": path}));
    d.ok("configurationDone", json!({}));
    std::thread::sleep(std::time::Duration::from_millis(200));
    // Not stopped: inspection is refused, the run goes on.
    assert!(
        d.refused("stackTrace", json!({"threadId": 1}))
            .contains("pause")
    );
    d.ok("pause", json!({"threadId": 1}));
    assert_eq!(d.stopped()["reason"], "pause");
    let (frame, _, _) = d.top();
    let n: i64 = d.eval(frame, "n")["result"]
        .as_str()
        .unwrap()
        .parse()
        .unwrap();
    assert!(n > 0);
    d.finish();
}

#[test]
fn a_program_with_errors_reports_them_and_ends() {
    let path = temp_file(
        "bad",
        "PROGRAM B\nVAR n : INT; END_VAR\n    LD   nn\n    ST   n\nEND_PROGRAM\n",
    );
    let mut d = Dap::start();
    d.ok("initialize", json!({"adapterID": "ilc"}));
    let msg = d.refused("launch", json!({"program": path}));
    assert!(
        msg.contains("cannot be run") && msg.contains("has errors"),
        "{msg}"
    );
    let out = d.event("output");
    assert!(
        out["body"]["output"].as_str().unwrap().contains("nn"),
        "{out}"
    );
    d.event("terminated");
    d.finish();
}

#[test]
fn bad_launch_arguments_and_requests_are_error_responses() {
    let mut d = Dap::start();
    d.ok("initialize", json!({"adapterID": "ilc"}));
    let m = d.refused(
        "launch",
        json!({"program": MOTOR, "pou": "Motor", "cycle": 3}),
    );
    assert!(
        m.contains("`cycle`") && m.contains("did you mean `cycles`"),
        "{m}"
    );
    assert!(
        d.refused("launch", json!({"program": MOTOR, "pou": "Nope"}))
            .contains("Nope")
    );
    assert!(d.refused("frobnicate", json!({})).contains("frobnicate"));
    assert!(
        !d.refused("variables", json!({"variablesReference": 1}))
            .is_empty()
    );
    d.send_raw("{not json");
    d.ok(
        "launch",
        json!({"program": MOTOR, "pou": "Motor", "cycles": 2, "force": {"stop": true}}),
    );
    d.ok("configurationDone", json!({}));
    d.event("terminated");
    d.finish();
}
