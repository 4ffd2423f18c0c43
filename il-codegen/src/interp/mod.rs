//! The reference interpreter: runs the checked program (after semantic
//! analysis, before emission) directly, following `docs/semantics.md` and
//! giving the same results as the generated Rust: wrapping integers, DIV/MOD by zero
//! → 0 with a `DivisionByZero` fault, index out of range → default value with
//! an `IndexOutOfRange` fault, the real il-std blocks, R_EDGE/F_EDGE memory,
//! FUNCTION outputs as out-parameters, EN/ENO.
//!
//! ```
//! use il_codegen::{diag::SourceFile, interp::{Machine, Value}};
//! let src = "PROGRAM P\nVAR n : INT; END_VAR\nLD n\nADD 1\nST n\nEND_PROGRAM\n";
//! let prog = il_codegen::interp::load(&SourceFile::new("p.il", src)).unwrap();
//! let mut m = Machine::new(&prog, "P").unwrap();
//! let mut ctx = il_std::Cycle::new();
//! m.scan(&mut ctx).unwrap();
//! m.scan(&mut ctx).unwrap();
//! assert_eq!(m.get("n"), Some(Value::Int(2, il_codegen::sema::types::Elem::INT)));
//! ```

mod stdfb;
mod stdfn;
mod value;

/// The runtime the interpreter runs on (for front ends without their own dependency).
pub use il_std;
pub use stdfb::StdFb;
pub use value::{Instance, Value, fmt_dur};

use crate::ast::{Edge, PouKind, VarKind};
use crate::diag::{SourceFile, has_errors};
use crate::sema::ir::{
    BinOp, CheckedPou, Condition, Expr, Init, Loc, Op, PathElem, Place, Program, Root, Stmt,
    Value as IrValue,
};
use crate::sema::types::{Elem, Ty};
use il_std::{Cycle, FaultKind};
use value::wrap;

/// Instructions one scan may execute before the interpreter gives up (an
/// endless IL loop would hang the PLC too; here it is an error).
pub const STEP_LIMIT: u64 = 50_000_000;

/// Parse and check one source file; the error is the rendered diagnostics.
pub fn load(file: &SourceFile) -> Result<Program, String> {
    let (unit, mut diags) = crate::syntax::parse(file);
    if !has_errors(&diags) {
        let (prog, d) = crate::sema::check(file, &unit);
        diags.extend(d);
        if !has_errors(&diags) {
            return Ok(prog);
        }
    }
    let msgs: Vec<String> = diags
        .iter()
        .filter(|d| d.severity == crate::diag::Severity::Error)
        .map(|d| crate::diag::render::render_short(file, d))
        .collect();
    Err(msgs.join("\n"))
}

/// A program (or function block) instance ready to scan.
#[derive(Clone, Debug)]
pub struct Machine {
    prog: std::sync::Arc<Program>,
    /// POU names as `&'static str` for `Cycle::fault` (leaked once per machine).
    names: Vec<&'static str>,
    inst: Instance,
    steps: u64,
}

struct Frame {
    pou: usize,
    vars: Vec<Value>,
    /// The edge seen in this call, for R_EDGE/F_EDGE inputs.
    edges: Vec<Option<bool>>,
    cr: Vec<Value>,
    saves: Vec<Value>,
    ret: Value,
}

/// A resolved step of a place's path.
enum Step {
    Field(String),
    /// Flat index, or `None` when a subscript is out of range.
    Index(Option<usize>),
}

fn io_area(l: &Loc) -> il_std::Area {
    match l.area {
        crate::ast::Area::Input => il_std::Area::Input,
        crate::ast::Area::Output => il_std::Area::Output,
        crate::ast::Area::Memory => il_std::Area::Memory,
    }
}

fn io_read(ctx: &Cycle, l: &Loc) -> Value {
    let (a, b) = (io_area(l), l.byte);
    if let Some(bit) = l.bit {
        return Value::Bool(ctx.io.bit(a, b, bit));
    }
    let e = l.elem;
    match e {
        Elem::BYTE | Elem::USINT => Value::Int(ctx.io.byte(a, b) as i128, e),
        Elem::SINT => Value::Int(ctx.io.byte(a, b) as i8 as i128, e),
        Elem::WORD | Elem::UINT => Value::Int(ctx.io.word(a, b) as i128, e),
        Elem::INT => Value::Int(ctx.io.word(a, b) as i16 as i128, e),
        Elem::DWORD | Elem::UDINT => Value::Int(ctx.io.dword(a, b) as i128, e),
        Elem::DINT => Value::Int(ctx.io.dword(a, b) as i32 as i128, e),
        Elem::REAL => Value::Real(f32::from_bits(ctx.io.dword(a, b))),
        Elem::LWORD | Elem::ULINT => Value::Int(ctx.io.lword(a, b) as i128, e),
        Elem::LINT => Value::Int(ctx.io.lword(a, b) as i64 as i128, e),
        _ => Value::LReal(f64::from_bits(ctx.io.lword(a, b))),
    }
}

