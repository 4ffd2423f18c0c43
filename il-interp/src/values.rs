//! Runtime values of the reference interpreter and the elementary operations
//! on them, with the same results as the Rust the emitter generates.

use il_codegen::ir::Const;
use il_codegen::ir::types::Elem;
use il_std::Cycle;

/// A runtime value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// `BOOL`.
    Bool(bool),
    /// An integer or bit string, always inside its type's range.
    Int(i128, Elem),
    /// `REAL`.
    Real(f32),
    /// `LREAL`.
    LReal(f64),
    /// TIME/LTIME (ns), DATE (days), TOD (ns), DT (ns): the il-std inner value.
    Time(i64, Elem),
    /// STRING (bytes) or WSTRING (UTF-16 units).
    Str {
        /// Bytes (as `u16`) of a STRING, or UTF-16 units of a WSTRING, already cut to the declared length.
        units: Vec<u16>,
        /// WSTRING rather than STRING.
        wide: bool,
    },
    /// Array elements, row-major over all dimensions.
    Array(Vec<Value>),
    /// A value of a user enumeration: its type and the value's name, both as
    /// declared (as [`Const::Enum`]; generated code holds a Rust enum).
    Enum {
        /// The enumeration type.
        ty: String,
        /// The value's name.
        value: String,
    },
    /// A value of a user STRUCT: its fields in declaration order.
    Struct(Box<Struct>),
    /// An instance of a user FUNCTION_BLOCK or PROGRAM.
    Fb(Box<Instance>),
    /// An instance of a standard function block (the real il-std block).
    StdFb(Box<StdFb>),
}

/// A value of a user STRUCT.
#[derive(Clone, Debug, PartialEq)]
pub struct Struct {
    /// The STRUCT type, as declared.
    pub ty: String,
    /// Each field's name (as declared) and value, in declaration order.
    pub fields: Vec<(String, Value)>,
}

impl Struct {
    /// The field named `name` (case-insensitive, as IEC names are).
    pub fn field(&self, name: &str) -> Option<&Value> {
        self.position(name).map(|i| &self.fields[i].1)
    }

    /// The field named `name`, to write.
    pub fn field_mut(&mut self, name: &str) -> Option<&mut Value> {
        self.position(name).map(|i| &mut self.fields[i].1)
    }

    fn position(&self, name: &str) -> Option<usize> {
        self.fields.iter().position(|(n, _)| n == name).or_else(|| {
            self.fields
                .iter()
                .position(|(n, _)| n.eq_ignore_ascii_case(name))
        })
    }
}

/// The memory of a user FUNCTION_BLOCK or PROGRAM instance.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Instance {
    /// Index into `Program::pous`.
    pub pou: usize,
    /// One slot per `CheckedPou::vars` entry (temporaries are re-initialised
    /// on every call).
    pub vars: Vec<Value>,
    /// R_EDGE/F_EDGE memory, per variable.
    pub edge_mem: Vec<bool>,
}

/// Two's complement truncation of `v` to the integer type `e`.
pub fn wrap(v: i128, e: Elem) -> i128 {
    match e {
        Elem::SINT => v as i8 as i128,
        Elem::INT => v as i16 as i128,
        Elem::DINT => v as i32 as i128,
        Elem::LINT => v as i64 as i128,
        Elem::USINT | Elem::BYTE => v as u8 as i128,
        Elem::UINT | Elem::WORD => v as u16 as i128,
        Elem::UDINT | Elem::DWORD => v as u32 as i128,
        Elem::ULINT | Elem::LWORD => v as u64 as i128,
        Elem::BOOL => (v & 1 != 0) as i128,
        _ => v,
    }
}

/// Bit width of an integer or bit-string type.
pub fn bits(e: Elem) -> u32 {
    match e {
        Elem::SINT | Elem::USINT | Elem::BYTE => 8,
        Elem::INT | Elem::UINT | Elem::WORD => 16,
        Elem::DINT | Elem::UDINT | Elem::DWORD => 32,
        _ => 64,
    }
}

