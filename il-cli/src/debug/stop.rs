//! The session as the interpreter's hook: before each statement, whether to
//! stop (pause, a step's end, a breakpoint whose condition and hit count
//! hold, a log point to print instead), and after it, the flow record and
//! fault stops. A stop sends `stopped` and answers requests on this thread,
//! with the interpreter's state at hand, until one resumes the run.

use std::panic::{AssertUnwindSafe, catch_unwind};

use serde_json::{Value, json};

use super::{FLOW_MAX, Mode, Session, cond};
use il_interp::{Here, Hook};

/// What a request answered while stopped does to the run.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Resume {
    Stay,
    Go,
    Quit,
}

/// Why the run ends when the debugger ends it (the scan's error).
const ENDED: &str = "the debugger ended the session";

impl Hook for Session {
    // A panic of the debugger's own code ends the run with an error, not
    // the adapter (the client gets `terminated`, and stderr says why).
    fn before(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        catch_unwind(AssertUnwindSafe(|| self.before_statement(at)))
            .unwrap_or_else(|_| Err("internal error in ilc debug (before a statement)".into()))
    }

    fn after(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        catch_unwind(AssertUnwindSafe(|| self.after_statement(at)))
            .unwrap_or_else(|_| Err("internal error in ilc debug (after a statement)".into()))
    }
}

impl Session {
    fn before_statement(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        if self.attention() {
            self.drain();
        }
        if self.quit {
            return Err(ENDED.into());
        }
        // Lines are the user's file's: an M221 listing's operation block
        // is several IL statements on one line, which stops and steps once.
        let (depth, pc) = (at.depth(), at.pc());
        let line = self.src.line(&at.pou().name, at.line());
        // A line starts unless the previous statement was the one before
        // this in the same frame and on the same line.
        let starts = self.last != Some((depth, pc.wrapping_sub(1), line));
        let scan_starts = self.last.is_none();
        self.last = Some((depth, pc, line));
        if !starts {
            return Ok(());
        }
        let step = match self.mode {
            Mode::Run => None,
            Mode::Pause(reason) => Some(reason),
            Mode::Next {
                depth: d,
                line: l,
                scan,
            } => (depth < d || scan != self.scan || (depth == d && line != l)).then_some("step"),
            Mode::In {
                depth: d,
                line: l,
                scan,
            } => (depth != d || line != l || scan != self.scan).then_some("step"),
            Mode::Out { depth: d, scan } => (depth < d || scan != self.scan).then_some("step"),
        };
        if let Some(reason) = step {
            return self.stop(at, reason, None, Vec::new());
        }
        if scan_starts && let Some(&(id, _)) = self.bps.scans.iter().find(|(_, n)| *n == self.scan)
        {
            return self.stop(at, "function breakpoint", None, vec![id]);
        }
        let mut hit = Vec::new();
        let mut errors = Vec::new();
        let mut logs = Vec::new();
        // Function breakpoints only look at a body's first statement.
        let pou = if pc == 0 && !self.bps.functions.is_empty() {
            at.pou().name.to_ascii_uppercase()
        } else {
            String::new()
        };
        let key = (self.src.file_of(&at.pou().name), line);
        let lines = self.bps.lines.get_mut(&key).into_iter().flatten();
        let funcs = self
            .bps
            .functions
            .get_mut(&pou)
            .into_iter()
            .flatten()
            .filter(|_| pc == 0);
        for bp in lines.chain(funcs) {
            let holds = match &bp.condition {
                None => true,
                Some(c) => cond::holds(at, c).unwrap_or_else(|e| {
                    // A condition that cannot be evaluated stops, saying why.
                    errors.push(e);
                    true
                }),
            };
            if !holds {
                continue;
            }
            bp.hits += 1;
            if bp.hit.is_some_and(|h| !h.holds(bp.hits)) {
                continue;
            }
            match &bp.log {
                Some(msg) => logs.push(msg.clone()),
                None => hit.push(bp.id),
            }
        }
        for msg in logs {
            let text = cond::interpolate(at, &msg);
            self.out.output("console", &text);
        }
        for e in &errors {
            self.out.output("stderr", e);
        }
        if hit.is_empty() {
            return Ok(());
        }
        let reason = if !pou.is_empty() && self.bps.functions.contains_key(&pou) {
            "function breakpoint"
        } else {
            "breakpoint"
        };
        self.stop(at, reason, None, hit)
    }

