//! The signature table of the standard functions: the data the compiler's type checker and
//! code emitter share to check and compile calls such as `LD x / LIMIT 0, 100` or
//! `LD a / MAX b, c, d`.
//!
//! Every entry names a real function in [`func`](crate::func) (a test checks this), with the
//! IEC parameter names (`IN`, `IN1`, `IN2`, `MN`, `MX`, `K`, `G`, `N`, `L`, `P`). The
//! `*_checked` companions of [`func`](crate::func) are not IEC functions and are not listed.

use crate::FaultKind;
use crate::func::conv_list::conversions;

mod blocks;
#[cfg(test)]
mod tests;

pub use blocks::{FB_SIGNATURES, FbParam, FbSignature, lookup_fb};

/// A generic type class of IEC 61131-3 (`ANY_NUM` ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Class {
    /// `ANY_NUM`: integers and reals.
    AnyNum,
    /// `ANY_INT`: signed and unsigned integers.
    AnyInt,
    /// `ANY_REAL`: `REAL`, `LREAL`.
    AnyReal,
    /// `ANY_BIT`: `BOOL` and the bit strings.
    AnyBit,
    /// The bit strings `BYTE WORD DWORD LWORD` (shifts and rotations).
    AnyBitString,
    /// `ANY_NUM` plus `TIME`/`LTIME`: what `ADD` and `SUB` accept.
    AnyMagnitude,
    /// `ANY_ELEMENTARY`: every elementary type.
    AnyElementary,
    /// `ANY_STRING`: `STRING`, `WSTRING`.
    AnyString,
    /// `ANY_DATE`: `DATE`, `TIME_OF_DAY`, `DATE_AND_TIME`.
    AnyDate,
    /// `ANY`: any type (here: any elementary type).
    Any,
    /// `BOOL` only.
    Bool,
}

/// The elementary types of IEC 61131-3.
#[allow(missing_docs)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Elem {
    BOOL,
    SINT,
    INT,
    DINT,
    LINT,
    USINT,
    UINT,
    UDINT,
    ULINT,
    BYTE,
    WORD,
    DWORD,
    LWORD,
    REAL,
    LREAL,
    TIME,
    LTIME,
    DATE,
    TOD,
    DT,
    STRING,
    WSTRING,
}

impl Elem {
    /// Every elementary type.
    pub const ALL: [Elem; 22] = [
        Elem::BOOL,
        Elem::SINT,
        Elem::INT,
        Elem::DINT,
        Elem::LINT,
        Elem::USINT,
        Elem::UINT,
        Elem::UDINT,
        Elem::ULINT,
        Elem::BYTE,
        Elem::WORD,
        Elem::DWORD,
        Elem::LWORD,
        Elem::REAL,
        Elem::LREAL,
        Elem::TIME,
        Elem::LTIME,
        Elem::DATE,
        Elem::TOD,
        Elem::DT,
        Elem::STRING,
        Elem::WSTRING,
    ];