pub fn str_units(s: &str, wide: bool, len: u32) -> Vec<u16> {
    let len = len as usize;
    if wide {
        let mut out = Vec::new();
        for c in s.chars() {
            let mut b = [0u16; 2];
            let enc = c.encode_utf16(&mut b);
            if out.len() + enc.len() > len {
                break;
            }
            out.extend_from_slice(enc);
        }
        out
    } else {
        let mut end = s.len().min(len);
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        s.as_bytes()[..end].iter().map(|&b| u16::from(b)).collect()
    }
}

impl Value {
    /// The runtime value of a checked constant (STRING/WSTRING cut to the declared length).
    pub fn from_const(c: &Const) -> Value {
        match c {
            Const::Bool(b) => Value::Bool(*b),
            Const::Enum(e) => Value::Enum {
                ty: e.ty.to_string(),
                value: e.value.clone(),
            },
            Const::Int(v, Elem::BOOL) => Value::Bool(v.get() != 0),
            Const::Int(v, e) => Value::Int(wrap(v.get(), *e), *e),
            Const::Real(v, Elem::REAL) => {
                let f = *v as f32;
                Value::Real(if f.is_finite() { f } else { 0.0 })
            }
            Const::Real(v, _) => Value::LReal(if v.is_finite() { *v } else { 0.0 }),
            Const::Time(v, e) => Value::Time(*v, *e),
            Const::Str(s) => Value::Str {
                units: str_units(&s.value, s.wide, s.len),
                wide: s.wide,
            },
        }
    }

    /// The value as a condition: TRUE, or a non-zero integer; anything else is FALSE.
    pub fn as_bool(&self) -> bool {
        match self {
            Value::Bool(b) => *b,
            Value::Int(v, _) => *v != 0,
            _ => false,
        }
    }

    /// The value as the emitter's `x as i64` (integers only).
    pub fn as_i64(&self) -> i64 {
        match self {
            Value::Int(v, _) => *v as i64,
            Value::Bool(b) => *b as i64,
            Value::Real(f) => *f as i64,
            Value::LReal(f) => *f as i64,
            Value::Time(v, _) => *v,
            _ => 0,
        }
    }

    /// The value as the emitter's `x as f64` (numbers, and the inner value of times).
    pub fn as_f64(&self) -> f64 {
        match self {
            Value::Int(v, _) => *v as f64,
            Value::Real(f) => *f as f64,
            Value::LReal(f) => *f,
            Value::Bool(b) => *b as u8 as f64,
            Value::Time(v, _) => *v as f64,
            _ => 0.0,
        }
    }

    /// Text for tables and dumps (IEC-like, but stable and exact).
    pub fn display(&self) -> String {
        match self {
            Value::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
            Value::Int(v, _) => v.to_string(),
            Value::Real(f) => format!("{f:?}"),
            Value::LReal(f) => format!("{f:?}"),
            Value::Time(v, Elem::TIME) => format!("T#{}", fmt_dur(*v)),
            Value::Time(v, Elem::LTIME) => format!("LTIME#{}", fmt_dur(*v)),
            Value::Time(v, e) => format!("{}#{v}", e.name()),
            Value::Str { units, wide } => {
                let s = if *wide {
                    String::from_utf16_lossy(units)
                } else {
                    String::from_utf8_lossy(&units.iter().map(|&u| u as u8).collect::<Vec<_>>())
                        .into_owned()
                };
                if *wide {
                    format!("\"{s}\"")
                } else {
                    format!("'{s}'")
                }
            }
            Value::Array(items) => {
                let v: Vec<String> = items.iter().map(Value::display).collect();
                format!("[{}]", v.join(", "))
            }
            // As the literal that names it (`--set` accepts the same text).
            Value::Enum { ty, value } => format!("{ty}#{value}"),
            // As a structure initialiser.
            Value::Struct(s) => {
                let v: Vec<String> = s
                    .fields
                    .iter()
                    .map(|(n, v)| format!("{n} := {}", v.display()))
                    .collect();
                format!("({})", v.join(", "))
            }
            Value::Fb(_) | Value::StdFb(_) => "<instance>".to_string(),
        }
    }
}

