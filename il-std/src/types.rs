//! The elementary IEC 61131-3 types that map directly onto Rust primitives.
//!
//! Every IEC type defaults to zero (`FALSE`, `0`, `0.0`), which is Rust's `Default` too.

/// `BOOL`: `FALSE`/`TRUE`, default `FALSE`.
pub type BOOL = bool;
/// `SINT`: 8-bit signed integer, −128..127, default 0.
pub type SINT = i8;
/// `INT`: 16-bit signed integer, −32768..32767, default 0.
pub type INT = i16;
/// `DINT`: 32-bit signed integer, −2³¹..2³¹−1, default 0.
pub type DINT = i32;
/// `LINT`: 64-bit signed integer, −2⁶³..2⁶³−1, default 0.
pub type LINT = i64;
/// `USINT`: 8-bit unsigned integer, 0..255, default 0.
pub type USINT = u8;
/// `UINT`: 16-bit unsigned integer, 0..65535, default 0.
pub type UINT = u16;
/// `UDINT`: 32-bit unsigned integer, 0..2³²−1, default 0.
pub type UDINT = u32;
/// `ULINT`: 64-bit unsigned integer, 0..2⁶⁴−1, default 0.
pub type ULINT = u64;
/// `BYTE`: bit string of length 8, default `16#00`.
pub type BYTE = u8;
/// `WORD`: bit string of length 16, default `16#0000`.
pub type WORD = u16;
/// `DWORD`: bit string of length 32, default 0.
pub type DWORD = u32;
/// `LWORD`: bit string of length 64, default 0.
pub type LWORD = u64;
/// `REAL`: IEC 60559 single precision (32 bits), default 0.0.
pub type REAL = f32;
/// `LREAL`: IEC 60559 double precision (64 bits), default 0.0.
pub type LREAL = f64;
