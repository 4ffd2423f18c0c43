//! Conversion helpers behind the `*_TO_*` functions of [`func`](crate::func), with `_checked`
//! variants that also report whether the value was out of range, so that generated code can
//! record a [`FaultKind::ConversionOutOfRange`](crate::FaultKind::ConversionOutOfRange) or
//! [`FaultKind::InvalidArgument`](crate::FaultKind::InvalidArgument) fault.

use crate::math::{round_half_even, trunc};
use crate::num::AnyInt;

fn int_bounds<I: AnyInt>() -> (f64, f64, I, I) {
    let (lo, hi) = if I::SIGNED {
        (-(1i128 << (I::BITS - 1)), (1i128 << (I::BITS - 1)) - 1)
    } else {
        (0, (1i128 << I::BITS) - 1)
    };
    // `lo` and `hi + 1` are powers of two (or zero), exactly representable as f64.
    (
        lo as f64,
        (hi + 1) as f64,
        I::from_i128_wrapping(lo),
        I::from_i128_wrapping(hi),
    )
}

fn float_to_int_checked<I: AnyInt>(r: f64) -> (I, bool) {
    let (lo, hi_excl, min, max) = int_bounds::<I>();
    if r.is_nan() {
        (I::from_i128_wrapping(0), true)
    } else if r < lo {
        (min, true)
    } else if r >= hi_excl {
        (max, true)
    } else {
        (I::from_i128_wrapping(r as i128), false)
    }
}

/// `REAL`/`LREAL` → integer as the `*_TO_*` functions do it: rounded to the nearest integer,
/// **ties to even** (`2.5 → 2`, `3.5 → 4`, `-2.5 → -2`); out of range saturates at the type's
/// bounds and NaN gives 0. The flag is `true` when the value was out of range or NaN.
pub fn real_to_int_checked<I: AnyInt>(x: f64) -> (I, bool) {
    float_to_int_checked(round_half_even(x))
}

/// [`real_to_int_checked`] without the flag.
pub fn real_to_int<I: AnyInt>(x: f64) -> I {
    real_to_int_checked(x).0
}

/// `REAL`/`LREAL` → integer truncated toward zero (`TRUNC`), saturating, NaN → 0; the flag
/// is `true` when the value was out of range or NaN.
pub fn trunc_to_int_checked<I: AnyInt>(x: f64) -> (I, bool) {
    float_to_int_checked(trunc(x))
}

/// Integer → integer as the `*_TO_*` functions do it: two's complement truncation (or sign/zero
/// extension), e.g. `DINT_TO_INT(70000) = 4464`, `INT_TO_UINT(-1) = 65535`. The flag is `true`
/// when the value changed.
pub fn int_to_int_checked<S: AnyInt, D: AnyInt>(x: S) -> (D, bool) {
    let v = x.to_i128();
    let d = D::from_i128_wrapping(v);
    (d, d.to_i128() != v)
}

/// Decodes packed BCD (4 bits per decimal digit, least significant digit in the low nibble).
/// A nibble above 9 is invalid: the result is then 0 and the flag `true`.
pub fn bcd_decode_checked(x: u64) -> (u64, bool) {
    let mut r: u64 = 0;
    let mut shift = 64;
    while shift > 0 {
        shift -= 4;
        let d = (x >> shift) & 0xF;
        if d > 9 {
            return (0, true);
        }
        r = r * 10 + d;
    }
    (r, false)
}

/// Encodes `v` as packed BCD of at most `digits` digits. A negative value or one with more
/// digits gives 0 and the flag `true`.
pub fn bcd_encode_checked(v: i128, digits: u32) -> (u64, bool) {
    if v < 0 {
        return (0, true);
    }
    let mut v = v;
    let mut r: u64 = 0;
    let mut i = 0;
    while v > 0 {
        if i >= digits || i >= 16 {
            return (0, true);
        }
        r |= ((v % 10) as u64) << (4 * i);
        v /= 10;
        i += 1;
    }
    (r, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn real_to_int_rounding_and_range() {
        assert_eq!(real_to_int::<i16>(2.5), 2);
        assert_eq!(real_to_int::<i16>(3.5), 4);
        assert_eq!(real_to_int::<i16>(-2.5), -2);
        assert_eq!(real_to_int::<i16>(-2.6), -3);
        assert_eq!(real_to_int::<i16>(0.49999999999999994), 0);
        assert_eq!(real_to_int_checked::<i16>(32767.4), (32767, false));
        assert_eq!(real_to_int_checked::<i16>(32767.5), (32767, true));
        assert_eq!(real_to_int_checked::<i16>(-32768.5), (-32768, false));
        assert_eq!(real_to_int_checked::<i16>(-32769.0), (-32768, true));
        assert_eq!(real_to_int_checked::<i16>(f64::NAN), (0, true));
        assert_eq!(real_to_int_checked::<u8>(-0.4), (0, false));
        assert_eq!(real_to_int_checked::<u8>(-0.6), (0, true));
        assert_eq!(real_to_int_checked::<u64>(1e30), (u64::MAX, true));
        assert_eq!(
            real_to_int_checked::<i64>(i64::MAX as f64),
            (i64::MAX, true)
        );
        assert_eq!(
            real_to_int_checked::<i64>(i64::MIN as f64),
            (i64::MIN, false)
        );
        assert_eq!(
            real_to_int_checked::<i64>(f64::NEG_INFINITY),
            (i64::MIN, true)
        );
        assert_eq!(real_to_int_checked::<u64>(f64::INFINITY), (u64::MAX, true));
        assert_eq!(trunc_to_int_checked::<i8>(-3.9), (-3, false));
        assert_eq!(trunc_to_int_checked::<i8>(127.9), (127, false));
        assert_eq!(trunc_to_int_checked::<i8>(128.0), (127, true));
    }

    #[test]
    fn int_to_int() {
        assert_eq!(int_to_int_checked::<i32, i16>(70000), (4464, true));
        assert_eq!(int_to_int_checked::<i16, u16>(-1), (65535, true));
        assert_eq!(int_to_int_checked::<i16, i64>(-1), (-1, false));
        assert_eq!(int_to_int_checked::<u64, i64>(u64::MAX), (-1, true));
    }

    #[test]
    fn bcd() {
        assert_eq!(bcd_decode_checked(0x1234), (1234, false));
        assert_eq!(
            bcd_decode_checked(0x9999_9999_9999_9999),
            (9_999_999_999_999_999, false)
        );
        assert_eq!(bcd_decode_checked(0x12A4), (0, true));
        assert_eq!(bcd_encode_checked(1234, 4), (0x1234, false));
        assert_eq!(bcd_encode_checked(0, 2), (0, false));
        assert_eq!(bcd_encode_checked(100, 2), (0, true));
        assert_eq!(bcd_encode_checked(-1, 4), (0, true));
        assert_eq!(
            bcd_encode_checked(9_999_999_999_999_999, 16),
            (0x9999_9999_9999_9999, false)
        );
        assert_eq!(bcd_encode_checked(i128::MAX, 16), (0, true));
    }
}
