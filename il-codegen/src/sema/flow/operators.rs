//! Operators: arithmetic, comparison and bitwise operators on the CR and
//! an operand, literal folding and the types each operator takes.

use super::*;

impl Walk<'_, '_> {
    /// `lhs op rhs` where lhs is the CR (or a saved CR) and rhs the operand.
    pub(super) fn binary(
        &mut self,
        op: ExprOp,
        negate: bool,
        lhs: Arg,
        rhs: Arg,
        span: Span,
    ) -> Cr {
        let bad = Cr::Undef(Why::Error);
        let bop = op;
        // A pending call meeting only literals takes its default type.
        let pending = |a: &Arg| matches!(a, Arg::Lit(LitClass::Pending(_), _));
        if matches!(lhs, Arg::Lit(..))
            && matches!(rhs, Arg::Lit(..))
            && (pending(&lhs) || pending(&rhs))
        {
            let (Some(l), Some(r)) = (self.settle(lhs), self.settle(rhs)) else {
                return bad;
            };
            return self.binary(op, negate, l, r, span);
        }
        // Both untyped literals: fold at compile time.
        if let (Arg::Lit(a, sa), Arg::Lit(b, _)) = (&lhs, &rhs) {
            return match fold(bop, negate, a, b) {
                Ok(Folded::Lit(l)) => Cr::Lit(l, sa.to(span)),
                Ok(Folded::Bool(v)) => {
                    let cr = self.cr_index(&Ty::BOOL);
                    self.push(Op::SetCr {
                        cr,
                        expr: Expr::Value(Value::Const(Const::Bool(v))),
                    });
                    Cr::Val(Ty::BOOL)
                }
                Err(m) => {
                    self.err(
                        if m.contains("zero") {
                            CONST_DIV_ZERO
                        } else {
                            BAD_OPERATOR_TYPE
                        },
                        span,
                        m,
                    );
                    bad
                }
            };
        }
        // TIME scaled by a number.
        if matches!(bop, BinOp::Mul | BinOp::Div)
            && let (Arg::Typed(lv, Ty::Elem(te)), r) = (&lhs, &rhs)
            && te.is_duration()
        {
            let (rv, ne) = match r {
                Arg::Typed(v, Ty::Elem(n)) if n.is_num() => (v.clone(), *n),
                Arg::Lit(LitClass::Int(n), _) if i64::try_from(*n).is_ok() => (
                    Value::Const(Const::Int((*n).into(), Elem::LINT)),
                    Elem::LINT,
                ),
                Arg::Lit(LitClass::Real(f, _), _) => {
                    (Value::Const(Const::Real(*f, Elem::LREAL)), Elem::LREAL)
                }
                _ => {
                    self.err(
                        TYPE_MISMATCH,
                        span,
                        format!("{} of {} needs a number", op.name(), te.name()),
                    );
                    return bad;
                }
            };
            let cr = self.cr_index(&Ty::Elem(*te));
            self.push(Op::SetCr {
                cr,
                expr: Expr::TimeScale {
                    div: bop == BinOp::Div,
                    time: *te,
                    lhs: lv.clone(),
                    num: ne,
                    rhs: rv,
                },
            });
            return Cr::Val(Ty::Elem(*te));
        }
        // A typed literal of another type meets the CR like a typed value
        // (`LD int_v / ADD DINT#5` widens the CR to DINT).
        let typed = |a: Arg, other: &Arg| match (a, other) {
            (Arg::Lit(LitClass::Typed(c), _), Arg::Typed(_, t)) if c.ty() != *t => {
                let ty = c.ty();
                Arg::Typed(Value::Const(c), ty)
            }
            (a, _) => a,
        };
        let rhs = typed(rhs, &lhs);
        let lhs = typed(lhs, &rhs);
        let (ty, lv, rv) = match (lhs, rhs) {
            (Arg::Typed(lv, t), Arg::Typed(rv, u)) => {
                // Strings of any two lengths compare by their contents.
                if t == u || t.resizes_to(&u) {
                    (t, lv, rv)
                } else if let Some(w) = super::super::widen::wider(&t, &u) {
                    // 3rd edition: both sides go to the wider type, and so does the CR.
                    let (Some(lv), Some(rv)) = (
                        self.widen_to(lv, &t, &w, span),
                        self.widen_to(rv, &u, &w, span),
                    ) else {
                        return bad;
                    };
                    (w, lv, rv)
                } else {
                    if let Some(d) = self.err(TYPE_MISMATCH, span, format!("{} of {t} and {u}: the current result and the operand must have the same type", op.name())) {
                        d.help = conversion_hint(&u, &t);
                    }
                    return bad;
                }
            }
            (Arg::Typed(lv, t), Arg::Lit(l, s)) => {
                match self.lit_value(&l, &operand_ty(&l, &t), s, TYPE_MISMATCH) {
                    Some(v) => (t, lv, v),
                    None => return bad,
                }
            }
            (Arg::Lit(l, s), Arg::Typed(rv, t)) => {
                match self.lit_value(&l, &operand_ty(&l, &t), s, TYPE_MISMATCH) {
                    Some(v) => (t, v, rv),
                    None => return bad,
                }
            }
            // Two literals were folded above.
            (Arg::Lit(..), Arg::Lit(..)) => return bad,
        };
        if let Err(m) = op_allowed(op, negate, &ty) {
            self.err(BAD_OPERATOR_TYPE, span, m);
            return bad;
        }
        let elem = ty.elem();
        let res = if op.is_compare() { Ty::BOOL } else { ty };
        let cr = self.cr_index(&res);
        self.push(Op::SetCr {
            cr,
            expr: Expr::Bin {
                op: bop,
                elem,
                lhs: lv,
                rhs: rv,
                negate_rhs: negate,
            },
        });
        Cr::Val(res)
    }
}