    /// The IEC name (short forms `TOD`, `DT`), which is also the Rust type name in this crate.
    pub fn name(self) -> &'static str {
        match self {
            Elem::BOOL => "BOOL",
            Elem::SINT => "SINT",
            Elem::INT => "INT",
            Elem::DINT => "DINT",
            Elem::LINT => "LINT",
            Elem::USINT => "USINT",
            Elem::UINT => "UINT",
            Elem::UDINT => "UDINT",
            Elem::ULINT => "ULINT",
            Elem::BYTE => "BYTE",
            Elem::WORD => "WORD",
            Elem::DWORD => "DWORD",
            Elem::LWORD => "LWORD",
            Elem::REAL => "REAL",
            Elem::LREAL => "LREAL",
            Elem::TIME => "TIME",
            Elem::LTIME => "LTIME",
            Elem::DATE => "DATE",
            Elem::TOD => "TOD",
            Elem::DT => "DT",
            Elem::STRING => "STRING",
            Elem::WSTRING => "WSTRING",
        }
    }

    /// The type named `name` (case-insensitive; also `TIME_OF_DAY` and `DATE_AND_TIME`).
    pub fn from_name(name: &str) -> Option<Elem> {
        if name.eq_ignore_ascii_case("TIME_OF_DAY") {
            return Some(Elem::TOD);
        }
        if name.eq_ignore_ascii_case("DATE_AND_TIME") {
            return Some(Elem::DT);
        }
        Elem::ALL
            .into_iter()
            .find(|e| e.name().eq_ignore_ascii_case(name))
    }

    /// Whether the type belongs to the class.
    pub fn class_member(self, class: Class) -> bool {
        use Elem::*;
        let int = matches!(
            self,
            SINT | INT | DINT | LINT | USINT | UINT | UDINT | ULINT
        );
        let real = matches!(self, REAL | LREAL);
        let bits = matches!(self, BYTE | WORD | DWORD | LWORD);
        match class {
            Class::AnyNum => int || real,
            Class::AnyInt => int,
            Class::AnyReal => real,
            Class::AnyBit => bits || self == BOOL,
            Class::AnyBitString => bits,
            Class::AnyMagnitude => int || real || matches!(self, TIME | LTIME),
            Class::AnyElementary | Class::Any => true,
            Class::AnyString => matches!(self, STRING | WSTRING),
            Class::AnyDate => matches!(self, DATE | TOD | DT),
            Class::Bool => self == BOOL,
        }
    }

    /// Width in bits (`BOOL` is 1; time and date types 64; strings `None`).
    pub fn bits(self) -> Option<u32> {
        use Elem::*;
        Some(match self {
            BOOL => 1,
            SINT | USINT | BYTE => 8,
            INT | UINT | WORD => 16,
            DINT | UDINT | DWORD | REAL => 32,
            LINT | ULINT | LWORD | LREAL | TIME | LTIME | DATE | TOD | DT => 64,
            STRING | WSTRING => return None,
        })
    }

    /// The value range of an integer or bit-string type (`BOOL` is `0..=1`), for range-checking
    /// literals; `None` for other types.
    pub fn min_max_i128(self) -> Option<(i128, i128)> {
        use Elem::*;
        Some(match self {
            BOOL => (0, 1),
            SINT => (i8::MIN.into(), i8::MAX.into()),
            INT => (i16::MIN.into(), i16::MAX.into()),
            DINT => (i32::MIN.into(), i32::MAX.into()),
            LINT => (i64::MIN.into(), i64::MAX.into()),
            USINT | BYTE => (0, u8::MAX.into()),
            UINT | WORD => (0, u16::MAX.into()),
            UDINT | DWORD => (0, u32::MAX.into()),
            ULINT | LWORD => (0, u64::MAX.into()),
            _ => return None,
        })
    }
}

/// The type of a parameter or of a result.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ParamTy {
    /// Exactly this type.
    Concrete(Elem),
    /// The function's generic type `T`, a member of the class: all `T` parameters and a `T`
    /// result of one call have the same type (strings may differ in length).
    T(Class),
    /// Any member of the class, independent of `T` and of other `Other` parameters
    /// (e.g. `SHL`'s `N`, `EXPT`'s `IN2`).
    Other(Class),
}

/// How a function takes more inputs than its listed parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Ext {
    /// Exactly the listed parameters.
    Fixed,
    /// Extensible by folding: `ADD(a,b,c) = ADD(ADD(a,b),c)`.
    Fold,
    /// Extensible comparison chain: `GT(a,b,c) = GT(a,b) AND GT(b,c)`.
    Chain,
    /// `MUX(K, IN0, IN1, ... INn)`: the Rust function takes `K` and a slice of the inputs.
    Mux,
}

/// One parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Param {
    /// IEC formal name (`IN`, `IN1`, `MN` ...).
    pub name: &'static str,
    /// Its type.
    pub ty: ParamTy,
}

