//! IEC types as the checker sees them, and their Rust spelling.

use proc_macro2::TokenStream;
use quote::quote;
use std::fmt;

/// Elementary types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(clippy::upper_case_acronyms)]
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
}

use Elem::*;

pub const ALL_ELEMS: &[Elem] = &[
    BOOL, SINT, INT, DINT, LINT, USINT, UINT, UDINT, ULINT, BYTE, WORD, DWORD, LWORD, REAL, LREAL,
    TIME, LTIME, DATE, TOD, DT,
];

impl Elem {
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

    pub fn from_name(name: &str) -> Option<Elem> {
        let up = name.to_ascii_uppercase();
        Some(match up.as_str() {
            "TOD" | "TIME_OF_DAY" => TOD,
            "DT" | "DATE_AND_TIME" => DT,
            _ => *ALL_ELEMS.iter().find(|e| e.name() == up)?,
        })
    }

    pub fn is_int(self) -> bool {
        matches!(
            self,
            SINT | INT | DINT | LINT | USINT | UINT | UDINT | ULINT
        )
    }
    pub fn is_signed_int(self) -> bool {
        matches!(self, SINT | INT | DINT | LINT)
    }
    pub fn is_real(self) -> bool {
        matches!(self, REAL | LREAL)
    }
    pub fn is_num(self) -> bool {
        self.is_int() || self.is_real()
    }
    /// BYTE WORD DWORD LWORD (BOOL is handled on its own).
    pub fn is_bitstring(self) -> bool {
        matches!(self, BYTE | WORD | DWORD | LWORD)
    }
    pub fn is_duration(self) -> bool {
        matches!(self, TIME | LTIME)
    }
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

    /// The Rust type.
    pub fn rust(self) -> TokenStream {
        match self {
            BOOL => quote!(bool),
            SINT => quote!(i8),
            INT => quote!(i16),
            DINT => quote!(i32),
            LINT => quote!(i64),
            USINT | BYTE => quote!(u8),
            UINT | WORD => quote!(u16),
            UDINT | DWORD => quote!(u32),
            ULINT | LWORD => quote!(u64),
            REAL => quote!(f32),
            LREAL => quote!(f64),
            TIME => quote!(::il_std::TIME),
            LTIME => quote!(::il_std::LTIME),
            DATE => quote!(::il_std::DATE),
            TOD => quote!(::il_std::TOD),
            DT => quote!(::il_std::DT),
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
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Ty {
    Elem(Elem),
    /// `STRING[len]` / `WSTRING[len]`
    Str {
        wide: bool,
        len: u32,
    },
    /// ARRAY[lo..hi, ...] OF elem
    Array {
        dims: Vec<(i64, i64)>,
        elem: Box<Ty>,
    },
    /// An instance of a standard or user function block (name as declared).
    Fb(String),
    /// A user STRUCT type (name as declared).
    Struct(String),
    /// A user enumeration (name as declared).
    Enum(String),
}

/// IEC's default STRING length (implementation-defined; il-std uses 80).
pub const DEFAULT_STRING_LEN: u32 = 80;

impl Ty {
    pub const BOOL: Ty = Ty::Elem(BOOL);

    pub fn elem(&self) -> Option<Elem> {
        match self {
            Ty::Elem(e) => Some(*e),
            _ => None,
        }
    }
    pub fn is_bool(&self) -> bool {
        *self == Ty::BOOL
    }
    /// BOOL or a bit string: what AND/OR/XOR/NOT accept.
    pub fn is_logic(&self) -> bool {
        matches!(self, Ty::Elem(e) if *e == BOOL || e.is_bitstring())
    }

    /// The Rust type, with `fb_path` giving the path of a function block type.
    pub fn rust(&self, fb_path: &dyn Fn(&str) -> TokenStream) -> TokenStream {
        match self {
            Ty::Elem(e) => e.rust(),
            Ty::Str { wide: false, len } => {
                let n = *len as usize;
                quote!(::il_std::STRING<#n>)
            }
            Ty::Str { wide: true, len } => {
                let n = *len as usize;
                quote!(::il_std::WSTRING<#n>)
            }
            Ty::Array { dims, elem } => {
                let mut t = elem.rust(fb_path);
                for (lo, hi) in dims.iter().rev() {
                    let n = (hi - lo + 1) as usize;
                    t = quote!([#t; #n]);
                }
                t
            }
            Ty::Fb(name) | Ty::Struct(name) | Ty::Enum(name) => fb_path(name),
        }
    }

    /// A name for generated CR locals (`__cr_int`, `__cr_string80`).
    pub fn mangle(&self) -> String {
        match self {
            Ty::Elem(e) => e.mangle().to_string(),
            Ty::Str { wide, len } => format!("{}string{len}", if *wide { "w" } else { "" }),
            Ty::Array { dims, elem } => {
                let mut s = String::from("array");
                for (lo, hi) in dims {
                    s.push_str(&format!("_{}_{}", lo, hi).replace('-', "m"));
                }
                s.push_str("_of_");
                s.push_str(&elem.mangle());
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
            Ty::Array { dims, elem } => {
                f.write_str("ARRAY[")?;
                for (i, (lo, hi)) in dims.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{lo}..{hi}")?;
                }
                write!(f, "] OF {elem}")
            }
            Ty::Fb(n) | Ty::Struct(n) | Ty::Enum(n) => f.write_str(n),
        }
    }
}
