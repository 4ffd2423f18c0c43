//! Array subscripts: integer variables, literals and direct addresses, and
//! expressions over them with `+ - *` (`a[i + 1]`, `m[2 * i - 1, j]`; Ed.2
//! B.1.4.2). An expression is computed in LINT with wrapping
//! ([`Value::Arith`]), then bound-checked like a variable subscript; one of
//! literals only is folded here and checked against the bounds now.

use super::*;
use crate::ast::Subscript;

/// A subscript (or part of one) as checked so far.
enum Sub {
    /// Known now: literals only.
    Lit(i128, Span),
    /// Computed at run time (an integer value).
    Val(Value),
}

impl Walk<'_, '_> {
    /// The subscript `s` of a dimension with bounds `lo..hi`.
    pub(super) fn subscript(&mut self, s: &Subscript, lo: i64, hi: i64) -> Option<Value> {
        match self.sub_part(s)? {
            Sub::Lit(n, sp) => {
                if n < lo as i128 || n > hi as i128 {
                    self.err(
                        BAD_INDEX,
                        sp,
                        format!("subscript {n} is outside the bounds {lo}..{hi}"),
                    );
                    return None;
                }
                Some(Value::Const(Const::Int(n.into(), Elem::LINT)))
            }
            Sub::Val(v) => Some(v),
        }
    }

    fn sub_part(&mut self, s: &Subscript) -> Option<Sub> {
        match s {
            Subscript::Operand(o) => match self.operand(o)? {
                Arg::Typed(val, t) if t.elem().is_some_and(Elem::is_int) => Some(Sub::Val(val)),
                Arg::Typed(_, t) => {
                    self.err(
                        BAD_INDEX,
                        o.span(),
                        format!("a subscript must be an integer, not {t}"),
                    );
                    None
                }
                Arg::Lit(LitClass::Int(n), sp) => Some(Sub::Lit(n, sp)),
                Arg::Lit(l, sp) => {
                    self.err(
                        BAD_INDEX,
                        sp,
                        format!("a subscript must be an integer, not {}", describe(&l)),
                    );
                    None
                }
            },
            Subscript::Bin { op, lhs, rhs, span } => {
                let (l, r) = (self.sub_part(lhs), self.sub_part(rhs));
                let (l, r) = (l?, r?);
                Some(match (l, r) {
                    // As at run time: LINT arithmetic, wrapping.
                    (Sub::Lit(a, _), Sub::Lit(b, _)) => {
                        let (a, b) = (a as i64, b as i64);
                        let n = match op {
                            BinOp::Add => a.wrapping_add(b),
                            BinOp::Sub => a.wrapping_sub(b),
                            _ => a.wrapping_mul(b),
                        };
                        Sub::Lit(n as i128, *span)
                    }
                    (l, r) => Sub::Val(Value::Arith(Box::new(ir::Arith {
                        op: *op,
                        lhs: lint(l),
                        rhs: lint(r),
                    }))),
                })
            }
        }
    }
}

/// A part of a subscript expression as a value (a literal as LINT, wrapped).
fn lint(s: Sub) -> Value {
    match s {
        Sub::Lit(n, _) => Value::Const(Const::Int((n as i64 as i128).into(), Elem::LINT)),
        Sub::Val(v) => v,
    }
}
