//! `ilc debug`: a Debug Adapter Protocol server on stdio over the reference
//! interpreter. One thread reads the client's messages into a channel (and
//! raises a flag); the main thread runs the scans with the [`Session`]
//! attached to the machine as its hook, so that every request is answered
//! where the interpreter's state is: between scans, or inside a stopped
//! statement. A running scan looks at the flag once per statement, which is
//! how `pause` stops a scan that never ends (a JMP loop).
//!
//! A panic in a handler is caught and answered with an error response, as
//! in `ilc lsp`; the session goes on.

mod breakpoints;
mod cond;
mod drive;
mod inspect;
mod launch;
mod proto;
mod stop;

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use crossbeam_channel::Receiver;
use serde_json::{Value, json};

use breakpoints::Breakpoints;
use il_codegen::ir::Program;
use proto::{Incoming, Out};

/// What the next statement does with a stop.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Mode {
    Run,
    /// `pause`, or `stopOnEntry` (reason `entry`).
    Pause(&'static str),
    /// `next`: the next line of this frame or an outer one.
    Next {
        depth: usize,
        line: u32,
        scan: u64,
    },
    /// `stepIn`: the next line anywhere, a called body's first included.
    In {
        depth: usize,
        line: u32,
        scan: u64,
    },
    /// `stepOut`: the next line of an outer frame (of the next scan at the top).
    Out {
        depth: usize,
        scan: u64,
    },
}

/// A `variablesReference` while stopped.
#[derive(Clone, Debug)]
enum Handle {
    /// The "Current result" scope of frame `depth`.
    Cr(usize),
    /// The variables of a section of frame `depth` (`VAR_INPUT` ...).
    Section(usize, il_codegen::ast::VarKind),
    /// The members of a path of frame `depth`.
    Path(usize, String),
    /// The CR after each line run so far in this scan.
    Flow,
    /// The direct addresses the POU of frame `depth` uses (`%IX0.0` ...).
    Image(usize),
    /// The result of the FUNCTION of frame `depth`.
    Result(usize),
    /// A configuration's globals (read only: written through the externals).
    Globals(usize),
}

pub struct Session {
    out: Out,
    rx: Receiver<Incoming>,
    attention: Arc<AtomicBool>,
    launch: Option<launch::Launch>,
    target: Option<launch::Target>,
    prog: Option<Arc<Program>>,
    /// An M221 program: its objects named as it writes them (`%MW1`).
    m221: bool,
    /// Where the interpreter's IL lines are in the user's files.
    src: crate::source_map::SourceMap,
    /// The client's numbering (`initialize`: `linesStartAt1`,
    /// `columnsStartAt1`): 1 or 0 for the first line and column.
    base: Base,
    bps: Breakpoints,
    mode: Mode,
    /// The last statement the hook saw before it ran: depth, pc, line.
    last: Option<(usize, usize, u32)>,
    /// The scan running (1-based) and its simulated time.
    scan: u64,
    now: il_interp::il_std::TIME,
    handles: Vec<Handle>,
    /// Pinned values: path and IL literal, written around every scan.
    forces: Vec<(String, String)>,
    /// The CR after each line run in this scan: POU, line, CR.
    flow: crate::flow::Lines,
    configured: bool,
    /// The fault the run stopped on (`exceptionInfo`).
    fault: Option<String>,
    /// End the run (`terminate`, `disconnect`, end of input).
    quit: bool,
    /// End the adapter (`disconnect`, end of input).
    gone: bool,
    /// The encoding of a launch that names none (`ilc --encoding X debug`).
    encoding: il_codegen::read::Encoding,
}

/// How many flow entries one scan keeps (a long loop keeps its last ones).
const FLOW_MAX: usize = 4096;

/// `ilc debug`: serve one debug session on stdin/stdout; the exit status.
/// `encoding`: how a launch without an `encoding` field reads its files
/// (`ilc --encoding X debug`).
pub fn run(encoding: il_codegen::read::Encoding) -> u8 {
    let (tx, rx) = crossbeam_channel::unbounded();
    let attention = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&attention);
    std::thread::spawn(move || {
        let stdin = std::io::stdin();
        let mut input = stdin.lock();
        loop {
            let m = proto::read(&mut input);
            let eof = matches!(m, Incoming::Eof);
            if tx.send(m).is_err() {
                return;
            }
            flag.store(true, Ordering::Release);
            if eof {
                return;
            }
        }
    });
    let out = Out::new(Box::new(std::io::stdout()));
    let mut s = Session::new(out, rx, attention);
    s.encoding = encoding;
    s.serve();
    0
}

