//! IEC types as the checker sees them, and their Rust spelling.

use std::fmt;

/// Elementary types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(clippy::upper_case_acronyms)]
pub enum Elem {
    /// `BOOL`: `bool`.
    BOOL,
    /// `SINT`: 8-bit signed integer (`i8`).
    SINT,
    /// `INT`: 16-bit signed integer (`i16`).
    INT,
    /// `DINT`: 32-bit signed integer (`i32`).
    DINT,
    /// `LINT`: 64-bit signed integer (`i64`).
    LINT,
    /// `USINT`: 8-bit unsigned integer (`u8`).
    USINT,
    /// `UINT`: 16-bit unsigned integer (`u16`).
    UINT,
    /// `UDINT`: 32-bit unsigned integer (`u32`).
    UDINT,
    /// `ULINT`: 64-bit unsigned integer (`u64`).
    ULINT,
    /// `BYTE`: 8-bit bit string (`u8`).
    BYTE,
    /// `WORD`: 16-bit bit string (`u16`).
    WORD,
    /// `DWORD`: 32-bit bit string (`u32`).
    DWORD,
    /// `LWORD`: 64-bit bit string (`u64`).
    LWORD,
    /// `REAL`: 32-bit float (`f32`).
    REAL,
    /// `LREAL`: 64-bit float (`f64`).
    LREAL,
    /// `TIME`: a duration (`il_std::TIME`, nanoseconds).
    TIME,
    /// `LTIME`: a long duration (`il_std::LTIME`, nanoseconds).
    LTIME,
    /// `DATE`: a calendar date (`il_std::DATE`, days since 1970-01-01).
    DATE,
    /// `TIME_OF_DAY` / `TOD`: nanoseconds since midnight (`il_std::TOD`).
    TOD,
    /// `DATE_AND_TIME` / `DT`: nanoseconds since 1970-01-01T00:00:00 (`il_std::DT`).
    DT,
}

use Elem::*;

/// Every elementary type, in declaration order.
pub const ALL_ELEMS: &[Elem] = &[
    BOOL, SINT, INT, DINT, LINT, USINT, UINT, UDINT, ULINT, BYTE, WORD, DWORD, LWORD, REAL, LREAL,
    TIME, LTIME, DATE, TOD, DT,
];

/// il-std's vocabulary of elementary types (its signature tables) and
/// this one are one: every type here is one there, matched arm by arm so
/// that a type added to either side fails to compile until both agree.
impl From<Elem> for il_std::signature::Elem {
    fn from(e: Elem) -> Self {
        use il_std::signature::Elem as S;
        match e {
            BOOL => S::BOOL,
            SINT => S::SINT,
            INT => S::INT,
            DINT => S::DINT,
            LINT => S::LINT,
            USINT => S::USINT,
            UINT => S::UINT,
            UDINT => S::UDINT,
            ULINT => S::ULINT,
            BYTE => S::BYTE,
            WORD => S::WORD,
            DWORD => S::DWORD,
            LWORD => S::LWORD,
            REAL => S::REAL,
            LREAL => S::LREAL,
            TIME => S::TIME,
            LTIME => S::LTIME,
            DATE => S::DATE,
            TOD => S::TOD,
            DT => S::DT,
        }
    }
}

impl Ty {
    /// The rows of an array: the array without its first dimension (the
    /// element type for one dimension); a large array on the heap is a
    /// boxed slice of its rows.
    pub fn row(&self) -> Ty {
        match self {
            Ty::Array(a) if a.dims.len() > 1 => Ty::Array(Box::new(ArrayTy {
                dims: a.dims[1..].to_vec(),
                elem: a.elem.clone(),
                range: a.range,
            })),
            Ty::Array(a) => a.elem.clone(),
            _ => self.clone(),
        }
    }
}

