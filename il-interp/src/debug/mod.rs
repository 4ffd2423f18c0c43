//! Stepping: a [`Hook`] called before and after each statement while one is
//! attached ([`Machine::set_hook`]), with the call stack (PROGRAM → FB
//! instance → FUNCTION, each frame at its IL line and instance path), the
//! current result as the body last set it, and the frames' variables.
//!
//! Without a hook the interpreter runs its usual loop ([`Machine::run`]
//! tests for one once per call of a body, not per statement), so a run
//! that is not debugged pays nothing per instruction.

use std::any::Any;

use crate::places::Step;
use crate::values::Value;
use crate::{Frame, Machine};
use il_codegen::ir::types::Ty;
use il_codegen::ir::{CheckedPou, Op, PathElem, Place, Root, Stmt};
use il_std::{Cycle, Fault};

/// What a debugger does at each statement of a hooked run. An `Err`
/// abandons the scan with that message (a debugger ending the session).
pub trait Hook: Any + Send {
    /// Before the statement at [`Here::line`] runs.
    fn before(&mut self, at: &mut Here<'_>) -> Result<(), String>;
    /// After it ran: [`Here::cr`] is the CR it left, [`Here::fault`] the
    /// runtime fault it recorded, if any.
    fn after(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        let _ = at;
        Ok(())
    }
}

/// The CR of a frame, as the statements run so far in it left it.
#[derive(Clone, Debug, PartialEq)]
enum CrNow {
    /// Nothing loaded yet in this call of the body.
    Unset,
    /// The CR local of this index (its type: `CheckedPou::cr_types`).
    Slot(u32),
    /// A `CAL` on this line left it undefined (IEC 61131-3: the checker's IL0108).
    AfterCal(u32),
    /// A literal the checker folds into the instruction that uses it
    /// (`LD 7` is an [`Op::Nop`]: no CR local holds it yet).
    Folded,
    /// A literal stored as it was (`LD 7` `ST x`): its value, typed as
    /// the place it went to (no CR local holds it either).
    Literal(Value, Ty),
}

/// One frame of the debugged call stack.
#[derive(Clone, Debug)]
struct Entry {
    pou: usize,
    /// `Main.pump.edge`; a FUNCTION's frame is named by the function.
    path: String,
    line: u32,
    cr: CrNow,
    /// The frame's variables and CR locals while a callee runs (the
    /// caller's `Frame` is borrowed by the call then; it does not change
    /// until the call returns).
    vars: Vec<Value>,
    crs: Vec<Value>,
    /// A FUNCTION's result so far, likewise.
    ret: Value,
    /// Writes to this frame while a callee runs ([`Here::set_in`]): the
    /// variable, the steps into it and the value, made when the call returns.
    pending: Vec<(usize, Vec<Step>, Value)>,
}

/// The hook and the call stack of a machine being debugged (`None`: not).
#[derive(Default)]
pub(crate) struct Dbg(Option<Box<State>>);

struct State {
    hook: Option<Box<dyn Hook>>,
    stack: Vec<Entry>,
    /// A configuration's globals as the program running now started
    /// (name, value, type); the ones it uses are its externals, live.
    globals: Vec<(String, Value, Ty)>,
    /// The path of the frame the next body starts (set by the caller).
    next_path: Option<String>,
}

impl Clone for Dbg {
    /// A copy of a machine has no debugger attached (a hook is not cloned).
    fn clone(&self) -> Self {
        Dbg(None)
    }
}

impl std::fmt::Debug for Dbg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() { "hooked" } else { "-" })
    }
}

impl Dbg {
    #[inline(always)]
    pub(crate) fn on(&self) -> bool {
        self.0.is_some()
    }
}

/// One frame of [`Here::frames`].
#[derive(Clone, Debug, PartialEq)]
pub struct FrameInfo {
    /// The POU's name as declared.
    pub pou: String,
    /// The instance path (`Main.pump.edge`), or the FUNCTION's name.
    pub path: String,
    /// The IL line the frame is at.
    pub line: u32,
}

/// The current result of a frame: its value and type, or why it has none.
#[derive(Clone, Debug, PartialEq)]
pub enum Cr {
    /// The value and its type as the checker typed the CR local.
    Value(Value, Ty),
    /// Undefined, and why.
    Undefined(Undefined),
}