fn io_write(ctx: &mut Cycle, l: &Loc, v: &Value) {
    let (a, b) = (io_area(l), l.byte);
    if let Some(bit) = l.bit {
        ctx.io.set_bit(a, b, bit, v.as_bool());
        return;
    }
    match (l.elem, v) {
        (Elem::REAL, Value::Real(f)) => ctx.io.set_dword(a, b, f.to_bits()),
        (Elem::LREAL, Value::LReal(f)) => ctx.io.set_lword(a, b, f.to_bits()),
        (e, v) => {
            let x = match v {
                Value::Int(x, _) => *x,
                other => other.as_i64() as i128,
            };
            match value::bits(e) {
                8 => ctx.io.set_byte(a, b, x as u8),
                16 => ctx.io.set_word(a, b, x as u16),
                32 => ctx.io.set_dword(a, b, x as u32),
                _ => ctx.io.set_lword(a, b, x as u64),
            }
        }
    }
}

fn find_var(pou: &CheckedPou, name: &str) -> Option<usize> {
    pou.vars.iter().position(|v| v.name == name).or_else(|| {
        pou.vars
            .iter()
            .position(|v| v.name.eq_ignore_ascii_case(name))
    })
}

/// Whether variable `i` is memory of the instance. A VAR_EXTERNAL is too:
/// a PROGRAM run alone keeps its own copy of the global, and a function
/// block gets the caller's value copied in and out around every call.
fn in_self(pou: &CheckedPou, i: usize) -> bool {
    let v = &pou.vars[i];
    pou.kind != PouKind::Function
        && !matches!(v.kind, VarKind::Temp | VarKind::InOut)
        && v.location.is_none()
}

/// Names of the variables of `pou` of kind `kind` (located ones excluded).
fn names_of(pou: &CheckedPou, kind: VarKind) -> Vec<String> {
    pou.vars
        .iter()
        .filter(|v| v.kind == kind && v.location.is_none())
        .map(|v| v.name.clone())
        .collect()
}

fn cond_holds(c: &Option<bool>, want: bool) -> bool {
    c.is_none_or(|b| b == want)
}