impl Ty {
    /// The type il-std's tables name: strings are [`Ty::Str`] of the
    /// default capacity, the others elementary.
    pub fn of_std(e: il_std::signature::Elem) -> Ty {
        use il_std::signature::Elem as S;
        Ty::Elem(match e {
            S::STRING | S::WSTRING => {
                return Ty::Str {
                    wide: e == S::WSTRING,
                    len: DEFAULT_STRING_LEN,
                };
            }
            S::BOOL => BOOL,
            S::SINT => SINT,
            S::INT => INT,
            S::DINT => DINT,
            S::LINT => LINT,
            S::USINT => USINT,
            S::UINT => UINT,
            S::UDINT => UDINT,
            S::ULINT => ULINT,
            S::BYTE => BYTE,
            S::WORD => WORD,
            S::DWORD => DWORD,
            S::LWORD => LWORD,
            S::REAL => REAL,
            S::LREAL => LREAL,
            S::TIME => TIME,
            S::LTIME => LTIME,
            S::DATE => DATE,
            S::TOD => TOD,
            S::DT => DT,
        })
    }
}

impl Elem {
    /// The IEC name (the long form for `TIME_OF_DAY` and `DATE_AND_TIME`).
    pub fn name(self) -> &'static str {
        match self {
            BOOL => "BOOL",
            SINT => "SINT",
            INT => "INT",
            DINT => "DINT",
            LINT => "LINT",
            USINT => "USINT",
            UINT => "UINT",
            UDINT => "UDINT",
            ULINT => "ULINT",
            BYTE => "BYTE",
            WORD => "WORD",
            DWORD => "DWORD",
            LWORD => "LWORD",
            REAL => "REAL",
            LREAL => "LREAL",
            TIME => "TIME",
            LTIME => "LTIME",
            DATE => "DATE",
            TOD => "TIME_OF_DAY",
            DT => "DATE_AND_TIME",
        }
    }

    /// Look a type name up, case-insensitively (`TOD` and `DT` also in their long forms).
    pub fn from_name(name: &str) -> Option<Elem> {
        let up = name.to_ascii_uppercase();
        Some(match up.as_str() {
            "TOD" | "TIME_OF_DAY" => TOD,
            "DT" | "DATE_AND_TIME" => DT,
            _ => *ALL_ELEMS.iter().find(|e| e.name() == up)?,
        })
    }

    /// Signed or unsigned integer (not a bit string).
    pub fn is_int(self) -> bool {
        matches!(
            self,
            SINT | INT | DINT | LINT | USINT | UINT | UDINT | ULINT
        )
    }
    /// SINT, INT, DINT or LINT.
    pub fn is_signed_int(self) -> bool {
        matches!(self, SINT | INT | DINT | LINT)
    }
    /// REAL or LREAL.
    pub fn is_real(self) -> bool {
        matches!(self, REAL | LREAL)
    }
    /// Integer or real: what ADD..DIV and the numeric comparisons accept.
    pub fn is_num(self) -> bool {
        self.is_int() || self.is_real()
    }
    /// BYTE WORD DWORD LWORD (BOOL is handled on its own).
    pub fn is_bitstring(self) -> bool {
        matches!(self, BYTE | WORD | DWORD | LWORD)
    }
    /// TIME or LTIME.
    pub fn is_duration(self) -> bool {
        matches!(self, TIME | LTIME)
    }
    /// DATE, TIME_OF_DAY or DATE_AND_TIME.
    pub fn is_date(self) -> bool {
        matches!(self, DATE | TOD | DT)
    }

    /// Inclusive value range of integer and bit-string types.
    pub fn int_range(self) -> Option<(i128, i128)> {
        Some(match self {
            BOOL => (0, 1),
            SINT => (i8::MIN as i128, i8::MAX as i128),
            INT => (i16::MIN as i128, i16::MAX as i128),
            DINT => (i32::MIN as i128, i32::MAX as i128),
            LINT => (i64::MIN as i128, i64::MAX as i128),
            USINT | BYTE => (0, u8::MAX as i128),
            UINT | WORD => (0, u16::MAX as i128),
            UDINT | DWORD => (0, u32::MAX as i128),
            ULINT | LWORD => (0, u64::MAX as i128),
            _ => return None,
        })
    }

    /// The Rust type (text).
    pub fn rust(self) -> &'static str {
        match self {
            BOOL => "bool",
            SINT => "i8",
            INT => "i16",
            DINT => "i32",
            LINT => "i64",
            USINT | BYTE => "u8",
            UINT | WORD => "u16",
            UDINT | DWORD => "u32",
            ULINT | LWORD => "u64",
            REAL => "f32",
            LREAL => "f64",
            TIME => "::il_std::TIME",
            LTIME => "::il_std::LTIME",
            DATE => "::il_std::DATE",
            TOD => "::il_std::TOD",
            DT => "::il_std::DT",
        }
    }

    /// A short name for generated local variables (`__cr_int`).
    pub fn mangle(self) -> &'static str {
        match self {
            BOOL => "bool",
            SINT => "sint",
            INT => "int",
            DINT => "dint",
            LINT => "lint",
            USINT => "usint",
            UINT => "uint",
            UDINT => "udint",
            ULINT => "ulint",
            BYTE => "byte",
            WORD => "word",
            DWORD => "dword",
            LWORD => "lword",
            REAL => "real",
            LREAL => "lreal",
            TIME => "time",
            LTIME => "ltime",
            DATE => "date",
            TOD => "tod",
            DT => "dt",
        }
    }
}