/// The signature of one standard function.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Signature {
    /// IEC name, which is also the Rust name in [`func`](crate::func).
    pub name: &'static str,
    /// Parameters in positional order (for `Fold`/`Chain`, the first two; for `Mux`, `K` and
    /// `IN0`, `IN1`).
    pub params: &'static [Param],
    /// Result type.
    pub ret: ParamTy,
    /// Extensibility.
    pub ext: Ext,
    /// The runtime fault a call may record in the [`Cycle`](crate::Cycle) (the result is then
    /// the documented fallback: 0, `T#0s`, the saturated or truncated value, `IN0`). A
    /// [`FaultKind::DivisionByZero`] applies only to an integer divisor: see
    /// [`Signature::fault_for`], which compilers and interpreters ask.
    pub fault: Option<FaultKind>,
    /// How a REAL argument becomes an integer result, for the conversions
    /// that do (REAL_TO_INT rounds half to even; TRUNC and REAL_TRUNC_INT
    /// truncate): what a compiler's or an interpreter's out-of-range check
    /// must round as the function does.
    pub rounding: Option<Rounding>,
    /// For a type conversion (`INT_TO_REAL`, `REAL_TRUNC_INT`, `INT_TO_BCD`):
    /// what it converts from and to, and how ([`Conversion`]); `None` for
    /// the other functions.
    pub conversion: Option<Conversion>,
    /// Which function it is: what a tool that evaluates calls (an
    /// interpreter) dispatches on, rather than on [`name`](Signature::name).
    pub func: Func,
    /// One line saying what the function does.
    pub doc: &'static str,
}

/// A type conversion of the table ([`Signature::conversion`]): a tool that
/// evaluates calls (an interpreter) converts by this, not by the name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Conversion {
    /// The argument's type.
    pub from: Elem,
    /// The result's type.
    pub to: Elem,
    /// How.
    pub kind: ConvKind,
}

/// How a [`Conversion`] converts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ConvKind {
    /// By the value and the two types (widening, narrowing with wrap, REAL
    /// rounding half to even, durations, strings ...), as `FROM_TO_TO` does.
    Value,
    /// REAL to an integer, truncated toward zero (`REAL_TRUNC_INT`).
    Trunc,
    /// An integer to its binary-coded decimal (`INT_TO_BCD`).
    ToBcd,
    /// A binary-coded decimal to an integer (`BCD_TO_INT`).
    FromBcd,
    /// The same bits seen as the other type, a bit string as a real or a
    /// real as a bit string (`DWORD_AS_REAL`, `REAL_AS_DWORD`).
    Bits,
}

/// The [`ConvKind`] of a conversion, by its kind in [`conversions`].
macro_rules! conv_kind {
    (trunc) => {
        ConvKind::Trunc
    };
    (to_bcd) => {
        ConvKind::ToBcd
    };
    (bcd_to) => {
        ConvKind::FromBcd
    };
    (bits_to_real) => {
        ConvKind::Bits
    };
    (real_to_bits) => {
        ConvKind::Bits
    };
    ($other:ident) => {
        ConvKind::Value
    };
}

/// How a real number becomes an integer ([`Signature::rounding`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Rounding {
    /// To the nearest integer, halves to the even one (`REAL_TO_INT`).
    HalfEven,
    /// Toward zero (`TRUNC`, `REAL_TRUNC_INT`).
    TowardZero,
}

impl Signature {
    /// The fault a call with arguments of the types `args` (positional, as resolved) may
    /// record: [`fault`](Signature::fault), except that a division (`DIV`, `MOD`, `DIV_TIME`)
    /// faults only when its divisor, the second argument, is an integer (a REAL divisor of 0
    /// gives an infinity, or a saturated duration, and no fault).
    pub fn fault_for(&self, args: &[Elem]) -> Option<FaultKind> {
        match self.fault? {
            FaultKind::DivisionByZero => args
                .get(1)
                .is_some_and(|d| d.class_member(Class::AnyInt))
                .then_some(FaultKind::DivisionByZero),
            k => Some(k),
        }
    }
}

macro_rules! pty {
    (C $e:ident) => {
        ParamTy::Concrete(Elem::$e)
    };
    (T $c:ident) => {
        ParamTy::T(Class::$c)
    };
    (O $c:ident) => {
        ParamTy::Other(Class::$c)
    };
}

/// The fault of a hand-written entry (`-> T AnyNum ! DivisionByZero`).
macro_rules! fault {
    () => {
        None
    };
    ($f:ident) => {
        Some(FaultKind::$f)
    };
}

/// The fault of a conversion, by its kind in [`conversions`]: REAL/LREAL to an integer or a bit
/// string (rounded or truncated) saturates out of range and records a fault.
macro_rules! conv_fault {
    (round) => {
        Some(FaultKind::ConversionOutOfRange)
    };
    (trunc) => {
        Some(FaultKind::ConversionOutOfRange)
    };
    ($other:ident) => {
        None
    };
}

