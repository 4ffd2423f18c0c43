//! The one parser of IEC literals, shared by the compiler (its lexer), the interpreter and the
//! runtime (`STRING_TO_*`), so that all of them accept the same texts and give the same values.
//!
//! Each function takes a literal's text without its type prefix and `#` and returns its value
//! or a [`LiteralError`]; the compiler turns the error into a diagnostic worded for the source.

use core::fmt;

mod dates;
mod durations;
mod numbers;
mod strings;
#[cfg(test)]
mod tests;

pub use dates::{parse_date, parse_dt, parse_tod};
pub use durations::parse_duration;
use numbers::*;
pub use numbers::{parse_int, parse_real};
pub use strings::{StrPiece, string_literal, unescape_string, wstring_literal};

use crate::string::{STRING, WSTRING};
use crate::time::{
    DATE, DT, NS_PER_DAY, NS_PER_H, NS_PER_MIN, NS_PER_MS, NS_PER_S, NS_PER_US, TOD,
    days_from_civil, days_in_month,
};

/// Why a literal's text was refused.
///
/// `start..end` and `at` are byte offsets into the text that was parsed, so that a caller can
/// quote the offending part; every other field is a value the message names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LiteralError {
    /// A number without digits (`""`, `16#`, `-`).
    EmptyNumber,
    /// The base before `#` is not 2, 8 or 16 (`3#12`).
    BadBase,
    /// A based integer with a sign (`-16#FF`): IEC writes based integers unsigned.
    SignedBasedInt,
    /// `digit` is not a digit in `radix` (`16#FG`).
    BadDigit {
        /// The offending character.
        digit: char,
        /// The base of the number.
        radix: u32,
    },
    /// `_` not between two digits (`_1`, `1_`, `1__0`) nor just before a duration's unit (`T#5_s`).
    BadUnderscore,
    /// An integer whose magnitude exceeds ULINT's (the largest IEC integer type).
    IntTooLarge,
    /// Not a real number (`1.5x`, `1e`).
    BadReal,
    /// A duration without anything after the sign (`T#`, `T#-`).
    EmptyDuration,
    /// A duration part that does not start with a number (`T#s`, `T#1h_s`).
    DurationNeedsNumber,
    /// A number at `start..end` without a unit after it (`T#5`).
    MissingDurationUnit {
        /// Start of the number.
        start: usize,
        /// End of the number.
        end: usize,
    },
    /// Letters at `start..end` that are not a unit of time (`T#5x`).
    BadDurationUnit {
        /// Start of the letters.
        start: usize,
        /// End of the letters.
        end: usize,
    },
    /// Units not in descending order, or one twice (`T#1s1h`, `T#1s1s`).
    DurationUnitOrder,
    /// A unit after the first at or over what the next larger unit holds
    /// (`T#1h_61m`): only the most significant unit may overflow (`T#61m`).
    DurationUnitOverflow {
        /// Start of the number.
        start: usize,
        /// End of its unit.
        end: usize,
        /// The first value too large (60 for minutes).
        limit: u32,
    },
    /// A fraction on a unit other than the last (`T#1.5s3ms`).
    FractionNotLast,
    /// A `.` without digits after it (`T#1.s`, `TOD#12:00:00.`).
    MissingFractionDigits,
    /// A duration that ends with `_` (`T#1s_`).
    TrailingUnderscore,
    /// A duration beyond the `i64` nanoseconds of TIME (about 292 years).
    DurationOutOfRange,
    /// Not `year-month-day` (`D#2001-04`).
    BadDateShape,
    /// Not `hours:minutes:seconds` (`TOD#12:00`).
    BadTimeShape,
    /// No `-` between the date and the time (`DT#2001-04-09`).
    BadDateTimeShape,
    /// The field at `start..end` is not 1 to 9 decimal digits (`D#2001-x-01`).
    BadField {
        /// Which field.
        field: DateField,
        /// Start of the field.
        start: usize,
        /// End of the field.
        end: usize,
    },
    /// The fraction of a second at `start..end` is not decimal digits (`TOD#12:00:00.5x`).
    BadFraction {
        /// Start of the fraction.
        start: usize,
        /// End of the fraction.
        end: usize,
    },
    /// Month not 1 to 12.
    MonthOutOfRange {
        /// The month written.
        month: u32,
    },
    /// A day that the month does not have (`D#2001-02-29`).
    DayOutOfRange {
        /// The year written.
        year: u32,
        /// The month written.
        month: u32,
        /// The day written.
        day: u32,
    },
    /// Hours not 0 to 23.
    HoursOutOfRange {
        /// The hours written.
        hours: u32,
    },
    /// Minutes not 0 to 59.
    MinutesOutOfRange {
        /// The minutes written.
        minutes: u32,
    },
    /// Seconds not 0 to 59.
    SecondsOutOfRange {
        /// The seconds written.
        seconds: u32,
    },
    /// A date and time outside DT's `i64` nanoseconds
    /// (`DT#1677-09-21-00:12:44` to `DT#2262-04-11-23:47:16`).
    DateTimeOutOfRange,
    /// A `$` at `at` that ends the string.
    EscapeAtEnd {
        /// Offset of the `$`.
        at: usize,
    },
    /// `$` at `at` followed by `escape`, which is no escape (`'$q'`).
    BadEscape {
        /// Offset of the `$`.
        at: usize,
        /// The character after the `$`.
        escape: char,
    },
    /// `$` at `at` starting a hex code with fewer than 2 (STRING) or 4 (`wide`, WSTRING) digits.
    HexEscapeDigits {
        /// Offset of the `$`.
        at: usize,
        /// In a WSTRING (4 digits) rather than a STRING (2).
        wide: bool,
    },
}

