//! The numeric standard functions, libm's (see the module doc of [`math`](super)).

const NAN: f64 = f64::from_bits(0x7ff8_0000_0000_0000);
const NANF: f32 = f32::from_bits(0x7fc0_0000);

/// `r`, or the one NaN of the module doc if `r` is a NaN.
#[inline]
fn canonical(r: f64) -> f64 {
    if r.is_nan() { NAN } else { r }
}

/// `r`, or the one `f32` NaN of the module doc if `r` is a NaN.
#[inline]
fn canonicalf(r: f32) -> f32 {
    if r.is_nan() { NANF } else { r }
}

macro_rules! unary {
    ($($name:ident, $namef:ident => $libm:ident, $libmf:ident, $doc:literal;)*) => {$(
        #[doc = concat!($doc, ", `f64` (`LREAL`).")]
        #[inline]
        pub fn $name(x: f64) -> f64 {
            canonical(libm::$libm(x))
        }

        #[doc = concat!($doc, ", `f32` (`REAL`).")]
        #[inline]
        pub fn $namef(x: f32) -> f32 {
            canonicalf(libm::$libmf(x))
        }
    )*};
}

unary! {
    sqrt, sqrtf => sqrt, sqrtf, "Square root (NaN for negative arguments, `sqrt(-0.0) = -0.0`)";
    ln, lnf => log, logf, "Natural logarithm (`ln(±0) = −∞`, NaN for negative arguments)";
    log10, log10f => log10, log10f,
        "Base-10 logarithm (`log10(±0) = −∞`, NaN for negative arguments)";
    exp, expf => exp, expf, "`eˣ` (overflow gives +∞, underflow 0)";
    sin, sinf => sin, sinf, "Sine of `x` radians (NaN for ±∞)";
    cos, cosf => cos, cosf, "Cosine of `x` radians (NaN for ±∞)";
    tan, tanf => tan, tanf, "Tangent of `x` radians (NaN for ±∞)";
    asin, asinf => asin, asinf, "Arc sine, in `[-π/2, π/2]` (NaN outside `[-1, 1]`)";
    acos, acosf => acos, acosf, "Arc cosine, in `[0, π]` (NaN outside `[-1, 1]`)";
    atan, atanf => atan, atanf, "Arc tangent, in `[-π/2, π/2]`";
}

/// `xʸ` (IEC `EXPT`) with the IEEE 754 `pow` special cases: `x⁰ = 1` and `1ʸ = 1` even for NaN,
/// a negative base needs an integer exponent (else NaN; an odd one keeps the sign), `0` to a
/// negative power is ∞ (−∞ for `-0.0` to an odd one), `(-1)^±∞ = 1`.
#[inline]
pub fn pow(x: f64, y: f64) -> f64 {
    canonical(libm::pow(x, y))
}

