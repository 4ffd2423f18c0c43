//! Standard functions on runtime values, dispatched on il-std's own table
//! ([`Func`], [`Signature::conversion`]), never on a name. Each computes
//! what the il-std function the emitter calls computes (most call it).

use crate::values::{Value, wrap};
use il_codegen::ir::StdCall;
use il_codegen::ir::types::{Elem, Ty};
use il_std::FaultKind;
use il_std::func as f;
use il_std::signature::{ConvKind, Conversion, Func, Rounding, Signature};
use std::cmp::Ordering;

mod strings;
use strings::string_fn;

/// Evaluates `$body` with the type alias `$t` naming the Rust type of the
/// integer or bit-string type `$e`.
macro_rules! by_type {
    ($e:expr, $t:ident => $body:expr) => {
        match $e {
            Elem::SINT => {
                type $t = i8;
                $body
            }
            Elem::INT => {
                type $t = i16;
                $body
            }
            Elem::DINT => {
                type $t = i32;
                $body
            }
            Elem::LINT => {
                type $t = i64;
                $body
            }
            Elem::USINT | Elem::BYTE => {
                type $t = u8;
                $body
            }
            Elem::UINT | Elem::WORD => {
                type $t = u16;
                $body
            }
            Elem::UDINT | Elem::DWORD => {
                type $t = u32;
                $body
            }
            _ => {
                type $t = u64;
                $body
            }
        }
    };
}

fn unsupported(name: &str) -> String {
    format!("the standard function {name} is not supported by the interpreter")
}

/// Ordering of two values of one elementary type (as Rust's `PartialOrd`).
pub fn compare(a: &Value, b: &Value) -> Option<Ordering> {
    match (a, b) {
        (Value::Bool(x), Value::Bool(y)) => x.partial_cmp(y),
        (Value::Int(x, _), Value::Int(y, _)) => x.partial_cmp(y),
        (Value::Real(x), Value::Real(y)) => x.partial_cmp(y),
        (Value::LReal(x), Value::LReal(y)) => x.partial_cmp(y),
        (Value::Time(x, _), Value::Time(y, _)) => x.partial_cmp(y),
        (Value::Str { units: x, .. }, Value::Str { units: y, .. }) => x.partial_cmp(y),
        // Enumerations only compare for equality (EQ/NE; the Rust enum is
        // `PartialEq` only): other values are unordered.
        (Value::Enum { value: x, .. }, Value::Enum { value: y, .. }) => {
            (x == y).then_some(Ordering::Equal)
        }
        _ => None,
    }
}

fn cmp_op(func: Func, a: &Value, b: &Value) -> Option<bool> {
    let o = compare(a, b);
    Some(match func {
        Func::GT => o == Some(Ordering::Greater),
        Func::GE => matches!(o, Some(Ordering::Greater | Ordering::Equal)),
        Func::EQ => o == Some(Ordering::Equal),
        Func::NE => o != Some(Ordering::Equal),
        Func::LE => matches!(o, Some(Ordering::Less | Ordering::Equal)),
        Func::LT => o == Some(Ordering::Less),
        _ => return None,
    })
}

/// Logical or bitwise complement.
pub fn not(v: &Value) -> Value {
    match v {
        Value::Bool(b) => Value::Bool(!b),
        Value::Int(x, e) => Value::Int(wrap(!x, *e), *e),
        other => other.clone(),
    }
}

/// `ADD SUB MUL` with wrapping integers, IEEE reals, wrapping durations.
fn arith(func: Func, a: &Value, b: &Value) -> Option<Value> {
    Some(match (a, b) {
        (Value::Int(x, e), Value::Int(y, _)) => {
            let r = match func {
                Func::ADD => x.wrapping_add(*y),
                Func::SUB => x.wrapping_sub(*y),
                Func::MUL => x.wrapping_mul(*y),
                _ => return None,
            };
            Value::Int(wrap(r, *e), *e)
        }
        (Value::Real(x), Value::Real(y)) => Value::Real(match func {
            Func::ADD => x + y,
            Func::SUB => x - y,
            Func::MUL => x * y,
            Func::DIV => x / y,
            Func::MOD => x % y,
            _ => return None,
        }),
        (Value::LReal(x), Value::LReal(y)) => Value::LReal(match func {
            Func::ADD => x + y,
            Func::SUB => x - y,
            Func::MUL => x * y,
            Func::DIV => x / y,
            Func::MOD => x % y,
            _ => return None,
        }),
        (Value::Time(x, e), Value::Time(y, _)) => Value::Time(
            match func {
                Func::ADD => x.wrapping_add(*y),
                Func::SUB => x.wrapping_sub(*y),
                _ => return None,
            },
            *e,
        ),
        _ => return None,
    })
}