impl Walk<'_, '_> {
    /// `v` of type `t` as a value of `to` (`t` itself, or widened).
    fn widen_to(&mut self, v: Value, t: &Ty, to: &Ty, span: Span) -> Option<Value> {
        if t == to {
            Some(v)
        } else {
            self.widen(v, t, to, span)
        }
    }
}

/// The default value of an elementary or string type, as a constant: FALSE,
/// 0, 0.0, T#0s (and the zero of the other durations and dates), `''`. Other
/// types (arrays, blocks, user types) have no single constant: `FALSE` is
/// returned, and callers build those values element by element.
pub fn default_const(t: &Ty) -> Const {
    match t {
        Ty::Elem(Elem::BOOL) => Const::Bool(false),
        Ty::Elem(e) if e.int_range().is_some() => Const::Int(0.into(), *e),
        Ty::Elem(e) if e.is_real() => Const::Real(0.0, *e),
        Ty::Elem(e) => Const::Time(0, *e),
        Ty::Str { wide, len } => Const::Str(Box::new(crate::sema::ir::StrConst {
            value: String::new(),
            wide: *wide,
            len: *len,
        })),
        _ => Const::Bool(false),
    }
}

pub(super) fn op_allowed(op: ExprOp, negate: bool, t: &Ty) -> Result<(), String> {
    let name = op.name();
    if negate && !op.is_logic() {
        return Err(format!("{name} has no N modifier"));
    }
    let ok = match t {
        Ty::Elem(e) => {
            if op.is_logic() {
                t.is_logic()
            } else if op == ExprOp::Mod {
                e.is_int()
            } else if op.is_arith() {
                e.is_num() || (e.is_duration() && matches!(op, ExprOp::Add | ExprOp::Sub))
            } else {
                true
            }
        }
        Ty::Str { .. } => op.is_compare(),
        Ty::Enum(_) => matches!(op, ExprOp::Eq | ExprOp::Ne),
        _ => false,
    };
    if ok {
        return Ok(());
    }
    let what = if op.is_logic() {
        "BOOL or a bit string (BYTE, WORD, DWORD, LWORD)"
    } else if op == ExprOp::Mod {
        "an integer type"
    } else if op.is_arith() {
        "a number (or TIME for ADD and SUB)"
    } else {
        "an elementary type"
    };
    Err(format!("{name} needs {what}; the current result is {t}"))
}