/// The rounding of a conversion, by its kind in [`conversions`].
macro_rules! conv_rounding {
    (round) => {
        Some(Rounding::HalfEven)
    };
    (trunc) => {
        Some(Rounding::TowardZero)
    };
    ($other:ident) => {
        None
    };
}

/// The rounding of a hand-written entry (`~ TowardZero`).
macro_rules! rounding {
    () => {
        None
    };
    ($r:ident) => {
        Some(Rounding::$r)
    };
}

macro_rules! build_table {
    ([ $( $name:ident $ext:ident ( $( $p:ident : $pk:ident $pc:ident ),* ) -> $rk:ident $rc:ident $( ! $fault:ident )? $( ~ $round:ident )? , $doc:literal ; )* ]
     $( $cname:ident : $src:ident => $dst:ident, $kind:ident ; )*) => {
        /// Which standard function a [`Signature`] describes, one variant per
        /// hand-written function of [`func`](crate::func) (named as it), and
        /// [`Func::Conversion`] for every type conversion (what it converts is
        /// [`Signature::conversion`]).
        #[allow(non_camel_case_types)]
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Func {
            $(
                #[doc = $doc]
                $name,
            )*
            /// A type conversion (`INT_TO_REAL`, `REAL_TRUNC_INT`, `INT_TO_BCD` ...).
            Conversion,
        }

        /// Every standard function of [`func`](crate::func): the hand-written overloaded ones
        /// first, then the type conversions.
        pub static SIGNATURES: &[Signature] = &[
            $( Signature {
                name: stringify!($name),
                params: &[ $( Param { name: stringify!($p), ty: pty!($pk $pc) } ),* ],
                ret: pty!($rk $rc),
                ext: Ext::$ext,
                fault: fault!($($fault)?),
                rounding: rounding!($($round)?),
                conversion: None,
                func: Func::$name,
                doc: $doc,
            }, )*
            $( Signature {
                name: stringify!($cname),
                params: &[Param { name: "IN", ty: ParamTy::Concrete(Elem::$src) }],
                ret: ParamTy::Concrete(Elem::$dst),
                ext: Ext::Fixed,
                fault: conv_fault!($kind),
                rounding: conv_rounding!($kind),
                conversion: Some(Conversion {
                    from: Elem::$src,
                    to: Elem::$dst,
                    kind: conv_kind!($kind),
                }),
                func: Func::Conversion,
                doc: concat!("Converts ", stringify!($src), " to ", stringify!($dst), "."),
            }, )*
        ];

        /// Compile-time proof that every entry names a real function of `func`.
        #[cfg(all(test, feature = "runtime"))]
        #[allow(unused_imports)]
        mod exists {
            use crate::func::{ $( $name, )* $( $cname, )* };
        }
    };
}

