//! The implicit widening conversions of the 3rd edition (Ed.3 Figures 11
//! and 12, the lossless ones only): the one table the checker consults.
//! The checker records each conversion it applies as an
//! [`ir::Widen`](super::ir::Widen); the emitter and the interpreter apply
//! the recorded conversion and never consult this table.

use super::ir::{Const, Widen};
use super::types::{Elem, Ty};
use Elem::*;

/// Bits of a signed integer type (0: not one).
fn signed_bits(e: Elem) -> u32 {
    match e {
        SINT => 8,
        INT => 16,
        DINT => 32,
        LINT => 64,
        _ => 0,
    }
}

/// Bits of an unsigned integer type (0: not one).
fn unsigned_bits(e: Elem) -> u32 {
    match e {
        USINT => 8,
        UINT => 16,
        UDINT => 32,
        ULINT => 64,
        _ => 0,
    }
}

/// Bits of BOOL or a bit string (0: neither).
fn bitstring_bits(e: Elem) -> u32 {
    match e {
        BOOL => 1,
        BYTE => 8,
        WORD => 16,
        DWORD => 32,
        LWORD => 64,
        _ => 0,
    }
}

/// Whether a value of `from` becomes a `to` implicitly, without loss:
/// SINT→INT→DINT→LINT, USINT→UINT→UDINT→ULINT, an unsigned integer into a
/// wider signed one, BOOL→BYTE→WORD→DWORD→LWORD, REAL→LREAL,
/// SINT/INT/USINT/UINT→REAL, integers of up to 32 bits→LREAL, TIME→LTIME
/// (and each chain's transitive steps).
pub fn widens(from: Elem, to: Elem) -> bool {
    let (s, u, b) = (signed_bits(from), unsigned_bits(from), bitstring_bits(from));
    match to {
        SINT | INT | DINT | LINT => {
            let t = signed_bits(to);
            (s > 0 && s < t) || (u > 0 && u < t)
        }
        USINT | UINT | UDINT | ULINT => u > 0 && u < unsigned_bits(to),
        BYTE | WORD | DWORD | LWORD => b > 0 && b < bitstring_bits(to),
        REAL => (s > 0 && s <= 16) || (u > 0 && u <= 16),
        LREAL => from == REAL || (s > 0 && s <= 32) || (u > 0 && u <= 32),
        LTIME => from == TIME,
        _ => false,
    }
}

/// The conversion of a value of type `from` to type `to`, when it is an
/// implicit widening.
pub fn widening(from: &Ty, to: &Ty) -> Option<Widen> {
    let (Ty::Elem(f), Ty::Elem(t)) = (from, to) else {
        return None;
    };
    widens(*f, *t).then_some(Widen { from: *f, to: *t })
}

/// The wider of two types that meet at an operator, when one widens into the
/// other: the CR and the operand both take it.
pub fn wider(a: &Ty, b: &Ty) -> Option<Ty> {
    if widening(a, b).is_some() {
        Some(b.clone())
    } else if widening(b, a).is_some() {
        Some(a.clone())
    } else {
        None
    }
}

/// A typed constant widened to `to` (for literals like `INT#5` and initial
/// values; the checker folds these instead of converting at run time).
pub fn widen_const(c: &Const, to: Elem) -> Option<Const> {
    let from = c.ty().elem()?;
    if !widens(from, to) {
        return None;
    }
    Some(match c {
        Const::Bool(b) => Const::Int(i128::from(*b).into(), to),
        Const::Int(v, _) if to.is_real() => Const::Real(v.get() as f64, to),
        Const::Int(v, _) => Const::Int(*v, to),
        // REAL constants are held as f64 already rounded to f32.
        Const::Real(v, _) => Const::Real(*v, to),
        Const::Time(v, _) => Const::Time(*v, to),
        _ => return None,
    })
}

/// The conversion function that narrows (or otherwise converts) `from`
/// into `to` explicitly: `DINT_TO_INT`.
pub fn conversion_name(from: Elem, to: Elem) -> String {
    let short = |e: Elem| match e {
        TOD => "TOD",
        DT => "DT",
        e => e.name(),
    };
    format!("{}_TO_{}", short(from), short(to))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sema::types::ALL_ELEMS;

    #[test]
    fn the_table_is_lossless_and_transitive() {
        // Every widening keeps every value: the target's range holds the source's.
        for &f in ALL_ELEMS {
            for &t in ALL_ELEMS {
                if !widens(f, t) {
                    continue;
                }
                if let (Some((fl, fh)), Some((tl, th))) = (f.int_range(), t.int_range()) {
                    assert!(tl <= fl && fh <= th, "{f:?} → {t:?}");
                }
                assert!(!widens(t, f), "{f:?} ↔ {t:?}");
                for &u in ALL_ELEMS {
                    if widens(t, u) {
                        assert!(widens(f, u), "{f:?} → {t:?} → {u:?}");
                    }
                }
            }
        }
        assert!(widens(SINT, LINT) && widens(USINT, INT) && widens(UDINT, LINT));
        assert!(widens(BOOL, LWORD) && widens(UINT, REAL) && widens(DINT, LREAL));
        assert!(widens(TIME, LTIME) && widens(REAL, LREAL));
        assert!(!widens(INT, UINT) && !widens(DINT, REAL) && !widens(LINT, LREAL));
        assert!(!widens(BYTE, INT) && !widens(INT, WORD) && !widens(BOOL, INT));
        assert!(!widens(ULINT, LINT) && !widens(DINT, INT));
    }
}