/// Why a frame's CR has no value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Undefined {
    /// Nothing was loaded yet in this call of the body.
    NothingLoaded,
    /// A `CAL` on this IL line left it undefined (IEC 61131-3: the checker's IL0108).
    AfterCal(u32),
    /// A literal the checker folds into the instruction that uses it
    /// (`LD 7` before `ADD x`): no value of a type yet.
    Folded,
}

impl std::fmt::Display for Undefined {
    /// `no value loaded`, `after CAL on line 18` (an IL line).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Undefined::NothingLoaded => f.write_str("no value loaded"),
            Undefined::AfterCal(l) => write!(f, "after CAL on line {l}"),
            Undefined::Folded => f.write_str("a literal, folded into the instruction that uses it"),
        }
    }
}

mod here;
mod show;
pub use here::Here;
pub(crate) use show::subscripts;
pub use show::{Shown, type_of_value};

impl Machine {
    /// Attach a debugger (`None`: detach it). Every body then runs
    /// statement by statement through the hook, without the step limit
    /// (the debugger pauses an endless loop).
    pub fn set_hook(&mut self, hook: Option<Box<dyn Hook>>) {
        self.dbg = Dbg(hook.map(|h| {
            Box::new(State {
                hook: Some(h),
                stack: Vec::new(),
                globals: Vec::new(),
                next_path: None,
            })
        }));
    }

    /// Detach the hook and have it back, if it is a `T`.
    pub fn take_hook<T: Hook>(&mut self) -> Option<Box<T>> {
        let h = self.dbg.0.take()?.hook?;
        (h as Box<dyn Any>).downcast::<T>().ok()
    }

    /// The attached hook, if it is a `T`.
    pub fn hook_mut<T: Hook>(&mut self) -> Option<&mut T> {
        let h = self.dbg.0.as_mut()?.hook.as_mut()?;
        (h.as_mut() as &mut dyn Any).downcast_mut::<T>()
    }

    /// A configuration's globals, for [`Here::globals`] while its next
    /// program runs.
    #[cold]
    #[inline(never)]
    pub(crate) fn dbg_globals(&mut self, globals: Vec<(String, Value, Ty)>) {
        if let Some(d) = &mut self.dbg.0 {
            d.globals = globals;
        }
    }

    /// The next body run is the frame at `path` (its instance path).
    #[cold]
    #[inline(never)]
    pub(crate) fn dbg_enter(&mut self, path: String) {
        if let Some(d) = &mut self.dbg.0 {
            d.next_path = Some(path);
        }
    }

    /// Before frame `f` calls `inst` (an FB instance, its steps already
    /// evaluated) or a FUNCTION (`inst` `None`, named `func`): keep the
    /// caller's values for the stack view and name the callee's frame.
    #[cold]
    #[inline(never)]
    pub(crate) fn dbg_call(&mut self, f: &Frame, inst: Option<(&Place, &[Step])>, func: &str) {
        let Some(d) = &mut self.dbg.0 else { return };
        let Some(top) = d.stack.last_mut() else {
            return;
        };
        top.vars = f.vars.clone();
        top.crs = f.cr.clone();
        top.ret = f.ret.clone();
        let path = match inst {
            Some((p, steps)) => {
                let pou = &self.prog.pous[f.pou];
                format!("{}.{}", top.path, place_text(pou, p, steps))
            }
            None => func.to_string(),
        };
        d.next_path = Some(path);
    }

    /// A call of frame `f` returned: the writes a debugger made to `f`'s
    /// variables while it ran ([`Here::set_in`]).
    #[cold]
    #[inline(never)]
    pub(crate) fn dbg_return(&mut self, f: &mut Frame) {
        let Some(top) = self.dbg.0.as_mut().and_then(|d| d.stack.last_mut()) else {
            return;
        };
        for (i, steps, v) in std::mem::take(&mut top.pending) {
            if let Some(slot) = f.vars.get_mut(i) {
                let mut root = std::mem::replace(slot, Value::Bool(false));
                self.write_at(&mut root, &steps, v);
                f.vars[i] = root;
            }
        }
    }

