//! A configuration with two tasks: breakpoints in the program of the slower
//! task stop only in the scans that release it, with the instance path.

use serde_json::json;

use super::{Dap, temp_file, var};

const PLANT: &str = "\
PROGRAM Fast
VAR_EXTERNAL n : INT; END_VAR
    LD   n
    ADD  1
    ST   n
END_PROGRAM
PROGRAM Slow
VAR_EXTERNAL n : INT; END_VAR
VAR seen : INT; END_VAR
    LD   n
    ST   seen
END_PROGRAM
CONFIGURATION Plant
VAR_GLOBAL n : INT; limit : INT := 7; END_VAR
RESOURCE Cpu ON PLC
    TASK Quick (INTERVAL := T#10ms, PRIORITY := 1);
    TASK Lazy (INTERVAL := T#30ms, PRIORITY := 2);
    PROGRAM Main WITH Quick : Fast;
    PROGRAM Other WITH Lazy : Slow;
END_RESOURCE
END_CONFIGURATION
";

#[test]
fn two_tasks_stop_where_the_slow_task_runs() {
    let path = temp_file("plant", PLANT);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "configuration": "Plant", "cycles": 5, "cycleTime": "10ms"}));
    let bps = d.breakpoints(&path, json!([{"line": 11}]));
    assert_eq!(bps[0]["verified"], true);
    d.ok("configurationDone", json!({}));
    let mut seen = Vec::new();
    for _ in 0..2 {
        d.stopped();
        let (frame, line, name) = d.top();
        assert_eq!((line, name.as_str()), (11, "Other (Slow)"));
        let cr = d.scope(frame, "Current result");
        let ext = d.scope(frame, "Externals (globals)");
        let globals = d.scope(frame, "Configuration globals");
        assert_eq!(var(&globals, "limit"), ("7", "INT"));
        assert_eq!(d.eval(frame, "limit")["result"], "7");
        seen.push((
            var(&cr, "scan").0.to_string(),
            var(&cr, "time").0.to_string(),
            var(&ext, "n").0.to_string(),
            var(&cr, "CR").0.to_string(),
        ));
        d.ok("continue", json!({"threadId": 1}));
    }
    // Lazy runs at 0 and 30ms (scans 1 and 4), after Quick (priority 1).
    assert_eq!(
        seen,
        [
            ("1".into(), "T#0s".into(), "1".into(), "1".into()),
            ("4".into(), "T#30ms".into(), "4".into(), "4".into())
        ]
    );
    d.event("terminated");
    d.finish();
}
