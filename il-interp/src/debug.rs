//! Stepping: a [`Hook`] called before and after each statement while one is
//! attached ([`Machine::set_hook`]), with the call stack (PROGRAM → FB
//! instance → FUNCTION, each frame at its IL line and instance path), the
//! current result as the body last set it, and the frames' variables.
//!
//! Without a hook the interpreter runs its usual loop ([`Machine::run`]
//! tests for one once per call of a body, not per statement), so a run
//! that is not debugged pays nothing per instruction.

use std::any::Any;

use crate::places::{Step, io_read};
use crate::values::Value;
use crate::{Frame, Machine};
use il_codegen::ir::types::Ty;
use il_codegen::ir::{CheckedPou, Op, PathElem, Place, Root, Stmt, TypeDef, Var};
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
#[derive(Clone, Copy, Debug, PartialEq)]
enum CrNow {
    /// Nothing loaded yet in this call of the body.
    Unset,
    /// The CR local of this index (its type: `CheckedPou::cr_types`).
    Slot(u32),
    /// A `CAL` on this line left it undefined (IEC 61131-3: the checker's IL0108).
    AfterCal(u32),
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
}

impl std::fmt::Display for Undefined {
    /// `no value loaded`, `after CAL on line 18` (an IL line).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Undefined::NothingLoaded => f.write_str("no value loaded"),
            Undefined::AfterCal(l) => write!(f, "after CAL on line {l}"),
        }
    }
}

/// A variable (or member, element) to show: its name, value and type.
#[derive(Clone, Debug)]
pub struct Shown {
    /// The name (`start`), member (`Q`) or subscripts (`[2, 3]`).
    pub name: String,
    /// Its value.
    pub value: Value,
    /// Its type as IEC writes it (`INT`, `R_TRIG`, `ARRAY [1..3] OF INT`).
    pub ty: String,
}

/// Where a path leads: a variable of the frame and the steps into it, or
/// the process image.
enum Target {
    Var(usize, Vec<Step>),
    Addr(il_codegen::ir::Loc),
}

/// Where a hooked run is: the statement, the frames and the cycle.
pub struct Here<'a> {
    m: &'a Machine,
    f: &'a mut Frame,
    ctx: &'a mut Cycle,
    stack: &'a [Entry],
    globals: &'a [(String, Value, Ty)],
    stmt: &'a Stmt,
    pc: usize,
    fault: Option<Fault>,
}

