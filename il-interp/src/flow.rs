//! Execution of a POU's body: one statement after the other, jumps, RET.

use crate::values::Value;
use crate::{Frame, Machine, STEP_LIMIT, stdfn};
use il_codegen::sema::ir::{Op, Stmt, Value as IrValue};
use il_std::{Cycle, FaultKind};

impl Machine {
    pub(crate) fn run(&mut self, f: &mut Frame, ctx: &mut Cycle) -> Result<(), String> {
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
                    // As the emitter: STN complements in the CR's type,
                    // before a widening.
                    let v = match (negate, value) {
                        (true, IrValue::Widen(inner, w)) => {
                            let x = stdfn::not(&self.value(f, inner, ctx, line)?);
                            stdfn::convert(w.from, w.to, &x)
                                .ok_or("internal: a widening the interpreter cannot convert")?
                        }
                        (true, v) => stdfn::not(&self.value(f, v, ctx, line)?),
                        (false, v) => self.value(f, v, ctx, line)?,
                    };
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
                Op::CallFb { cond, .. } => {
                    if self.condition(f, cond, ctx, line)? {
                        self.cal(f, &s.op, ctx, line)?;
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
}