conversions!(build_table;
    ADD Fold (IN1: T AnyMagnitude, IN2: T AnyMagnitude) -> T AnyMagnitude, "Addition (integers and TIME wrap).";
    SUB Fixed (IN1: T AnyMagnitude, IN2: T AnyMagnitude) -> T AnyMagnitude, "Subtraction (integers and TIME wrap).";
    MUL Fold (IN1: T AnyNum, IN2: T AnyNum) -> T AnyNum, "Multiplication (integers wrap).";
    DIV Fixed (IN1: T AnyNum, IN2: T AnyNum) -> T AnyNum ! DivisionByZero, "Division (integers truncate toward zero; by zero gives 0 and a fault).";
    MOD Fixed (IN1: T AnyInt, IN2: T AnyInt) -> T AnyInt ! DivisionByZero, "Remainder with the dividend's sign (by zero gives 0 and a fault).";
    MOVE Fixed (IN: T Any) -> T Any, "Assignment: returns IN.";
    ABS Fixed (IN: T AnyNum) -> T AnyNum, "Absolute value.";
    SQRT Fixed (IN: T AnyReal) -> T AnyReal, "Square root.";
    LN Fixed (IN: T AnyReal) -> T AnyReal, "Natural logarithm.";
    LOG Fixed (IN: T AnyReal) -> T AnyReal, "Base-10 logarithm.";
    EXP Fixed (IN: T AnyReal) -> T AnyReal, "Natural exponential.";
    SIN Fixed (IN: T AnyReal) -> T AnyReal, "Sine (radians).";
    COS Fixed (IN: T AnyReal) -> T AnyReal, "Cosine (radians).";
    TAN Fixed (IN: T AnyReal) -> T AnyReal, "Tangent (radians).";
    ASIN Fixed (IN: T AnyReal) -> T AnyReal, "Principal arc sine.";
    ACOS Fixed (IN: T AnyReal) -> T AnyReal, "Principal arc cosine.";
    ATAN Fixed (IN: T AnyReal) -> T AnyReal, "Principal arc tangent.";
    EXPT Fixed (IN1: T AnyReal, IN2: O AnyNum) -> T AnyReal, "Exponentiation IN1 ** IN2.";
    TRUNC Fixed (IN: O AnyReal) -> C DINT ! ConversionOutOfRange ~ TowardZero, "Truncation toward zero to DINT.";
    SHL Fixed (IN: T AnyBitString, N: O AnyInt) -> T AnyBitString, "Shift left by N bits, zero-filled.";
    SHR Fixed (IN: T AnyBitString, N: O AnyInt) -> T AnyBitString, "Shift right by N bits, zero-filled.";
    ROL Fixed (IN: T AnyBitString, N: O AnyInt) -> T AnyBitString, "Rotate left by N bits.";
    ROR Fixed (IN: T AnyBitString, N: O AnyInt) -> T AnyBitString, "Rotate right by N bits.";
    AND Fold (IN1: T AnyBit, IN2: T AnyBit) -> T AnyBit, "Bitwise/Boolean AND.";
    OR Fold (IN1: T AnyBit, IN2: T AnyBit) -> T AnyBit, "Bitwise/Boolean OR.";
    XOR Fold (IN1: T AnyBit, IN2: T AnyBit) -> T AnyBit, "Bitwise/Boolean exclusive OR.";
    NOT Fixed (IN: T AnyBit) -> T AnyBit, "Bitwise/Boolean complement.";
    SEL Fixed (G: C BOOL, IN0: T Any, IN1: T Any) -> T Any, "Binary selection: IN0 if G is FALSE, else IN1.";
    MAX Fold (IN1: T AnyElementary, IN2: T AnyElementary) -> T AnyElementary, "Maximum.";
    MIN Fold (IN1: T AnyElementary, IN2: T AnyElementary) -> T AnyElementary, "Minimum.";
    LIMIT Fixed (MN: T AnyElementary, IN: T AnyElementary, MX: T AnyElementary) -> T AnyElementary, "IN limited to [MN, MX].";
    MUX Mux (K: O AnyInt, IN0: T Any, IN1: T Any) -> T Any ! InvalidArgument, "Multiplexer: selects input K (IN0 if out of range, with a fault).";
    GT Chain (IN1: T AnyElementary, IN2: T AnyElementary) -> C BOOL, "Greater than (decreasing sequence).";
    GE Chain (IN1: T AnyElementary, IN2: T AnyElementary) -> C BOOL, "Greater or equal (monotonic sequence).";
    EQ Chain (IN1: T AnyElementary, IN2: T AnyElementary) -> C BOOL, "Equality.";
    LE Chain (IN1: T AnyElementary, IN2: T AnyElementary) -> C BOOL, "Less or equal (monotonic sequence).";
    LT Chain (IN1: T AnyElementary, IN2: T AnyElementary) -> C BOOL, "Less than (increasing sequence).";
    NE Fixed (IN1: T AnyElementary, IN2: T AnyElementary) -> C BOOL, "Inequality.";
    LEN Fixed (IN: O AnyString) -> C INT, "Length of a string.";
    LEFT Fixed (IN: T AnyString, L: O AnyInt) -> T AnyString, "Leftmost L characters.";
    RIGHT Fixed (IN: T AnyString, L: O AnyInt) -> T AnyString, "Rightmost L characters.";
    MID Fixed (IN: T AnyString, L: O AnyInt, P: O AnyInt) -> T AnyString, "L characters from position P.";
    CONCAT Fold (IN1: T AnyString, IN2: T AnyString) -> T AnyString ! StringOverflow, "Concatenation (capacity of IN1; a longer result is truncated, with a fault).";
    INSERT Fixed (IN1: T AnyString, IN2: T AnyString, P: O AnyInt) -> T AnyString ! StringOverflow, "IN2 inserted after position P of IN1 (capacity of IN1; a longer result is truncated, with a fault).";
    DELETE Fixed (IN: T AnyString, L: O AnyInt, P: O AnyInt) -> T AnyString, "Deletes L characters from position P.";
    REPLACE Fixed (IN1: T AnyString, IN2: T AnyString, L: O AnyInt, P: O AnyInt) -> T AnyString ! StringOverflow, "Replaces L characters of IN1 from position P by IN2 (capacity of IN1; a longer result is truncated, with a fault).";
    FIND Fixed (IN1: T AnyString, IN2: T AnyString) -> C INT, "Position of IN2 in IN1 (0 if absent).";
    ADD_TIME Fixed (IN1: C TIME, IN2: C TIME) -> C TIME, "TIME + TIME.";
    SUB_TIME Fixed (IN1: C TIME, IN2: C TIME) -> C TIME, "TIME - TIME.";
    MUL_TIME Fixed (IN1: C TIME, IN2: O AnyNum) -> C TIME, "TIME * number.";
    DIV_TIME Fixed (IN1: C TIME, IN2: O AnyNum) -> C TIME ! DivisionByZero, "TIME / number (integer 0 gives T#0s and a fault).";
    ADD_TOD_TIME Fixed (IN1: C TOD, IN2: C TIME) -> C TOD, "Time of day + TIME (modulo 24 h).";
    SUB_TOD_TIME Fixed (IN1: C TOD, IN2: C TIME) -> C TOD, "Time of day - TIME (modulo 24 h).";
    ADD_DT_TIME Fixed (IN1: C DT, IN2: C TIME) -> C DT, "Date and time + TIME.";
    SUB_DT_TIME Fixed (IN1: C DT, IN2: C TIME) -> C DT, "Date and time - TIME.";
    SUB_DATE_DATE Fixed (IN1: C DATE, IN2: C DATE) -> C TIME, "Duration between two dates.";
    SUB_TOD_TOD Fixed (IN1: C TOD, IN2: C TOD) -> C TIME, "Duration between two times of day.";
    SUB_DT_DT Fixed (IN1: C DT, IN2: C DT) -> C TIME, "Duration between two dates and times.";
    CONCAT_DATE_TOD Fixed (IN1: C DATE, IN2: C TOD) -> C DT, "Date and time from a date and a time of day.";
);