impl Here<'_> {
    /// The POU of the innermost frame.
    pub fn pou(&self) -> &CheckedPou {
        &self.m.prog.pous[self.f.pou]
    }
    /// The IL line of the statement.
    pub fn line(&self) -> u32 {
        self.stmt.line
    }
    /// Its index in the body (an IL line may become several statements).
    pub fn pc(&self) -> usize {
        self.pc
    }
    /// How many frames are on the stack (1: the program itself).
    pub fn depth(&self) -> usize {
        self.stack.len()
    }
    /// The simulated time of the cycle.
    pub fn now(&self) -> il_std::TIME {
        self.ctx.now()
    }
    /// The runtime fault the statement just recorded ([`Hook::after`]).
    pub fn fault(&self) -> Option<&Fault> {
        self.fault.as_ref()
    }
    /// The statement is a `CAL` or calls a user FUNCTION (where "step in" goes).
    pub fn is_call(&self) -> bool {
        use il_codegen::ir::Expr;
        match &self.stmt.op {
            Op::CallFb(_) => true,
            Op::SetCr { expr, .. } => matches!(expr, Expr::CallUser(_)),
            _ => false,
        }
    }

    /// The frames, innermost first.
    pub fn frames(&self) -> Vec<FrameInfo> {
        self.stack
            .iter()
            .rev()
            .map(|e| FrameInfo {
                pou: self.m.prog.pous[e.pou].name.clone(),
                path: e.path.clone(),
                line: e.line,
            })
            .collect()
    }

    /// The entry and the live values of frame `depth` (0: innermost).
    fn frame(&self, depth: usize) -> Option<(&Entry, &[Value], &[Value])> {
        let e = self.stack.iter().rev().nth(depth)?;
        Some(if depth == 0 {
            (e, &self.f.vars[..], &self.f.cr[..])
        } else {
            (e, &e.vars[..], &e.crs[..])
        })
    }

    /// The current result of frame `depth`.
    pub fn cr(&self, depth: usize) -> Option<Cr> {
        let (e, _, crs) = self.frame(depth)?;
        let pou = &self.m.prog.pous[e.pou];
        Some(match e.cr {
            CrNow::Unset => Cr::Undefined(Undefined::NothingLoaded),
            CrNow::AfterCal(l) => Cr::Undefined(Undefined::AfterCal(l)),
            CrNow::Slot(i) => match (crs.get(i as usize), pou.cr_types.get(i as usize)) {
                (Some(v), Some(t)) => Cr::Value(v.clone(), t.clone()),
                _ => Cr::Undefined(Undefined::NothingLoaded),
            },
        })
    }

    /// The result of a FUNCTION's frame so far (its name, value and type);
    /// `None` for the frame of an instance.
    pub fn result(&self, depth: usize) -> Option<(String, Value, Ty)> {
        let e = self.stack.iter().rev().nth(depth)?;
        let pou = &self.m.prog.pous[e.pou];
        let ty = pou.ret.clone()?;
        let v = if depth == 0 { &self.f.ret } else { &e.ret };
        Some((pou.name.clone(), v.clone(), ty))
    }

    /// A configuration's globals (`g`, `Resource.g`) with their values as
    /// the running program started; empty for a single POU.
    pub fn globals(&self) -> &[(String, Value, Ty)] {
        self.globals
    }

    /// The variables of frame `depth` in declaration order.
    pub fn vars(&self, depth: usize) -> Vec<(&Var, Value)> {
        let Some((e, vars, _)) = self.frame(depth) else {
            return Vec::new();
        };
        self.m.prog.pous[e.pou]
            .vars
            .iter()
            .zip(vars)
            .map(|(v, x)| (v, x.clone()))
            .collect()
    }

    /// The value and type of a path in frame `depth`: a variable with
    /// members and subscripts (`edge.Q`, `m[2, 3]`, through the IR's one
    /// path resolver), the same prefixed with a frame's instance path
    /// (`Main.pump.starts`), or a direct address (`%IX0.0`).
    pub fn eval(&self, depth: usize, text: &str) -> Result<(Value, Ty), String> {
        let r = self.eval_frame(depth, text);
        if r.is_err()
            && let Some(g) = self.eval_global(text.trim())
        {
            return g;
        }
        r
    }

    /// A path into a configuration's global (`g.x`, `Resource.g[2]`).
    fn eval_global(&self, text: &str) -> Option<Result<(Value, Ty), String>> {
        let (name, v, ty) = self.globals.iter().find(|(n, ..)| {
            text.len() >= n.len()
                && text.is_char_boundary(n.len())
                && text[..n.len()].eq_ignore_ascii_case(n)
                && matches!(text.as_bytes().get(n.len()), None | Some(b'.' | b'['))
        })?;
        let rest = &text[name.len()..];
        if rest.is_empty() {
            return Some(Ok((v.clone(), ty.clone())));
        }
        let parts = match il_codegen::ir::path::parse(&format!("x{rest}")) {
            Ok(p) => p.parts,
            Err(e) => return Some(Err(e)),
        };
        Some(
            self.m
                .resolve_parts(ty.clone(), None, &parts, text)
                .and_then(|(steps, ty, _)| {
                    self.m
                        .read_at(v, &steps)
                        .map(|v| (v, ty))
                        .ok_or_else(|| format!("`{text}` has no value here"))
                }),
        )
    }

    fn eval_frame(&self, depth: usize, text: &str) -> Result<(Value, Ty), String> {
        let (depth, rest) = self.frame_of(depth, text.trim());
        if let Some((name, v, ty)) = self.result(depth)
            && name.eq_ignore_ascii_case(rest)
        {
            return Ok((v, ty));
        }
        let (target, ty) = self.resolve(depth, rest)?;
        let v = match target {
            Target::Addr(l) => io_read(self.ctx, &l),
            Target::Var(i, steps) => {
                let (_, vars, _) = self.frame(depth).ok_or("no such frame")?;
                vars.get(i)
                    .and_then(|root| self.m.read_at(root, &steps))
                    .ok_or_else(|| format!("`{rest}` has no value here"))?
            }
        };
        Ok((v, ty))
    }

    /// Write `text` (an IL literal of the place's type) to a path of the
    /// innermost frame (the outer ones are borrowed by their calls); the
    /// value written.
    pub fn set(&mut self, path: &str, text: &str) -> Result<Value, String> {
        let (depth, rest) = self.frame_of(0, path.trim());
        if depth != 0 {
            return Err("only the innermost frame's variables can be set".into());
        }
        let (target, ty) = self.resolve(0, rest)?;
        let v = self.m.parse_typed(rest, &ty, None, text)?;
        match target {
            Target::Addr(l) => crate::places::io_write(self.ctx, &l, &v),
            Target::Var(i, steps) => {
                let Some(slot) = self.f.vars.get_mut(i) else {
                    return Err(format!("cannot write `{rest}`"));
                };
                let mut root = std::mem::replace(slot, Value::Bool(false));
                let ok = self.m.write_at(&mut root, &steps, v.clone());
                self.f.vars[i] = root;
                if !ok {
                    return Err(format!("cannot write `{rest}`"));
                }
            }
        }
        Ok(v)
    }

    /// A path that starts with a frame's instance path names a variable of
    /// that frame: the frame and the rest of the path.
    fn frame_of<'t>(&self, depth: usize, text: &'t str) -> (usize, &'t str) {
        for (d, e) in self.stack.iter().rev().enumerate() {
            let n = e.path.len();
            if text.len() > n
                && text.is_char_boundary(n)
                && text[..n].eq_ignore_ascii_case(&e.path)
                && text[n..].starts_with('.')
            {
                return (d, &text[n + 1..]);
            }
        }
        (depth, text)
    }

    /// Where a path of frame `depth` leads, and the type found there.
    fn resolve(&self, depth: usize, text: &str) -> Result<(Target, Ty), String> {
        if text.starts_with('%') {
            let l = il_codegen::ir::parse_address(text)?;
            let ty = Ty::Elem(l.elem);
            return Ok((Target::Addr(l), ty));
        }
        let (e, _, _) = self.frame(depth).ok_or("no such frame")?;
        let pou = &self.m.prog.pous[e.pou];
        let (root, parts) = crate::host::split(text)?;
        let rooted = il_codegen::ir::path::resolve_var(
            &self.m.prog,
            pou,
            (&root, &parts),
            text,
            il_codegen::ir::path::Scope::All,
            |hint| format!("no variable `{root}` in {}{hint}", pou.name),
        )?;
        Ok(match rooted {
            // A located variable lives in the process image.
            il_codegen::ir::path::Rooted::Located(l, ty, _) => (Target::Addr(l), ty),
            il_codegen::ir::path::Rooted::Var(i, r) => {
                (Target::Var(i, crate::host::steps_of(r.steps)), r.ty)
            }
        })
    }

    /// The members of a value of type `ty`: an FB instance's variables, a
    /// standard block's inputs and outputs, a structure's fields, an
    /// array's elements (named by their subscripts); empty for the others.
    pub fn members(&self, v: &Value, ty: &Ty) -> Vec<Shown> {
        members(self.m, v, ty)
    }
}

