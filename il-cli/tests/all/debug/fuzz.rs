//! Random request sequences against a few programs: every request is
//! answered, the adapter neither panics nor hangs, and it exits on
//! `disconnect`. The sequences come from a fixed seed (reproducible).

use serde_json::{Value, json};

use super::{Dap, MOTOR, temp_file};

/// A small linear congruential generator (no dependency, fixed seed).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[(self.next() % xs.len() as u64) as usize]
    }
}

fn random_args(r: &mut Rng, program: &str) -> (String, Value) {
    let commands = [
        "launch",
        "setBreakpoints",
        "setFunctionBreakpoints",
        "setExceptionBreakpoints",
        "configurationDone",
        "threads",
        "stackTrace",
        "scopes",
        "variables",
        "evaluate",
        "setVariable",
        "continue",
        "next",
        "stepIn",
        "stepOut",
        "pause",
        "force",
        "exceptionInfo",
        "terminate",
        "nonsense",
        "flow",
        "nextScan",
        // The requests that read a stop, twice as likely.
        "stackTrace",
        "scopes",
        "variables",
        "evaluate",
        "setVariable",
        "variables",
    ];
    let c = r.pick(&commands).to_string();
    let n = (r.next() % 16) as i64 - 2;
    let exprs = [
        "starts",
        "edge.Q",
        "n",
        "%IX0.0",
        "x[",
        "",
        "a.b.c",
        "count > 5",
        "[]",
        "pump.n",
    ];
    let e = r.pick(&exprs).to_string();
    let args = match r.next() % 8 {
        0 => Value::Null,
        1 => json!({}),
        2 => json!([1, 2]),
        3 => json!("text"),
        _ => json!({
            "program": program, "cycles": (n.max(1)), "stopOnEntry": n % 2 == 0,
            "source": {"path": program}, "breakpoints": [{"line": n, "condition": e}, {"name": e}],
            "filters": ["faults"], "frameId": n, "variablesReference": n, "expression": e,
            "name": e, "value": n.to_string(), "threadId": 1,
        }),
    };
    (c, args)
}

#[test]
fn random_request_sequences_never_panic_or_hang() {
    let looping = temp_file(
        "fuzzloop",
        "PROGRAM L\nVAR n : INT; z : INT; END_VAR\nagain:\n    LD   n\n    DIV  z\n    ADD  1\n    ST   n\n    GT   0\n    JMPC again\nEND_PROGRAM\n",
    );
    let programs = [MOTOR.to_string(), looping, "/nonexistent/x.il".to_string()];
    let start = std::time::Instant::now();
    let mut rng = Rng(0x1b2c3d4e5f);
    for session in 0..24 {
        let program = programs[session % programs.len()].clone();
        let mut d = Dap::start();
        d.ok("initialize", json!({"adapterID": "ilc"}));
        // Half the sessions start stopped, so that the requests that need
        // a stop reach their handlers with the interpreter's state.
        if session % 2 == 0 && !program.starts_with("/nonexistent") {
            let pou = if program == MOTOR { "Motor" } else { "L" };
            d.ok(
                "launch",
                json!({"program": program, "pou": pou, "cycles": 4, "stopOnEntry": true}),
            );
            d.event("initialized");
            d.breakpoints(&program, json!([{"line": 14}, {"line": 21}, {"line": 5}]));
            d.ok("configurationDone", json!({}));
            d.stopped();
        }
        for _ in 0..80 {
            let (c, args) = random_args(&mut rng, &program);
            // Every request is answered (success or error), in bounded time.
            let r = d.request(&c, args);
            assert!(r["success"].is_boolean(), "{r}");
        }
        let stderr = d.finish();
        assert!(!stderr.contains("panicked"), "session {session}: {stderr}");
    }
    assert!(start.elapsed() < std::time::Duration::from_secs(120));
}