impl Session {
    fn new(out: Out, rx: Receiver<Incoming>, attention: Arc<AtomicBool>) -> Session {
        Session {
            out,
            rx,
            attention,
            launch: None,
            target: None,
            prog: None,
            m221: false,
            src: Default::default(),
            base: Base::default(),
            bps: Breakpoints::default(),
            mode: Mode::Run,
            last: None,
            scan: 0,
            now: il_interp::il_std::TIME(0),
            handles: Vec::new(),
            forces: Vec::new(),
            flow: Default::default(),
            configured: false,
            fault: None,
            quit: false,
            gone: false,
            encoding: Default::default(),
        }
    }

    /// The session: set-up requests until launched and configured, the
    /// run, then requests until the client disconnects.
    fn serve(mut self) {
        while !(self.configured && self.target.is_some()) {
            if !self.next_request(Self::setup) || self.gone {
                return;
            }
            if self.quit {
                // `terminate` before the run: it never starts.
                self.target = None;
                self.out.event("terminated", Value::Null);
                self.quit = false;
            }
        }
        let Some(target) = self.target.take() else {
            return;
        };
        let s = match target {
            launch::Target::Pou(m) => drive::drive(*m, self),
            launch::Target::Config(c) => drive::drive(*c, self),
        };
        let Some(mut s) = s else { return };
        while !s.gone {
            if !s.next_request(Self::running) {
                return;
            }
        }
    }

    /// Wait for one message and answer it with `handler` (a panic in it
    /// answered with an error); false at the end of input.
    fn next_request(&mut self, handler: fn(&mut Session, i64, &str, &Value)) -> bool {
        let Ok(m) = self.rx.recv() else { return false };
        self.dispatch(m, handler)
    }

    /// Answer one message; false at the end of input.
    fn dispatch(
        &mut self,
        m: Incoming,
        mut handler: impl FnMut(&mut Session, i64, &str, &Value),
    ) -> bool {
        match m {
            Incoming::Eof => {
                self.quit = true;
                self.gone = true;
                false
            }
            Incoming::Bad { seq, why } => {
                match seq {
                    Some(seq) => self.out.error(seq, "", &why),
                    None => self
                        .out
                        .output("stderr", &format!("ilc debug: ignored a message: {why}")),
                }
                true
            }
            Incoming::Request { seq, command, args } => {
                self.guarded(seq, &command, |s| handler(s, seq, &command, &args));
                true
            }
        }
    }

    /// `f` answering request `seq`; a panic in it is caught and answered
    /// with an error response, and the session goes on (as `ilc lsp` does).
    fn guarded<T>(
        &mut self,
        seq: i64,
        command: &str,
        f: impl FnOnce(&mut Session) -> T,
    ) -> Option<T> {
        let r = catch_unwind(AssertUnwindSafe(|| f(self)));
        if r.is_err() {
            eprintln!("ilc debug: the handler of `{command}` panicked; the session goes on");
            self.out.error(
                seq,
                command,
                &format!("internal error while answering `{command}`"),
            );
        }
        r.ok()
    }

    /// Requests before the run starts.
    fn setup(&mut self, seq: i64, command: &str, args: &Value) {
        match command {
            "initialize" => {
                // Lines and columns count from 1 unless the client says not.
                let from1 = |k: &str| args.get(k).and_then(Value::as_bool).unwrap_or(true);
                self.base = Base {
                    line: u32::from(from1("linesStartAt1")),
                    column: u32::from(from1("columnsStartAt1")),
                };
                self.out.ok(seq, command, capabilities())
            }
            "launch" => self.launch(seq, args),
            "configurationDone" => {
                self.configured = true;
                self.out.ok(seq, command, Value::Null);
            }
            _ => self.running(seq, command, args),
        }
    }

