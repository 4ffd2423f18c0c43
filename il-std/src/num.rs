//! Traits for the IEC generic type classes (`ANY_NUM`, `ANY_INT`, `ANY_REAL`, `ANY_BIT` ...),
//! implemented for the Rust types of the elementary IEC types. The overloaded standard functions
//! of [`func`](crate::func) are generic over them. All operations wrap or saturate; none panics.

use crate::time::{LTIME, TIME};

pub use crate::string::AnyString;

/// Types on which `ADD` and `SUB` are defined: `ANY_NUM` plus `TIME`/`LTIME`.
pub trait AnyMagnitude: Copy + PartialOrd + Default {
    /// `self + rhs` (integers and durations wrap; reals follow IEEE 754).
    fn iec_add(self, rhs: Self) -> Self;
    /// `self - rhs` (integers and durations wrap; reals follow IEEE 754).
    fn iec_sub(self, rhs: Self) -> Self;
}

/// `ANY_NUM`: the integer and real types.
pub trait AnyNum: AnyMagnitude {
    /// `self * rhs` (integers wrap).
    fn iec_mul(self, rhs: Self) -> Self;
    /// `self / rhs`; integers truncate toward zero, division by zero gives 0 and `true`
    /// (`MIN / -1` wraps); reals follow IEEE 754 and never report a fault.
    fn iec_div(self, rhs: Self) -> (Self, bool);
    /// Absolute value (`MIN` of a signed integer type wraps to itself).
    fn iec_abs(self) -> Self;
    /// The value as `f64` (rounded for 64-bit integers).
    fn to_f64(self) -> f64;
    /// The value as an integer if it is one: `Some` for integer types (`ULINT` above
    /// `i64::MAX` wraps), `None` for reals.
    fn as_i64_exact(self) -> Option<i64>;
}

/// `ANY_INT`: signed and unsigned integers (and, in Rust, the bit strings that share their
/// representation: `BYTE` is `u8` like `USINT`).
pub trait AnyInt: AnyNum + Ord {
    /// Width in bits.
    const BITS: u32;
    /// Whether the type is signed.
    const SIGNED: bool;
    /// `self MOD rhs`: the sign follows the dividend; modulo by zero gives 0 and `true`.
    fn iec_rem(self, rhs: Self) -> (Self, bool);
    /// The exact value.
    fn to_i128(self) -> i128;
    /// `v` truncated to the type's width (two's complement).
    fn from_i128_wrapping(v: i128) -> Self;
    /// `Some(v)` if `v` is in range.
    fn from_i128_checked(v: i128) -> Option<Self>;
}

/// `ANY_REAL`: `REAL` and `LREAL`.
pub trait AnyReal: AnyNum {
    /// The value from `f64` (rounded to nearest for `REAL`).
    fn from_f64(v: f64) -> Self;
    /// `lreal(self)` for `LREAL`, `real(self)` for `REAL`: how the numeric functions of
    /// [`func`](crate::func) pick the [`math`](crate::math) function of their type.
    fn apply(self, lreal: fn(f64) -> f64, real: fn(f32) -> f32) -> Self;
    /// `self` to the power `y` (`EXPT`): [`math::pow`](crate::math::pow) for `LREAL`,
    /// [`math::powf`](crate::math::powf) for `REAL`. `y` is any IEC number as `f64`.
    fn iec_pow(self, y: f64) -> Self;
}

/// `ANY_BIT`: `BOOL` and the bit strings (`BYTE WORD DWORD LWORD`).
pub trait AnyBit: Copy + PartialEq + Default {
    /// Bitwise AND.
    fn iec_and(self, rhs: Self) -> Self;
    /// Bitwise OR.
    fn iec_or(self, rhs: Self) -> Self;
    /// Bitwise XOR.
    fn iec_xor(self, rhs: Self) -> Self;
    /// Bitwise complement.
    fn iec_not(self) -> Self;
}

/// The bit strings of length 8..64, on which shifts and rotations are defined.
pub trait AnyBitString: AnyBit {
    /// Width in bits.
    const BITS: u32;
    /// Shift left by `n`; 0 when `n >= BITS`.
    fn iec_shl(self, n: u32) -> Self;
    /// Logical shift right by `n`; 0 when `n >= BITS`.
    fn iec_shr(self, n: u32) -> Self;
    /// Rotate left by `n mod BITS`.
    fn iec_rol(self, n: u32) -> Self;
    /// Rotate right by `n mod BITS`.
    fn iec_ror(self, n: u32) -> Self;
}

