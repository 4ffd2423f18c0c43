//! `ilc debug` driven as an editor drives it: a client in the test speaks
//! the Debug Adapter Protocol (Content-Length framed JSON) to the built
//! `ilc debug` over its stdin/stdout.

use std::io::{Read, Write};
use std::path::PathBuf;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::Receiver;
use std::time::Duration;

use serde_json::{Value, json};

mod breakpoints;
mod config;
mod faults;
mod force;
mod frames;
mod functions;
mod fuzz;
mod multi;
mod picture;
mod sources;

pub const MOTOR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/motor.il");

/// Waits are bounded so that a broken adapter fails the test instead of
/// hanging it (this measures nothing).
const PATIENCE: Duration = Duration::from_secs(60);

pub struct Dap {
    child: Child,
    stdin: Option<ChildStdin>,
    incoming: Receiver<Value>,
    seq: i64,
    /// Events received while waiting for a response.
    pub events: Vec<Value>,
    /// What the adapter wrote on stderr (a caught panic says so there).
    stderr: std::sync::Arc<std::sync::Mutex<String>>,
}

impl Dap {
    pub fn start() -> Dap {
        Dap::start_with(&[])
    }

    /// `ilc ARGS debug`.
    pub fn start_with(args: &[&str]) -> Dap {
        let mut child = Command::new(env!("CARGO_BIN_EXE_ilc"))
            .args(args)
            .arg("debug")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("start ilc debug");
        let stdin = child.stdin.take();
        let stderr = std::sync::Arc::new(std::sync::Mutex::new(String::new()));
        let (mut err, into) = (child.stderr.take().unwrap(), stderr.clone());
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = err.read_to_string(&mut text);
            if let Ok(mut s) = into.lock() {
                *s = text;
            }
        });
        let incoming = il_testkit::framed::reader(child.stdout.take().unwrap());
        Dap {
            child,
            stdin,
            incoming,
            seq: 0,
            events: Vec::new(),
            stderr,
        }
    }

    /// What the adapter wrote on stderr until it exited.
    pub fn stderr(&self) -> String {
        self.stderr.lock().map(|s| s.clone()).unwrap_or_default()
    }

    pub fn send_raw(&mut self, body: &str) {
        if let Some(w) = &mut self.stdin {
            let _ = write!(w, "Content-Length: {}\r\n\r\n{body}", body.len());
            let _ = w.flush();
        }
    }

    /// Send a request; its seq.
    pub fn send(&mut self, command: &str, args: Value) -> i64 {
        self.seq += 1;
        let msg =
            json!({"seq": self.seq, "type": "request", "command": command, "arguments": args});
        self.send_raw(&msg.to_string());
        self.seq
    }

    fn next(&mut self) -> Value {
        self.incoming.recv_timeout(PATIENCE).unwrap_or_else(|_| {
            panic!(
                "no message from ilc debug; events so far: {:?}",
                self.events
            )
        })
    }

    /// The whole response to a request.
    pub fn request(&mut self, command: &str, args: Value) -> Value {
        let seq = self.send(command, args);
        loop {
            let m = self.next();
            if m["type"] == "response" && m["request_seq"] == seq {
                assert_eq!(m["command"], command, "{m}");
                return m;
            }
            self.events.push(m);
        }
    }

    /// The body of a successful response.
    pub fn ok(&mut self, command: &str, args: Value) -> Value {
        let r = self.request(command, args);
        assert_eq!(r["success"], true, "{command}: {r}");
        r["body"].clone()
    }

    /// The message of an error response.
    pub fn refused(&mut self, command: &str, args: Value) -> String {
        let r = self.request(command, args);
        assert_eq!(r["success"], false, "{command} should fail: {r}");
        r["message"].as_str().unwrap_or("").to_string()
    }

    /// The next event `name` (earlier ones of other names are kept).
    pub fn event(&mut self, name: &str) -> Value {
        if let Some(k) = self.events.iter().position(|e| e["event"] == name) {
            return self.events.remove(k);
        }
        loop {
            let m = self.next();
            if m["type"] == "event" && m["event"] == name {
                return m;
            }
            self.events.push(m);
        }
    }

    /// initialize + launch; the `initialized` event awaited.
    pub fn launch(&mut self, args: Value) {
        let caps = self.ok(
            "initialize",
            json!({"adapterID": "ilc", "linesStartAt1": true}),
        );
        assert_eq!(caps["supportsConditionalBreakpoints"], true);
        self.ok("launch", args);
        self.event("initialized");
    }

    /// Set breakpoints on lines of `path`; the breakpoints answered.
    pub fn breakpoints(&mut self, path: &str, bps: Value) -> Vec<Value> {
        let b = self.ok(
            "setBreakpoints",
            json!({"source": {"path": path}, "breakpoints": bps}),
        );
        b["breakpoints"].as_array().unwrap().clone()
    }

    /// Wait for `stopped`: its body.
    pub fn stopped(&mut self) -> Value {
        self.event("stopped")["body"].clone()
    }

    /// The innermost frame: its id, line and name.
    pub fn top(&mut self) -> (u64, u64, String) {
        let st = self.ok("stackTrace", json!({"threadId": 1}));
        let f = &st["stackFrames"][0];
        (
            f["id"].as_u64().unwrap(),
            f["line"].as_u64().unwrap(),
            f["name"].as_str().unwrap().to_string(),
        )
    }

    /// The scopes of a frame by name → variables (name → (value, type)).
    pub fn scope(&mut self, frame: u64, name: &str) -> Vec<(String, String, String)> {
        let scopes = self.ok("scopes", json!({"frameId": frame}));
        let s = scopes["scopes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|s| s["name"] == name)
            .unwrap_or_else(|| panic!("no scope {name}: {scopes}"))
            .clone();
        self.children(s["variablesReference"].as_u64().unwrap())
    }

    pub fn children(&mut self, reference: u64) -> Vec<(String, String, String)> {
        let v = self.ok("variables", json!({"variablesReference": reference}));
        v["variables"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| {
                (
                    x["name"].as_str().unwrap().to_string(),
                    x["value"].as_str().unwrap().to_string(),
                    x["type"].as_str().unwrap_or("").to_string(),
                )
            })
            .collect()
    }

    pub fn eval(&mut self, frame: u64, e: &str) -> Value {
        self.ok(
            "evaluate",
            json!({"expression": e, "frameId": frame, "context": "watch"}),
        )
    }

    /// disconnect and wait for the adapter to exit (bounded); its stderr.
    pub fn finish(mut self) -> String {
        let _ = self.request("disconnect", json!({}));
        drop(self.stdin.take());
        let t = std::time::Instant::now();
        loop {
            if let Ok(Some(status)) = self.child.try_wait() {
                assert!(status.success(), "{status}");
                // The stderr reader ends with the process.
                std::thread::sleep(Duration::from_millis(50));
                return self.stderr();
            }
            assert!(t.elapsed() < PATIENCE, "ilc debug did not exit");
            std::thread::sleep(Duration::from_millis(10));
        }
    }
}

