//! Offering a block's variables to a tool: waveform recorders, loggers, debuggers.
//!
//! Generated FUNCTION_BLOCKs, PROGRAMs and CONFIGURATIONs have
//! `pub fn visit(&self, v: &mut dyn Visitor)`, which calls [`Visitor::var`]
//! for each variable with its name, IEC type and current [`Value`], and goes
//! into function block instances and STRUCTs with [`Visitor::enter`] /
//! [`Visitor::leave`] and into arrays element by element ([`Visitor::elem`],
//! [`Visitor::enter_elem`]). The standard blocks implement [`Visit`] too.
//! Nothing here allocates: names and types are `&str`, values are borrowed.
//! The `il-trace` crate has a recorder that writes these as a VCD file.
//!
//! ```
//! use il_std::trace::{Value, Visit, Visitor};
//! struct Count(usize);
//! impl Visitor for Count {
//!     fn enter(&mut self, _: &str) {}
//!     fn enter_elem(&mut self, _: &str, _: &[i64]) {}
//!     fn leave(&mut self) {}
//!     fn var(&mut self, _: &str, _: &str, _: Value<'_>) { self.0 += 1 }
//!     fn elem(&mut self, _: &str, _: &[i64], _: &str, _: Value<'_>) { self.0 += 1 }
//! }
//! let mut n = Count(0);
//! il_std::TON::new().visit(&mut n);
//! assert_eq!(n.0, 4); // IN, PT, Q, ET
//! ```

use crate::{DATE, DT, LTIME, STRING, TIME, TOD, WSTRING};

/// The current value of a variable, as a tool needs it (widths included).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value<'a> {
    /// `BOOL`.
    Bool(bool),
    /// A signed integer (`SINT`, `INT`, `DINT`, `LINT`) and its width in bits.
    Int {
        /// The value.
        value: i64,
        /// 8, 16, 32 or 64.
        bits: u8,
    },
    /// An unsigned integer or bit string (`USINT` ... `ULINT`, `BYTE` ... `LWORD`) and its width.
    UInt {
        /// The value.
        value: u64,
        /// 8, 16, 32 or 64.
        bits: u8,
    },
    /// `REAL` (widened) or `LREAL`.
    Real(f64),
    /// `TIME`, `LTIME`, `TIME_OF_DAY` (since midnight) and `DATE_AND_TIME`
    /// (since 1970-01-01): nanoseconds.
    Time(i64),
    /// `DATE`: days since 1970-01-01.
    Date(i64),
    /// A value of an enumeration: its integer value and its name.
    Enum {
        /// The integer value (as the generated Rust enum's discriminant).
        value: i64,
        /// The value's name as declared.
        name: &'a str,
    },
    /// `STRING`: its bytes.
    Str(&'a [u8]),
    /// `WSTRING`: its UTF-16 code units.
    WStr(&'a [u16]),
}

/// Receives the variables of a block, depth first, in declaration order.
pub trait Visitor {
    /// Into the function block instance or STRUCT variable `name`; [`Visitor::leave`] follows.
    fn enter(&mut self, name: &str);
    /// Into element `index` (one number per dimension, as declared) of the
    /// array `name` of instances or STRUCTs; [`Visitor::leave`] follows.
    fn enter_elem(&mut self, name: &str, index: &[i64]);
    /// Out of the last [`Visitor::enter`] or [`Visitor::enter_elem`].
    fn leave(&mut self);
    /// A variable of elementary, string or enumeration type `ty` (as IEC writes it).
    fn var(&mut self, name: &str, ty: &str, value: Value<'_>);
    /// Element `index` (one number per dimension, as declared) of the array `name`.
    fn elem(&mut self, name: &str, index: &[i64], ty: &str, value: Value<'_>);
}

/// Something that offers its variables to a [`Visitor`]: generated blocks,
/// STRUCTs and the standard function blocks.
pub trait Visit {
    /// Call the visitor for each variable (members of an instance or STRUCT).
    fn visit(&self, v: &mut dyn Visitor);
}

/// A Rust value of an IEC type, as a [`Value`]; generated code uses it with
/// the IEC type name it knows (`u16` is both `UINT` and `WORD`); generated
/// enumerations implement it as [`Value::Enum`].
pub trait AsValue {
    /// The value to offer a [`Visitor`].
    fn as_value(&self) -> Value<'_>;
}

macro_rules! as_value {
    ($($t:ty => |$x:ident| $e:expr),* $(,)?) => {
        $(impl AsValue for $t {
            fn as_value(&self) -> Value<'_> {
                let $x = self;
                $e
            }
        })*
    };
}
as_value!(
    bool => |x| Value::Bool(*x),
    i8 => |x| Value::Int { value: *x as i64, bits: 8 },
    i16 => |x| Value::Int { value: *x as i64, bits: 16 },
    i32 => |x| Value::Int { value: *x as i64, bits: 32 },
    i64 => |x| Value::Int { value: *x, bits: 64 },
    u8 => |x| Value::UInt { value: *x as u64, bits: 8 },
    u16 => |x| Value::UInt { value: *x as u64, bits: 16 },
    u32 => |x| Value::UInt { value: *x as u64, bits: 32 },
    u64 => |x| Value::UInt { value: *x, bits: 64 },
    f32 => |x| Value::Real(*x as f64),
    f64 => |x| Value::Real(*x),
    TIME => |x| Value::Time(x.0),
    LTIME => |x| Value::Time(x.0),
    TOD => |x| Value::Time(x.0),
    DT => |x| Value::Time(x.0),
    DATE => |x| Value::Date(x.0),
);

impl<const N: usize> AsValue for STRING<N> {
    fn as_value(&self) -> Value<'_> {
        Value::Str(self.as_bytes())
    }
}

impl<const N: usize> AsValue for WSTRING<N> {
    fn as_value(&self) -> Value<'_> {
        Value::WStr(self.as_units())
    }
}

