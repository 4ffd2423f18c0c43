//! Arithmetic: ADD SUB MUL DIV MOD MOVE ABS.

use crate::num::{AnyInt, AnyMagnitude, AnyNum};

/// `ADD`: `IN1 + IN2` (extensible: fold for more inputs). Integers and `TIME` wrap (two's
/// complement); reals follow IEEE 754.
pub fn ADD<T: AnyMagnitude>(IN1: T, IN2: T) -> T {
    IN1.iec_add(IN2)
}

/// `SUB`: `IN1 - IN2`. Integers and `TIME` wrap; reals follow IEEE 754.
pub fn SUB<T: AnyMagnitude>(IN1: T, IN2: T) -> T {
    IN1.iec_sub(IN2)
}

/// `MUL`: `IN1 * IN2` (extensible: fold for more inputs). Integers wrap.
pub fn MUL<T: AnyNum>(IN1: T, IN2: T) -> T {
    IN1.iec_mul(IN2)
}

/// `DIV`: `IN1 / IN2`. Integers truncate toward zero (`-7 / 2 = -3`), `MIN / -1` wraps, and
/// division by zero gives 0 (see [`div_checked`] for the fault flag). Reals follow IEEE 754
/// (`1.0 / 0.0 = +∞`).
pub fn DIV<T: AnyNum>(IN1: T, IN2: T) -> T {
    IN1.iec_div(IN2).0
}

/// [`DIV`] plus `true` if it was an integer division by zero (the caller records
/// [`FaultKind::DivisionByZero`](crate::FaultKind::DivisionByZero)).
pub fn div_checked<T: AnyNum>(IN1: T, IN2: T) -> (T, bool) {
    IN1.iec_div(IN2)
}

/// `MOD`: remainder of the integer division; its sign is the dividend's (`-7 MOD 2 = -1`).
/// Modulo zero gives 0 (see [`mod_checked`]).
pub fn MOD<T: AnyInt>(IN1: T, IN2: T) -> T {
    IN1.iec_rem(IN2).0
}

/// [`MOD`] plus `true` if it was a modulo by zero.
pub fn mod_checked<T: AnyInt>(IN1: T, IN2: T) -> (T, bool) {
    IN1.iec_rem(IN2)
}

/// `MOVE`: returns its input unchanged (assignment).
pub fn MOVE<T>(IN: T) -> T {
    IN
}

/// `ABS`: absolute value. For signed integers `ABS(MIN)` wraps to `MIN` (e.g. `ABS(INT#-32768)
/// = -32768`); unsigned values are returned unchanged; `ABS(-0.0) = 0.0`, NaN stays NaN.
pub fn ABS<T: AnyNum>(IN: T) -> T {
    IN.iec_abs()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TIME;

    #[test]
    fn arithmetic() {
        assert_eq!(ADD(i16::MAX, 1), i16::MIN);
        assert_eq!(ADD(1.5f32, 2.0), 3.5);
        assert_eq!(ADD(TIME::from_ms(1), TIME::from_ms(2)), TIME::from_ms(3));
        assert_eq!(SUB(0u8, 1), 255);
        assert_eq!(SUB(TIME::from_ms(1), TIME::from_ms(2)), TIME::from_ms(-1));
        assert_eq!(MUL(i32::MAX, 2), -2);
        assert_eq!(MUL(1.5f64, 2.0), 3.0);
        assert_eq!(DIV(-7i16, 2), -3);
        assert_eq!(DIV(7i16, -2), -3);
        assert_eq!(DIV(i16::MIN, -1), i16::MIN);
        assert_eq!(DIV(5i32, 0), 0);
        assert_eq!(div_checked(5u64, 0), (0, true));
        assert_eq!(div_checked(5u64, 2), (2, false));
        assert_eq!(DIV(1.0f32, 0.0), f32::INFINITY);
        assert!(DIV(0.0f64, 0.0).is_nan());
        assert_eq!(div_checked(1.0f64, 0.0), (f64::INFINITY, false));
        assert_eq!(MOD(-7i16, 2), -1);
        assert_eq!(MOD(7i16, -2), 1);
        assert_eq!(MOD(i64::MIN, -1), 0);
        assert_eq!(MOD(7u8, 0), 0);
        assert_eq!(mod_checked(7i8, 0), (0, true));
        assert_eq!(MOVE(42i8), 42);
        assert_eq!(ABS(-5i16), 5);
        assert_eq!(ABS(i16::MIN), i16::MIN);
        assert_eq!(ABS(200u8), 200);
        assert_eq!(ABS(-2.5f32), 2.5);
        assert_eq!(ABS(-0.0f64).to_bits(), 0);
        assert!(ABS(f64::NAN).is_nan());
    }
}