    fn launch(&mut self, seq: i64, args: &Value) {
        if self.launch.is_some() {
            return self
                .out
                .error(seq, "launch", "this session has already launched a program");
        }
        let l = match launch::parse(args, self.encoding) {
            Ok(l) => l,
            Err(e) => return self.out.error(seq, "launch", &e),
        };
        match launch::load(&l) {
            Ok(launch::Loaded {
                prog,
                target,
                lines,
                warnings,
                m221,
            }) => {
                self.m221 = m221;
                if !warnings.is_empty() {
                    self.out.output("stderr", &warnings);
                }
                self.src = lines;
                if l.stop_on_entry {
                    self.mode = Mode::Pause("entry");
                }
                self.forces = l.forces.clone();
                self.prog = Some(Arc::new(prog));
                self.target = Some(target);
                self.launch = Some(l);
                self.out.ok(seq, "launch", Value::Null);
                self.out.event("initialized", Value::Null);
            }
            Err(e) => {
                // The diagnostics, then the end: the program never runs.
                self.out.output("stderr", &e);
                // The last line says what stops the run (after the diagnostics).
                let why = e.lines().last().unwrap_or("");
                self.out.error(
                    seq,
                    "launch",
                    &format!("`{}` cannot be run: {why}", l.program),
                );
                self.out.event("terminated", Value::Null);
            }
        }
    }

    /// Requests that need no stopped statement: answered between scans,
    /// while a scan runs (the hook drains them), and after the run.
    fn running(&mut self, seq: i64, command: &str, args: &Value) {
        match command {
            "initialize" | "launch" => {
                self.out
                    .error(seq, command, "the session is already set up")
            }
            "setBreakpoints" => match &self.prog {
                Some(p) => match self.bps.set_lines((p, &self.src), self.base, args) {
                    Ok(body) => self.out.ok(seq, command, body),
                    Err(e) => self.out.error(seq, command, &e),
                },
                None => self.out.error(seq, command, "launch a program first"),
            },
            "setFunctionBreakpoints" => match &self.prog {
                Some(p) => {
                    let body = self.bps.set_functions((p, &self.src), self.base, args);
                    self.out.ok(seq, command, body);
                }
                None => self.out.error(seq, command, "launch a program first"),
            },
            "setExceptionBreakpoints" => {
                // `filters`, or `filterOptions` (clients that support conditions send these).
                let filters = args.get("filters").and_then(Value::as_array);
                let options = args.get("filterOptions").and_then(Value::as_array);
                self.bps.faults = filters.is_some_and(|f| f.iter().any(|x| x == "faults"))
                    || options.is_some_and(|f| f.iter().any(|x| x["filterId"] == "faults"));
                self.out.ok(seq, command, json!({}));
            }
            "configurationDone" => self.out.ok(seq, command, Value::Null),
            "threads" => self.out.ok(
                seq,
                command,
                json!({ "threads": [{ "id": 1, "name": "scan" }] }),
            ),
            "pause" => {
                self.mode = Mode::Pause("pause");
                self.out.ok(seq, command, Value::Null);
            }
            "continue" => self
                .out
                .ok(seq, command, json!({ "allThreadsContinued": true })),
            "force" => self.force(seq, args, None),
            "flow" => {
                let body = self.flow_lines();
                self.out.ok(seq, command, body);
            }
            "terminate" => {
                self.quit = true;
                self.out.ok(seq, command, Value::Null);
            }
            "disconnect" => {
                self.quit = true;
                self.gone = true;
                self.out.ok(seq, command, Value::Null);
            }
            "stackTrace" | "scopes" | "variables" | "evaluate" | "setVariable" | "next"
            | "stepIn" | "stepOut" | "nextScan" | "exceptionInfo" => {
                let why = if self.configured && self.target.is_none() && self.scan > 0 {
                    "the program is running (or has ended): pause it first"
                } else {
                    "the program is not stopped"
                };
                self.out.error(seq, command, why)
            }
            _ => self.out.error(
                seq,
                command,
                &format!("`{command}` is not a request ilc debug knows"),
            ),
        }
    }