/// Integer DIV/MOD: `None` for a zero divisor.
pub fn int_divmod(div: bool, x: i128, y: i128, e: Elem) -> Option<i128> {
    if y == 0 {
        return None;
    }
    Some(wrap(if div { x / y } else { x % y }, e))
}

fn bitop(func: Func, a: &Value, b: &Value) -> Option<Value> {
    Some(match (a, b) {
        (Value::Bool(x), Value::Bool(y)) => Value::Bool(match func {
            Func::AND => x & y,
            Func::OR => x | y,
            Func::XOR => x ^ y,
            _ => return None,
        }),
        (Value::Int(x, e), Value::Int(y, _)) => Value::Int(
            match func {
                Func::AND => x & y,
                Func::OR => x | y,
                Func::XOR => x ^ y,
                _ => return None,
            },
            *e,
        ),
        _ => return None,
    })
}

fn max_min(max: bool, a: Value, b: Value) -> Value {
    let o = compare(&b, &a);
    let nan_a = compare(&a, &a).is_none();
    let take_b = if max {
        o == Some(Ordering::Greater)
    } else {
        o == Some(Ordering::Less)
    };
    if take_b || nan_a { b } else { a }
}

fn real_unary(func: Func, v: &Value) -> Option<Value> {
    macro_rules! un {
        ($x:expr) => {
            match func {
                Func::SQRT => f::SQRT($x),
                Func::LN => f::LN($x),
                Func::LOG => f::LOG($x),
                Func::EXP => f::EXP($x),
                Func::SIN => f::SIN($x),
                Func::COS => f::COS($x),
                Func::TAN => f::TAN($x),
                Func::ASIN => f::ASIN($x),
                Func::ACOS => f::ACOS($x),
                Func::ATAN => f::ATAN($x),
                _ => return None,
            }
        };
    }
    Some(match v {
        Value::Real(x) => Value::Real(un!(*x)),
        Value::LReal(x) => Value::LReal(un!(*x)),
        _ => return None,
    })
}

fn shift(func: Func, v: &Value, n: &Value) -> Option<Value> {
    let Value::Int(x, e) = v else { return None };
    let Value::Int(n, _) = n else { return None };
    let e = *e;
    // The count's type only matters through its value.
    macro_rules! op {
        ($y:expr, $c:expr) => {
            match func {
                Func::SHL => f::SHL($y, $c),
                Func::SHR => f::SHR($y, $c),
                Func::ROL => f::ROL($y, $c),
                Func::ROR => f::ROR($y, $c),
                _ => return None,
            } as i128
        };
    }
    macro_rules! sh {
        ($c:expr) => {
            Value::Int(
                match crate::values::bits(e) {
                    8 => op!(*x as u8, $c),
                    16 => op!(*x as u16, $c),
                    32 => op!(*x as u32, $c),
                    _ => op!(*x as u64, $c),
                },
                e,
            )
        };
    }
    Some(if *n < 0 {
        sh!(*n as i64)
    } else {
        sh!(*n as u64)
    })
}

fn two(args: &[Value], func: Func) -> Result<(&Value, &Value), String> {
    match args {
        [a, b, ..] => Ok((a, b)),
        _ => Err(format!("{func:?}: missing arguments")),
    }
}

fn bad_args(func: Func) -> String {
    format!("{func:?}: unexpected argument types in the interpreter")
}

