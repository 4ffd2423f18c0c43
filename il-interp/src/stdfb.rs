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
                            return Some(_b.$i.to_value());
                        })*
                        $(if field.eq_ignore_ascii_case(stringify!($o)) {
                            return Some(_b.$o.to_value());
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