impl Drop for Dap {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Variables as the client lists them: name, value, type.
pub type Vars = Vec<(String, String, String)>;

/// `name → (value, type)` lookup in a list of variables.
pub fn var<'a>(vars: &'a [(String, String, String)], name: &str) -> (&'a str, &'a str) {
    let v = vars
        .iter()
        .find(|v| v.0 == name)
        .unwrap_or_else(|| panic!("no variable {name} in {vars:?}"));
    (&v.1, &v.2)
}

/// The `flow` request's lines without their `source` (a temporary path).
pub fn without_source(lines: &Value) -> Value {
    let mut lines = lines.clone();
    for l in lines.as_array_mut().into_iter().flatten() {
        if let Some(o) = l.as_object_mut() {
            o.remove("source");
        }
    }
    lines
}

/// A file of `text` in a fresh temporary folder.
pub fn temp_file(tag: &str, text: &str) -> String {
    let d = std::env::temp_dir().join(format!("ilc-debug-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    let p: PathBuf = d.join(format!("{tag}.il"));
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn motor_line_22_stops_in_scan_3_with_the_current_result() {
    // The lines the test is about, as the file has them.
    let src = std::fs::read_to_string(MOTOR).unwrap();
    let lines: Vec<&str> = src.lines().collect();
    assert_eq!(lines[21].trim(), "ADD  1");
    assert_eq!(lines[22].trim(), "ST   starts");

    let mut d = Dap::start();
    d.launch(json!({"program": MOTOR, "pou": "Motor", "cycles": 6, "set": ["start=TRUE@3"]}));
    let bps = d.breakpoints(MOTOR, json!([{"line": 22}]));
    assert_eq!(bps[0]["verified"], true);
    assert_eq!(bps[0]["line"], 22);
    d.ok("setExceptionBreakpoints", json!({"filters": []}));
    d.ok("configurationDone", json!({}));

    let stop = d.stopped();
    assert_eq!(stop["reason"], "breakpoint", "{stop}");
    assert_eq!(stop["hitBreakpointIds"][0], bps[0]["id"]);
    let (frame, line, name) = d.top();
    assert_eq!((line, name.as_str()), (22, "Motor"));
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "CR"), ("0", "INT"));
    assert_eq!(var(&cr, "scan").0, "3");
    assert_eq!(var(&cr, "time").0, "T#20ms");
    let inputs = d.scope(frame, "Inputs");
    assert_eq!(var(&inputs, "start"), ("TRUE", "BOOL"));
    assert_eq!(var(&inputs, "stop"), ("FALSE", "BOOL"));
    let outputs = d.scope(frame, "Outputs");
    assert_eq!(var(&outputs, "starts"), ("0", "INT"));
    assert_eq!(var(&outputs, "run"), ("TRUE", "BOOL"));
    // The R_TRIG instance expands to its inputs and outputs.
    let locals = d.ok("scopes", json!({"frameId": frame}))["scopes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == "Locals")
        .unwrap()["variablesReference"]
        .as_u64()
        .unwrap();
    let edge = d.ok("variables", json!({"variablesReference": locals}))["variables"][0].clone();
    assert_eq!(
        (edge["name"].as_str(), edge["value"].as_str()),
        (Some("edge"), Some("R_TRIG"))
    );
    let members = d.children(edge["variablesReference"].as_u64().unwrap());
    assert_eq!(var(&members, "Q"), ("TRUE", "BOOL"));
    assert_eq!(var(&members, "CLK"), ("TRUE", "BOOL"));

    let e = d.eval(frame, "edge.Q");
    assert_eq!(
        (e["result"].as_str(), e["type"].as_str()),
        (Some("TRUE"), Some("BOOL"))
    );
    assert!(
        d.refused(
            "evaluate",
            json!({"expression": "edge.X", "frameId": frame})
        )
        .contains("X")
    );
    // A comparison evaluates as a breakpoint condition would.
    assert_eq!(d.eval(frame, "starts < 1")["result"], "TRUE");
    assert_eq!(d.eval(frame, "starts <> 0")["result"], "FALSE");

    d.ok("next", json!({"threadId": 1}));
    assert_eq!(d.stopped()["reason"], "step");
    let (frame, line, _) = d.top();
    assert_eq!(line, 23);
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "CR"), ("1", "INT"));

    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    let exited = d.event("exited");
    assert_eq!(exited["body"]["exitCode"], 0);
    // The breakpoint hit once: the edge is in scan 3 only.
    assert!(
        !d.events.iter().any(|e| e["event"] == "stopped"),
        "{:?}",
        d.events
    );
    d.finish();
}