/// `impl Visit` for every standard block of the table: its inputs, then its
/// outputs, with the IEC type names the table gives them.
macro_rules! visit_std {
    ($( $fb:ident ( $( $i:ident : $it:ident ),* ) -> ( $( $o:ident : $ot:ident ),* ); )*) => {
        $(impl Visit for crate::$fb {
            fn visit(&self, v: &mut dyn Visitor) {
                $(v.var(stringify!($i), stringify!($it), self.$i.as_value());)*
                $(v.var(stringify!($o), stringify!($ot), self.$o.as_value());)*
            }
        })*
    };
}
crate::std_function_blocks!(visit_std);

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::{String, ToString};
    use std::vec::Vec;

    #[derive(Default)]
    struct Log(Vec<String>);
    impl Visitor for Log {
        fn enter(&mut self, n: &str) {
            self.0.push(std::format!("enter {n}"));
        }
        fn enter_elem(&mut self, n: &str, i: &[i64]) {
            self.0.push(std::format!("enter {n}{i:?}"));
        }
        fn leave(&mut self) {
            self.0.push("leave".to_string());
        }
        fn var(&mut self, n: &str, t: &str, x: Value<'_>) {
            self.0.push(std::format!("{n}: {t} = {x:?}"));
        }
        fn elem(&mut self, n: &str, i: &[i64], t: &str, x: Value<'_>) {
            self.0.push(std::format!("{n}{i:?}: {t} = {x:?}"));
        }
    }

    #[test]
    fn std_blocks_offer_their_members() {
        let mut t = crate::TON::new();
        t.PT = TIME::from_ms(5);
        t.IN = true;
        let mut log = Log::default();
        t.visit(&mut log);
        assert_eq!(
            log.0,
            [
                "IN: BOOL = Bool(true)",
                "PT: TIME = Time(5000000)",
                "Q: BOOL = Bool(false)",
                "ET: TIME = Time(0)"
            ]
        );
        let mut c = crate::CTU_UDINT::new();
        c.CV = 7;
        let mut log = Log::default();
        c.visit(&mut log);
        assert!(
            log.0
                .contains(&"CV: UDINT = UInt { value: 7, bits: 32 }".to_string())
        );
    }

    #[test]
    fn values_keep_sign_and_width() {
        assert_eq!((-1i8).as_value(), Value::Int { value: -1, bits: 8 });
        assert_eq!(
            u64::MAX.as_value(),
            Value::UInt {
                value: u64::MAX,
                bits: 64
            }
        );
        assert_eq!(DATE(3).as_value(), Value::Date(3));
        let (s, _) = STRING::<4>::from_str_truncating("abcdef");
        assert_eq!(s.as_value(), Value::Str(b"abcd"));
    }
}
