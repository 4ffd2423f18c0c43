//! The string functions, by il-std's own implementations on il-std strings
//! sized at run time.

use crate::values::Value;
use il_codegen::ir::types::{Elem, Ty};
use il_std::signature::Func;

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
pub(super) fn string_fn(func: Func, args: &[Value], ret: &Ty) -> Option<(Value, bool)> {
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
            string_op::<WSTRING<N>>(func, st(0)?, st(1), &ints)?
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
            string_op::<STRING<N>>(func, st(0)?, st(1), &ints)?
        })
    };
    if func == Func::FIND {
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
fn string_op<S>(func: Func, a: S, b: Option<S>, ints: &[i64]) -> Option<Vec<u16>>
where
    S: il_std::num::AnyString,
    S::Unit: Into<u16>,
{
    use il_std::func as f;
    let int = |i: usize| ints.get(i).copied();
    let r: S = match func {
        Func::LEFT => f::LEFT(a, int(0)?),
        Func::RIGHT => f::RIGHT(a, int(0)?),
        Func::MID => f::MID(a, int(0)?, int(1)?),
        Func::CONCAT => f::CONCAT(a, b?),
        Func::INSERT => f::INSERT(a, b?, int(0)?),
        Func::DELETE => f::DELETE(a, int(0)?, int(1)?),
        Func::REPLACE => f::REPLACE(a, b?, int(0)?, int(1)?),
        Func::FIND => return Some(vec![f::FIND(a, b?) as u16]),
        _ => return None,
    };
    Some(r.units().iter().map(|&u| u.into()).collect())
}
