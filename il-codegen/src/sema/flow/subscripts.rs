//! Array subscripts: integer expressions over variables, literals and
//! direct addresses with `+ - * / MOD`, parentheses and unary minus
//! (`a[i + 1]`, `m[2 * i - 1, j]`, `a[k MOD 4]`; Ed.2 B.1.4.2 with the
//! integer operators of ST's expressions).
//!
//! An expression is typed as the operators of the body type theirs: both
//! sides meet at the wider type (the implicit widenings), an untyped literal
//! takes the other side's type and must fit it, and the operation is
//! computed in that type ([`Value::Arith`]): wrapping, with a division by
//! zero giving 0 and a recorded fault. Sides of which neither widens into
//! the other (INT and UINT) meet at the smallest signed type holding both.
//! An expression of literals only is folded here, exactly, and checked
//! against the bounds now.

use super::*;
use crate::ast::Subscript;
use crate::sema::widen::widens;

/// A subscript (or part of one) as checked so far.
enum Sub {
    /// Known now: literals only, folded exactly.
    Lit(i128, Span),
    /// Computed at run time: an integer value of that type.
    Val(Value, Elem),
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
            Sub::Val(v, _) => Some(v),
        }
    }

    fn sub_part(&mut self, s: &Subscript) -> Option<Sub> {
        match s {
            Subscript::Operand(o) => match self.operand(o)? {
                Arg::Typed(val, t) => match t.elem() {
                    Some(e) if e.is_int() => Some(Sub::Val(val, e)),
                    _ => {
                        self.err(
                            BAD_INDEX,
                            o.span(),
                            format!("a subscript must be an integer, not {t}"),
                        );
                        None
                    }
                },
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
            Subscript::Neg { operand, span } => match self.sub_part(operand)? {
                Sub::Lit(n, _) => Some(Sub::Lit(-n, *span)),
                Sub::Val(v, e) if e.is_signed_int() => Some(Sub::Val(
                    arith(BinOp::Sub, e, Value::Const(Const::Int(0.into(), e)), v),
                    e,
                )),
                Sub::Val(_, e) => {
                    self.err(
                        BAD_INDEX,
                        *span,
                        format!(
                            "`{}` negates an unsigned integer ({}); convert it to a signed type first",
                            self.cx.file.snippet(*span),
                            e.name()
                        ),
                    );
                    None
                }
            },
            Subscript::Bin { op, lhs, rhs, span } => {
                let (l, r) = (self.sub_part(lhs), self.sub_part(rhs));
                let (l, r) = (l?, r?);
                if matches!(op, BinOp::Div | BinOp::Mod) && matches!(r, Sub::Lit(0, _)) {
                    self.err(
                        BAD_INDEX,
                        rhs.span(),
                        format!("`{}` divides by zero", self.cx.file.snippet(*span)),
                    );
                    return None;
                }
                match (l, r) {
                    (Sub::Lit(a, _), Sub::Lit(b, _)) => {
                        let n =
                            crate::ir::path::fold(*op, a, b).filter(|n| i64::try_from(*n).is_ok());
                        let Some(n) = n else {
                            self.err(BAD_INDEX, *span, "the subscript overflows LINT");
                            return None;
                        };
                        Some(Sub::Lit(n, *span))
                    }
                    (Sub::Lit(a, sp), Sub::Val(v, e)) => {
                        let a = self.sub_literal(a, e, sp)?;
                        Some(Sub::Val(arith(*op, e, a, v), e))
                    }
                    (Sub::Val(v, e), Sub::Lit(b, sp)) => {
                        let b = self.sub_literal(b, e, sp)?;
                        Some(Sub::Val(arith(*op, e, v, b), e))
                    }
                    (Sub::Val(a, ea), Sub::Val(b, eb)) => {
                        let Some(e) = meet(ea, eb) else {
                            self.err(
                                BAD_INDEX,
                                *span,
                                format!(
                                    "no integer type holds both {} and {} in `{}`; convert one side ({})",
                                    ea.name(),
                                    eb.name(),
                                    self.cx.file.snippet(*span),
                                    // The unsigned side (ULINT) into LINT.
                                    crate::sema::widen::conversion_name(
                                        if ea.is_signed_int() { eb } else { ea },
                                        Elem::LINT
                                    )
                                ),
                            );
                            return None;
                        };
                        Some(Sub::Val(arith(*op, e, widen(a, ea, e), widen(b, eb, e)), e))
                    }
                }
            }
        }
    }

    /// An untyped literal beside a value of type `e`: it takes that type.
    fn sub_literal(&mut self, n: i128, e: Elem, sp: Span) -> Option<Value> {
        match coerce(&LitClass::Int(n), &Ty::Elem(e)) {
            Ok(c) => Some(Value::Const(c)),
            Err(m) => {
                self.err(
                    BAD_INDEX,
                    sp,
                    format!("in a subscript of type {}: {m}", e.name()),
                );
                None
            }
        }
    }
}

/// The type two integer types meet at: the wider when one widens into the
/// other, else the smallest signed type both widen into.
fn meet(a: Elem, b: Elem) -> Option<Elem> {
    if a == b || widens(b, a) {
        return Some(a);
    }
    if widens(a, b) {
        return Some(b);
    }
    [Elem::INT, Elem::DINT, Elem::LINT]
        .into_iter()
        .find(|&t| widens(a, t) && widens(b, t))
}

fn widen(v: Value, from: Elem, to: Elem) -> Value {
    if from == to {
        v
    } else {
        Value::Widen(Box::new((v, ir::Widen { from, to })))
    }
}

fn arith(op: BinOp, elem: Elem, lhs: Value, rhs: Value) -> Value {
    Value::Arith(Box::new(ir::Arith { op, elem, lhs, rhs }))
}