/// A type of a variable or of the current result.
#[derive(Debug, PartialEq, Eq, Hash)]
pub enum Ty {
    /// An elementary type.
    Elem(Elem),
    /// `STRING[len]` / `WSTRING[len]`
    Str {
        /// WSTRING (UTF-16) rather than STRING (bytes).
        wide: bool,
        /// Maximum length in characters.
        len: u32,
    },
    /// ARRAY[lo..hi, ...] OF elem. Boxed: rarer than the others, and its
    /// parts inline made every type (so every IR value and statement) much
    /// larger.
    Array(Box<ArrayTy>),
    /// An instance of a standard or user function block (name as declared).
    Fb(Name),
    /// A user STRUCT type (name as declared).
    Struct(Name),
    /// A user enumeration (name as declared).
    Enum(Name),
}

/// The name of a user type or function block in a [`Ty`]: shared, and one
/// pointer wide, so that a type is two words (an IR value three).
pub type Name = std::sync::Arc<String>;

/// An array type ([`Ty::Array`]).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ArrayTy {
    /// `(lo, hi)` per dimension, inclusive.
    pub dims: Vec<(i64, i64)>,
    /// The element type.
    pub elem: Ty,
    /// The element type is a subrange of an integer type: its bounds.
    /// The elements start at the lower one and every store into one is
    /// range-checked (as for a subrange variable).
    pub range: Option<(i128, i128)>,
}

// By hand, for an inlined fast path: the checker clones a type about ten
// times per instruction (into the IR, the current result, the CR state),
// almost always an elementary one; the derived `clone` was a call and a
// match every time (36 M instructions for a 100k-line POU).
impl Clone for Ty {
    #[inline]
    fn clone(&self) -> Ty {
        match self {
            Ty::Elem(e) => Ty::Elem(*e),
            other => other.clone_slow(),
        }
    }
}

impl Ty {
    #[inline(never)]
    fn clone_slow(&self) -> Ty {
        match self {
            Ty::Elem(e) => Ty::Elem(*e),
            Ty::Str { wide, len } => Ty::Str {
                wide: *wide,
                len: *len,
            },
            Ty::Array(a) => Ty::Array(a.clone()),
            Ty::Fb(n) => Ty::Fb(n.clone()),
            Ty::Struct(n) => Ty::Struct(n.clone()),
            Ty::Enum(n) => Ty::Enum(n.clone()),
        }
    }
}

