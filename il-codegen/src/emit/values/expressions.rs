//! Expressions: the CR and operand values, operators, standard function
//! calls with their faults.

use super::*;
use il_std::signature::Rounding;

impl PouEmitter<'_> {
    pub(crate) fn expr(&self, e: &Expr, line: u32) -> String {
        match e {
            Expr::Value(v) => self.value(v, line),
            Expr::Not(v) => self.negated(v, line),
            Expr::Bin {
                op,
                elem,
                lhs,
                rhs,
                negate_rhs,
            } => {
                let l = self.receiver(lhs, line);
                let r = if *negate_rhs {
                    self.negated(rhs, line)
                } else {
                    self.value(rhs, line)
                };
                // A literal divisor other than 0 needs no zero check.
                let nonzero =
                    !*negate_rhs && matches!(rhs, Value::Const(Const::Int(n, _)) if n.get() != 0);
                self.binary(*op, *elem, l, r, nonzero, line)
            }
            Expr::TimeScale {
                div,
                time,
                lhs,
                num,
                rhs,
            } => {
                let t = time.rust();
                let l = self.receiver(lhs, line);
                let r = self.receiver(rhs, line);
                // TIME: the operator and MUL_TIME/DIV_TIME are one rule.
                if *time == Elem::TIME {
                    if !*div {
                        return format!("::il_std::func::MUL_TIME({l}, {r})");
                    }
                    let fault = self.fault("DivisionByZero", line);
                    return format!(
                        "{{ let (__v, __bad) = ::il_std::func::div_time_checked({l}, {r}); if __bad {{ {fault}; }} __v }}"
                    );
                }
                match (div, num.is_real()) {
                    (false, false) => format!("{t}({l}.0.wrapping_mul({r} as i64))"),
                    (false, true) => format!("{t}((({l}.0 as f64) * ({r} as f64)) as i64)"),
                    (true, true) => format!("{t}((({l}.0 as f64) / ({r} as f64)) as i64)"),
                    (true, false) => {
                        let fault = self.fault("DivisionByZero", line);
                        format!(
                            "{{ let __d = {r} as i64; if __d == 0 {{ {fault}; {t}(0) }} else {{ {t}({l}.0.wrapping_div(__d)) }} }}"
                        )
                    }
                }
            }
            Expr::CallUser(c) => {
                let crate::ir::UserCall {
                    name,
                    args,
                    inouts,
                    outputs,
                    out_types,
                    en,
                    eno,
                    ret,
                } = &**c;
                let call = self.user_call(name, args, inouts, outputs, out_types, line);
                let Some(en) = en else { return call };
                // EN = FALSE: the function does not run; its result is the
                // default and ENO (if read with `=>`) is FALSE.
                let en = self.value(en, line);
                let d = default_value(ret);
                let eno_false: String = outputs
                    .iter()
                    .filter(|(k, ..)| Some(*k) == *eno)
                    .map(|(_, place, neg, w)| {
                        let v = widened(neg.to_string(), w);
                        self.write(place, v, line)
                    })
                    .collect();
                format!("if {en} {{ {call} }} else {{ {eno_false} {d} }}")
            }
            Expr::CallStd(c) => {
                let crate::ir::StdFnCall {
                    sig,
                    en,
                    call,
                    args,
                    arg_types: _,
                    ret,
                    fault,
                } = &**c;
                let call = {
                    let args: Vec<_> = args.iter().map(|a| self.value(a, line)).collect();
                    match (call, fault) {
                        // REAL → integer out of range (or NaN) saturates, as the
                        // plain function does, and is recorded as a fault.
                        (StdCall::Plain(_), Some(k @ FaultKind::ConversionOutOfRange)) => {
                            let t = rust_ty(ret);
                            // The fault and the rounding are the table's.
                            let f = match sig.rounding {
                                Some(Rounding::TowardZero) => "trunc_to_int_checked",
                                _ => "real_to_int_checked",
                            };
                            let a = &args[0];
                            let fault = self.fault_of(*k, line);
                            format!(
                                "{{ let (__v, __bad) = ::il_std::conv::{f}::<{t}>({a} as f64); if __bad {{ {fault}; }} __v }}"
                            )
                        }
                        // DIV, MOD, DIV_TIME by an integer zero, INSERT and
                        // REPLACE cut to the capacity: the `*_checked`
                        // companion gives the result and the flag.
                        (
                            StdCall::Plain(n),
                            Some(k @ (FaultKind::DivisionByZero | FaultKind::StringOverflow)),
                        ) => {
                            let f = rust_ident(&format!("{}_checked", n.to_ascii_lowercase()));
                            let fault = self.fault_of(*k, line);
                            let args = join(&args, ", ");
                            format!(
                                "{{ let (__v, __bad) = ::il_std::func::{f}({args}); if __bad {{ {fault}; }} __v }}"
                            )
                        }
                        (StdCall::Plain(n), _) => {
                            let f = rust_ident(n);
                            format!("::il_std::func::{f}({})", join(&args, ", "))
                        }
                        // A result longer than the first string's capacity is
                        // truncated and recorded (CONCAT, step by step).
                        (StdCall::Fold(n), Some(k @ FaultKind::StringOverflow)) => {
                            let checked =
                                rust_ident(&format!("{}_checked", n.to_ascii_lowercase()));
                            let fault = self.fault_of(*k, line);
                            let mut it = args.into_iter();
                            let mut acc = it.next().unwrap_or_default();
                            for a in it {
                                acc = format!(
                                    "{{ let (__v, __bad) = ::il_std::func::{checked}({acc}, {a}); if __bad {{ {fault}; }} __v }}"
                                );
                            }
                            acc
                        }
                        (StdCall::Fold(n), _) => {
                            let f = rust_ident(n);
                            let mut it = args.into_iter();
                            let mut acc = it.next().unwrap_or_default();
                            for a in it {
                                acc = format!("::il_std::func::{f}({acc}, {a})");
                            }
                            acc
                        }
                        (StdCall::Chain(n), _) => {
                            let f = rust_ident(n);
                            let pairs = args
                                .windows(2)
                                .map(|w| format!("::il_std::func::{f}({}, {})", w[0], w[1]));
                            join(pairs, " & ")
                        }
                        // MUX returns the flag with the value: a selector out of
                        // range (the table's InvalidArgument) is recorded.
                        (StdCall::Mux, k) => {
                            let fault =
                                self.fault_of(k.unwrap_or(FaultKind::InvalidArgument), line);
                            let k = &args[0];
                            let in0 = &args[1];
                            let rest = join(&args[2..], ", ");
                            format!(
                                "{{ let (__v, __bad) = ::il_std::func::mux_checked({k} as i64, {in0}, &[{rest}]); if __bad {{ {fault}; }} __v }}"
                            )
                        }
                    }
                };
                // EN FALSE: not evaluated, the result is the type's default.
                match en {
                    Some(en) => {
                        let en = self.value(en, line);
                        let d = default_value(ret);
                        format!("if {en} {{ {call} }} else {{ {d} }}")
                    }
                    None => call,
                }
            }
        }
    }

    pub(super) fn binary(
        &self,
        op: BinOp,
        e: Option<Elem>,
        l: String,
        r: String,
        nonzero: bool,
        line: u32,
    ) -> String {
        let int = e.is_some_and(|e| e.is_int() || e.is_bitstring());
        let dur = e.filter(|e| e.is_duration()).map(Elem::rust);
        // The common shapes are joined, not formatted (a few per IL line).
        let infix = |sep: &str| [l.as_str(), sep, r.as_str()].concat();
        let method = |f: &str| [l.as_str(), ".", f, "(", r.as_str(), ")"].concat();
        match op {
            BinOp::And => infix(" & "),
            BinOp::Or => infix(" | "),
            BinOp::Xor => infix(" ^ "),
            BinOp::Gt => infix(" > "),
            BinOp::Ge => infix(" >= "),
            BinOp::Eq => infix(" == "),
            BinOp::Ne => infix(" != "),
            BinOp::Le => infix(" <= "),
            BinOp::Lt => infix(" < "),
            BinOp::Add | BinOp::Sub if dur.is_some() => {
                let t = dur.unwrap_or_default();
                if op == BinOp::Add {
                    format!("{t}({l}.0.wrapping_add({r}.0))")
                } else {
                    format!("{t}({l}.0.wrapping_sub({r}.0))")
                }
            }
            BinOp::Add if int => method("wrapping_add"),
            BinOp::Sub if int => method("wrapping_sub"),
            BinOp::Mul if int => method("wrapping_mul"),
            BinOp::Div if int && nonzero => method("wrapping_div"),
            BinOp::Mod if int && nonzero => method("wrapping_rem"),
            BinOp::Div | BinOp::Mod if int => {
                let fault = self.fault("DivisionByZero", line);
                let f = if op == BinOp::Div {
                    "wrapping_div"
                } else {
                    "wrapping_rem"
                };
                format!("{{ let __d = {r}; if __d == 0 {{ {fault}; 0 }} else {{ {l}.{f}(__d) }} }}")
            }
            BinOp::Add => infix(" + "),
            BinOp::Sub => infix(" - "),
            BinOp::Mul => infix(" * "),
            BinOp::Div => infix(" / "),
            BinOp::Mod => infix(" % "),
        }
    }
}
