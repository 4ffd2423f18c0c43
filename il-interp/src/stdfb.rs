//! The standard function blocks, held as the real il-std blocks so that the
//! interpreter and generated code share one implementation.

use crate::values::Value;
use il_codegen::sema::types::Elem;
use il_std::Cycle;

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
int_field!(i16 => INT, i32 => DINT, i64 => LINT, u32 => UDINT, u64 => ULINT);

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

macro_rules! std_fbs {
    ($($name:ident { $($f:ident),* })*) => {
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
                        $(if field.eq_ignore_ascii_case(stringify!($f)) {
                            return Some(_b.$f.to_value());
                        })*
                        None
                    })*
                }
            }

            /// Set an input (or output) by name (case-insensitive); false if there is no such
            /// field or the value is of another kind.
            pub fn set(&mut self, field: &str, v: &Value) -> bool {
                match self {
                    $(StdFb::$name(_b) => {
                        $(if field.eq_ignore_ascii_case(stringify!($f)) {
                            if let Some(x) = Field::from_value(v) {
                                _b.$f = x;
                                return true;
                            }
                            return false;
                        })*
                        false
                    })*
                }
            }
        }
    };
}

std_fbs! {
    SR { S1, R, Q1 }
    RS { S, R1, Q1 }
    R_TRIG { CLK, Q }
    F_TRIG { CLK, Q }
    CTU { CU, R, PV, Q, CV }
    CTU_DINT { CU, R, PV, Q, CV }
    CTU_LINT { CU, R, PV, Q, CV }
    CTU_UDINT { CU, R, PV, Q, CV }
    CTU_ULINT { CU, R, PV, Q, CV }
    CTD { CD, LD, PV, Q, CV }
    CTD_DINT { CD, LD, PV, Q, CV }
    CTD_LINT { CD, LD, PV, Q, CV }
    CTD_UDINT { CD, LD, PV, Q, CV }
    CTD_ULINT { CD, LD, PV, Q, CV }
    CTUD { CU, CD, R, LD, PV, QU, QD, CV }
    CTUD_DINT { CU, CD, R, LD, PV, QU, QD, CV }
    CTUD_LINT { CU, CD, R, LD, PV, QU, QD, CV }
    CTUD_UDINT { CU, CD, R, LD, PV, QU, QD, CV }
    CTUD_ULINT { CU, CD, R, LD, PV, QU, QD, CV }
    TP { IN, PT, Q, ET }
    TON { IN, PT, Q, ET }
    TOF { IN, PT, Q, ET }
    RTC { IN, PDT, Q, CDT }
}