/// The IL operator computing `func` (ADD, DIV, AND, GT ...: see
/// [`il_codegen::ir::BinOp::func`]) on `a` and `b`, as the standard
/// function: none of them needs the result type.
pub fn operator(func: Func, a: &Value, b: &Value) -> Result<Value, String> {
    let bad = || bad_args(func);
    match func {
        Func::ADD | Func::SUB | Func::MUL => arith(func, a, b).ok_or_else(bad),
        Func::DIV | Func::MOD => match (a, b) {
            // A zero divisor gives 0 (il_std::func::DIV); `call` records
            // the fault the checked call carries.
            (Value::Int(x, e), Value::Int(y, _)) => Ok(Value::Int(
                int_divmod(func == Func::DIV, *x, *y, *e).unwrap_or(0),
                *e,
            )),
            _ => arith(func, a, b).ok_or_else(bad),
        },
        Func::AND | Func::OR | Func::XOR => bitop(func, a, b).ok_or_else(bad),
        Func::GT | Func::GE | Func::EQ | Func::NE | Func::LE | Func::LT => {
            Ok(Value::Bool(cmp_op(func, a, b).ok_or_else(bad)?))
        }
        _ => Err(format!("{func:?}: not an operator")),
    }
}

/// One call of the two-argument (or fixed) form of the function `func`
/// (every one but the conversions, which [`conversion`] evaluates).
fn plain(func: Func, args: &[Value], ret: &Ty) -> Result<Value, String> {
    let bad = || bad_args(func);
    let first = || args.first().ok_or_else(bad);
    match func {
        Func::ADD
        | Func::SUB
        | Func::MUL
        | Func::DIV
        | Func::MOD
        | Func::AND
        | Func::OR
        | Func::XOR
        | Func::GT
        | Func::GE
        | Func::EQ
        | Func::NE
        | Func::LE
        | Func::LT => {
            let (a, b) = two(args, func)?;
            operator(func, a, b)
        }
        Func::NOT => Ok(not(first()?)),
        Func::MOVE => first().cloned(),
        Func::ABS => Ok(match first()? {
            Value::Int(x, e) => Value::Int(wrap(x.abs(), *e), *e),
            Value::Real(x) => Value::Real(f::ABS(*x)),
            Value::LReal(x) => Value::LReal(f::ABS(*x)),
            _ => return Err(bad()),
        }),
        Func::SQRT
        | Func::LN
        | Func::LOG
        | Func::EXP
        | Func::SIN
        | Func::COS
        | Func::TAN
        | Func::ASIN
        | Func::ACOS
        | Func::ATAN => real_unary(func, first()?).ok_or_else(bad),
        Func::EXPT => {
            let (a, b) = two(args, func)?;
            let e = b.as_f64();
            Ok(match a {
                Value::Real(x) => Value::Real(f::EXPT(*x, e)),
                Value::LReal(x) => Value::LReal(f::EXPT(*x, e)),
                _ => return Err(bad()),
            })
        }
        Func::TRUNC => Ok(match first()? {
            Value::Real(x) => Value::Int(f::TRUNC(*x) as i128, Elem::DINT),
            Value::LReal(x) => Value::Int(f::TRUNC(*x) as i128, Elem::DINT),
            _ => return Err(bad()),
        }),
        Func::SHL | Func::SHR | Func::ROL | Func::ROR => {
            let (a, b) = two(args, func)?;
            shift(func, a, b).ok_or_else(bad)
        }
        Func::SEL => match args {
            [g, a, b] => Ok(if g.as_bool() { b.clone() } else { a.clone() }),
            _ => Err(bad()),
        },
        Func::MAX | Func::MIN => {
            let (a, b) = two(args, func)?;
            Ok(max_min(func == Func::MAX, a.clone(), b.clone()))
        }
        Func::LIMIT => match args {
            [mn, x, mx] => Ok(max_min(
                false,
                max_min(true, x.clone(), mn.clone()),
                mx.clone(),
            )),
            _ => Err(bad()),
        },
        Func::ADD_TIME | Func::SUB_TIME => {
            let (a, b) = two(args, func)?;
            let op = if func == Func::ADD_TIME {
                Func::ADD
            } else {
                Func::SUB
            };
            arith(op, a, b).ok_or_else(bad)
        }
        Func::MUL_TIME | Func::DIV_TIME => {
            let (a, b) = two(args, func)?;
            let Value::Time(t, _) = a else {
                return Err(bad());
            };
            let t = il_std::TIME(*t);
            let mul = func == Func::MUL_TIME;
            let r = match b {
                Value::Int(n, e) => by_type!(*e, T => {
                    let n = *n as T;
                    if mul { f::MUL_TIME(t, n) } else { f::DIV_TIME(t, n) }
                }),
                Value::Real(n) => {
                    if mul {
                        f::MUL_TIME(t, *n)
                    } else {
                        f::DIV_TIME(t, *n)
                    }
                }
                Value::LReal(n) => {
                    if mul {
                        f::MUL_TIME(t, *n)
                    } else {
                        f::DIV_TIME(t, *n)
                    }
                }
                _ => return Err(bad()),
            };
            Ok(Value::Time(r.0, Elem::TIME))
        }
        Func::ADD_TOD_TIME
        | Func::SUB_TOD_TIME
        | Func::ADD_DT_TIME
        | Func::SUB_DT_TIME
        | Func::SUB_DATE_DATE
        | Func::SUB_TOD_TOD
        | Func::SUB_DT_DT
        | Func::CONCAT_DATE_TOD => {
            let (a, b) = two(args, func)?;
            let (Value::Time(x, _), Value::Time(y, _)) = (a, b) else {
                return Err(bad());
            };
            let (x, y) = (*x, *y);
            use il_std::{DATE, DT, TIME, TOD};
            Ok(match func {
                Func::ADD_TOD_TIME => Value::Time(f::ADD_TOD_TIME(TOD(x), TIME(y)).0, Elem::TOD),
                Func::SUB_TOD_TIME => Value::Time(f::SUB_TOD_TIME(TOD(x), TIME(y)).0, Elem::TOD),
                Func::ADD_DT_TIME => Value::Time(f::ADD_DT_TIME(DT(x), TIME(y)).0, Elem::DT),
                Func::SUB_DT_TIME => Value::Time(f::SUB_DT_TIME(DT(x), TIME(y)).0, Elem::DT),
                Func::SUB_DATE_DATE => {
                    Value::Time(f::SUB_DATE_DATE(DATE(x), DATE(y)).0, Elem::TIME)
                }
                Func::SUB_TOD_TOD => Value::Time(f::SUB_TOD_TOD(TOD(x), TOD(y)).0, Elem::TIME),
                Func::SUB_DT_DT => Value::Time(f::SUB_DT_DT(DT(x), DT(y)).0, Elem::TIME),
                _ => Value::Time(f::CONCAT_DATE_TOD(DATE(x), TOD(y)).0, Elem::DT),
            })
        }
        Func::LEN => match args.first() {
            Some(Value::Str { units, .. }) => Ok(Value::Int(units.len() as i128, Elem::INT)),
            _ => Err(bad()),
        },
        Func::LEFT
        | Func::RIGHT
        | Func::MID
        | Func::CONCAT
        | Func::INSERT
        | Func::DELETE
        | Func::REPLACE
        | Func::FIND => string_fn(func, args, ret).map(|(v, _)| v).ok_or_else(bad),
        // MUX is a call form of its own ([`StdCall::Mux`]); conversions are
        // evaluated from their table entry.
        Func::MUX | Func::Conversion => {
            Err(format!("internal: {func:?} evaluated as a plain function"))
        }
    }
}