    fn after_statement(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        let (src, base) = (&self.src, self.base);
        crate::flow::record(&mut self.flow, at, FLOW_MAX, &|pou, l| {
            base.out(src.line(pou, l))
        });
        if self.bps.faults
            && let Some(f) = at.fault()
        {
            let path = self.src.path_of(f.pou);
            let name = std::path::Path::new(path)
                .file_name()
                .map_or(path.into(), |n| n.to_string_lossy());
            let line = self.base.out(self.src.line(f.pou, f.line));
            let text = format!("{:?} in {} at line {line} of {name}", f.kind, f.pou);
            return self.stop(at, "exception", Some(text), Vec::new());
        }
        Ok(())
    }

    /// Stop here: send `stopped`, then answer requests until one resumes.
    fn stop(
        &mut self,
        at: &mut Here<'_>,
        reason: &str,
        text: Option<String>,
        hit: Vec<i64>,
    ) -> Result<(), String> {
        self.mode = Mode::Run;
        self.handles.clear();
        self.fault = text.clone();
        let mut body = json!({ "reason": reason, "threadId": 1, "allThreadsStopped": true });
        if let Some(t) = &text {
            body["description"] = json!(format!("Paused on fault: {t}"));
            body["text"] = json!(t);
        }
        if !hit.is_empty() {
            body["hitBreakpointIds"] = json!(hit);
        }
        self.out.event("stopped", body);
        loop {
            let Ok(m) = self.rx.recv() else {
                self.quit = true;
                return Err(ENDED.into());
            };
            let mut resume = Resume::Stay;
            let alive = self.dispatch_stopped(m, at, &mut resume);
            match resume {
                Resume::Go if alive => {
                    self.fault = None;
                    return Ok(());
                }
                Resume::Stay if alive => {}
                _ => {
                    self.quit = true;
                    return Err(ENDED.into());
                }
            }
        }
    }

    /// Answer one message while stopped; false at the end of input.
    fn dispatch_stopped(
        &mut self,
        m: super::proto::Incoming,
        at: &mut Here<'_>,
        resume: &mut Resume,
    ) -> bool {
        use super::proto::Incoming;
        match m {
            Incoming::Request { seq, command, args } => {
                if let Some(x) =
                    self.guarded(seq, &command, |s| s.stopped(at, seq, &command, &args))
                {
                    *resume = x;
                }
                true
            }
            other => self.dispatch(other, Self::running),
        }
    }

    /// Requests while stopped.
    fn stopped(&mut self, at: &mut Here<'_>, seq: i64, command: &str, args: &Value) -> Resume {
        let line = self.src.line(&at.pou().name, at.line());
        let (depth, scan) = (at.depth(), self.scan);
        let go = |s: &mut Session, mode: Mode| {
            s.mode = mode;
            s.out
                .ok(seq, command, json!({ "allThreadsContinued": true }));
            Resume::Go
        };
        match command {
            "continue" => go(self, Mode::Run),
            "next" => go(self, Mode::Next { depth, line, scan }),
            "stepIn" => go(self, Mode::In { depth, line, scan }),
            "stepOut" => go(self, Mode::Out { depth, scan }),
            "nextScan" => go(self, Mode::Out { depth: 0, scan }),
            "pause" => {
                self.out.ok(seq, command, Value::Null);
                Resume::Stay
            }
            "stackTrace" => self.answer(seq, command, |s| s.stack_trace(at)),
            "scopes" => self.answer(seq, command, |s| s.scopes(at, args)),
            "variables" => self.answer(seq, command, |s| s.variables(at, args)),
            "evaluate" => self.answer(seq, command, |s| s.evaluate(at, args)),
            "setVariable" => self.answer(seq, command, |s| s.set_variable(at, args)),
            "exceptionInfo" => match &self.fault {
                Some(t) => {
                    let body =
                        json!({ "exceptionId": "fault", "description": t, "breakMode": "always" });
                    self.out.ok(seq, command, body);
                    Resume::Stay
                }
                None => {
                    self.out
                        .error(seq, command, "the program did not stop on a fault");
                    Resume::Stay
                }
            },
            "force" => {
                self.force(seq, args, Some(at));
                Resume::Stay
            }
            _ => {
                self.running(seq, command, args);
                if self.quit {
                    Resume::Quit
                } else {
                    Resume::Stay
                }
            }
        }
    }

    fn answer(
        &mut self,
        seq: i64,
        command: &str,
        f: impl FnOnce(&mut Session) -> Result<Value, String>,
    ) -> Resume {
        match f(self) {
            Ok(body) => self.out.ok(seq, command, body),
            Err(e) => self.out.error(seq, command, &e),
        }
        Resume::Stay
    }
}
