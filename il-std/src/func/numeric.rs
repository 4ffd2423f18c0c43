//! Numeric functions of `ANY_REAL`: SQRT LN LOG EXP SIN COS TAN ASIN ACOS ATAN EXPT, and TRUNC.
//!
//! Computed by [`math`](crate::math): libm's pure-Rust code, the same bits on every target, so
//! results are reproducible, and within 1 ulp of the correctly rounded result. `REAL` uses the
//! `f32` functions, `LREAL` the `f64` ones. NaN and infinities follow IEEE 754.

use crate::math;
use crate::num::{AnyNum, AnyReal};

macro_rules! unary_real {
    ($($name:ident => $f:ident, $ff:ident, $doc:literal;)*) => {$(
        #[doc = $doc]
        pub fn $name<T: AnyReal>(IN: T) -> T {
            IN.apply(math::$f, math::$ff)
        }
    )*};
}

unary_real! {
    SQRT => sqrt, sqrtf, "`SQRT`: square root (`SQRT(-1.0)` is NaN).";
    LN => ln, lnf, "`LN`: natural logarithm (`LN(0.0) = -∞`, negative arguments give NaN).";
    LOG => log10, log10f, "`LOG`: base-10 logarithm (`LOG(0.0) = -∞`, negative arguments give NaN).";
    EXP => exp, expf, "`EXP`: natural exponential `e^IN` (overflow gives +∞).";
    SIN => sin, sinf, "`SIN`: sine of `IN` radians.";
    COS => cos, cosf, "`COS`: cosine of `IN` radians.";
    TAN => tan, tanf, "`TAN`: tangent of `IN` radians.";
    ASIN => asin, asinf, "`ASIN`: principal arc sine in `[-π/2, π/2]` (NaN outside `[-1, 1]`).";
    ACOS => acos, acosf, "`ACOS`: principal arc cosine in `[0, π]` (NaN outside `[-1, 1]`).";
    ATAN => atan, atanf, "`ATAN`: principal arc tangent in `[-π/2, π/2]`.";
}

/// `EXPT`: `IN1` raised to the power `IN2` (`IN1: ANY_REAL`, `IN2: ANY_NUM`), with the IEEE 754
/// `pow` special cases (`EXPT(x, 0) = 1`, a negative base with a non-integer exponent is NaN,
/// `EXPT(0.0, -1) = +∞`). The exponent is used exactly, whatever its type (see
/// [`math::powf`]): an integer exponent of a negative base keeps its parity.
pub fn EXPT<T: AnyReal, E: AnyNum>(IN1: T, IN2: E) -> T {
    IN1.iec_pow(IN2.to_f64())
}

/// `TRUNC`: truncates toward zero to a `DINT` (`TRUNC(-1.6) = -1`); out of range saturates
/// and NaN gives 0. The typed forms `REAL_TRUNC_INT` ... `LREAL_TRUNC_ULINT` give other
/// integer types.
pub fn TRUNC<T: AnyReal>(IN: T) -> i32 {
    crate::conv::trunc_to_int_checked(IN.to_f64()).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals() {
        assert_eq!(SQRT(4.0f32), 2.0);
        assert_eq!(SQRT(2.0f64), 2f64.sqrt());
        assert!(SQRT(-1.0f32).is_nan());
        assert_eq!(LN(1.0f32), 0.0);
        assert_eq!(LN(0.0f64), f64::NEG_INFINITY);
        assert_eq!(LOG(1000.0f32), 3.0);
        assert_eq!(EXP(0.0f32), 1.0);
        assert_eq!(EXP(100.0f32), f32::INFINITY);
        assert_eq!(SIN(0.0f32), 0.0);
        assert_eq!(COS(0.0f64), 1.0);
        assert!((TAN(core::f32::consts::FRAC_PI_4) - 1.0).abs() < 1e-6);
        assert!((ASIN(1.0f32) - core::f32::consts::FRAC_PI_2).abs() < 1e-6);
        assert_eq!(ACOS(1.0f64), 0.0);
        assert!(ACOS(2.0f32).is_nan());
        assert!((ATAN(1.0f64) - core::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert_eq!(EXPT(2.0f32, 10i16), 1024.0);
        assert_eq!(EXPT(2.0f64, -1i32), 0.5);
        assert_eq!(EXPT(4.0f32, 0.5f32), 2.0);
        assert_eq!(EXPT(-8.0f64, 3u8), -512.0);
        assert!(EXPT(-8.0f64, 0.5f64).is_nan());
        assert_eq!(EXPT(0.0f32, -1i16), f32::INFINITY);
        assert_eq!(TRUNC(-1.6f32), -1);
        assert_eq!(TRUNC(1.6f64), 1);
        assert_eq!(TRUNC(1e20f64), i32::MAX);
        assert_eq!(TRUNC(f32::NAN), 0);
    }

    #[test]
    fn real_functions_f32_match_std() {
        let mut x = -20.0f32;
        while x < 20.0 {
            let tol = |ours: f32, std: f32| {
                if std.is_nan() {
                    assert!(ours.is_nan());
                } else if std != 0.0 {
                    assert!(((ours - std) / std).abs() <= 1e-6, "{x}: {ours} vs {std}");
                }
            };
            tol(SIN(x), x.sin());
            tol(COS(x), x.cos());
            tol(TAN(x), x.tan());
            tol(EXP(x), x.exp());
            tol(ATAN(x), x.atan());
            tol(SQRT(x), x.sqrt());
            tol(LN(x), x.ln());
            tol(LOG(x), x.log10());
            tol(ASIN(x / 20.0), (x / 20.0).asin());
            tol(ACOS(x / 20.0), (x / 20.0).acos());
            tol(EXPT(x, 1.7f32), x.powf(1.7));
            x += 0.0137;
        }
    }
}
