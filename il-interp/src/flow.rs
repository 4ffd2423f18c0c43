//! Execution of a POU's body: one statement after the other, jumps, RET.

use crate::values::Value;
use crate::{Frame, Machine, STEP_LIMIT, stdfn};
use il_codegen::ir::{Op, Stmt, Value as IrValue};
use il_std::{Cycle, FaultKind};

impl Machine {
    /// An error of statement `s` with the place in the source it comes from
    /// (`file:line:col: in POU: ...`, placed by [`Machine::set_locate`]
    /// when one is given); an error from a nested call already has its
    /// own, and keeps it.
    pub(crate) fn located(&mut self, pou: usize, s: &Stmt, e: String) -> String {
        if std::mem::replace(&mut self.error_located, true) {
            return e;
        }
        let (file, name) = (&self.prog.file, &self.prog.pous[pou].name);
        let at = match &self.locate.0 {
            Some(f) => f(name, s.line, s.col),
            None => format!("{file}:{}:{}", s.line, s.col),
        };
        format!("{at}: in {name}: {e}")
    }

    pub(crate) fn run(&mut self, f: &mut Frame, ctx: &mut Cycle) -> Result<(), String> {
        // Once per body, not per statement: an undebugged run keeps its speed.
        if self.dbg.on() {
            return self.run_hooked(f, ctx);
        }
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
                let e = format!("more than {STEP_LIMIT} instructions in one scan (endless loop?)");
                return Err(self.located(pou, s, e));
            }
            pc += 1;
            match self.exec(f, s, &labels, ctx) {
                Ok(Some(usize::MAX)) => break,
                Ok(Some(to)) => pc = to,
                Ok(None) => {}
                Err(e) => return Err(self.located(pou, s, e)),
            }
        }
        Ok(())
    }

    /// Execute one statement: `Some(pc)` to jump there (`usize::MAX`: leave
    /// the POU), `None` to go on with the next one. Inlined into both loops
    /// (the plain one and the debugger's): with a second caller the
    /// compiler stopped inlining it into the plain loop, which cost an
    /// undebugged run 8%.
    #[inline(always)]
    pub(crate) fn exec(
        &mut self,
        f: &mut Frame,
        s: &Stmt,
        labels: &[usize],
        ctx: &mut Cycle,
    ) -> Result<Option<usize>, String> {
        let line = s.line;
        match &s.op {
            Op::SetCr { cr, expr } => {
                let v = self.expr(f, expr, ctx, line)?;
                let slot = Self::cr_slot(f, *cr)?;
                f.cr[slot] = v;
            }
            Op::Save { slot, value } => {
                let v = self.value(f, value, ctx, line)?;
                let slot = *slot as usize;
                if f.saves.len() <= slot {
                    f.saves.resize(slot + 1, Value::Bool(false));
                }
                f.saves[slot] = v;
            }
            Op::Store {
                place,
                value,
                negate,
            } => {
                // STN complements in the CR's type, before a widening
                // (`Op::Store::negate`).
                let v = match (negate, value) {
                    (true, IrValue::Widen(b)) => {
                        let (inner, w) = &**b;
                        let x = stdfn::not(&self.value(f, inner, ctx, line)?);
                        stdfn::convert(w.from, w.to, &x)
                            .ok_or("internal: a widening the interpreter cannot convert")?
                    }
                    (true, v) => stdfn::not(&self.value(f, v, ctx, line)?),
                    (false, v) => self.value(f, v, ctx, line)?,
                };
                let place = self.prog.pous[f.pou].place(*place);
                // A store outside a subrange (an inline `INT (0..100)`) does
                // not happen and is recorded (`Place::range`).
                if let (Some(&(lo, hi)), Value::Int(x, _)) = (place.range.as_deref(), &v)
                    && !(lo..=hi).contains(x)
                {
                    self.fault(ctx, f, FaultKind::SubrangeViolation, line);
                    return Ok(None);
                }
                self.write(f, place, v, ctx, line)?;
            }
            Op::SetIf { place, value, cond } => {
                if self.value(f, cond, ctx, line)?.as_bool() {
                    let place = self.prog.pous[f.pou].place(*place);
                    self.write(f, place, Value::Bool(*value), ctx, line)?;
                }
            }
            Op::CallFb(c) => {
                if self.condition(f, &c.cond, ctx, line)? {
                    self.cal(f, &s.op, ctx, line)?;
                }
            }
            Op::Jump { label, cond } => {
                if self.condition(f, cond, ctx, line)? {
                    return labels
                        .get(*label)
                        .copied()
                        .filter(|p| *p != usize::MAX)
                        .map(Some)
                        .ok_or_else(|| "internal: jump to a missing label".into());
                }
            }
            Op::Label(_) | Op::Nop => {}
            Op::Return { cond } => {
                if self.condition(f, cond, ctx, line)? {
                    return Ok(Some(usize::MAX));
                }
            }
        }
        Ok(None)
    }
}