/// `xʸ` for a `REAL` base, as [`pow`] does it. The exponent comes as `f64`, which holds every
/// IEC exponent exactly (but 64-bit integers beyond 2⁵³). When it is an `f32` too (`REAL`
/// exponents, integers up to 2²⁴) this is libm's `powf`; else (a larger integer, whose parity
/// decides the sign, or an `LREAL` exponent) it is `f64` `pow` rounded once, still within 1 ulp:
/// rounding the exponent to `f32` would be up to dozens of ulps off, or of the wrong sign.
#[inline]
pub fn powf(x: f32, y: f64) -> f32 {
    let y32 = y as f32;
    if f64::from(y32) == y {
        canonicalf(libm::powf(x, y32))
    } else {
        canonicalf(libm::pow(f64::from(x), y) as f32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn special_values() {
        assert_eq!(sqrt(4.0), 2.0);
        assert_eq!(sqrt(-0.0).to_bits(), (-0.0f64).to_bits());
        assert!(sqrt(-1.0).is_nan() && sqrtf(-1.0).is_nan());
        assert_eq!(sqrt(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp(1000.0), f64::INFINITY);
        assert_eq!(expf(100.0), f32::INFINITY);
        assert_eq!(ln(1.0), 0.0);
        assert_eq!(ln(0.0), f64::NEG_INFINITY);
        assert_eq!(ln(-0.0), f64::NEG_INFINITY);
        assert!(ln(-1.0).is_nan() && lnf(-1.0).is_nan());
        assert!(sin(f64::INFINITY).is_nan() && cosf(f32::NEG_INFINITY).is_nan());
        assert!(sin(1e300).abs() <= 1.0);
        assert!(asin(1.5).is_nan() && acosf(-1.5).is_nan());
        assert_eq!(atan(f64::INFINITY), core::f64::consts::FRAC_PI_2);
        assert_eq!(asin(-0.0).to_bits(), (-0.0f64).to_bits());
    }

    #[test]
    fn exact_results_stay_exact() {
        // Powers of ten have exact logarithms (as the hand-written log10 special-cased).
        let mut p = 1.0;
        for n in 0..=22 {
            assert_eq!(log10(p), f64::from(n), "1e{n}");
            p *= 10.0;
        }
        let mut p = 1.0f32;
        for n in 0..=10 {
            assert_eq!(log10f(p), n as f32, "1e{n}");
            p *= 10.0;
        }
        // Integer powers come out exact where the type holds them (f32: below 2^24).
        for x in -10..=10 {
            for n in 0..=15 {
                let want = f64::from(x).powi(n);
                assert_eq!(pow(f64::from(x), f64::from(n)), want, "{x}^{n}");
                if want.abs() < 16_777_216.0 {
                    assert_eq!(powf(x as f32, f64::from(n)), want as f32, "{x}^{n}");
                }
            }
        }
        assert_eq!(pow(2.0, -2.0), 0.25);
        assert_eq!(powf(4.0, 0.5), 2.0);
        // Correctly rounded (the hand-written pow gave 1.414213562373095).
        assert_eq!(pow(2.0, 0.5), core::f64::consts::SQRT_2);
    }

    #[test]
    fn pow_special_cases() {
        assert_eq!(pow(3.0, 2.0), 9.0);
        assert_eq!(pow(-2.0, 3.0), -8.0);
        assert!(pow(-2.0, 0.5).is_nan());
        assert_eq!(pow(f64::NAN, 0.0), 1.0);
        assert_eq!(pow(1.0, f64::NAN), 1.0);
        assert_eq!(pow(-1.0, f64::INFINITY), 1.0);
        assert_eq!(pow(0.0, -1.0), f64::INFINITY);
        assert_eq!(pow(-0.0, -3.0), f64::NEG_INFINITY);
        assert_eq!(pow(0.0, 2.5), 0.0);
        assert_eq!(pow(2.0, f64::INFINITY), f64::INFINITY);
        assert_eq!(pow(0.5, f64::INFINITY), 0.0);
        assert_eq!(pow(f64::INFINITY, -1.0), 0.0);
        assert_eq!(pow(f64::NEG_INFINITY, 3.0), f64::NEG_INFINITY);
        assert_eq!(pow(-8.0, 1e20), f64::INFINITY);
        assert_eq!(pow(10.0, 400.0), f64::INFINITY);
        assert_eq!(powf(f32::NAN, 0.0), 1.0);
        assert_eq!(powf(0.0, -1.0), f32::INFINITY);
    }

    #[test]
    fn real_base_keeps_the_exponent_exact() {
        // 2^24 + 1 is odd but rounds to the even 2^24 as an f32: the sign must stay negative.
        let x = -(1.0 + f32::EPSILON);
        let r = powf(x, 16_777_217.0);
        assert!(r < 0.0, "{r}");
        assert_eq!(r, (f64::from(x).powf(16_777_217.0)) as f32);
        // An LREAL exponent that no f32 holds.
        assert_eq!(powf(10.0, 0.1), 10f64.powf(0.1) as f32);
    }

    #[test]
    fn nan_results_are_one_nan() {
        let neg_nan = f64::from_bits(0xfff8_0000_0000_0001);
        for r in [
            sqrt(-1.0),
            ln(-1.0),
            sin(f64::INFINITY),
            asin(2.0),
            exp(neg_nan),
            pow(-2.0, 0.5),
        ] {
            assert_eq!(r.to_bits(), 0x7ff8_0000_0000_0000);
        }
        let neg_nan = f32::from_bits(0xffc0_0001);
        for r in [
            sqrtf(-1.0),
            lnf(-1.0),
            tanf(f32::INFINITY),
            acosf(2.0),
            atanf(neg_nan),
        ] {
            assert_eq!(r.to_bits(), 0x7fc0_0000);
        }
        assert_eq!(powf(-2.0, 0.5).to_bits(), 0x7fc0_0000);
        assert_eq!(powf(neg_nan, 1.0).to_bits(), 0x7fc0_0000);
    }
}