/// A type conversion, by its entry in il-std's table (what it converts
/// from and to, and how), not by its name.
fn conversion(c: &Conversion, name: &str, args: &[Value]) -> Result<Value, String> {
    let bad = || format!("{name}: unexpected argument types in the interpreter");
    let x = args.first().ok_or_else(bad)?;
    let (Ty::Elem(from), Ty::Elem(to)) = (Ty::of_std(c.from), Ty::of_std(c.to)) else {
        return Err(unsupported(name));
    };
    match c.kind {
        ConvKind::Trunc => {
            let x = x.as_f64();
            let r = by_type!(to, T => il_std::conv::trunc_to_int_checked::<T>(x).0 as i128);
            Ok(Value::Int(r, to))
        }
        ConvKind::FromBcd | ConvKind::ToBcd => {
            let Value::Int(x, _) = x else {
                return Err(bad());
            };
            let r = if c.kind == ConvKind::FromBcd {
                il_std::conv::bcd_decode_checked(*x as u64).0 as i128
            } else {
                il_std::conv::bcd_encode_checked(*x, crate::values::bits(to) / 4).0 as i128
            };
            Ok(Value::Int(wrap(r, to), to))
        }
        ConvKind::Bits => match (x, to) {
            (Value::Int(b, _), Elem::REAL) => Ok(Value::Real(f32::from_bits(*b as u32))),
            (Value::Int(b, _), Elem::LREAL) => Ok(Value::LReal(f64::from_bits(*b as u64))),
            (Value::Real(r), _) => Ok(Value::Int(i128::from(r.to_bits()), to)),
            (Value::LReal(r), _) => Ok(Value::Int(i128::from(r.to_bits()), to)),
            _ => Err(bad()),
        },
        ConvKind::Value => convert(from, to, x).ok_or_else(|| unsupported(name)),
    }
}

