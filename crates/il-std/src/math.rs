//! Deterministic floating-point math in pure Rust (no `std`, no dependencies).

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

/// Absolute value (clears the sign bit, so `abs(-0.0) == 0.0` and `abs(-NaN)` is NaN).
pub fn abs(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & !(1u64 << 63))
}
