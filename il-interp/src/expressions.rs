//! Expressions that set the current result: operators, TIME scaling, conditions.

use crate::values::Value;
use crate::{Frame, Machine, stdfn};
use il_codegen::ir::types::Elem;
use il_codegen::ir::{BinOp, Condition, Expr, Value as IrValue};
use il_std::{Cycle, FaultKind};

fn cond_holds(c: &Option<bool>, want: bool) -> bool {
    c.is_none_or(|b| b == want)
}

impl Machine {
    /// The frame's slot of CR local `i` (the frame holds them in the
    /// order of [`il_codegen::ir::CheckedPou::cr_types`]).
    pub(crate) fn cr_slot(f: &Frame, i: u32) -> Result<usize, String> {
        let i = i as usize;
        if i < f.cr.len() {
            Ok(i)
        } else {
            Err(format!("internal: no CR local {i}"))
        }
    }
    /// `lhs op rhs` (the operand complemented first with `negate`) in
    /// `elem`: the operators of the body and the subscript expressions.
    pub(crate) fn binary(
        &self,
        f: &mut Frame,
        op: BinOp,
        elem: Option<Elem>,
        (lhs, rhs, negate): (&IrValue, &IrValue, bool),
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Value, String> {
        let int = elem.is_some_and(|e| e.is_int() || e.is_bitstring());
        if int && matches!(op, BinOp::Div | BinOp::Mod) {
            // `{ let d = rhs; if d == 0 { fault; 0 } else { lhs op d } }`
            let mut r = self.value(f, rhs, ctx, line)?;
            if negate {
                r = stdfn::not(&r);
            }
            let Value::Int(d, e) = r else {
                return Err("internal: DIV operand".into());
            };
            if d == 0 {
                self.fault(ctx, f, FaultKind::DivisionByZero, line);
                return Ok(Value::Int(0, e));
            }
            let l = self.value(f, lhs, ctx, line)?;
            let Value::Int(x, _) = l else {
                return Err("internal: DIV operand".into());
            };
            return Ok(Value::Int(
                stdfn::int_divmod(op == BinOp::Div, x, d, e).unwrap_or(0),
                e,
            ));
        }
        let l = self.value(f, lhs, ctx, line)?;
        let mut r = self.value(f, rhs, ctx, line)?;
        if negate {
            r = stdfn::not(&r);
        }
        stdfn::operator(op.func(), &l, &r)
    }

    pub(crate) fn expr(
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
                elem,
            } => self.binary(f, *op, *elem, (lhs, rhs, *negate_rhs), ctx, line),
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
                    // TIME: il-std's MUL_TIME / DIV_TIME (`Expr::TimeScale`).
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
            Expr::CallUser(_) => self.call_user(f, e, ctx, line),
            Expr::CallStd(_) => self.call_std(f, e, ctx, line),
        }
    }

    pub(crate) fn condition(
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
}

/// `MUL_TIME` / `div_time_checked` of il-std with the number in its own Rust
/// type, exactly as generated code calls them.
pub(crate) fn time_scale(div: bool, t: i64, r: &Value, num: Elem) -> (i64, bool) {
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