/// IEC's default STRING length (implementation-defined; il-std uses 80).
pub const DEFAULT_STRING_LEN: u32 = 80;

impl Ty {
    /// The type of conditions and comparison results.
    pub const BOOL: Ty = Ty::Elem(BOOL);

    /// The elementary type, if it is one.
    pub fn elem(&self) -> Option<Elem> {
        match self {
            Ty::Elem(e) => Some(*e),
            _ => None,
        }
    }
    /// Exactly BOOL (not a bit string).
    pub fn is_bool(&self) -> bool {
        *self == Ty::BOOL
    }
    /// BOOL or a bit string: what AND/OR/XOR/NOT accept.
    pub fn is_logic(&self) -> bool {
        matches!(self, Ty::Elem(e) if *e == BOOL || e.is_bitstring())
    }

    /// Both are strings of one kind (STRING or WSTRING) with different
    /// capacities: one type for assignment, parameters and comparison
    /// (docs/semantics.md, "Types"); a value going to `to` is cut at its
    /// length ([`super::Value::Resized`]).
    pub fn resizes_to(&self, to: &Ty) -> bool {
        matches!((self, to), (Ty::Str { wide: a, len: m }, Ty::Str { wide: b, len: n }) if a == b && m != n)
    }

    /// The Rust type, with `fb_path` giving the path of a function block type.
    /// (Rust text: the emitter writes it as it is.)
    pub fn rust(&self, fb_path: &dyn Fn(&str) -> String) -> String {
        match self {
            Ty::Elem(e) => e.rust().to_string(),
            Ty::Str { wide: false, len } => format!("::il_std::STRING<{len}>"),
            Ty::Str { wide: true, len } => format!("::il_std::WSTRING<{len}>"),
            Ty::Array(a) => {
                let mut t = a.elem.rust(fb_path);
                for (lo, hi) in a.dims.iter().rev() {
                    let n = (hi - lo + 1) as usize;
                    t = format!("[{t}; {n}]");
                }
                t
            }
            Ty::Fb(name) | Ty::Struct(name) | Ty::Enum(name) => fb_path(name.as_str()),
        }
    }

    /// A name for generated CR locals (`__cr_int`, `__cr_string80`).
    pub fn mangle(&self) -> String {
        match self {
            Ty::Elem(e) => e.mangle().to_string(),
            Ty::Str { wide, len } => format!("{}string{len}", if *wide { "w" } else { "" }),
            Ty::Array(a) => {
                let mut s = String::from("array");
                for (lo, hi) in &a.dims {
                    s.push_str(&format!("_{}_{}", lo, hi).replace('-', "m"));
                }
                s.push_str("_of_");
                s.push_str(&a.elem.mangle());
                if let Some((lo, hi)) = a.range {
                    s.push_str(&format!("_{lo}_{hi}").replace('-', "m"));
                }
                s
            }
            Ty::Fb(n) | Ty::Struct(n) | Ty::Enum(n) => n.to_ascii_lowercase(),
        }
    }
}

impl fmt::Display for Ty {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ty::Elem(e) => f.write_str(e.name()),
            Ty::Str { wide, len } => {
                let kw = if *wide { "WSTRING" } else { "STRING" };
                if *len == DEFAULT_STRING_LEN {
                    f.write_str(kw)
                } else {
                    write!(f, "{kw}[{len}]")
                }
            }
            Ty::Array(a) => {
                f.write_str("ARRAY[")?;
                for (i, (lo, hi)) in a.dims.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{lo}..{hi}")?;
                }
                write!(f, "] OF {}", a.elem)?;
                match a.range {
                    Some((lo, hi)) => write!(f, " ({lo}..{hi})"),
                    None => Ok(()),
                }
            }
            Ty::Fb(n) | Ty::Struct(n) | Ty::Enum(n) => f.write_str(n),
        }
    }
}