    /// Run a body statement by statement through the hook (kept out of
    /// the plain loop's code).
    #[inline(never)]
    #[cold]
    pub(crate) fn run_hooked(&mut self, f: &mut Frame, ctx: &mut Cycle) -> Result<(), String> {
        let pou = f.pou;
        let prog = self.prog.clone();
        let body: &[Stmt] = &prog.pous[pou].body;
        let mut labels = vec![usize::MAX; prog.pous[pou].label_count];
        for (i, s) in body.iter().enumerate() {
            if let Op::Label(l) = s.op {
                labels[l] = i;
            }
        }
        if let Some(d) = &mut self.dbg.0 {
            let path = d
                .next_path
                .take()
                .unwrap_or_else(|| prog.pous[pou].name.clone());
            d.stack.push(Entry {
                pou,
                path,
                line: body.first().map_or(0, |s| s.line),
                cr: CrNow::Unset,
                vars: Vec::new(),
                crs: Vec::new(),
                ret: Value::Bool(false),
                pending: Vec::new(),
            });
        }
        let r = self.hooked_body(f, ctx, body, &labels);
        if let Some(d) = &mut self.dbg.0 {
            d.stack.pop();
        }
        r
    }

    fn hooked_body(
        &mut self,
        f: &mut Frame,
        ctx: &mut Cycle,
        body: &[Stmt],
        labels: &[usize],
    ) -> Result<(), String> {
        let mut pc = 0;
        while let Some(s) = body.get(pc) {
            if let Some(top) = self.dbg.0.as_mut().and_then(|d| d.stack.last_mut()) {
                top.line = s.line;
            }
            self.call_hook(f, ctx, s, pc, None, true)?;
            pc += 1;
            let faults = ctx.fault_count();
            let r = self.exec(f, s, labels, ctx);
            let now = match &s.op {
                Op::SetCr { cr, .. } => Some(CrNow::Slot(*cr)),
                Op::CallFb(_) => Some(CrNow::AfterCal(s.line)),
                Op::Nop => Some(CrNow::Folded),
                Op::Store {
                    place,
                    value: il_codegen::ir::Value::Const(c),
                    negate: false,
                } => {
                    let ty = self.prog.pous[f.pou].place(*place).ty.clone();
                    Some(CrNow::Literal(Value::from_const(c), ty))
                }
                _ => None,
            };
            if let Some(now) = now
                && let Some(top) = self.dbg.0.as_mut().and_then(|d| d.stack.last_mut())
            {
                top.cr = now;
            }
            let fault = if ctx.fault_count() > faults {
                ctx.faults().last().copied()
            } else {
                None
            };
            let r = match r {
                Ok(x) => x,
                Err(e) => return Err(self.located(f.pou, s, e)),
            };
            self.call_hook(f, ctx, s, pc - 1, fault, false)?;
            match r {
                Some(usize::MAX) => break,
                Some(to) => pc = to,
                None => {}
            }
        }
        Ok(())
    }

    fn call_hook(
        &mut self,
        f: &mut Frame,
        ctx: &mut Cycle,
        stmt: &Stmt,
        pc: usize,
        fault: Option<Fault>,
        before: bool,
    ) -> Result<(), String> {
        let Some(d) = &mut self.dbg.0 else {
            return Ok(());
        };
        let Some(mut hook) = d.hook.take() else {
            return Ok(());
        };
        // The stack is moved out for the call, so that the hook sees the
        // machine (its program, its reads) and the stack together.
        let mut stack = std::mem::take(&mut d.stack);
        let globals = std::mem::take(&mut d.globals);
        let mut here = Here {
            m: self,
            f,
            ctx,
            stack: &mut stack,
            globals: &globals,
            stmt,
            pc,
            fault,
        };
        let r = if before {
            hook.before(&mut here)
        } else {
            hook.after(&mut here)
        };
        if let Some(d) = &mut self.dbg.0 {
            d.hook = Some(hook);
            d.stack = stack;
            d.globals = globals;
        }
        // An error of the hook is the debugger's own: it is not located.
        if r.is_err() {
            self.error_located = true;
        }
        r
    }
}

/// `pump.edge`, `valves[2]`: an instance place of `pou` with its evaluated steps.
fn place_text(pou: &CheckedPou, p: &Place, steps: &[Step]) -> String {
    let mut s = match &p.root {
        Root::Var(i) => pou.vars.get(*i).map_or("?".into(), |v| v.name.clone()),
        Root::Ret => pou.name.clone(),
        Root::Addr(l) => l.text.clone(),
    };
    let mut steps = steps.iter();
    for e in &p.path {
        match (e, steps.next()) {
            (PathElem::Field(n), _) => {
                s.push('.');
                s.push_str(&n.name);
            }
            (PathElem::Index { dims, .. }, Some(Step::Index(Some(k)))) => {
                s.push_str(&subscripts(dims, *k));
            }
            _ => s.push_str("[?]"),
        }
    }
    s
}