/// A field of a date or time of day, for [`LiteralError::BadField`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DateField {
    /// The year.
    Year,
    /// The month.
    Month,
    /// The day.
    Day,
    /// The hours.
    Hour,
    /// The minutes.
    Minute,
    /// The seconds.
    Second,
}

impl DateField {
    /// `"year"`, `"month"` ...
    pub fn name(self) -> &'static str {
        match self {
            DateField::Year => "year",
            DateField::Month => "month",
            DateField::Day => "day",
            DateField::Hour => "hour",
            DateField::Minute => "minute",
            DateField::Second => "second",
        }
    }
}

const UNITS_HELP: &str = "d, h, m, s, ms, us or ns";

impl fmt::Display for LiteralError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use LiteralError::*;
        match *self {
            EmptyNumber => f.write_str("this number has no digits"),
            BadBase => f.write_str("not a base: IEC integers are written in base 2#, 8#, 10 or 16#"),
            SignedBasedInt => f.write_str("a based integer (`16#FF`) cannot have a sign"),
            BadDigit { digit, radix } => write!(f, "`{digit}` is not a digit in base {radix}"),
            BadUnderscore => f.write_str("`_` may only separate digits"),
            IntTooLarge => f.write_str(
                "this number is too large for any IEC integer type (the largest is ULINT)",
            ),
            BadReal => f.write_str("not a valid REAL number"),
            EmptyDuration => f.write_str("a duration needs a value and a unit, e.g. `T#500ms`"),
            DurationNeedsNumber => f.write_str("expected a number before each unit of a duration"),
            MissingDurationUnit { .. } => write!(f, "missing unit ({UNITS_HELP})"),
            BadDurationUnit { .. } => write!(f, "unknown unit (expected {UNITS_HELP})"),
            DurationUnitOrder => {
                f.write_str("units must go from days down to nanoseconds, each at most once")
            }
            DurationUnitOverflow { limit, .. } => write!(
                f,
                "after a larger unit, a unit holds less than {limit} (only the first unit may overflow)"
            ),
            FractionNotLast => f.write_str(
                "only the last unit of a duration may have a fraction (`T#1.5s`)",
            ),
            MissingFractionDigits => f.write_str("expected digits after the decimal point"),
            TrailingUnderscore => f.write_str("a duration cannot end with `_`"),
            DurationOutOfRange => {
                f.write_str("this duration is too long (the limit is about 292 years)")
            }
            BadDateShape => f.write_str("expected a date as year-month-day"),
            BadTimeShape => f.write_str("expected a time of day as hours:minutes:seconds"),
            BadDateTimeShape => {
                f.write_str("expected a date and time as year-month-day-hours:minutes:seconds")
            }
            BadField { field, .. } => write!(f, "not a valid {}", field.name()),
            BadFraction { .. } => f.write_str("not a fraction of a second"),
            MonthOutOfRange { month } => write!(f, "month {month} does not exist (1 to 12)"),
            DayOutOfRange { year, month, day } => {
                write!(f, "day {day} does not exist in month {month} of {year}")
            }
            HoursOutOfRange { hours } => write!(f, "hour {hours} does not exist (0 to 23)"),
            MinutesOutOfRange { minutes } => {
                write!(f, "minute {minutes} does not exist (0 to 59)")
            }
            SecondsOutOfRange { seconds } => {
                write!(f, "second {seconds} does not exist (0 to 59)")
            }
            DateTimeOutOfRange => f.write_str(
                "this date and time is out of range (DT holds DT#1677-09-21-00:12:44 to DT#2262-04-11-23:47:16)",
            ),
            EscapeAtEnd { .. } => f.write_str("a `$` at the end of a string must be written `$$`"),
            BadEscape { escape, .. } => write!(
                f,
                "`${escape}` is not a string escape: use $$, $', $\", $L, $N, $P, $R, $T or $ and hex digits"
            ),
            HexEscapeDigits { wide, .. } => write!(
                f,
                "`$` followed by a hex code needs {} hex digits here",
                if wide { 4 } else { 2 }
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for LiteralError {}

impl LiteralError {
    /// The error with its offsets moved by `by` (for a part parsed out of a longer text).
    fn shifted(self, by: usize) -> Self {
        use LiteralError::*;
        match self {
            BadField { field, start, end } => BadField {
                field,
                start: start + by,
                end: end + by,
            },
            BadFraction { start, end } => BadFraction {
                start: start + by,
                end: end + by,
            },
            e => e,
        }
    }
}
