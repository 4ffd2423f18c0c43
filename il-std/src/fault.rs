//! The kinds of runtime fault: recorded by generated code in the `Cycle`, and named by the
//! signature table (which the compiler reads without the runtime).

use core::fmt;

/// The kind of a runtime fault recorded in a `Cycle`.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FaultKind {
    /// Integer `DIV` or `MOD` by zero (the result was 0).
    #[default]
    DivisionByZero,
    /// An array index outside the declared bounds.
    IndexOutOfRange,
    /// A value assigned to a subrange-typed variable was outside the subrange.
    SubrangeViolation,
    /// A string result did not fit its capacity and was truncated.
    StringOverflow,
    /// A conversion whose source value does not fit the target type (e.g. `REAL_TO_INT(1e9)`).
    ConversionOutOfRange,
    /// Any other invalid argument to a standard function (e.g. an invalid BCD digit, a `MUX`
    /// selector out of range).
    InvalidArgument,
}

impl fmt::Display for FaultKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FaultKind::DivisionByZero => "integer division by zero",
            FaultKind::IndexOutOfRange => "array index out of range",
            FaultKind::SubrangeViolation => "value outside the subrange",
            FaultKind::StringOverflow => "string truncated to its capacity",
            FaultKind::ConversionOutOfRange => "conversion out of the target type's range",
            FaultKind::InvalidArgument => "invalid argument to a standard function",
        })
    }
}
