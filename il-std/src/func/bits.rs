//! Bit-string functions: SHL SHR ROL ROR, AND OR XOR NOT.

use crate::num::{AnyBit, AnyBitString, AnyInt};

fn count<C: AnyInt>(n: C) -> Option<u32> {
    u32::try_from(n.to_i128()).ok().or(if n.to_i128() > 0 {
        Some(u32::MAX)
    } else {
        None
    })
}

fn rot_count<T: AnyBitString, C: AnyInt>(n: C) -> Option<u32> {
    let n = n.to_i128();
    if n < 0 {
        None
    } else {
        u32::try_from(n % i128::from(T::BITS)).ok()
    }
}

/// `SHL`: `IN` shifted left by `N` bits, zero-filled. `N` ≥ the width gives 0; a negative `N`
/// gives `IN` unchanged.
pub fn SHL<T: AnyBitString, C: AnyInt>(IN: T, N: C) -> T {
    count(N).map_or(IN, |n| IN.iec_shl(n))
}

/// `SHR`: `IN` shifted right by `N` bits, zero-filled (logical). `N` ≥ the width gives 0; a
/// negative `N` gives `IN` unchanged.
pub fn SHR<T: AnyBitString, C: AnyInt>(IN: T, N: C) -> T {
    count(N).map_or(IN, |n| IN.iec_shr(n))
}

/// `ROL`: `IN` rotated left by `N` bits (modulo the width). A negative `N` gives `IN`
/// unchanged.
pub fn ROL<T: AnyBitString, C: AnyInt>(IN: T, N: C) -> T {
    rot_count::<T, C>(N).map_or(IN, |n| IN.iec_rol(n))
}

/// `ROR`: `IN` rotated right by `N` bits (modulo the width). A negative `N` gives `IN`
/// unchanged.
pub fn ROR<T: AnyBitString, C: AnyInt>(IN: T, N: C) -> T {
    rot_count::<T, C>(N).map_or(IN, |n| IN.iec_ror(n))
}

/// `AND`: bitwise (or Boolean) AND (extensible: fold).
pub fn AND<T: AnyBit>(IN1: T, IN2: T) -> T {
    IN1.iec_and(IN2)
}
/// `OR`: bitwise (or Boolean) OR (extensible: fold).
pub fn OR<T: AnyBit>(IN1: T, IN2: T) -> T {
    IN1.iec_or(IN2)
}
/// `XOR`: bitwise (or Boolean) exclusive OR (extensible: fold).
pub fn XOR<T: AnyBit>(IN1: T, IN2: T) -> T {
    IN1.iec_xor(IN2)
}
/// `NOT`: bitwise (or Boolean) complement.
pub fn NOT<T: AnyBit>(IN: T) -> T {
    IN.iec_not()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shifts() {
        assert_eq!(SHL(0x81u8, 1i16), 0x02);
        assert_eq!(SHL(0x81u8, 8i16), 0);
        assert_eq!(SHL(0x81u8, 200u64), 0);
        assert_eq!(SHL(0x81u8, -1i8), 0x81);
        assert_eq!(SHL(1u64, 63i32), 1 << 63);
        assert_eq!(SHR(0x8001u16, 15i16), 1);
        assert_eq!(SHR(0x8001u16, 16i16), 0);
        assert_eq!(SHR(0xFFFF_FFFFu32, i64::MAX), 0);
        assert_eq!(SHR(0x10u8, i64::MIN), 0x10);
        assert_eq!(ROL(0x81u8, 1i16), 0x03);
        assert_eq!(ROL(0x81u8, 9i16), 0x03);
        assert_eq!(ROL(0x81u8, -1i16), 0x81);
        assert_eq!(ROR(0x81u8, 1i16), 0xC0);
        assert_eq!(ROR(0x0001u16, 17u32), 0x8000);
        assert_eq!(ROR(1u64, u64::MAX - 1), 1u64.rotate_right(62));
        assert_eq!(ROL(1u8, 1u64 << 40), 1);
    }

    #[test]
    fn logic() {
        assert!(AND(true, true) && !AND(true, false));
        assert!(OR(false, true) && !OR(false, false));
        assert!(XOR(true, false) && !XOR(true, true));
        assert!(NOT(false));
        assert_eq!(AND(0xF0u8, 0x3C), 0x30);
        assert_eq!(OR(0xF0u16, 0x0F), 0xFF);
        assert_eq!(XOR(0xFFu32, 0x0F), 0xF0);
        assert_eq!(NOT(0x00FFu16), 0xFF00);
        assert_eq!(NOT(0u64), u64::MAX);
    }
}