#[test]
fn step_in_and_out_of_a_function_block_and_set_variable() {
    let src = "\
FUNCTION_BLOCK Counter
VAR_INPUT up : BOOL; END_VAR
VAR_OUTPUT n : INT; END_VAR
    LD   n
    ADD  1
    ST   n
END_FUNCTION_BLOCK
PROGRAM Main
VAR pump : Counter; total : INT; END_VAR
    CAL  pump(up := TRUE)
    LD   pump.n
    ST   total
END_PROGRAM
";
    let path = temp_file("stepin", src);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 2, "stopOnEntry": true}));
    d.ok("configurationDone", json!({}));
    assert_eq!(d.stopped()["reason"], "entry");
    assert_eq!(d.top().1, 10);
    d.ok("stepIn", json!({"threadId": 1}));
    d.stopped();
    let st = d.ok("stackTrace", json!({"threadId": 1}));
    let names: Vec<&str> = st["stackFrames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["Main.pump (Counter)", "Main"]);
    assert_eq!(st["stackFrames"][0]["line"], 4);
    assert_eq!(st["stackFrames"][1]["line"], 10);
    // The caller's variables are shown as they were at the call.
    let e = d.eval(2, "total");
    assert_eq!(e["result"], "0");
    let e = d.eval(1, "Main.pump.n");
    assert_eq!(e["result"], "0");
    // setVariable writes the innermost frame.
    let outs = d.ok("scopes", json!({"frameId": 1}))["scopes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == "Outputs")
        .unwrap()["variablesReference"]
        .clone();
    let r = d.ok(
        "setVariable",
        json!({"variablesReference": outs, "name": "n", "value": "41"}),
    );
    assert_eq!(r["value"], "41");
    assert!(
        !d.refused(
            "setVariable",
            json!({"variablesReference": outs, "name": "n", "value": "TRUE"})
        )
        .is_empty()
    );
    d.ok("stepOut", json!({"threadId": 1}));
    d.stopped();
    let (frame, line, name) = d.top();
    assert_eq!((line, name.as_str()), (11, "Main"));
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "CR"), ("42", "INT"));
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}