/// The signature of the function `name` (case-insensitive; the long type names
/// `TIME_OF_DAY` and `DATE_AND_TIME` inside a name are accepted for `TOD` and `DT`, e.g.
/// `DATE_AND_TIME_TO_TIME_OF_DAY`).
pub fn lookup(name: &str) -> Option<&'static Signature> {
    if let Some(s) = SIGNATURES
        .iter()
        .find(|s| s.name.eq_ignore_ascii_case(name))
    {
        return Some(s);
    }
    // Normalise long type names into a small stack buffer, then retry.
    let mut buf = [0u8; 64];
    let mut n = 0;
    let mut rest = name.as_bytes();
    while let Some((&c, tail)) = rest.split_first() {
        let (rep, skip): (&[u8], usize) = if starts_with_ci(rest, b"DATE_AND_TIME") {
            (b"DT", 13)
        } else if starts_with_ci(rest, b"TIME_OF_DAY") {
            (b"TOD", 11)
        } else {
            (core::slice::from_ref(&c), 1)
        };
        for &b in rep {
            *buf.get_mut(n)? = b;
            n += 1;
        }
        rest = if skip == 1 { tail } else { rest.get(skip..)? };
    }
    let norm = core::str::from_utf8(buf.get(..n)?).ok()?;
    SIGNATURES
        .iter()
        .find(|s| s.name.eq_ignore_ascii_case(norm))
}

fn starts_with_ci(s: &[u8], p: &[u8]) -> bool {
    s.get(..p.len()).is_some_and(|h| h.eq_ignore_ascii_case(p))
}