/// `1s500ms`, `-2ms`, `0s`, `1.5us`-free exact form: whole units down to ns.
pub fn fmt_dur(ns: i64) -> String {
    if ns == 0 {
        return "0s".into();
    }
    let mut out = String::new();
    let neg = ns < 0;
    let mut n = ns.unsigned_abs();
    if neg {
        out.push('-');
    }
    for (unit, size) in [
        ("d", 86_400_000_000_000u64),
        ("h", 3_600_000_000_000),
        ("m", 60_000_000_000),
        ("s", 1_000_000_000),
        ("ms", 1_000_000),
        ("us", 1_000),
        ("ns", 1),
    ] {
        if n >= size {
            out.push_str(&format!("{}{unit}", n / size));
            n %= size;
        }
    }
    out
}

// The standard function blocks, held as the real il-std blocks so that the
// interpreter and generated code share one implementation (here, beside
// `Value`, which holds them).

/// Conversion between a block's Rust field type and a runtime value.
trait Field: Sized {
    fn to_value(&self) -> Value;
    fn from_value(v: &Value) -> Option<Self>;
}

impl Field for bool {
    fn to_value(&self) -> Value {
        Value::Bool(*self)
    }
    fn from_value(v: &Value) -> Option<Self> {
        match v {
            Value::Bool(b) => Some(*b),
            _ => None,
        }
    }
}

macro_rules! int_field {
    ($($t:ty => $e:ident),*) => {$(
        impl Field for $t {
            fn to_value(&self) -> Value {
                Value::Int(*self as i128, Elem::$e)
            }
            fn from_value(v: &Value) -> Option<Self> {
                match v {
                    Value::Int(x, _) => Some(*x as $t),
                    _ => None,
                }
            }
        }
    )*};
}
// `u16` is WORD or UINT: `tagged` gives a field the type the table names.
int_field!(i16 => INT, u16 => WORD, i32 => DINT, i64 => LINT, u32 => UDINT, u64 => ULINT);

/// A block field's value with the type il-std's table gives it (a Rust type can stand
/// for several IEC ones: `u16` for WORD and UINT).
fn tagged<T: Field>(x: &T, e: Elem) -> Value {
    match x.to_value() {
        Value::Int(v, _) => Value::Int(v, e),
        v => v,
    }
}

macro_rules! time_field {
    ($($t:ident => $e:ident),*) => {$(
        impl Field for il_std::$t {
            fn to_value(&self) -> Value {
                Value::Time(self.0, Elem::$e)
            }
            fn from_value(v: &Value) -> Option<Self> {
                match v {
                    Value::Time(x, _) => Some(il_std::$t(*x)),
                    _ => None,
                }
            }
        }
    )*};
}
time_field!(TIME => TIME, DT => DT);

/// Set a field from a value of its kind; false for another kind.
fn set<T: Field>(slot: &mut T, v: &Value) -> bool {
    match T::from_value(v) {
        Some(x) => {
            *slot = x;
            true
        }
        None => false,
    }
}

