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

#[cfg(feature = "runtime")]
mod arith;
#[cfg(feature = "runtime")]
mod bits;
#[cfg(feature = "runtime")]
mod conv;
pub(crate) mod conv_list;
#[cfg(feature = "runtime")]
mod numeric;
#[cfg(feature = "runtime")]
mod select;
#[cfg(feature = "runtime")]
mod string;
#[cfg(feature = "runtime")]
mod time;

#[cfg(feature = "runtime")]
pub use arith::*;
#[cfg(feature = "runtime")]
pub use bits::*;
#[cfg(feature = "runtime")]
pub use conv::*;
#[cfg(feature = "runtime")]
pub use numeric::*;
#[cfg(feature = "runtime")]
pub use select::*;
#[cfg(feature = "runtime")]
pub use string::*;
#[cfg(feature = "runtime")]
pub use time::*;
