//! Standard functions, dispatched by name on runtime values. Each computes
//! what the il-std function the emitter calls computes (most call it).

use crate::values::{Value, wrap};
use il_codegen::ir::StdCall;
use il_codegen::ir::types::{Elem, Ty};
use il_std::FaultKind;
use il_std::func as f;
use il_std::signature::{ConvKind, Conversion, Rounding, Signature};
use std::cmp::Ordering;

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

pub fn cmp_op(name: &str, a: &Value, b: &Value) -> Option<bool> {
    let o = compare(a, b);
    Some(match name {
        "GT" => o == Some(Ordering::Greater),
        "GE" => matches!(o, Some(Ordering::Greater | Ordering::Equal)),
        "EQ" => o == Some(Ordering::Equal),
        "NE" => o != Some(Ordering::Equal),
        "LE" => matches!(o, Some(Ordering::Less | Ordering::Equal)),
        "LT" => o == Some(Ordering::Less),
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
pub fn arith(name: &str, a: &Value, b: &Value) -> Option<Value> {
    Some(match (a, b) {
        (Value::Int(x, e), Value::Int(y, _)) => {
            let r = match name {
                "ADD" => x.wrapping_add(*y),
                "SUB" => x.wrapping_sub(*y),
                "MUL" => x.wrapping_mul(*y),
                _ => return None,
            };
            Value::Int(wrap(r, *e), *e)
        }
        (Value::Real(x), Value::Real(y)) => Value::Real(match name {
            "ADD" => x + y,
            "SUB" => x - y,
            "MUL" => x * y,
            "DIV" => x / y,
            "MOD" => x % y,
            _ => return None,
        }),
        (Value::LReal(x), Value::LReal(y)) => Value::LReal(match name {
            "ADD" => x + y,
            "SUB" => x - y,
            "MUL" => x * y,
            "DIV" => x / y,
            "MOD" => x % y,
            _ => return None,
        }),
        (Value::Time(x, e), Value::Time(y, _)) => Value::Time(
            match name {
                "ADD" => x.wrapping_add(*y),
                "SUB" => x.wrapping_sub(*y),
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

fn bitop(name: &str, a: &Value, b: &Value) -> Option<Value> {
    Some(match (a, b) {
        (Value::Bool(x), Value::Bool(y)) => Value::Bool(match name {
            "AND" => x & y,
            "OR" => x | y,
            "XOR" => x ^ y,
            _ => return None,
        }),
        (Value::Int(x, e), Value::Int(y, _)) => Value::Int(
            match name {
                "AND" => x & y,
                "OR" => x | y,
                "XOR" => x ^ y,
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

fn real_unary(name: &str, v: &Value) -> Option<Value> {
    macro_rules! un {
        ($x:expr) => {
            match name {
                "SQRT" => f::SQRT($x),
                "LN" => f::LN($x),
                "LOG" => f::LOG($x),
                "EXP" => f::EXP($x),
                "SIN" => f::SIN($x),
                "COS" => f::COS($x),
                "TAN" => f::TAN($x),
                "ASIN" => f::ASIN($x),
                "ACOS" => f::ACOS($x),
                "ATAN" => f::ATAN($x),
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

fn shift(name: &str, v: &Value, n: &Value) -> Option<Value> {
    let Value::Int(x, e) = v else { return None };
    let Value::Int(n, _) = n else { return None };
    let e = *e;
    // The count's type only matters through its value.
    macro_rules! op {
        ($y:expr, $c:expr) => {
            match name {
                "SHL" => f::SHL($y, $c),
                "SHR" => f::SHR($y, $c),
                "ROL" => f::ROL($y, $c),
                "ROR" => f::ROR($y, $c),
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

fn two<'a>(args: &'a [Value], name: &str) -> Result<(&'a Value, &'a Value), String> {
    match args {
        [a, b, ..] => Ok((a, b)),
        _ => Err(format!("{name}: missing arguments")),
    }
}

/// The IL operator `name` (ADD, DIV, AND, GT ...) on `a` and `b`, as the
/// standard function of that name: none of them needs the result type.
pub fn operator(name: &str, a: &Value, b: &Value) -> Result<Value, String> {
    let bad = || format!("{name}: unexpected argument types in the interpreter");
    match name {
        "ADD" | "SUB" | "MUL" => arith(name, a, b).ok_or_else(bad),
        "DIV" | "MOD" => match (a, b) {
            // A zero divisor gives 0 (il_std::func::DIV); `call` records
            // the fault the checked call carries.
            (Value::Int(x, e), Value::Int(y, _)) => Ok(Value::Int(
                int_divmod(name == "DIV", *x, *y, *e).unwrap_or(0),
                *e,
            )),
            _ => arith(name, a, b).ok_or_else(bad),
        },
        "AND" | "OR" | "XOR" => bitop(name, a, b).ok_or_else(bad),
        "GT" | "GE" | "EQ" | "NE" | "LE" | "LT" => {
            Ok(Value::Bool(cmp_op(name, a, b).ok_or_else(bad)?))
        }
        _ => Err(format!("{name}: not an operator")),
    }
}

/// One call of the two-argument (or fixed) form of the function `name`.
pub fn plain(name: &str, args: &[Value], ret: &Ty) -> Result<Value, String> {
    let bad = || format!("{name}: unexpected argument types in the interpreter");
    match name {
        "ADD" | "SUB" | "MUL" | "DIV" | "MOD" | "AND" | "OR" | "XOR" | "GT" | "GE" | "EQ"
        | "NE" | "LE" | "LT" => {
            let (a, b) = two(args, name)?;
            operator(name, a, b)
        }
        "NOT" => Ok(not(args.first().ok_or_else(bad)?)),
        "MOVE" => args.first().cloned().ok_or_else(bad),
        "ABS" => Ok(match args.first().ok_or_else(bad)? {
            Value::Int(x, e) => Value::Int(wrap(x.abs(), *e), *e),
            Value::Real(x) => Value::Real(f::ABS(*x)),
            Value::LReal(x) => Value::LReal(f::ABS(*x)),
            _ => return Err(bad()),
        }),
        "SQRT" | "LN" | "LOG" | "EXP" | "SIN" | "COS" | "TAN" | "ASIN" | "ACOS" | "ATAN" => {
            real_unary(name, args.first().ok_or_else(bad)?).ok_or_else(bad)
        }
        "EXPT" => {
            let (a, b) = two(args, name)?;
            let e = b.as_f64();
            Ok(match a {
                Value::Real(x) => Value::Real(f::EXPT(*x, e)),
                Value::LReal(x) => Value::LReal(f::EXPT(*x, e)),
                _ => return Err(bad()),
            })
        }
        "TRUNC" => Ok(match args.first().ok_or_else(bad)? {
            Value::Real(x) => Value::Int(f::TRUNC(*x) as i128, Elem::DINT),
            Value::LReal(x) => Value::Int(f::TRUNC(*x) as i128, Elem::DINT),
            _ => return Err(bad()),
        }),
        "SHL" | "SHR" | "ROL" | "ROR" => {
            let (a, b) = two(args, name)?;
            shift(name, a, b).ok_or_else(bad)
        }
        "SEL" => match args {
            [g, a, b] => Ok(if g.as_bool() { b.clone() } else { a.clone() }),
            _ => Err(bad()),
        },
        "MAX" | "MIN" => {
            let (a, b) = two(args, name)?;
            Ok(max_min(name == "MAX", a.clone(), b.clone()))
        }
        "LIMIT" => match args {
            [mn, x, mx] => Ok(max_min(
                false,
                max_min(true, x.clone(), mn.clone()),
                mx.clone(),
            )),
            _ => Err(bad()),
        },
        "ADD_TIME" | "SUB_TIME" => {
            let (a, b) = two(args, name)?;
            arith(&name[..3], a, b).ok_or_else(bad)
        }
        "MUL_TIME" | "DIV_TIME" => {
            let (a, b) = two(args, name)?;
            let Value::Time(t, _) = a else {
                return Err(bad());
            };
            let t = il_std::TIME(*t);
            let mul = name == "MUL_TIME";
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
        "ADD_TOD_TIME" | "SUB_TOD_TIME" | "ADD_DT_TIME" | "SUB_DT_TIME" | "SUB_DATE_DATE"
        | "SUB_TOD_TOD" | "SUB_DT_DT" | "CONCAT_DATE_TOD" => {
            let (a, b) = two(args, name)?;
            let (Value::Time(x, _), Value::Time(y, _)) = (a, b) else {
                return Err(bad());
            };
            let (x, y) = (*x, *y);
            use il_std::{DATE, DT, TIME, TOD};
            Ok(match name {
                "ADD_TOD_TIME" => Value::Time(f::ADD_TOD_TIME(TOD(x), TIME(y)).0, Elem::TOD),
                "SUB_TOD_TIME" => Value::Time(f::SUB_TOD_TIME(TOD(x), TIME(y)).0, Elem::TOD),
                "ADD_DT_TIME" => Value::Time(f::ADD_DT_TIME(DT(x), TIME(y)).0, Elem::DT),
                "SUB_DT_TIME" => Value::Time(f::SUB_DT_TIME(DT(x), TIME(y)).0, Elem::DT),
                "SUB_DATE_DATE" => Value::Time(f::SUB_DATE_DATE(DATE(x), DATE(y)).0, Elem::TIME),
                "SUB_TOD_TOD" => Value::Time(f::SUB_TOD_TOD(TOD(x), TOD(y)).0, Elem::TIME),
                "SUB_DT_DT" => Value::Time(f::SUB_DT_DT(DT(x), DT(y)).0, Elem::TIME),
                _ => Value::Time(f::CONCAT_DATE_TOD(DATE(x), TOD(y)).0, Elem::DT),
            })
        }
        "LEN" => match args.first() {
            Some(Value::Str { units, .. }) => Ok(Value::Int(units.len() as i128, Elem::INT)),
            _ => Err(bad()),
        },
        "LEFT" | "RIGHT" | "MID" | "CONCAT" | "INSERT" | "DELETE" | "REPLACE" | "FIND" => {
            string_fn(name, args, ret).map(|(v, _)| v).ok_or_else(bad)
        }
        _ => Err(unsupported(name)),
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
        ConvKind::Value => convert(from, to, x).ok_or_else(|| unsupported(name)),
    }
}

/// An integer argument for il-std's string functions, saturated to `i64`
/// (they clamp lengths and positions, so a saturated ULINT clamps the same).
fn int_arg(v: &Value) -> Option<i64> {
    match v {
        Value::Int(x, _) => Some((*x).clamp(i64::MIN as i128, i64::MAX as i128) as i64),
        _ => None,
    }
}

/// Runs `$body` with `$N` a capacity of at least `$n` (il-std strings have
/// their capacity in the type; the interpreter's have it at run time).
macro_rules! with_capacity {
    ($n:expr, $N:ident => $body:expr) => {{
        let n: usize = $n;
        if n <= 16 {
            const $N: usize = 16;
            $body
        } else if n <= 256 {
            const $N: usize = 256;
            $body
        } else if n <= 4096 {
            const $N: usize = 4096;
            $body
        } else {
            // Two strings of the largest declared length (65535) together.
            const $N: usize = 2 * 65535;
            $body
        }
    }};
}

/// The string functions LEFT RIGHT MID CONCAT INSERT DELETE REPLACE FIND, by
/// il-std's own implementations (so clamping of lengths and positions is the
/// generated code's). They run on il-std strings large enough to hold all the
/// arguments together, so il-std never truncates; the result is then cut to
/// the capacity of the result type `ret` (the first argument's, as in il-std)
/// and the flag says whether that cut something off.
fn string_fn(name: &str, args: &[Value], ret: &Ty) -> Option<(Value, bool)> {
    let mut strs: Vec<&[u16]> = Vec::new();
    let mut ints: Vec<i64> = Vec::new();
    let mut wide = false;
    for a in args {
        match a {
            Value::Str { units, wide: w } => {
                strs.push(units);
                wide = *w;
            }
            other => ints.push(int_arg(other)?),
        }
    }
    let total: usize = strs.iter().map(|u| u.len()).sum();
    let units: Vec<u16> = if wide {
        use il_std::WSTRING;
        with_capacity!(total, N => {
            let st = |i: usize| strs.get(i).map(|u| WSTRING::<N>::from_units_truncating(u).0);
            string_op::<WSTRING<N>>(name, st(0)?, st(1), &ints)?
        })
    } else {
        use il_std::STRING;
        with_capacity!(total, N => {
            let st = |i: usize| {
                strs.get(i).map(|u| {
                    let bytes: Vec<u8> = u.iter().map(|&c| c as u8).collect();
                    STRING::<N>::from_units_truncating(&bytes).0
                })
            };
            string_op::<STRING<N>>(name, st(0)?, st(1), &ints)?
        })
    };
    if name == "FIND" {
        return Some((
            Value::Int(units.first().copied()? as i16 as i128, Elem::INT),
            false,
        ));
    }
    let cap = match ret {
        Ty::Str { len, .. } => *len as usize,
        _ => units.len(),
    };
    let cut = units.len() > cap;
    let mut units = units;
    units.truncate(cap);
    Some((Value::Str { units, wide }, cut))
}

/// One il-std string function on il-std strings; the result's units (FIND:
/// the position as the only unit).
fn string_op<S>(name: &str, a: S, b: Option<S>, ints: &[i64]) -> Option<Vec<u16>>
where
    S: il_std::num::AnyString,
    S::Unit: Into<u16>,
{
    use il_std::func as f;
    let int = |i: usize| ints.get(i).copied();
    let r: S = match name {
        "LEFT" => f::LEFT(a, int(0)?),
        "RIGHT" => f::RIGHT(a, int(0)?),
        "MID" => f::MID(a, int(0)?, int(1)?),
        "CONCAT" => f::CONCAT(a, b?),
        "INSERT" => f::INSERT(a, b?, int(0)?),
        "DELETE" => f::DELETE(a, int(0)?, int(1)?),
        "REPLACE" => f::REPLACE(a, b?, int(0)?, int(1)?),
        "FIND" => return Some(vec![f::FIND(a, b?) as u16]),
        _ => return None,
    };
    Some(r.units().iter().map(|&u| u.into()).collect())
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

/// A standard function call as the emitter generates it. `kind` is the
/// fault the checked call carries (from the signature table); `fault`
/// records it when its condition holds.
pub fn call(
    call: &StdCall,
    args: &[Value],
    ret: &Ty,
    (kind, sig): (Option<FaultKind>, &Signature),
    fault: &mut dyn FnMut(FaultKind),
) -> Result<Value, String> {
    let rounding = sig.rounding;
    // A conversion is evaluated from its table entry; the others by name.
    let plain = |n: &str, args: &[Value], ret: &Ty| match &sig.conversion {
        Some(c) => conversion(c, n, args),
        None => plain(n, args, ret),
    };
    match (call, kind) {
        // As the emitter: DIV, MOD and DIV_TIME by an integer zero give 0
        // (T#0s) and record the fault.
        (StdCall::Plain(n), Some(k @ FaultKind::DivisionByZero)) => {
            if let Some(Value::Int(0, _)) = args.get(1) {
                fault(k);
            }
            plain(n, args, ret)
        }
        // As the emitter: REAL → integer conversions out of range (or NaN)
        // saturate and record the fault.
        (StdCall::Plain(n), Some(k @ FaultKind::ConversionOutOfRange)) => {
            let x = args.first().map(Value::as_f64).unwrap_or(0.0);
            // The fault and the rounding are the table's.
            let r = match rounding {
                Some(Rounding::TowardZero) => x.trunc(),
                _ => x.round_ties_even(),
            };
            let (lo, hi) = ret.elem().and_then(Elem::int_range).unwrap_or((0, 0));
            if !r.is_finite() || r < lo as f64 || r > hi as f64 {
                fault(k);
            }
            plain(n, args, ret)
        }
        // As the emitter: INSERT and REPLACE cut to the capacity record it.
        (StdCall::Plain(n), Some(k @ FaultKind::StringOverflow)) => {
            let (v, cut) = string_fn(n, args, ret)
                .ok_or_else(|| format!("{n}: unexpected argument types in the interpreter"))?;
            if cut {
                fault(k);
            }
            Ok(v)
        }
        (StdCall::Plain(n), _) => plain(n, args, ret),
        // As the emitter: each step of CONCAT that truncates records a fault.
        (StdCall::Fold(n), Some(k @ FaultKind::StringOverflow)) => {
            let mut it = args.iter();
            let mut acc = it
                .next()
                .cloned()
                .ok_or_else(|| format!("{n}: no arguments"))?;
            for a in it {
                let (v, cut) = string_fn(n, &[acc, a.clone()], ret)
                    .ok_or_else(|| format!("{n}: unexpected argument types in the interpreter"))?;
                if cut {
                    fault(k);
                }
                acc = v;
            }
            Ok(acc)
        }
        (StdCall::Fold(n), _) => {
            let mut it = args.iter();
            let mut acc = it
                .next()
                .cloned()
                .ok_or_else(|| format!("{n}: no arguments"))?;
            for a in it {
                acc = plain(n, &[acc, a.clone()], ret)?;
            }
            Ok(acc)
        }
        (StdCall::Chain(n), _) => {
            let mut all = true;
            for w in args.windows(2) {
                all &= plain(n, w, ret)?.as_bool();
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
