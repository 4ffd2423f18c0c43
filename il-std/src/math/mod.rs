//! Floating-point math: exact rounding helpers, and the numeric standard functions.
//!
//! `core` has no transcendental functions without `std`, so `SQRT`, `LN`, `LOG`, `EXP`, `SIN`
//! ... `EXPT` call these, which are `libm`'s: the Rust project's pure-Rust port of musl's libm,
//! `no_std` and without dependencies (the `runtime` feature brings it in). Pure Rust on IEEE 754
//! arithmetic computes the same bits on every target, so a program gets the same results on the
//! host, on the controller and in the interpreter. (The exception is 32-bit x86 without SSE2,
//! where libm computes `exp` with x87 instructions and Rust's own `f64` arithmetic rounds
//! differently too.) The `REAL` (`f32`)
//! functions are libm's `f32` ones (`sinf`, `logf` ...), not the `f64` ones rounded.
//!
//! Accuracy: within 1 ulp of the correctly rounded result; the tests compare millions of inputs
//! with the host's `std` (with a more exact reference where glibc is less accurate) and print
//! the worst distance per function. Within 1 ulp is not always the nearest: `acosf` of a tiny
//! argument and `atanf` of a huge one give 1.5707962, the `f32` below the nearest to π/2. NaN and infinities follow
//! IEEE 754 and C99's Annex F (`sqrt(-1)` is NaN, `ln(0)` is −∞, `pow(NaN, 0)` is 1 ...). A NaN
//! result is always the quiet NaN with a clear sign bit (`0x7ff8…`), whatever NaN the argument
//! or the target's arithmetic gave: IEEE 754 leaves a NaN's sign and payload open, so this is
//! what makes NaNs the same bits everywhere too.

#[cfg(all(test, feature = "runtime"))]
mod accuracy;
#[cfg(feature = "runtime")]
mod functions;

#[cfg(feature = "runtime")]
pub use functions::*;

/// Rounds to the nearest integer, ties to even (`0.5 → 0`, `1.5 → 2`, `-2.5 → -2`).
/// NaN and infinities are returned unchanged.
pub fn round_half_even(x: f64) -> f64 {
    const TWO52: f64 = 4_503_599_627_370_496.0;
    let a = abs(x);
    if a.is_nan() || a >= TWO52 {
        return x;
    }
    // Adding and subtracting 2^52 rounds to an integer in the default rounding mode
    // (nearest, ties to even).
    let r = (a + TWO52) - TWO52;
    if x.is_sign_negative() { -r } else { r }
}

/// Rounds toward zero. NaN and infinities are returned unchanged.
pub fn trunc(x: f64) -> f64 {
    const TWO52: f64 = 4_503_599_627_370_496.0;
    let a = abs(x);
    if a.is_nan() || a >= TWO52 {
        return x;
    }
    let r = (a as u64) as f64;
    if x.is_sign_negative() { -r } else { r }
}

/// Absolute value (clears the sign bit, so `abs(-0.0) == 0.0` and `abs(-NaN)` is NaN).
pub fn abs(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & !(1u64 << 63))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding() {
        for (x, r) in [
            (0.5, 0.0),
            (1.5, 2.0),
            (2.5, 2.0),
            (-2.5, -2.0),
            (-0.4, -0.0),
            (3.7, 4.0),
            (-3.7, -4.0),
            (1e300, 1e300),
        ] {
            assert_eq!(round_half_even(x), r, "{x}");
        }
        assert!(round_half_even(f64::NAN).is_nan());
        assert_eq!(trunc(-3.7), -3.0);
        assert_eq!(trunc(3.7), 3.0);
        assert_eq!(abs(-0.0).to_bits(), 0);
    }
}