/// `ilc run --flow`: the CR after every line of the last scan, FB bodies
/// included, after the table; the earlier scans are not shown.
#[test]
fn run_flow_prints_the_current_result_of_each_line_of_the_last_scan() {
    let o = crate::run::ilc(&[
        "run",
        MOTOR,
        "--program",
        "Motor",
        "--cycles",
        "3",
        "--set",
        "start=TRUE@3",
        "--flow",
    ]);
    let out = crate::run::text(&o.stdout);
    assert!(o.status.success(), "{out}{}", crate::run::text(&o.stderr));
    let flow: Vec<&str> = out
        .lines()
        .skip_while(|l| !l.starts_with("flow of cycle 3 (time 20ms)"))
        .skip(1)
        .collect();
    let cols = |l: &str| l.split_whitespace().map(str::to_string).collect::<Vec<_>>();
    assert_eq!(flow.len(), 11, "{out}");
    assert_eq!(
        cols(flow[0]),
        ["Motor", "14", "LD", "start", "TRUE", ":", "BOOL"]
    );
    assert!(
        flow[4].ends_with("undefined (after CAL on line 18)"),
        "{}",
        flow[4]
    );
    assert_eq!(cols(flow[8]), ["Motor", "22", "ADD", "1", "1", ":", "INT"]);
    assert_eq!(out.matches("flow of").count(), 1);
}

/// A literal load is folded by the checker into the instruction that uses
/// it (`LD 7` has no statement): the flow says so instead of showing the
/// CR local an earlier line left, and `ST x` after it shows the literal
/// typed as `x`.
#[test]
fn run_flow_shows_literal_loads_as_folded_and_their_stores() {
    let path = temp_file(
        "literal",
        "PROGRAM P\nVAR x : INT; y : INT; s : STRING[8]; END_VAR\n    LD 5\n    ADD x\n    ST y\n    LD 7\n    ST x\n    LD 'ab'\n    ST s\nEND_PROGRAM\n",
    );
    let o = crate::run::ilc(&["run", &path, "--cycles", "1", "--flow"]);
    let out = crate::run::text(&o.stdout);
    assert!(o.status.success(), "{out}{}", crate::run::text(&o.stderr));
    // Each line's words: POU, line, instruction, CR.
    let cr: Vec<String> = out
        .lines()
        .skip_while(|l| !l.starts_with("flow of cycle 1"))
        .skip(1)
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();
    let folded = "undefined (a literal, folded into the instruction that uses it)";
    assert_eq!(cr[0], format!("P 3 LD 5 {folded}"), "{out}");
    assert_eq!(cr[1], "P 4 ADD x 5 : INT", "{out}");
    assert_eq!(cr[3], format!("P 6 LD 7 {folded}"), "{out}");
    assert_eq!(cr[4], "P 7 ST x 7 : INT", "{out}");
    assert_eq!(cr[6], "P 9 ST s 'ab' : STRING[8]", "{out}");
}