/// [`Here::members`].
fn members(m: &Machine, v: &Value, ty: &Ty) -> Vec<Shown> {
    match (v, ty) {
        (Value::Fb(inst), _) => {
            let pou = &m.prog.pous[inst.pou];
            pou.vars
                .iter()
                .zip(&inst.vars)
                .filter(|(d, _)| crate::held(d))
                .map(|(d, x)| Shown {
                    name: d.name.clone(),
                    value: x.clone(),
                    ty: d.ty.to_string(),
                })
                .collect()
        }
        (Value::StdFb(b), _) => b
            .fields()
            .into_iter()
            .map(|(n, x)| Shown {
                name: n.to_string(),
                ty: type_of_value(&x),
                value: x,
            })
            .collect(),
        (Value::Struct(s), Ty::Struct(n)) => {
            let types: Vec<Ty> = match m.type_def(n) {
                Ok(TypeDef::Struct { fields, .. }) => fields.iter().map(|f| f.ty.clone()).collect(),
                _ => Vec::new(),
            };
            s.fields
                .iter()
                .enumerate()
                .map(|(k, (n, x))| Shown {
                    name: n.clone(),
                    value: x.clone(),
                    ty: types
                        .get(k)
                        .map_or_else(|| type_of_value(x), |t| t.to_string()),
                })
                .collect()
        }
        (Value::Array(items), Ty::Array(a)) => items
            .iter()
            .enumerate()
            .map(|(k, x)| Shown {
                name: subscripts(&a.dims, k),
                value: x.clone(),
                ty: a.elem.to_string(),
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// `[2, 3]`: the subscripts of flat (row-major) element `k` of an array
/// with these bounds.
pub(crate) fn subscripts(dims: &[(i64, i64)], mut k: usize) -> String {
    let mut subs = vec![0i64; dims.len()];
    for (d, &(lo, hi)) in dims.iter().enumerate().rev() {
        let n = (hi - lo + 1).max(1) as usize;
        subs[d] = lo + (k % n) as i64;
        k /= n;
    }
    let s: Vec<String> = subs.iter().map(|x| x.to_string()).collect();
    format!("[{}]", s.join(", "))
}

/// The IEC type of a value whose declaration is not at hand (a standard
/// block's members carry their type in the value).
pub fn type_of_value(v: &Value) -> String {
    use il_codegen::ir::types::Elem;
    match v {
        Value::Bool(_) => "BOOL".into(),
        Value::Int(_, e) | Value::Time(_, e) => e.name().into(),
        Value::Real(_) => Elem::REAL.name().into(),
        Value::LReal(_) => Elem::LREAL.name().into(),
        Value::Str { wide, .. } => if *wide { "WSTRING" } else { "STRING" }.into(),
        Value::Array(_) => "ARRAY".into(),
        Value::Enum { ty, .. } => ty.clone(),
        Value::Struct(s) => s.ty.clone(),
        Value::Fb(_) => "FUNCTION_BLOCK".into(),
        Value::StdFb(b) => b.name().into(),
    }
}

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
            if let Some(top) = self.dbg.0.as_mut().and_then(|d| d.stack.last_mut()) {
                match &s.op {
                    Op::SetCr { cr, .. } => top.cr = CrNow::Slot(*cr),
                    Op::CallFb(_) => top.cr = CrNow::AfterCal(s.line),
                    _ => {}
                }
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
        let stack = std::mem::take(&mut d.stack);
        let globals = std::mem::take(&mut d.globals);
        let mut here = Here {
            m: self,
            f,
            ctx,
            stack: &stack,
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
