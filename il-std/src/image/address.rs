//! Typed IEC addresses, so a host binds I/O by the address it reads in the
//! IL, with the Rust type that address holds:
//!
//! ```
//! use il_std::addr::{iw, ix, qx, md};
//! let mut ctx = il_std::Cycle::new();
//! ctx.io.set(iw(1), 500);          // %IW1: the word at input byte 2
//! ctx.io.set(ix(0, 3), true);      // %IX0.3
//! ctx.io.set(iw(2).int(), -5);     // %IW2 read as an INT
//! ctx.io.set(md(4).real(), 1.5);   // %MD4 as a REAL
//! assert_eq!(ctx.io.word(il_std::Area::Input, 2), 500);
//! assert!(!ctx.io.get(qx(0, 0)));
//! ```
//!
//! A wrong value type does not compile (`ctx.io.set(ix(0, 0), 1)` is an
//! error: `%IX0.0` holds a `bool`), and no byte offset is computed by hand.

use super::{Area, ProcessImage};

/// An address in the process image and the Rust type it holds.
pub trait Address: Copy {
    /// What is stored there.
    type Value: Copy;
    /// Reads it (0 or `false` outside the area).
    fn get(self, io: &ProcessImage) -> Self::Value;
    /// Writes it (nothing outside the area).
    fn set(self, io: &mut ProcessImage, v: Self::Value);
}

/// A bit address `%IXb.n` (`bool`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Bit {
    area: Area,
    /// Bits counted from bit 0 of byte 0, as `%IX17` is written.
    bit: usize,
}

/// A byte, word, double word or long word address: `%IB`, `%IW`, `%ID`, `%IL`.
/// `N` is its size in bytes; `T` the Rust type it is read as (`u8`, `u16`,
/// `u32`, `u64` by default; [`Word::int`] and its siblings pick another).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Bytes<const N: usize, T> {
    area: Area,
    byte: usize,
    ty: core::marker::PhantomData<T>,
}

/// `%IBn`, `%QBn`, `%MBn` (BYTE).
pub type Byte<T = u8> = Bytes<1, T>;
/// `%IWn`, `%QWn`, `%MWn` (WORD): the word at byte `2n`.
pub type Word<T = u16> = Bytes<2, T>;
/// `%IDn`, `%QDn`, `%MDn` (DWORD): the double word at byte `4n`.
pub type DWord<T = u32> = Bytes<4, T>;
/// `%ILn`, `%QLn`, `%MLn` (LWORD): the long word at byte `8n`.
pub type LWord<T = u64> = Bytes<8, T>;

impl Address for Bit {
    type Value = bool;
    fn get(self, io: &ProcessImage) -> bool {
        io.bit(self.area, self.bit / 8, (self.bit % 8) as u8)
    }
    fn set(self, io: &mut ProcessImage, v: bool) {
        io.set_bit(self.area, self.bit / 8, (self.bit % 8) as u8, v)
    }
}

impl<const N: usize, T> Bytes<N, T> {
    const fn at(area: Area, n: usize) -> Self {
        Bytes {
            area,
            byte: n.saturating_mul(N),
            ty: core::marker::PhantomData,
        }
    }
    const fn retyped<U>(self) -> Bytes<N, U> {
        Bytes {
            area: self.area,
            byte: self.byte,
            ty: core::marker::PhantomData,
        }
    }
    /// The byte offset in its area.
    pub const fn byte(self) -> usize {
        self.byte
    }
}

// Each (size, type) pair: how the bytes become the value, little-endian,
// exactly as generated code reads and writes them.
macro_rules! typed {
    ($($n:literal $t:ty => $bits:ty, $from:expr, $to:expr;)*) => {$(
        impl Address for Bytes<$n, $t> {
            type Value = $t;
            fn get(self, io: &ProcessImage) -> $t {
                let raw = <$bits>::from_le_bytes(io.read::<$n>(self.area, self.byte));
                ($from)(raw)
            }
            fn set(self, io: &mut ProcessImage, v: $t) {
                let raw: $bits = ($to)(v);
                io.write::<$n>(self.area, self.byte, raw.to_le_bytes());
            }
        }
    )*};
}

