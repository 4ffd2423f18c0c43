//! Calls: user FUNCTIONs (with EN/ENO, outputs and in-outs), standard
//! functions, `CAL` of function block instances, and the frames they run in.

use crate::places::self_root;
use crate::values::{Instance, Value};
use crate::{Frame, Machine, held, stdfn};
use il_codegen::ir::types::Ty;
use il_codegen::ir::{Edge, PouKind, VarKind};
use il_codegen::ir::{Expr, Op, PathElem, Place, Root, Storage};
use il_std::{Cycle, FaultKind};

impl Machine {
    /// A call of a user FUNCTION in an expression.
    pub(crate) fn call_user(
        &mut self,
        f: &mut Frame,
        call: &Expr,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Value, String> {
        let Expr::CallUser(c) = call else {
            return Err("internal: not a user function call".into());
        };
        let il_codegen::ir::UserCall {
            en,
            eno,
            ret,
            name,
            args,
            inouts,
            out_types: _,
            outputs,
        } = &**c;
        if let Some(en) = en
            && !self.value(f, en, ctx, line)?.as_bool()
        {
            for (k, place, neg, w) in outputs {
                if Some(*k) == *eno {
                    let v = widened(Value::Bool(*neg), w)?;
                    self.write(f, place, v, ctx, line)?;
                }
            }
            return self.default_of(ret);
        }
        let mut vals = Vec::with_capacity(args.len());
        for a in args {
            vals.push(self.value(f, a, ctx, line)?);
        }
        let p =
            self.prog
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
        if self.dbg.on() {
            self.dbg_call(f, None, name);
        }
        let (r, outs, back) = self.call_function(p, vals, refs, ctx)?;
        if self.dbg.on() {
            self.dbg_return(f);
        }
        // VAR_IN_OUT: copy-in/copy-out (`UserCall::inouts`).
        for (place, v) in inouts.iter().zip(back) {
            self.write(f, place, v, ctx, line)?;
        }
        for (k, place, neg, w) in outputs {
            let v = outs.get(*k).cloned().ok_or("internal: output index")?;
            let v = widened(if *neg { stdfn::not(&v) } else { v }, w)?;
            let v = self.cut_string(f, v, &place.ty, ctx, line);
            self.write(f, place, v, ctx, line)?;
        }
        Ok(r)
    }

    /// A call of a standard function in an expression (its faults recorded at `line`).
    pub(crate) fn call_std(
        &mut self,
        f: &mut Frame,
        e: &Expr,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Value, String> {
        let Expr::CallStd(c) = e else {
            return Err("internal: not a standard function call".into());
        };
        let il_codegen::ir::StdFnCall {
            sig,
            en,
            call,
            args,
            ret,
            fault,
            arg_types: _,
        } = &**c;
        // EN FALSE: not evaluated, the result is the type's default.
        if let Some(en) = en
            && !self.value(f, en, ctx, line)?.as_bool()
        {
            return self.default_of(ret);
        }
        let mut vals = Vec::with_capacity(args.len());
        for a in args {
            vals.push(self.value(f, a, ctx, line)?);
        }
        let mut faults = Vec::new();
        let r = stdfn::call(call, &vals, ret, (*fault, sig), &mut |k| faults.push(k))?;
        for k in faults {
            self.fault(ctx, f, k, line);
        }
        Ok(r)
    }

    /// `CAL inst(...)`: inputs, in-outs and externals copied in, the call, outputs copied out.
    pub(crate) fn cal(
        &mut self,
        f: &mut Frame,
        op: &Op,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<(), String> {
        let Op::CallFb(c) = op else {
            return Err("internal: not a CAL".into());
        };
        let il_codegen::ir::FbCall {
            inst,
            inputs,
            outputs,
            inouts,
            inouts_in_instance,
            externals,
            cond: _,
        } = &**c;
        let mut ins = Vec::with_capacity(inputs.len());
        for (n, v) in inputs {
            ins.push((n.index as usize, self.value(f, v, ctx, line)?));
        }
        // In-outs and the globals the block uses: copied in, and out after the call.
        let mut places: Vec<Place> = inouts.iter().map(|(_, p)| p.clone()).collect();
        for e in externals {
            let k = e.caller as usize;
            let var = (self.prog.pous[f.pou].vars.get(k))
                .ok_or_else(|| format!("internal: caller has no external {}", e.name))?;
            places.push(Place {
                root: Root::Var(k),
                path: Vec::new(),
                ty: var.ty.clone(),
                range: None,
            });
        }
        // The FB's variable each place is bound to, as the checker decided.
        let vars = (inouts.iter().map(|(k, _)| k)).chain(externals.iter().map(|e| &e.callee));
        let refs: Vec<(usize, &Place)> = vars.map(|&k| k as usize).zip(&places).collect();
        let back = self.call_fb_at(f, inst, ins, (&refs, *inouts_in_instance), ctx, line)?;
        for (p, v) in places.iter().zip(back) {
            self.write(f, p, v, ctx, line)?;
        }
        for (n, target, neg, w) in outputs {
            let mut src = inst.clone();
            src.path.push(PathElem::Field(n.clone()));
            // The output's type: what a bad subscript of the instance reads
            // (its default, as generated code's `Default::default()`).
            src.ty = match w {
                Some(w) => Ty::Elem(w.from),
                None => target.ty.clone(),
            };
            let mut v = self.read(f, &src, ctx, line)?;
            if *neg {
                v = stdfn::not(&v);
            }
            let v = self.cut_string(f, widened(v, w)?, &target.ty, ctx, line);
            self.write(f, target, v, ctx, line)?;
        }
        Ok(())
    }

    /// `CAL inst(inputs)`: set the inputs, bind the in-outs (`refs`: each
    /// one's name and the caller's place), then call; the values to copy
    /// back into those places (none when a bad subscript faults and skips
    /// the call).
    pub(crate) fn call_fb_at(
        &mut self,
        f: &mut Frame,
        inst: &Place,
        ins: Vec<(usize, Value)>,
        (refs, inouts_in_instance): (&[(usize, &Place)], bool),
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Vec<Value>, String> {
        let (steps, ok) = self.steps(f, inst, ctx, line)?;
        if !ok {
            self.fault(ctx, f, FaultKind::IndexOutOfRange, line);
            return Ok(Vec::new());
        }
        let mut back = Vec::with_capacity(refs.len());
        let mut b = match self.read_at(self_root(f, &inst.root)?, &steps) {
            Some(v) => v,
            None => return Err("internal: FB instance not found".into()),
        };
        match &mut b {
            Value::StdFb(fb) => {
                for (k, v) in &ins {
                    if !fb.set_input(*k, v) {
                        return Err(format!("internal: cannot set input {k}"));
                    }
                }
                fb.call(ctx);
            }
            Value::Fb(i) => {
                for (k, v) in ins {
                    let slot = i
                        .vars
                        .get_mut(k)
                        .ok_or_else(|| format!("internal: no input {k}"))?;
                    *slot = v;
                }
                // The in-outs are read with the inputs set: one bound to a
                // member of the instance itself sees the input, so the
                // instance goes back to its place first (only then: it is
                // a copy of the whole instance).
                if inouts_in_instance {
                    let mut root = std::mem::replace(self_root(f, &inst.root)?, Value::Bool(false));
                    let done = self.write_at(&mut root, &steps, Value::Fb(i.clone()));
                    *self_root(f, &inst.root)? = root;
                    if !done {
                        return Err("internal: cannot store the instance".into());
                    }
                }
                let mut ref_idx = Vec::with_capacity(refs.len());
                for &(k, p) in refs {
                    let v = self.read(f, p, ctx, line)?;
                    *i.vars
                        .get_mut(k)
                        .ok_or_else(|| format!("internal: no in-out {k}"))? = v;
                    ref_idx.push(k);
                }
                if self.dbg.on() {
                    self.dbg_call(f, Some((inst, &steps)), "");
                }
                self.call_instance(i, ctx)?;
                if self.dbg.on() {
                    self.dbg_return(f);
                }
                back.extend(ref_idx.iter().map(|&k| i.vars[k].clone()));
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

    pub(crate) fn call_instance(
        &mut self,
        inst: &mut Instance,
        ctx: &mut Cycle,
    ) -> Result<(), String> {
        let pou = inst.pou;
        let p = &self.prog.pous[pou];
        let mut edges = vec![None; p.vars.len()];
        for (i, v) in p.vars.iter().enumerate() {
            if let Some(e) = v.edge
                && held(v)
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
            .filter(|&i| {
                !matches!(
                    p.vars[i].storage,
                    Storage::Instance | Storage::External | Storage::InOut
                )
            })
            .collect();
        for i in temps {
            let v = &self.prog.pous[pou].vars[i];
            vars[i] = self.init_of(&v.ty, v.init.as_ref())?;
        }
        let mut f = self.frame(pou, vars, edges)?;
        // A host block (`{extern}`, or a CODESYS POU not in IL): the
        // registered closure is its body (its result is no block's); without
        // one it is its interface only, its outputs keep their values.
        let r = if self.prog.pous[pou].host {
            if let Some(h) = self.hosts.get(&self.prog.pous[pou].name).cloned() {
                let _ = h(ctx, &mut f.vars);
            }
            Ok(())
        } else {
            self.run(&mut f, ctx)
        };
        inst.vars = f.vars;
        r
    }

    pub(crate) fn frame(
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
    pub(crate) fn call_function(
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
        if p.host {
            if let Some(h) = self.hosts.get(&p.name).cloned() {
                let r = h(ctx, &mut f.vars);
                // The closure is the embedder's: a value of another kind
                // than the declared result would break the program later.
                if std::mem::discriminant(&r) != std::mem::discriminant(&f.ret) {
                    let ty = p.ret.as_ref().map_or("BOOL".to_string(), |t| t.to_string());
                    return Err(format!(
                        "host function `{}` returned {}, which is no {ty}",
                        p.name,
                        r.display(),
                    ));
                }
                f.ret = r;
            }
        } else {
            self.run(&mut f, ctx)?;
        }
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

/// `v` converted by the checker's implicit widening of an output, if any.
fn widened(v: Value, w: &Option<il_codegen::ir::Widen>) -> Result<Value, String> {
    match w {
        Some(w) => stdfn::convert(w.from, w.to, &v)
            .ok_or_else(|| "internal: a widening the interpreter cannot convert".into()),
        None => Ok(v),
    }
}