impl Machine {
    /// An instance of the PROGRAM or FUNCTION_BLOCK `name` (case-insensitive)
    /// with its declared initial values.
    pub fn new(prog: &Program, name: &str) -> Result<Machine, String> {
        let names = prog
            .pous
            .iter()
            .map(|p| &*Box::leak(p.name.clone().into_boxed_str()))
            .collect();
        let mut m = Machine {
            prog: std::sync::Arc::new(prog.clone()),
            names,
            inst: Instance {
                pou: 0,
                vars: Vec::new(),
                edge_mem: Vec::new(),
            },
            steps: 0,
        };
        let Some(pou) = m
            .prog
            .pous
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name) && p.kind != PouKind::Function)
        else {
            let avail: Vec<&str> = m
                .prog
                .pous
                .iter()
                .filter(|p| p.kind != PouKind::Function)
                .map(|p| p.name.as_str())
                .collect();
            return Err(format!(
                "no PROGRAM or FUNCTION_BLOCK named `{name}` (there is {})",
                if avail.is_empty() {
                    "none".to_string()
                } else {
                    avail.join(", ")
                }
            ));
        };
        m.inst = m.new_instance(pou)?;
        Ok(m)
    }

    /// The POU this machine runs.
    pub fn pou(&self) -> &CheckedPou {
        &self.prog.pous[self.inst.pou]
    }

    /// Names of the instance's variables (not temporaries), as declared.
    pub fn var_names(&self) -> Vec<String> {
        let pou = self.pou();
        (0..pou.vars.len())
            .filter(|&i| in_self(pou, i))
            .map(|i| pou.vars[i].name.clone())
            .collect()
    }

    /// Every variable of the instance with its value, in declaration order.
    pub fn vars(&self) -> Vec<(String, Value)> {
        let pou = self.pou();
        (0..pou.vars.len())
            .filter(|&i| in_self(pou, i))
            .map(|i| (pou.vars[i].name.clone(), self.inst.vars[i].clone()))
            .collect()
    }

    /// Read a variable, or a member with a dotted path (`t1.Q`, `sub.x`).
    pub fn get(&self, name: &str) -> Option<Value> {
        let mut parts = name.split('.');
        let pou = self.pou();
        let i = find_var(pou, parts.next()?)?;
        if !in_self(pou, i) {
            return None;
        }
        let mut v = self.inst.vars[i].clone();
        for f in parts {
            v = self.field(&v, f)?;
        }
        Some(v)
    }

    /// The declared type of a variable or dotted member.
    pub fn type_of(&self, name: &str) -> Option<Ty> {
        let mut parts = name.split('.');
        let mut pou = self.pou();
        let i = find_var(pou, parts.next()?)?;
        let mut ty = pou.vars[i].ty.clone();
        for f in parts {
            let Ty::Fb(fb) = &ty else { return None };
            if let Some(p) = self
                .prog
                .pous
                .iter()
                .find(|p| p.name.eq_ignore_ascii_case(fb))
            {
                pou = p;
                ty = pou.vars[find_var(pou, f)?].ty.clone();
            } else {
                ty = match StdFb::new(&fb.to_ascii_uppercase())?.get(f)? {
                    Value::Bool(_) => Ty::BOOL,
                    Value::Int(_, e) | Value::Time(_, e) => Ty::Elem(e),
                    _ => return None,
                };
            }
        }
        Some(ty)
    }

    /// Write a variable or dotted member; the value must have its type.
    pub fn set(&mut self, name: &str, v: Value) -> Result<(), String> {
        let ty = self
            .type_of(name)
            .ok_or_else(|| format!("no variable `{name}` in {}", self.pou().name))?;
        let want = self.default_of(&ty)?;
        if std::mem::discriminant(&want) != std::mem::discriminant(&v)
            || matches!((&want, &v), (Value::Int(_, a), Value::Int(_, b)) if a != b)
            || matches!((&want, &v), (Value::Time(_, a), Value::Time(_, b)) if a != b)
        {
            return Err(format!("`{name}` is {ty}, not {}", v.display()));
        }
        let mut parts: Vec<&str> = name.split('.').collect();
        let first = parts.remove(0);
        let i = find_var(self.pou(), first).ok_or_else(|| format!("no variable `{name}`"))?;
        let steps: Vec<Step> = parts.iter().map(|f| Step::Field(f.to_string())).collect();
        let mut root = std::mem::replace(&mut self.inst.vars[i], Value::Bool(false));
        let ok = self.write_at(&mut root, &steps, v);
        self.inst.vars[i] = root;
        if ok {
            Ok(())
        } else {
            Err(format!("cannot write `{name}`"))
        }
    }

    /// Parse `text` as a value of the type of variable `name` (IEC literal
    /// forms: `TRUE`, `42`, `-1.5`, `T#10ms`, `16#FF`, `'text'`).
    pub fn parse_value(&self, name: &str, text: &str) -> Result<Value, String> {
        let ty = self
            .type_of(name)
            .ok_or_else(|| format!("no variable `{name}` in {}", self.pou().name))?;
        parse_literal(&ty, text).ok_or_else(|| format!("`{text}` is not a valid {ty} value"))
    }

    /// One scan (one call of the instance).
    pub fn scan(&mut self, ctx: &mut Cycle) -> Result<(), String> {
        self.steps = 0;
        let mut inst = std::mem::replace(
            &mut self.inst,
            Instance {
                pou: 0,
                vars: Vec::new(),
                edge_mem: Vec::new(),
            },
        );
        let r = self.call_instance(&mut inst, ctx);
        self.inst = inst;
        r
    }

    /// Call the user FUNCTION `name` with its inputs in declaration order:
    /// its result and its outputs in declaration order.
    pub fn call_function_named(
        &mut self,
        name: &str,
        args: Vec<Value>,
        ctx: &mut Cycle,
    ) -> Result<(Value, Vec<Value>), String> {
        let p = self
            .prog
            .pous
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name) && p.kind == PouKind::Function)
            .ok_or_else(|| format!("no FUNCTION named `{name}`"))?;
        self.steps = 0;
        let (r, outs, _) = self.call_function(p, args, Vec::new(), ctx)?;
        Ok((r, outs))
    }

    fn new_instance(&self, pou: usize) -> Result<Instance, String> {
        let p = &self.prog.pous[pou];
        let vars = p
            .vars
            .iter()
            .map(|v| self.init_of(&v.ty, v.init.as_ref()))
            .collect::<Result<_, _>>()?;
        Ok(Instance {
            pou,
            vars,
            edge_mem: vec![false; p.vars.len()],
        })
    }

    fn default_of(&self, t: &Ty) -> Result<Value, String> {
        Ok(match t {
            Ty::Struct(n) | Ty::Enum(n) => {
                return Err(format!(
                    "user type `{n}`: TYPE declarations are not supported by the interpreter yet"
                ));
            }
            Ty::Elem(_) | Ty::Str { .. } => Value::from_const(&crate::sema::default_const(t)),
            Ty::Array { dims, elem } => {
                let n: i64 = dims.iter().map(|(lo, hi)| hi - lo + 1).product();
                let d = self.default_of(elem)?;
                Value::Array(vec![d; n.max(0) as usize])
            }
            Ty::Fb(name) => {
                if let Some(b) = StdFb::new(&name.to_ascii_uppercase()) {
                    Value::StdFb(Box::new(b))
                } else if let Some(p) = self
                    .prog
                    .pous
                    .iter()
                    .position(|p| p.name.eq_ignore_ascii_case(name))
                {
                    Value::Fb(Box::new(self.new_instance(p)?))
                } else {
                    return Err(format!(
                        "the function block {name} is not supported by the interpreter"
                    ));
                }
            }
        })
    }

    fn init_of(&self, t: &Ty, init: Option<&Init>) -> Result<Value, String> {
        match (init, t) {
            (Some(Init::Const(c)), _) => Ok(Value::from_const(c)),
            (Some(Init::Array(items)), Ty::Array { elem, .. }) => {
                let mut v = self.default_of(t)?;
                if let Value::Array(slots) = &mut v {
                    let d = self.default_of(elem)?;
                    let mut values = items
                        .iter()
                        .flat_map(|(n, c)| std::iter::repeat_n(c, *n))
                        .map(Value::from_const);
                    for s in slots.iter_mut() {
                        *s = values.next().unwrap_or_else(|| d.clone());
                    }
                }
                Ok(v)
            }
            (Some(Init::Fields(fields)), Ty::Fb(_)) => {
                let mut v = self.default_of(t)?;
                for (n, c) in fields {
                    if !self.write_at(&mut v, &[Step::Field(n.clone())], Value::from_const(c)) {
                        return Err(format!("cannot initialise field {n}"));
                    }
                }
                Ok(v)
            }
            _ => self.default_of(t),
        }
    }

    fn field(&self, v: &Value, f: &str) -> Option<Value> {
        match v {
            Value::Fb(inst) => {
                let i = find_var(&self.prog.pous[inst.pou], f)?;
                Some(inst.vars[i].clone())
            }
            Value::StdFb(b) => b.get(f),
            _ => None,
        }
    }

    fn read_at(&self, v: &Value, steps: &[Step]) -> Option<Value> {
        let Some((first, rest)) = steps.split_first() else {
            return Some(v.clone());
        };
        match (first, v) {
            (Step::Field(f), Value::Fb(inst)) => {
                let i = find_var(&self.prog.pous[inst.pou], f)?;
                self.read_at(&inst.vars[i], rest)
            }
            (Step::Field(f), Value::StdFb(b)) if rest.is_empty() => b.get(f),
            (Step::Index(Some(k)), Value::Array(items)) => self.read_at(items.get(*k)?, rest),
            _ => None,
        }
    }

    fn write_at(&self, v: &mut Value, steps: &[Step], new: Value) -> bool {
        let Some((first, rest)) = steps.split_first() else {
            *v = new;
            return true;
        };
        match (first, v) {
            (Step::Field(f), Value::Fb(inst)) => {
                let Some(i) = find_var(&self.prog.pous[inst.pou], f) else {
                    return false;
                };
                self.write_at(&mut inst.vars[i], rest, new)
            }
            (Step::Field(f), Value::StdFb(b)) if rest.is_empty() => b.set(f, &new),
            (Step::Index(Some(k)), Value::Array(items)) => match items.get_mut(*k) {
                Some(slot) => self.write_at(slot, rest, new),
                None => false,
            },
            _ => false,
        }
    }

    fn fault(&self, ctx: &mut Cycle, f: &Frame, kind: FaultKind, line: u32) {
        ctx.fault(kind, self.names[f.pou], line);
    }

    // ---- evaluation -------------------------------------------------------

    fn cr_slot(&self, f: &Frame, t: &Ty) -> Result<usize, String> {
        self.prog.pous[f.pou]
            .cr_types
            .iter()
            .position(|c| c == t)
            .ok_or_else(|| format!("internal: no CR of type {t}"))
    }

    fn value(
        &self,
        f: &mut Frame,
        v: &IrValue,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Value, String> {
        Ok(match v {
            IrValue::Cr(t) => f.cr[self.cr_slot(f, t)?].clone(),
            IrValue::Const(c) => Value::from_const(c),
            IrValue::Read(p) => self.read(f, p, ctx, line)?,
            IrValue::Saved(i, _) => f
                .saves
                .get(*i)
                .cloned()
                .ok_or("internal: no such save slot")?,
        })
    }

    /// Resolve a place's path, evaluating every subscript first (as the emitter does).
    fn steps(
        &self,
        f: &mut Frame,
        p: &Place,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<(Vec<Step>, bool), String> {
        let mut steps = Vec::new();
        let mut ok = true;
        for e in &p.path {
            match e {
                PathElem::Field(n) => steps.push(Step::Field(n.clone())),
                PathElem::Index { dims, subs } => {
                    let mut flat: Option<usize> = Some(0);
                    for (s, (lo, hi)) in subs.iter().zip(dims) {
                        let v = self.value(f, s, ctx, line)?;
                        let size = (hi - lo + 1).max(0) as usize;
                        let k = usize::try_from(v.as_i64().wrapping_sub(*lo))
                            .ok()
                            .filter(|k| *k < size);
                        flat = match (flat, k) {
                            (Some(acc), Some(k)) => Some(acc * size + k),
                            _ => None,
                        };
                    }
                    ok &= flat.is_some();
                    steps.push(Step::Index(flat));
                }
            }
        }
        Ok((steps, ok))
    }

    fn root_value<'a>(&self, f: &'a mut Frame, r: &Root) -> Result<&'a mut Value, String> {
        match r {
            Root::Ret => Ok(&mut f.ret),
            Root::Var(i) => f
                .vars
                .get_mut(*i)
                .ok_or_else(|| "internal: bad variable".into()),
            Root::Addr(_) => Err("internal: process image is not a variable".into()),
        }
    }

    fn read(&self, f: &mut Frame, p: &Place, ctx: &mut Cycle, line: u32) -> Result<Value, String> {
        if let Root::Addr(l) = &p.root {
            return Ok(io_read(ctx, l));
        }
        if let Root::Var(i) = &p.root
            && let Some(e) = f.edges.get(*i).copied().flatten()
        {
            return Ok(Value::Bool(e));
        }
        let (steps, ok) = self.steps(f, p, ctx, line)?;
        let root = self.root_value(f, &p.root)?;
        let got = if ok { self.read_at(root, &steps) } else { None };
        match got {
            Some(v) => Ok(v),
            None if !ok => {
                self.fault(ctx, f, FaultKind::IndexOutOfRange, line);
                self.default_of(&p.ty)
            }
            None => Err(format!("internal: cannot read {p:?}")),
        }
    }

    fn write(
        &self,
        f: &mut Frame,
        p: &Place,
        v: Value,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<(), String> {
        if let Root::Addr(l) = &p.root {
            io_write(ctx, l, &v);
            return Ok(());
        }
        if let Root::Var(i) = &p.root
            && f.edges.get(*i).copied().flatten().is_some()
        {
            f.edges[*i] = Some(v.as_bool());
            return Ok(());
        }
        let (steps, ok) = self.steps(f, p, ctx, line)?;
        if !ok {
            self.fault(ctx, f, FaultKind::IndexOutOfRange, line);
            return Ok(());
        }
        let root = self.root_value(f, &p.root)?;
        let mut tmp = std::mem::replace(root, Value::Bool(false));
        let done = self.write_at(&mut tmp, &steps, v);
        *self.root_value(f, &p.root)? = tmp;
        if done {
            Ok(())
        } else {
            Err(format!("internal: cannot write {p:?}"))
        }
    }

    fn expr(
        &mut self,
        f: &mut Frame,
        e: &Expr,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Value, String> {
        match e {
            Expr::Value(v) => self.value(f, v, ctx, line),
            Expr::Not(v) => Ok(stdfn::not(&self.value(f, v, ctx, line)?)),
            Expr::Bin {
                op,
                lhs,
                rhs,
                negate_rhs,
                ty,
            } => {
                let int = ty.elem().is_some_and(|e| e.is_int() || e.is_bitstring());
                if int && matches!(op, BinOp::Div | BinOp::Mod) {
                    // `{ let d = rhs; if d == 0 { fault; 0 } else { lhs op d } }`
                    let mut r = self.value(f, rhs, ctx, line)?;
                    if *negate_rhs {
                        r = stdfn::not(&r);
                    }
                    let (Value::Int(d, e), true) = (&r, true) else {
                        return Err("internal: DIV operand".into());
                    };
                    if *d == 0 {
                        self.fault(ctx, f, FaultKind::DivisionByZero, line);
                        return Ok(Value::Int(0, *e));
                    }
                    let l = self.value(f, lhs, ctx, line)?;
                    let Value::Int(x, _) = l else {
                        return Err("internal: DIV operand".into());
                    };
                    return Ok(Value::Int(
                        stdfn::int_divmod(*op == BinOp::Div, x, *d, *e).unwrap_or(0),
                        *e,
                    ));
                }
                let l = self.value(f, lhs, ctx, line)?;
                let mut r = self.value(f, rhs, ctx, line)?;
                if *negate_rhs {
                    r = stdfn::not(&r);
                }
                let name = op.name();
                stdfn::plain(name, &[l, r], ty)
            }
            Expr::TimeScale {
                div,
                time,
                lhs,
                num,
                rhs,
            } => {
                let l = self.value(f, lhs, ctx, line)?;
                let r = self.value(f, rhs, ctx, line)?;
                let t = match l {
                    Value::Time(t, _) => t,
                    _ => return Err("internal: TIME operand".into()),
                };
                if *time == Elem::TIME {
                    // As the emitter: the operator is MUL_TIME / DIV_TIME.
                    let (v, bad) = time_scale(*div, t, &r, *num);
                    if bad {
                        self.fault(ctx, f, FaultKind::DivisionByZero, line);
                    }
                    return Ok(Value::Time(v, *time));
                }
                let v = match (div, num.is_real()) {
                    (false, false) => t.wrapping_mul(r.as_i64()),
                    (false, true) => ((t as f64) * r.as_f64()) as i64,
                    (true, true) => ((t as f64) / r.as_f64()) as i64,
                    (true, false) => {
                        let d = r.as_i64();
                        if d == 0 {
                            self.fault(ctx, f, FaultKind::DivisionByZero, line);
                            0
                        } else {
                            t.wrapping_div(d)
                        }
                    }
                };
                Ok(Value::Time(v, *time))
            }
            Expr::CallUser {
                en,
                eno,
                ret,
                name,
                args,
                inouts,
                out_types: _,
                outputs,
            } => {
                if let Some(en) = en
                    && !self.value(f, en, ctx, line)?.as_bool()
                {
                    for (k, place, neg) in outputs {
                        if Some(*k) == *eno {
                            self.write(f, place, Value::Bool(*neg), ctx, line)?;
                        }
                    }
                    return self.default_of(ret);
                }
                let mut vals = Vec::with_capacity(args.len());
                for a in args {
                    vals.push(self.value(f, a, ctx, line)?);
                }
                let p = self
                    .prog
                    .pous
                    .iter()
                    .position(|p| p.name == *name && p.kind == PouKind::Function)
                    .or_else(|| {
                        self.prog.pous.iter().position(|p| {
                            p.name.eq_ignore_ascii_case(name) && p.kind == PouKind::Function
                        })
                    })
                    .ok_or_else(|| format!("internal: no FUNCTION {name}"))?;
                let mut refs = Vec::with_capacity(inouts.len());
                for place in inouts {
                    refs.push(self.read(f, place, ctx, line)?);
                }
                let (r, outs, back) = self.call_function(p, vals, refs, ctx)?;
                // VAR_IN_OUT: copy-in/copy-out, as the emitter does for places it cannot borrow.
                for (place, v) in inouts.iter().zip(back) {
                    self.write(f, place, v, ctx, line)?;
                }
                for (k, place, neg) in outputs {
                    let v = outs.get(*k).cloned().ok_or("internal: output index")?;
                    let v = if *neg { stdfn::not(&v) } else { v };
                    self.write(f, place, v, ctx, line)?;
                }
                Ok(r)
            }
            Expr::CallStd {
                call, args, ret, ..
            } => {
                let mut vals = Vec::with_capacity(args.len());
                for a in args {
                    vals.push(self.value(f, a, ctx, line)?);
                }
                let mut faults = Vec::new();
                let r = stdfn::call(call, &vals, ret, &mut |k| faults.push(k))?;
                for k in faults {
                    self.fault(ctx, f, k, line);
                }
                Ok(r)
            }
        }
    }

    fn condition(
        &self,
        f: &mut Frame,
        c: &Condition,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<bool, String> {
        match c {
            None => Ok(true),
            Some((v, want)) => {
                let b = self.value(f, v, ctx, line)?.as_bool();
                Ok(cond_holds(&Some(b), *want))
            }
        }
    }

    // ---- execution --------------------------------------------------------

    fn run(&mut self, f: &mut Frame, ctx: &mut Cycle) -> Result<(), String> {
        let pou = f.pou;
        let prog = self.prog.clone();
        let body: &[Stmt] = &prog.pous[pou].body;
        let mut labels = vec![usize::MAX; self.prog.pous[pou].label_count];
        for (i, s) in body.iter().enumerate() {
            if let Op::Label(l) = s.op {
                labels[l] = i;
            }
        }
        let mut pc = 0;
        while let Some(s) = body.get(pc) {
            self.steps += 1;
            if self.steps > STEP_LIMIT {
                return Err(format!(
                    "{}: more than {STEP_LIMIT} instructions in one scan (endless loop?) at IL line {}",
                    self.prog.pous[pou].name, s.line
                ));
            }
            let line = s.line;
            pc += 1;
            match &s.op {
                Op::SetCr { ty, expr } => {
                    let v = self.expr(f, expr, ctx, line)?;
                    let slot = self.cr_slot(f, ty)?;
                    f.cr[slot] = v;
                }
                Op::Save { slot, value } => {
                    let v = self.value(f, value, ctx, line)?;
                    if f.saves.len() <= *slot {
                        f.saves.resize(*slot + 1, Value::Bool(false));
                    }
                    f.saves[*slot] = v;
                }
                Op::Store {
                    place,
                    value,
                    negate,
                } => {
                    let mut v = self.value(f, value, ctx, line)?;
                    if *negate {
                        v = stdfn::not(&v);
                    }
                    // As the emitter: a store outside a subrange (an inline
                    // `INT (0..100)`) is skipped and recorded.
                    if let (Some((lo, hi)), Value::Int(x, _)) = (place.range, &v)
                        && !(lo..=hi).contains(x)
                    {
                        self.fault(ctx, f, FaultKind::SubrangeViolation, line);
                        continue;
                    }
                    self.write(f, place, v, ctx, line)?;
                }
                Op::SetIf { place, value, cond } => {
                    if self.value(f, cond, ctx, line)?.as_bool() {
                        self.write(f, place, Value::Bool(*value), ctx, line)?;
                    }
                }
                Op::CallFb {
                    inst,
                    inputs,
                    outputs,
                    inouts,
                    externals,
                    cond,
                } => {
                    if !self.condition(f, cond, ctx, line)? {
                        continue;
                    }
                    let mut ins = Vec::with_capacity(inputs.len());
                    for (n, v) in inputs {
                        ins.push((n.clone(), self.value(f, v, ctx, line)?));
                    }
                    // In-outs and the globals the block uses: copied in, and out after the call.
                    let mut places: Vec<Place> = inouts.clone();
                    for (e, _) in externals {
                        let k = find_var(&self.prog.pous[f.pou], e)
                            .ok_or_else(|| format!("internal: caller has no external {e}"))?;
                        places.push(Place {
                            root: Root::Var(k),
                            path: Vec::new(),
                            ty: self.prog.pous[f.pou].vars[k].ty.clone(),
                            range: None,
                        });
                    }
                    let mut names = match &inst.ty {
                        Ty::Fb(fb) => self
                            .prog
                            .pous
                            .iter()
                            .find(|p| p.name.eq_ignore_ascii_case(fb))
                            .map(|p| names_of(p, VarKind::InOut))
                            .unwrap_or_default(),
                        _ => Vec::new(),
                    };
                    names.extend(externals.iter().map(|(e, _)| e.clone()));
                    let mut refs = Vec::with_capacity(places.len());
                    for (n, p) in names.iter().zip(&places) {
                        refs.push((n.clone(), self.read(f, p, ctx, line)?));
                    }
                    let back = self.call_fb_at(f, inst, ins, refs, ctx, line)?;
                    for (p, v) in places.iter().zip(back) {
                        self.write(f, p, v, ctx, line)?;
                    }
                    for (n, target, neg) in outputs {
                        let mut src = inst.clone();
                        src.path.push(PathElem::Field(n.clone()));
                        let mut v = self.read(f, &src, ctx, line)?;
                        if *neg {
                            v = stdfn::not(&v);
                        }
                        self.write(f, target, v, ctx, line)?;
                    }
                }
                Op::Jump { label, cond } => {
                    if self.condition(f, cond, ctx, line)? {
                        pc = labels
                            .get(*label)
                            .copied()
                            .filter(|p| *p != usize::MAX)
                            .ok_or("internal: jump to a missing label")?;
                    }
                }
                Op::Label(_) | Op::Nop => {}
                Op::Return { cond } => {
                    if self.condition(f, cond, ctx, line)? {
                        break;
                    }
                }
            }
        }
        Ok(())
    }

    /// `CAL inst(inputs)`: set the inputs, then call (a bad subscript faults and skips the call).
    fn call_fb_at(
        &mut self,
        f: &mut Frame,
        inst: &Place,
        ins: Vec<(String, Value)>,
        refs: Vec<(String, Value)>,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Vec<Value>, String> {
        let (steps, ok) = self.steps(f, inst, ctx, line)?;
        // The values to copy back (unchanged if the call does not happen).
        let mut back: Vec<Value> = refs.iter().map(|(_, v)| v.clone()).collect();
        if !ok {
            self.fault(ctx, f, FaultKind::IndexOutOfRange, line);
            return Ok(back);
        }
        let mut b = match self.read_at(self_root(f, &inst.root)?, &steps) {
            Some(v) => v,
            None => return Err("internal: FB instance not found".into()),
        };
        match &mut b {
            Value::StdFb(fb) => {
                for (n, v) in &ins {
                    if !fb.set(n, v) {
                        return Err(format!("internal: cannot set input {n}"));
                    }
                }
                fb.call(ctx);
            }
            Value::Fb(i) => {
                let mut ref_idx = Vec::with_capacity(refs.len());
                for (n, v) in ins.into_iter().chain(refs) {
                    let k = find_var(&self.prog.pous[i.pou], &n)
                        .ok_or_else(|| format!("internal: no input {n}"))?;
                    i.vars[k] = v;
                    ref_idx.push(k);
                }
                self.call_instance(i, ctx)?;
                let skip = ref_idx.len() - back.len();
                for (slot, k) in back.iter_mut().zip(&ref_idx[skip..]) {
                    *slot = i.vars[*k].clone();
                }
            }
            _ => return Err("internal: CAL of a non-instance".into()),
        }
        let mut root = std::mem::replace(self_root(f, &inst.root)?, Value::Bool(false));
        let done = self.write_at(&mut root, &steps, b);
        *self_root(f, &inst.root)? = root;
        if done {
            Ok(back)
        } else {
            Err("internal: cannot store the instance".into())
        }
    }

    fn call_instance(&mut self, inst: &mut Instance, ctx: &mut Cycle) -> Result<(), String> {
        let pou = inst.pou;
        let p = &self.prog.pous[pou];
        let mut edges = vec![None; p.vars.len()];
        for (i, v) in p.vars.iter().enumerate() {
            if let Some(e) = v.edge
                && in_self(p, i)
            {
                let x = inst.vars[i].as_bool();
                let m = inst.edge_mem[i];
                edges[i] = Some(match e {
                    Edge::Rising => {
                        inst.edge_mem[i] = x;
                        x && !m
                    }
                    Edge::Falling => {
                        inst.edge_mem[i] = !x;
                        !x && !m
                    }
                });
            }
        }
        let mut vars = std::mem::take(&mut inst.vars);
        let temps: Vec<usize> = (0..p.vars.len())
            .filter(|&i| !in_self(p, i) && p.vars[i].kind != VarKind::InOut)
            .collect();
        for i in temps {
            let v = &self.prog.pous[pou].vars[i];
            vars[i] = self.init_of(&v.ty, v.init.as_ref())?;
        }
        let mut f = self.frame(pou, vars, edges)?;
        let r = self.run(&mut f, ctx);
        inst.vars = f.vars;
        r
    }

    fn frame(
        &self,
        pou: usize,
        vars: Vec<Value>,
        edges: Vec<Option<bool>>,
    ) -> Result<Frame, String> {
        let p = &self.prog.pous[pou];
        let cr = p
            .cr_types
            .iter()
            .map(|t| self.default_of(t))
            .collect::<Result<_, _>>()?;
        let saves = p
            .save_types
            .iter()
            .map(|t| self.default_of(t))
            .collect::<Result<_, _>>()?;
        let ret = match &p.ret {
            Some(t) => self.default_of(t)?,
            None => Value::Bool(false),
        };
        Ok(Frame {
            pou,
            vars,
            edges,
            cr,
            saves,
            ret,
        })
    }

    /// Call a user FUNCTION: its result and all its outputs in declaration order.
    fn call_function(
        &mut self,
        pou: usize,
        args: Vec<Value>,
        inouts: Vec<Value>,
        ctx: &mut Cycle,
    ) -> Result<(Value, Vec<Value>, Vec<Value>), String> {
        let p = &self.prog.pous[pou];
        let mut args = args.into_iter();
        let mut inouts = inouts.into_iter();
        let mut vars = Vec::with_capacity(p.vars.len());
        for v in &p.vars {
            vars.push(match v.kind {
                VarKind::Input => args.next().ok_or("internal: missing argument")?,
                VarKind::InOut => inouts.next().ok_or("internal: missing in-out")?,
                _ => self.init_of(&v.ty, v.init.as_ref())?,
            });
        }
        let n = p.vars.len();
        let mut f = self.frame(pou, vars, vec![None; n])?;
        self.run(&mut f, ctx)?;
        let p = &self.prog.pous[pou];
        let outs = p
            .vars
            .iter()
            .zip(f.vars)
            .map(|(v, x)| (v.kind, x))
            .collect::<Vec<_>>();
        let (outs, back): (Vec<_>, Vec<_>) = outs
            .into_iter()
            .filter(|(k, _)| matches!(k, VarKind::Output | VarKind::InOut))
            .partition(|(k, _)| *k == VarKind::Output);
        Ok((
            f.ret,
            outs.into_iter().map(|(_, x)| x).collect(),
            back.into_iter().map(|(_, x)| x).collect(),
        ))
    }
}

fn self_root<'a>(f: &'a mut Frame, r: &Root) -> Result<&'a mut Value, String> {
    match r {
        Root::Ret => Ok(&mut f.ret),
        Root::Var(i) => f
            .vars
            .get_mut(*i)
            .ok_or_else(|| "internal: bad variable".into()),
        Root::Addr(_) => Err("internal: process image is not an instance".into()),
    }
}

/// Parse an IEC literal as a value of type `ty`.
pub fn parse_literal(ty: &Ty, text: &str) -> Option<Value> {
    let t = text.trim();
    match ty {
        Ty::Elem(Elem::BOOL) => match t.to_ascii_uppercase().as_str() {
            "TRUE" | "1" | "BOOL#TRUE" | "BOOL#1" => Some(Value::Bool(true)),
            "FALSE" | "0" | "BOOL#FALSE" | "BOOL#0" => Some(Value::Bool(false)),
            _ => None,
        },
        Ty::Elem(e) if e.is_int() || e.is_bitstring() => {
            let body = match t.split_once('#') {
                Some((pre, rest)) if Elem::from_name(pre) == Some(*e) => rest,
                _ => t,
            };
            let v = il_std::literal::parse_int(body).ok()?;
            let (lo, hi) = e.int_range()?;
            (lo..=hi).contains(&v).then_some(Value::Int(v, *e))
        }
        Ty::Elem(e) if e.is_real() => {
            let body = match t.split_once('#') {
                Some((pre, rest)) if Elem::from_name(pre) == Some(*e) => rest,
                _ => t,
            };
            let v = il_std::literal::parse_real(body).ok()?;
            Some(if *e == Elem::REAL {
                Value::Real(v as f32)
            } else {
                Value::LReal(v)
            })
        }
        Ty::Elem(e @ (Elem::TIME | Elem::LTIME)) => {
            let up = t.to_ascii_uppercase();
            let body = ["LTIME#", "TIME#", "LT#", "T#"]
                .iter()
                .find_map(|p| up.strip_prefix(p).map(|_| &t[p.len()..]))
                .unwrap_or(t);
            il_std::literal::parse_duration(body)
                .ok()
                .map(|ns| Value::Time(ns, *e))
        }
        Ty::Str { wide, len } => {
            let q = if *wide { '"' } else { '\'' };
            let inner = t
                .strip_prefix(q)
                .and_then(|s| s.strip_suffix(q))
                .unwrap_or(t);
            Some(Value::Str {
                units: value::str_units(inner, *wide, *len),
                wide: *wide,
            })
        }
        _ => None,
    }
}

/// Wrapping of an integer into a type, for callers building values by hand.
pub fn int(v: i128, e: Elem) -> Value {
    Value::Int(wrap(v, e), e)
}

/// `MUL_TIME` / `div_time_checked` of il-std with the number in its own Rust
/// type, exactly as generated code calls them.
fn time_scale(div: bool, t: i64, r: &Value, num: Elem) -> (i64, bool) {
    use il_std::func::{MUL_TIME, div_time_checked};
    let t = il_std::TIME(t);
    macro_rules! go {
        ($v:expr) => {
            if div {
                let (v, bad) = div_time_checked(t, $v);
                (v.0, bad)
            } else {
                (MUL_TIME(t, $v).0, false)
            }
        };
    }
    let i = match r {
        Value::Int(v, _) => *v,
        _ => 0,
    };
    match (num, r) {
        (_, Value::Real(x)) => go!(*x),
        (_, Value::LReal(x)) => go!(*x),
        (Elem::SINT, _) => go!(i as i8),
        (Elem::INT, _) => go!(i as i16),
        (Elem::DINT, _) => go!(i as i32),
        (Elem::LINT, _) => go!(i as i64),
        (Elem::USINT | Elem::BYTE, _) => go!(i as u8),
        (Elem::UINT | Elem::WORD, _) => go!(i as u16),
        (Elem::UDINT | Elem::DWORD, _) => go!(i as u32),
        _ => go!(i as u64),
    }
}