    /// `force`: `{ "expression": path, "value": literal }` pins the value
    /// (written before and after every scan, and now when stopped in the
    /// program's own frame); without `value` it releases the path.
    fn force(&mut self, seq: i64, args: &Value, at: Option<&mut il_interp::Here<'_>>) {
        let Some(path) = args
            .get("expression")
            .and_then(Value::as_str)
            .map(str::trim)
        else {
            return self.out.error(
                seq,
                "force",
                "force needs `expression`: the variable's path",
            );
        };
        self.forces.retain(|(p, _)| !p.eq_ignore_ascii_case(path));
        let value = match args.get("value") {
            None | Some(Value::Null) => {
                return self
                    .out
                    .ok(seq, "force", json!({ "forced": self.forced() }));
            }
            Some(Value::String(s)) => s.clone(),
            Some(Value::Bool(b)) => if *b { "TRUE" } else { "FALSE" }.to_string(),
            Some(Value::Number(n)) => n.to_string(),
            Some(_) => {
                return self
                    .out
                    .error(seq, "force", "`value` must be an IL literal");
            }
        };
        if let Some(at) = at
            && at.depth() == 1
            && let Err(e) = at.set(path, &value)
        {
            return self.out.error(seq, "force", &e);
        }
        self.forces.push((path.to_string(), value));
        self.out
            .ok(seq, "force", json!({ "forced": self.forced() }));
    }

    /// The custom `flow` request: the CR after each line run so far in
    /// this scan, the last value of each line (what an editor shows next
    /// to the lines: CODESYS's "flow control"), in the order first run.
    fn flow_lines(&self) -> Value {
        let mut lines: Vec<(&str, u32, &str)> = Vec::new();
        for (pou, line, cr) in &self.flow {
            let line = self.base.out(self.src.line(pou, *line));
            match lines.iter_mut().find(|(p, l, _)| *p == pou && *l == line) {
                Some(x) => x.2 = cr,
                None => lines.push((pou, line, cr)),
            }
        }
        let lines: Vec<Value> = lines
            .into_iter()
            .map(|(pou, line, cr)| {
                let path = self.src.path_of(pou);
                json!({ "pou": pou, "line": line, "cr": cr, "source": source(path) })
            })
            .collect();
        json!({ "scan": self.scan, "lines": lines })
    }

    fn forced(&self) -> Value {
        self.forces
            .iter()
            .map(|(p, v)| json!({ "expression": p, "value": v }))
            .collect()
    }

    /// Answer what has arrived while a scan runs; the run ends on `quit`.
    fn drain(&mut self) {
        while let Ok(m) = self.rx.try_recv() {
            if !self.dispatch(m, Self::running) {
                break;
            }
        }
    }

    fn attention(&self) -> bool {
        self.attention.swap(false, Ordering::Acquire)
    }
}

/// How the client numbers lines and columns: the number of the first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Base {
    pub line: u32,
    pub column: u32,
}

impl Default for Base {
    fn default() -> Base {
        Base { line: 1, column: 1 }
    }
}

impl Base {
    /// A line of ours (from 1) as the client numbers it.
    pub fn out(self, line: u32) -> u32 {
        line.saturating_add(self.line).saturating_sub(1)
    }
    /// A line the client sent, numbered from 1 (`None`: not a line).
    pub fn read(self, line: u64) -> Option<u32> {
        let l = u32::try_from(line).ok()?.checked_add(1 - self.line)?;
        (l >= 1).then_some(l)
    }
}

/// A DAP `Source` of a path: its name and its absolute path (clients
/// compare these with the files they have open).
pub fn source(path: &str) -> Value {
    let abs = std::fs::canonicalize(path)
        .map(|p| p.display().to_string())
        .unwrap_or_else(|_| path.to_string());
    let name = std::path::Path::new(path)
        .file_name()
        .map_or(path.to_string(), |n| n.to_string_lossy().into_owned());
    json!({ "name": name, "path": abs })
}

/// What the adapter supports (the `initialize` response).
fn capabilities() -> Value {
    json!({
        "supportsConfigurationDoneRequest": true,
        "supportsFunctionBreakpoints": true,
        "supportsConditionalBreakpoints": true,
        "supportsHitConditionalBreakpoints": true,
        "supportsLogPoints": true,
        "supportsEvaluateForHovers": true,
        "supportsSetVariable": true,
        "supportsTerminateRequest": true,
        "supportsExceptionInfoRequest": true,
        "exceptionBreakpointFilters": [{
            "filter": "faults",
            "label": "Runtime faults",
            "description": "Division by zero, subscript out of range, subrange violation ...",
            "default": true,
        }],
    })
}