typed! {
    1 u8 => u8, |b| b, |v| v;
    1 i8 => u8, u8::cast_signed, i8::cast_unsigned;
    2 u16 => u16, |b| b, |v| v;
    2 i16 => u16, u16::cast_signed, i16::cast_unsigned;
    4 u32 => u32, |b| b, |v| v;
    4 i32 => u32, u32::cast_signed, i32::cast_unsigned;
    4 f32 => u32, f32::from_bits, f32::to_bits;
    8 u64 => u64, |b| b, |v| v;
    8 i64 => u64, u64::cast_signed, i64::cast_unsigned;
    8 f64 => u64, f64::from_bits, f64::to_bits;
}

impl Byte {
    /// Read as SINT (`i8`).
    pub const fn sint(self) -> Byte<i8> {
        self.retyped()
    }
}
impl Word {
    /// Read as INT (`i16`).
    pub const fn int(self) -> Word<i16> {
        self.retyped()
    }
}
impl DWord {
    /// Read as DINT (`i32`).
    pub const fn dint(self) -> DWord<i32> {
        self.retyped()
    }
    /// Read as REAL (`f32`).
    pub const fn real(self) -> DWord<f32> {
        self.retyped()
    }
}
impl LWord {
    /// Read as LINT (`i64`).
    pub const fn lint(self) -> LWord<i64> {
        self.retyped()
    }
    /// Read as LREAL (`f64`).
    pub const fn lreal(self) -> LWord<f64> {
        self.retyped()
    }
}

macro_rules! constructors {
    ($($area:ident: $x:ident $b:ident $w:ident $d:ident $l:ident;)*) => {$(
        #[doc = concat!("`%", stringify!($x), "byte.bit` (bits past 7 go on into the next bytes, as `%IX17` does).")]
        pub const fn $x(byte: usize, bit: usize) -> Bit {
            Bit { area: Area::$area, bit: byte.saturating_mul(8).saturating_add(bit) }
        }
        #[doc = concat!("`%", stringify!($b), "n`: byte n.")]
        pub const fn $b(n: usize) -> Byte { Bytes::at(Area::$area, n) }
        #[doc = concat!("`%", stringify!($w), "n`: the word at byte 2n.")]
        pub const fn $w(n: usize) -> Word { Bytes::at(Area::$area, n) }
        #[doc = concat!("`%", stringify!($d), "n`: the double word at byte 4n.")]
        pub const fn $d(n: usize) -> DWord { Bytes::at(Area::$area, n) }
        #[doc = concat!("`%", stringify!($l), "n`: the long word at byte 8n.")]
        pub const fn $l(n: usize) -> LWord { Bytes::at(Area::$area, n) }
    )*};
}

constructors! {
    Input: ix ib iw id il;
    Output: qx qb qw qd ql;
    Memory: mx mb mw md ml;
}

impl ProcessImage {
    /// The value at a typed address: `ctx.io.get(qx(0, 1))`.
    pub fn get<A: Address>(&self, a: A) -> A::Value {
        a.get(self)
    }
    /// Stores a value at a typed address: `ctx.io.set(iw(1), 500)`.
    pub fn set<A: Address>(&mut self, a: A, v: A::Value) {
        a.set(self, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addresses_land_where_the_byte_api_puts_them() {
        let mut io = ProcessImage::default();
        io.set(iw(3), 0xBEEF);
        assert_eq!(io.word(Area::Input, 6), 0xBEEF);
        io.set(mx(1, 2), true);
        assert!(io.bit(Area::Memory, 1, 2));
        io.set(qx(0, 17), true); // bit 17: byte 2, bit 1
        assert!(io.bit(Area::Output, 2, 1));
        io.set(md(2).real(), -2.5);
        assert_eq!(f32::from_bits(io.dword(Area::Memory, 8)), -2.5);
        io.set(ib(5).sint(), -1);
        assert_eq!(io.get(ib(5)), 0xFF);
        io.set(ql(1).lint(), -3);
        assert_eq!(io.get(ql(1)), (-3i64).cast_unsigned());
        assert_eq!(io.get(ml(4).lreal()), 0.0);
        assert_eq!(io.get(id(0).dint()), 0);
        assert_eq!(io.get(iw(3).int()), 0xBEEFu16.cast_signed());
    }

    #[test]
    fn outside_the_area_reads_zero_and_writes_nothing() {
        let mut io = ProcessImage::default();
        io.set(iw(usize::MAX), 7);
        assert_eq!(io.get(iw(usize::MAX)), 0);
        io.set(ix(usize::MAX, usize::MAX), true);
        assert!(!io.get(ix(usize::MAX, usize::MAX)));
        assert_eq!(io, ProcessImage::default());
    }
}