/// The interpreter's view of the blocks of `il_std::std_function_blocks!`
/// (the list [`il_std::signature::FB_SIGNATURES`] is built from).
macro_rules! std_fbs {
    ($( $name:ident ( $( $i:ident : $it:ident ),* ) -> ( $( $o:ident : $ot:ident ),* ); )*) => {
        /// A standard function block instance.
        #[allow(non_camel_case_types, clippy::upper_case_acronyms)]
        #[derive(Clone, Debug, PartialEq)]
        pub enum StdFb {
            $(#[doc = concat!("An [`il_std::", stringify!($name), "`] instance.")] $name(il_std::$name),)*
        }

        impl StdFb {
            /// A fresh instance of the block named `name` (upper case).
            pub fn new(name: &str) -> Option<StdFb> {
                match name {
                    $(stringify!($name) => Some(StdFb::$name(Default::default())),)*
                    _ => None,
                }
            }

            /// The block's name (`TON`).
            pub fn name(&self) -> &'static str {
                match self {
                    $(StdFb::$name(_) => stringify!($name),)*
                }
            }

            /// Its inputs, then its outputs, by name with their values (a debugger's view).
            pub fn fields(&self) -> Vec<(&'static str, Value)> {
                match self {
                    $(StdFb::$name(_b) => vec![
                        $((stringify!($i), tagged(&_b.$i, Elem::$it)),)*
                        $((stringify!($o), tagged(&_b.$o, Elem::$ot)),)*
                    ],)*
                }
            }

            /// Run the block once (one `CAL`) with its current inputs; `ctx` supplies the time.
            pub fn call(&mut self, ctx: &mut Cycle) {
                match self {
                    $(StdFb::$name(b) => b.call(ctx),)*
                }
            }

            /// Read an input or output by name (case-insensitive); `None` if the block has none such.
            pub fn get(&self, field: &str) -> Option<Value> {
                match self {
                    $(StdFb::$name(_b) => {
                        $(if field.eq_ignore_ascii_case(stringify!($i)) {
                            return Some(tagged(&_b.$i, Elem::$it));
                        })*
                        $(if field.eq_ignore_ascii_case(stringify!($o)) {
                            return Some(tagged(&_b.$o, Elem::$ot));
                        })*
                        None
                    })*
                }
            }

            /// Set input `k` (in the order of il-std's table); false if there is no such
            /// input or the value is of another kind.
            pub fn set_input(&mut self, k: usize, v: &Value) -> bool {
                match self {
                    $(StdFb::$name(_b) => {
                        // The fields in the table's order, counted.
                        let mut _n = 0usize;
                        $(if _n == k {
                            return set(&mut _b.$i, v);
                        }
                        _n += 1;)*
                        false
                    })*
                }
            }

            /// Member `k` (its inputs, then its outputs, in the order of
            /// il-std's table: [`il_codegen::ir::Member::index`]).
            pub fn get_at(&self, k: usize) -> Option<Value> {
                match self {
                    $(StdFb::$name(_b) => {
                        let mut _n = 0usize;
                        $(if _n == k {
                            return Some(_b.$i.to_value());
                        }
                        _n += 1;)*
                        $(if _n == k {
                            return Some(_b.$o.to_value());
                        }
                        _n += 1;)*
                        None
                    })*
                }
            }

            /// Set member `k` (as [`StdFb::get_at`] counts); false if there
            /// is no such member or the value is of another kind.
            pub fn set_at(&mut self, k: usize, v: &Value) -> bool {
                match self {
                    $(StdFb::$name(_b) => {
                        let mut _n = 0usize;
                        $(if _n == k {
                            return set(&mut _b.$i, v);
                        }
                        _n += 1;)*
                        $(if _n == k {
                            return set(&mut _b.$o, v);
                        }
                        _n += 1;)*
                        false
                    })*
                }
            }

            /// Set an input (or output) by name (case-insensitive); false if there is no such
            /// field or the value is of another kind.
            pub fn set(&mut self, field: &str, v: &Value) -> bool {
                match self {
                    $(StdFb::$name(_b) => {
                        $(if field.eq_ignore_ascii_case(stringify!($i)) {
                            return set(&mut _b.$i, v);
                        })*
                        $(if field.eq_ignore_ascii_case(stringify!($o)) {
                            return set(&mut _b.$o, v);
                        })*
                        false
                    })*
                }
            }
        }
    };
}

il_std::std_function_blocks!(std_fbs);