/// Rounds `x` (ties to even, saturating, NaN → 0) into the integer type `to`.
fn real_to_int(x: f64, to: Elem) -> i128 {
    by_type!(to, T => il_std::conv::real_to_int::<T>(x) as i128)
}

/// An elementary conversion `FROM_TO_TO` (numbers, BOOL, durations, DT parts).
pub fn convert(from: Elem, to: Elem, v: &Value) -> Option<Value> {
    use Elem::*;
    let int_like = |e: Elem| e.is_int() || e.is_bitstring();
    Some(match (v, to) {
        (Value::Bool(b), _) if int_like(to) => Value::Int(*b as i128, to),
        (Value::Bool(b), REAL) => Value::Real(*b as u8 as f32),
        (Value::Bool(b), LREAL) => Value::LReal(*b as u8 as f64),
        (Value::Int(x, _), BOOL) => Value::Bool(*x != 0),
        (Value::Real(x), BOOL) => Value::Bool(*x != 0.0),
        (Value::LReal(x), BOOL) => Value::Bool(*x != 0.0),
        (Value::Int(x, _), _) if int_like(to) => Value::Int(wrap(*x, to), to),
        (Value::Int(x, _), REAL) => Value::Real(*x as f32),
        (Value::Int(x, _), LREAL) => Value::LReal(*x as f64),
        (Value::Real(x), _) if int_like(to) => Value::Int(real_to_int(*x as f64, to), to),
        (Value::LReal(x), _) if int_like(to) => Value::Int(real_to_int(*x, to), to),
        (Value::Real(x), LREAL) => Value::LReal(*x as f64),
        (Value::LReal(x), REAL) => Value::Real(*x as f32),
        (Value::Real(x), REAL) => Value::Real(*x),
        (Value::LReal(x), LREAL) => Value::LReal(*x),
        // TIME ↔ numbers: milliseconds.
        (Value::Time(ns, TIME), _) if int_like(to) => {
            Value::Int(wrap(il_std::TIME(*ns).as_ms() as i128, to), to)
        }
        (Value::Time(ns, TIME), REAL) => Value::Real((*ns as f64 / 1e6) as f32),
        (Value::Time(ns, TIME), LREAL) => Value::LReal(*ns as f64 / 1e6),
        (Value::Int(x, _), TIME) => Value::Time(il_std::TIME::from_ms(*x as i64).0, TIME),
        (Value::Real(x), TIME) => Value::Time(f::REAL_TO_TIME(*x).0, TIME),
        (Value::LReal(x), TIME) => Value::Time(f::LREAL_TO_TIME(*x).0, TIME),
        // LTIME ↔ numbers: nanoseconds.
        (Value::Time(ns, LTIME), _) if int_like(to) => Value::Int(wrap(*ns as i128, to), to),
        (Value::Time(ns, LTIME), REAL) => Value::Real(*ns as f32),
        (Value::Time(ns, LTIME), LREAL) => Value::LReal(*ns as f64),
        (Value::Int(x, _), LTIME) => Value::Time(*x as i64, LTIME),
        (Value::Real(x), LTIME) => Value::Time(f::REAL_TO_LTIME(*x).0, LTIME),
        (Value::LReal(x), LTIME) => Value::Time(f::LREAL_TO_LTIME(*x).0, LTIME),
        (Value::Time(ns, TIME | LTIME), TIME | LTIME) => Value::Time(*ns, to),
        (Value::Time(v, DT), TOD) => Value::Time(il_std::DT(*v).tod().0, TOD),
        (Value::Time(v, DT), DATE) => Value::Time(il_std::DT(*v).date().0, DATE),
        _ => {
            let _ = from;
            return None;
        }
    })
}