pub(super) enum Folded {
    Lit(LitClass),
    Bool(bool),
}

/// Evaluate an operation on two untyped literals exactly.
pub(super) fn fold(op: BinOp, negate: bool, a: &LitClass, b: &LitClass) -> Result<Folded, String> {
    use LitClass::{Int, Real};
    let cmp = |o: std::cmp::Ordering| -> bool {
        match op {
            BinOp::Gt => o.is_gt(),
            BinOp::Ge => o.is_ge(),
            BinOp::Eq => o.is_eq(),
            BinOp::Ne => o.is_ne(),
            BinOp::Le => o.is_le(),
            _ => o.is_lt(),
        }
    };
    if negate {
        return Err("N on untyped literals: give one of them a type (BOOL#1, WORD#16#FF)".into());
    }
    match (a, b) {
        (Int(x), Int(y)) => {
            let (x, y) = (*x, *y);
            let r = match op {
                BinOp::And => Some(x & y),
                BinOp::Or => Some(x | y),
                BinOp::Xor => Some(x ^ y),
                BinOp::Add => x.checked_add(y),
                BinOp::Sub => x.checked_sub(y),
                BinOp::Mul => x.checked_mul(y),
                BinOp::Div | BinOp::Mod if y == 0 => {
                    return Err("division by zero in a constant expression".into());
                }
                BinOp::Div => x.checked_div(y),
                BinOp::Mod => x.checked_rem(y),
                _ => return Ok(Folded::Bool(cmp(x.cmp(&y)))),
            };
            r.map(|v| Folded::Lit(Int(v)))
                .ok_or_else(|| "constant expression overflows".into())
        }
        (Int(_) | Real(..), Int(_) | Real(..)) => {
            let f = |l: &LitClass| match l {
                Int(v) => *v as f64,
                Real(v, _) => *v,
                _ => 0.0,
            };
            let (x, y) = (f(a), f(b));
            let r = match op {
                BinOp::Add => x + y,
                BinOp::Sub => x - y,
                BinOp::Mul => x * y,
                BinOp::Div => x / y,
                BinOp::And | BinOp::Or | BinOp::Xor | BinOp::Mod => {
                    return Err("this operator needs integers".into());
                }
                _ => return Ok(Folded::Bool(x.partial_cmp(&y).is_some_and(cmp))),
            };
            Ok(Folded::Lit(Real(r, format!("{r:?}"))))
        }
        _ => Err("this operation on two literals needs typed literals".into()),
    }
}

/// The standard conversion from `from` to `to` (`INT_TO_REAL`), if there is one.
pub(super) fn conversion_name(from: &Ty, to: &Ty) -> Option<String> {
    let (Ty::Elem(a), Ty::Elem(b)) = (from, to) else {
        return None;
    };
    let name = format!("{}_TO_{}", short(*a), short(*b));
    stdfn::is_std(&name).then_some(name)
}

/// "use INT_TO_REAL" when a conversion function exists.
pub(super) fn conversion_hint(from: &Ty, to: &Ty) -> Option<String> {
    let name = conversion_name(from, to)?;
    let (Ty::Elem(a), Ty::Elem(b)) = (from, to) else {
        return None;
    };
    // A number where a BOOL is wanted is mostly a missing comparison.
    if *b == Elem::BOOL && (a.is_int() || a.is_real()) {
        return Some(format!(
            "to test the value, compare it first (`GT 0`, `NE 0`); to convert it, `{name}`"
        ));
    }
    Some(format!("convert with `{name}`"))
}

pub(super) fn short(e: Elem) -> &'static str {
    match e {
        Elem::TOD => "TOD",
        Elem::DT => "DT",
        e => e.name(),
    }
}
