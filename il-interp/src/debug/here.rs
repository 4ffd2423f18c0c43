//! [`Here`]: what a hook sees of a stopped statement — the frames, their
//! current results and variables, paths evaluated through the IR's one
//! path resolver, and writes.

use super::{Cr, CrNow, Entry, FrameInfo, Undefined};
use crate::Frame;
use crate::Machine;
use crate::places::{Step, io_read};
use crate::values::Value;
use il_codegen::ir::types::Ty;
use il_codegen::ir::{CheckedPou, Op, Stmt, Var};
use il_std::{Cycle, Fault};

use super::show::{Shown, members};

/// Where a path leads: a variable of the frame and the steps into it, or
/// the process image.
enum Target {
    Var(usize, Vec<Step>),
    Addr(il_codegen::ir::Loc),
}

/// Where a hooked run is: the statement, the frames and the cycle.
pub struct Here<'a> {
    pub(super) m: &'a Machine,
    pub(super) f: &'a mut Frame,
    pub(super) ctx: &'a mut Cycle,
    pub(super) stack: &'a mut [Entry],
    pub(super) globals: &'a [(String, Value, Ty)],
    pub(super) stmt: &'a Stmt,
    pub(super) pc: usize,
    pub(super) fault: Option<Fault>,
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
    /// The runtime fault the statement just recorded ([`super::Hook::after`]).
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
        Some(match &e.cr {
            CrNow::Unset => Cr::Undefined(Undefined::NothingLoaded),
            CrNow::AfterCal(l) => Cr::Undefined(Undefined::AfterCal(*l)),
            CrNow::Folded => Cr::Undefined(Undefined::Folded),
            CrNow::Literal(v, t) => Cr::Value(v.clone(), t.clone()),
            CrNow::Slot(i) => match (crs.get(*i as usize), pou.cr_types.get(*i as usize)) {
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

    /// Write `text` (an IL literal of the place's type) to a path: of the
    /// innermost frame, or of the frame whose instance path starts it
    /// (`Main.total`); the value written.
    pub fn set(&mut self, path: &str, text: &str) -> Result<Value, String> {
        let (depth, rest) = self.frame_of(0, path.trim());
        self.set_in(depth, rest, text)
    }

    /// Write `text` to a path of frame `depth` (0: innermost). An outer
    /// frame's `Frame` is borrowed by the call it is in: the write shows in
    /// its view now and reaches its variable when that call returns (before
    /// the call's outputs and in-outs are copied back, as a write the
    /// caller made just before them). The instance that frame is calling is
    /// the callee's to write.
    pub fn set_in(&mut self, depth: usize, path: &str, text: &str) -> Result<Value, String> {
        let rest = path.trim();
        let (target, ty) = self.resolve(depth, rest)?;
        let v = self.m.parse_typed(rest, &ty, None, text)?;
        let (i, steps) = match target {
            Target::Addr(l) => {
                crate::places::io_write(self.ctx, &l, &v);
                return Ok(v);
            }
            Target::Var(i, steps) => (i, steps),
        };
        let cannot = || format!("cannot write `{rest}`");
        if depth == 0 {
            let slot = self.f.vars.get_mut(i).ok_or_else(cannot)?;
            if !write(self.m, slot, &steps, &v) {
                return Err(cannot());
            }
            return Ok(v);
        }
        let n = self.stack.len();
        let callee = n.checked_sub(depth).ok_or("no such frame")?;
        let (outer, inner) = self.stack.split_at_mut(callee);
        let e = outer.last_mut().ok_or("no such frame")?;
        if let Some(called) = inner.first()
            && let Some(var) = self.m.prog.pous[e.pou].vars.get(i)
            && calls_into(&e.path, &called.path, &var.name)
        {
            return Err(format!(
                "`{rest}` is in `{}`, which {} is calling: set it in that frame",
                called.path, e.path
            ));
        }
        let slot = e.vars.get_mut(i).ok_or_else(cannot)?;
        if !write(self.m, slot, &steps, &v) {
            return Err(cannot());
        }
        e.pending.push((i, steps, v.clone()));
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

/// Write `v` at `steps` into the variable `slot`.
fn write(m: &Machine, slot: &mut Value, steps: &[Step], v: &Value) -> bool {
    let mut root = std::mem::replace(slot, Value::Bool(false));
    let ok = m.write_at(&mut root, steps, v.clone());
    *slot = root;
    ok
}

/// Whether frame `caller`'s variable `var` holds the instance of frame
/// `callee` (`Main` calling `Main.pumps[2].edge`, variable `pumps`).
fn calls_into(caller: &str, callee: &str, var: &str) -> bool {
    let Some(rel) = callee
        .get(caller.len()..)
        .filter(|_| callee.is_char_boundary(caller.len()))
        .and_then(|r| r.strip_prefix('.'))
    else {
        return false;
    };
    let root = rel.split(['.', '[']).next().unwrap_or("");
    root.eq_ignore_ascii_case(var)
}
