//! setVariable in an outer frame: a variable of the PROGRAM written while
//! stopped inside the FB instance it calls reaches the PROGRAM's variable
//! (when the call returns), and the instance being called is refused there.

use serde_json::{Value, json};

use super::{Dap, temp_file};

const SRC: &str = "\
FUNCTION_BLOCK Counter
VAR_INPUT up : BOOL; END_VAR
VAR_OUTPUT n : INT; END_VAR
    LD   n
    ADD  1
    ST   n
END_FUNCTION_BLOCK
PROGRAM Main
VAR pump : Counter; total : INT; seen : INT; END_VAR
    CAL  pump(up := TRUE)
    LD   total
    ST   seen
    LD   pump.n
    ST   total
END_PROGRAM
";

/// The `variablesReference` of scope `name` of frame `frame`.
fn scope_ref(d: &mut Dap, frame: u64, name: &str) -> Value {
    let scopes = d.ok("scopes", json!({"frameId": frame}));
    scopes["scopes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == name)
        .unwrap_or_else(|| panic!("no scope {name}: {scopes}"))["variablesReference"]
        .clone()
}

#[test]
fn set_variable_in_the_programs_frame_from_inside_an_instance() {
    let path = temp_file("outer", SRC);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 1, "stopOnEntry": true}));
    d.ok("configurationDone", json!({}));
    d.stopped();
    d.ok("stepIn", json!({"threadId": 1}));
    d.stopped();
    let (_, line, name) = d.top();
    assert_eq!((line, name.as_str()), (4, "Main.pump (Counter)"));
    // Frame 2 is Main: its locals, written from here.
    let locals = scope_ref(&mut d, 2, "Locals");
    let r = d.ok(
        "setVariable",
        json!({"variablesReference": locals, "name": "total", "value": "41"}),
    );
    assert_eq!(
        (r["value"].as_str(), r["type"].as_str()),
        (Some("41"), Some("INT"))
    );
    // Main's view shows it at once, the instance's frame is untouched.
    assert_eq!(d.eval(2, "total")["result"], "41");
    assert_eq!(d.eval(1, "Main.total")["result"], "41");
    // A bad literal is refused, and so is the instance Main is calling.
    assert!(
        !d.refused(
            "setVariable",
            json!({"variablesReference": locals, "name": "total", "value": "TRUE"})
        )
        .is_empty()
    );
    let pump = d.ok("variables", json!({"variablesReference": locals}))["variables"]
        .as_array()
        .unwrap()
        .iter()
        .find(|v| v["name"] == "pump")
        .unwrap()["variablesReference"]
        .clone();
    let e = d.refused(
        "setVariable",
        json!({"variablesReference": pump, "name": "n", "value": "7"}),
    );
    assert!(e.contains("Main.pump") && e.contains("that frame"), "{e}");
    // Back in Main: the write reached its variable, which the next lines read.
    d.ok("stepOut", json!({"threadId": 1}));
    d.stopped();
    let (frame, line, _) = d.top();
    assert_eq!(line, 11);
    assert_eq!(d.eval(frame, "total")["result"], "41");
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    assert_eq!(d.top().1, 13);
    assert_eq!(d.eval(frame, "seen")["result"], "41");
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}
