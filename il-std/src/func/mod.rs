//! The standard functions of IEC 61131-3, each a plain `pub fn` with its IEC name.
//!
//! Arguments are taken by value (strings are `Copy`) and no function panics. Overloaded
//! functions are generic over the class traits of [`num`](crate::num); extensible ones (`ADD`,
//! `MUL`, `AND`, `OR`, `XOR`, `MAX`, `MIN`, `CONCAT`, `GT`, `GE`, `EQ`, `LE`, `LT`) are given in
//! their two-input form: the compiler folds (`ADD(a,b,c) = ADD(ADD(a,b),c)`) or chains
//! (`GT(a,b,c) = GT(a,b) AND GT(b,c)`) them, as [`signature`](crate::signature) says.
//!
//! Where a function can fault (integer division by zero, out-of-range conversion, string
//! truncation ...), the plain function returns the documented result and a lower-case
//! `*_checked` companion also returns the flag, so that generated code can record the fault in
//! the [`Cycle`](crate::Cycle).

mod arith;
mod bits;
mod conv;
pub(crate) mod conv_list;
mod numeric;
mod select;
mod string;
mod time;

pub use arith::*;
pub use bits::*;
pub use conv::*;
pub use numeric::*;
pub use select::*;
pub use string::*;
pub use time::*;