/// A standard function call. `kind` is the fault the checked call carries
/// (from the signature table); `fault` records it when its condition holds,
/// as the il-std function the generated code calls does.
pub fn call(
    call: &StdCall,
    args: &[Value],
    ret: &Ty,
    (kind, sig): (Option<FaultKind>, &Signature),
    fault: &mut dyn FnMut(FaultKind),
) -> Result<Value, String> {
    let name = sig.name;
    // A conversion is evaluated from its table entry, the others by the
    // table's `func`.
    let plain = |args: &[Value]| match &sig.conversion {
        Some(c) => conversion(c, name, args),
        None => plain(sig.func, args, ret),
    };
    match (call, kind) {
        // DIV, MOD and DIV_TIME by an integer zero give 0 (T#0s) and record
        // the fault.
        (StdCall::Plain(_), Some(k @ FaultKind::DivisionByZero)) => {
            if let Some(Value::Int(0, _)) = args.get(1) {
                fault(k);
            }
            plain(args)
        }
        // REAL → integer conversions out of range (or NaN) saturate and
        // record the fault; the rounding is the table's.
        (StdCall::Plain(_), Some(k @ FaultKind::ConversionOutOfRange)) => {
            let x = args.first().map(Value::as_f64).unwrap_or(0.0);
            let r = match sig.rounding {
                Some(Rounding::TowardZero) => x.trunc(),
                _ => x.round_ties_even(),
            };
            let (lo, hi) = ret.elem().and_then(Elem::int_range).unwrap_or((0, 0));
            if !r.is_finite() || r < lo as f64 || r > hi as f64 {
                fault(k);
            }
            plain(args)
        }
        // INSERT and REPLACE cut to the capacity record it.
        (StdCall::Plain(_), Some(k @ FaultKind::StringOverflow)) => {
            let (v, cut) = string_fn(sig.func, args, ret).ok_or_else(|| bad_args(sig.func))?;
            if cut {
                fault(k);
            }
            Ok(v)
        }
        (StdCall::Plain(_), _) => plain(args),
        // Each step of CONCAT that truncates records a fault.
        (StdCall::Fold(_), Some(k @ FaultKind::StringOverflow)) => {
            let mut it = args.iter();
            let mut acc = it
                .next()
                .cloned()
                .ok_or_else(|| format!("{name}: no arguments"))?;
            for a in it {
                let (v, cut) = string_fn(sig.func, &[acc, a.clone()], ret)
                    .ok_or_else(|| bad_args(sig.func))?;
                if cut {
                    fault(k);
                }
                acc = v;
            }
            Ok(acc)
        }
        (StdCall::Fold(_), _) => {
            let mut it = args.iter();
            let mut acc = it
                .next()
                .cloned()
                .ok_or_else(|| format!("{name}: no arguments"))?;
            for a in it {
                acc = plain(&[acc, a.clone()])?;
            }
            Ok(acc)
        }
        (StdCall::Chain(_), _) => {
            let mut all = true;
            for w in args.windows(2) {
                all &= plain(w)?.as_bool();
            }
            Ok(Value::Bool(all))
        }
        // MUX: a selector out of range gives IN0 and records the fault.
        (StdCall::Mux, kind) => {
            let k = args.first().map(Value::as_i64).unwrap_or(0);
            let ins = args.get(1..).unwrap_or_default();
            match usize::try_from(k).ok().and_then(|k| ins.get(k)) {
                Some(v) => Ok(v.clone()),
                None => {
                    fault(kind.unwrap_or(FaultKind::InvalidArgument));
                    ins.first()
                        .cloned()
                        .ok_or_else(|| "MUX without inputs".to_string())
                }
            }
        }
    }
}