macro_rules! int_impls {
    ($($t:ty, $signed:literal);* $(;)?) => {$(
        impl AnyMagnitude for $t {
            fn iec_add(self, rhs: Self) -> Self { self.wrapping_add(rhs) }
            fn iec_sub(self, rhs: Self) -> Self { self.wrapping_sub(rhs) }
        }
        impl AnyNum for $t {
            fn iec_mul(self, rhs: Self) -> Self { self.wrapping_mul(rhs) }
            fn iec_div(self, rhs: Self) -> (Self, bool) {
                if rhs == 0 { (0, true) } else { (self.wrapping_div(rhs), false) }
            }
            #[allow(clippy::cast_sign_loss, unused_comparisons)]
            fn iec_abs(self) -> Self {
                if self < 0 { (0 as $t).wrapping_sub(self) } else { self }
            }
            fn to_f64(self) -> f64 { self as f64 }
            fn as_i64_exact(self) -> Option<i64> { Some(self as i64) }
        }
        impl AnyInt for $t {
            const BITS: u32 = <$t>::BITS;
            const SIGNED: bool = $signed;
            fn iec_rem(self, rhs: Self) -> (Self, bool) {
                if rhs == 0 { (0, true) } else { (self.wrapping_rem(rhs), false) }
            }
            fn to_i128(self) -> i128 { self as i128 }
            fn from_i128_wrapping(v: i128) -> Self { v as $t }
            fn from_i128_checked(v: i128) -> Option<Self> { <$t>::try_from(v).ok() }
        }
    )*};
}
int_impls!(i8, true; i16, true; i32, true; i64, true; u8, false; u16, false; u32, false; u64, false);

macro_rules! real_impls {
    ($($t:ty, $mask:expr);*) => {$(
        impl AnyMagnitude for $t {
            fn iec_add(self, rhs: Self) -> Self { self + rhs }
            fn iec_sub(self, rhs: Self) -> Self { self - rhs }
        }
        impl AnyNum for $t {
            fn iec_mul(self, rhs: Self) -> Self { self * rhs }
            fn iec_div(self, rhs: Self) -> (Self, bool) { (self / rhs, false) }
            fn iec_abs(self) -> Self { <$t>::from_bits(self.to_bits() & $mask) }
            fn to_f64(self) -> f64 { self as f64 }
            fn as_i64_exact(self) -> Option<i64> { None }
        }
    )*};
}
real_impls!(f32, 0x7fff_ffff; f64, 0x7fff_ffff_ffff_ffff);

impl AnyReal for f32 {
    fn from_f64(v: f64) -> Self {
        v as f32
    }
    #[inline]
    fn apply(self, _: fn(f64) -> f64, real: fn(f32) -> f32) -> Self {
        real(self)
    }
    #[inline]
    fn iec_pow(self, y: f64) -> Self {
        crate::math::powf(self, y)
    }
}

impl AnyReal for f64 {
    fn from_f64(v: f64) -> Self {
        v
    }
    #[inline]
    fn apply(self, lreal: fn(f64) -> f64, _: fn(f32) -> f32) -> Self {
        lreal(self)
    }
    #[inline]
    fn iec_pow(self, y: f64) -> Self {
        crate::math::pow(self, y)
    }
}

macro_rules! dur_impls {
    ($($t:ident),*) => {$(
        impl AnyMagnitude for $t {
            fn iec_add(self, rhs: Self) -> Self { self.wrapping_add(rhs) }
            fn iec_sub(self, rhs: Self) -> Self { self.wrapping_sub(rhs) }
        }
    )*};
}
dur_impls!(TIME, LTIME);

impl AnyBit for bool {
    fn iec_and(self, rhs: Self) -> Self {
        self & rhs
    }
    fn iec_or(self, rhs: Self) -> Self {
        self | rhs
    }
    fn iec_xor(self, rhs: Self) -> Self {
        self ^ rhs
    }
    fn iec_not(self) -> Self {
        !self
    }
}

macro_rules! bits_impls {
    ($($t:ty),*) => {$(
        impl AnyBit for $t {
            fn iec_and(self, rhs: Self) -> Self { self & rhs }
            fn iec_or(self, rhs: Self) -> Self { self | rhs }
            fn iec_xor(self, rhs: Self) -> Self { self ^ rhs }
            fn iec_not(self) -> Self { !self }
        }
        impl AnyBitString for $t {
            const BITS: u32 = <$t>::BITS;
            fn iec_shl(self, n: u32) -> Self { self.checked_shl(n).unwrap_or(0) }
            fn iec_shr(self, n: u32) -> Self { self.checked_shr(n).unwrap_or(0) }
            fn iec_rol(self, n: u32) -> Self { self.rotate_left(n % <$t>::BITS) }
            fn iec_ror(self, n: u32) -> Self { self.rotate_right(n % <$t>::BITS) }
        }
    )*};
}
bits_impls!(u8, u16, u32, u64);
