//! The one parser of IEC literals, shared by the compiler (its lexer), the interpreter and the
//! runtime (`STRING_TO_*`), so that all of them accept the same texts and give the same values.
//!
//! Each function takes a literal's text without its type prefix and `#` and returns its value
//! or a [`LiteralError`]; the compiler turns the error into a diagnostic worded for the source.

use core::fmt;

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

fn split_sign(text: &str) -> (bool, &str) {
    match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    }
}

/// Digits in `radix` with single `_` between digits (IEC `digit {[_] digit}`).
fn digits(text: &str, radix: u32) -> Result<i128, LiteralError> {
    if text.is_empty() {
        return Err(LiteralError::EmptyNumber);
    }
    if text.starts_with('_') || text.ends_with('_') || text.contains("__") {
        return Err(LiteralError::BadUnderscore);
    }
    let mut v: i128 = 0;
    for c in text.chars().filter(|&c| c != '_') {
        let d = c
            .to_digit(radix)
            .ok_or(LiteralError::BadDigit { digit: c, radix })?;
        v = v
            .checked_mul(i128::from(radix))
            .and_then(|v| v.checked_add(i128::from(d)))
            .ok_or(LiteralError::IntTooLarge)?;
    }
    Ok(v)
}

/// Parses an IEC integer literal: decimal with an optional sign (`-12`, `+7`, `1_000`) or based
/// `2#1010_1010`, `8#777`, `16#FF` (no sign). `_` may separate digits. The magnitude is at most
/// ULINT's (`u64::MAX`), the largest of any IEC integer type; the caller range-checks against
/// the target type (e.g. with [`Elem::min_max_i128`](crate::signature::Elem::min_max_i128)).
pub fn parse_int(text: &str) -> Result<i128, LiteralError> {
    let (neg, body) = split_sign(text);
    let v = match body.split_once('#') {
        Some((base, rest)) => {
            let radix = match base {
                "2" => 2,
                "8" => 8,
                "16" => 16,
                _ => return Err(LiteralError::BadBase),
            };
            if body.len() != text.len() {
                return Err(LiteralError::SignedBasedInt);
            }
            digits(rest, radix)?
        }
        None => digits(body, 10)?,
    };
    if v > i128::from(u64::MAX) {
        return Err(LiteralError::IntTooLarge);
    }
    Ok(if neg { -v } else { v })
}

/// Parses an IEC real literal such as `1.5`, `-0.5`, `1.0E-3`, `1_000.25`, `3e5`
/// (`_` only between digits).
pub fn parse_real(text: &str) -> Result<f64, LiteralError> {
    let mut prev = 0u8;
    for &b in text.as_bytes() {
        let ok = if b == b'_' {
            prev.is_ascii_digit()
        } else if prev == b'_' {
            b.is_ascii_digit()
        } else {
            // Also keeps out `inf` and `NaN`, which Rust parses but IEC does not have.
            b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-')
        };
        if !ok {
            return Err(if b == b'_' || prev == b'_' {
                LiteralError::BadUnderscore
            } else {
                LiteralError::BadReal
            });
        }
        prev = b;
    }
    if prev == b'_' {
        return Err(LiteralError::BadUnderscore);
    }
    if !text.contains('_') {
        return text.parse::<f64>().map_err(|_| LiteralError::BadReal);
    }
    // Without `_` for `str::parse`; no allocation, so the copy is bounded (longer reals with
    // `_` are refused; IEC REALs have at most 17 significant digits).
    let mut buf = [0u8; 256];
    let mut n = 0;
    for &b in text.as_bytes().iter().filter(|&&b| b != b'_') {
        *buf.get_mut(n).ok_or(LiteralError::BadReal)? = b;
        n += 1;
    }
    core::str::from_utf8(&buf[..n])
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .ok_or(LiteralError::BadReal)
}

/// Parses the part of a duration literal after `T#`/`TIME#`/`LTIME#`, giving nanoseconds.
///
/// Units `d h m s ms us ns` (any case), from largest to smallest, each at most once, optionally
/// separated by `_`; a fraction only on the last unit; a leading `-` (e.g. `1h_15m_30s_60ms`,
/// `500ms`, `1.5s`, `-5s`, `1d2h`). The first unit may exceed its usual range (`25h`, `90s`).
/// A fraction finer than a nanosecond is rounded to the nearest nanosecond.
pub fn parse_duration(text: &str) -> Result<i64, LiteralError> {
    let (neg, body) = split_sign(text);
    if body.is_empty() {
        return Err(LiteralError::EmptyDuration);
    }
    let b = text.as_bytes();
    let mut i = text.len() - body.len();
    let mut total: i128 = 0;
    let mut last_rank = usize::MAX;
    let mut had_fraction = false;
    while i < b.len() {
        if had_fraction {
            return Err(LiteralError::FractionNotLast);
        }
        let start = i;
        // Digits with single `_` between digits: a `_` before a non-digit ends the number.
        while i < b.len()
            && (b[i].is_ascii_digit()
                || (b[i] == b'_' && b.get(i + 1).is_some_and(u8::is_ascii_digit)))
        {
            i += 1;
        }
        let int_part = match digits(&text[start..i], 10) {
            Ok(v) => v,
            Err(LiteralError::IntTooLarge) => return Err(LiteralError::DurationOutOfRange),
            Err(LiteralError::EmptyNumber) => return Err(LiteralError::DurationNeedsNumber),
            Err(e) => return Err(e),
        };
        let mut frac: i128 = 0;
        let mut frac_scale: i128 = 1;
        if b.get(i) == Some(&b'.') {
            i += 1;
            let fs = i;
            while b.get(i).is_some_and(u8::is_ascii_digit) {
                // Digits beyond 10⁻²⁰ cannot change the rounded nanoseconds of a day.
                if i - fs < 20 {
                    frac = frac * 10 + i128::from(b[i] - b'0');
                    frac_scale *= 10;
                }
                i += 1;
            }
            if i == fs {
                return Err(LiteralError::MissingFractionDigits);
            }
            had_fraction = true;
        }
        // `_` separates digits or follows a unit, never precedes one (`5_s`, `1__0s`).
        if b.get(i) == Some(&b'_') {
            return Err(LiteralError::BadUnderscore);
        }
        let us = i;
        while b.get(i).is_some_and(u8::is_ascii_alphabetic) {
            i += 1;
        }
        const UNITS: [(&str, i64); 7] = [
            ("d", NS_PER_DAY),
            ("h", NS_PER_H),
            ("m", NS_PER_MIN),
            ("s", NS_PER_S),
            ("ms", NS_PER_MS),
            ("us", NS_PER_US),
            ("ns", 1),
        ];
        let unit = &text[us..i];
        let Some((rank, ns)) = UNITS
            .iter()
            .position(|(name, _)| name.eq_ignore_ascii_case(unit))
            .map(|r| (r, UNITS[r].1))
        else {
            return Err(if unit.is_empty() {
                LiteralError::MissingDurationUnit { start, end: i }
            } else {
                LiteralError::BadDurationUnit { start: us, end: i }
            });
        };
        if last_rank != usize::MAX && rank <= last_rank {
            return Err(LiteralError::DurationUnitOrder);
        }
        last_rank = rank;
        let ns = i128::from(ns);
        let frac_ns = (frac * ns * 2 + frac_scale) / (2 * frac_scale); // rounded half up
        total = int_part
            .checked_mul(ns)
            .and_then(|v| v.checked_add(frac_ns))
            .and_then(|v| total.checked_add(v))
            .ok_or(LiteralError::DurationOutOfRange)?;
        if b.get(i) == Some(&b'_') {
            i += 1;
            if i == b.len() {
                return Err(LiteralError::TrailingUnderscore);
            }
        }
    }
    let total = if neg { -total } else { total };
    i64::try_from(total).map_err(|_| LiteralError::DurationOutOfRange)
}

/// A date or time field at `start..end` of `text`: 1 to 9 decimal digits (so that it fits).
fn field(text: &str, start: usize, end: usize, field: DateField) -> Result<u32, LiteralError> {
    let s = &text[start..end];
    if s.is_empty() || s.len() > 9 || !s.bytes().all(|b| b.is_ascii_digit()) {
        return Err(LiteralError::BadField { field, start, end });
    }
    s.parse()
        .map_err(|_| LiteralError::BadField { field, start, end })
}

/// Parses the part of a date literal after `D#`/`DATE#`: `2001-04-09`.
pub fn parse_date(text: &str) -> Result<DATE, LiteralError> {
    let mut dashes = text.match_indices('-').map(|(i, _)| i);
    let (Some(a), Some(b), None) = (dashes.next(), dashes.next(), dashes.next()) else {
        return Err(LiteralError::BadDateShape);
    };
    let year = field(text, 0, a, DateField::Year)?;
    let month = field(text, a + 1, b, DateField::Month)?;
    let day = field(text, b + 1, text.len(), DateField::Day)?;
    if !(1..=12).contains(&month) {
        return Err(LiteralError::MonthOutOfRange { month });
    }
    if day < 1 || day > days_in_month(i64::from(year), month) {
        return Err(LiteralError::DayOutOfRange { year, month, day });
    }
    Ok(DATE(days_from_civil(i64::from(year), month, day)))
}

/// Parses the part of a time-of-day literal after `TOD#`/`TIME_OF_DAY#`: `11:36:15.20`
/// (fraction of a second optional, up to nanoseconds; further digits are ignored).
pub fn parse_tod(text: &str) -> Result<TOD, LiteralError> {
    let mut colons = text.match_indices(':').map(|(i, _)| i);
    let (Some(a), Some(b), None) = (colons.next(), colons.next(), colons.next()) else {
        return Err(LiteralError::BadTimeShape);
    };
    let h = field(text, 0, a, DateField::Hour)?;
    let m = field(text, a + 1, b, DateField::Minute)?;
    let dot = text[b + 1..].find('.').map(|d| b + 1 + d);
    let s = field(text, b + 1, dot.unwrap_or(text.len()), DateField::Second)?;
    let frac = dot.map_or("", |d| &text[d + 1..]);
    if dot.is_some() && frac.is_empty() {
        return Err(LiteralError::MissingFractionDigits);
    }
    if !frac.bytes().all(|b| b.is_ascii_digit()) {
        let start = dot.map_or(text.len(), |d| d + 1);
        return Err(LiteralError::BadFraction {
            start,
            end: text.len(),
        });
    }
    if h > 23 {
        return Err(LiteralError::HoursOutOfRange { hours: h });
    }
    if m > 59 {
        return Err(LiteralError::MinutesOutOfRange { minutes: m });
    }
    if s > 59 {
        return Err(LiteralError::SecondsOutOfRange { seconds: s });
    }
    let mut ns: u32 = 0;
    for i in 0..9 {
        ns = ns * 10 + frac.as_bytes().get(i).map_or(0, |b| u32::from(b - b'0'));
    }
    TOD::from_hms_nanos(h, m, s, ns).ok_or(LiteralError::BadTimeShape)
}

/// Parses the part of a date-and-time literal after `DT#`/`DATE_AND_TIME#`:
/// `2001-04-09-11:36:15.20`.
pub fn parse_dt(text: &str) -> Result<DT, LiteralError> {
    // The date has exactly two '-'; the third separates date and time.
    let split = text
        .match_indices('-')
        .nth(2)
        .map(|(i, _)| i)
        .ok_or(LiteralError::BadDateTimeShape)?;
    let date = parse_date(&text[..split])?;
    let tod = parse_tod(&text[split + 1..]).map_err(|e| e.shifted(split + 1))?;
    DT::checked_from_date_tod(date, tod).ok_or(LiteralError::DateTimeOutOfRange)
}

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

/// One element of an unescaped string literal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StrPiece {
    /// A character written as itself or with a named escape (`$N` gives `'\n'`).
    Char(char),
    /// A character code given in hex: `$hh` (STRING, 0..=255) or `$hhhh` (WSTRING).
    Code(u16),
}

/// Unescapes the body of a string literal (without its quotes), passing each character to
/// `out`. Escapes: `$$ $' $" $L $N $P $R $T` (any case; `$L` and `$N` are line feed, `$P` form
/// feed) and `$hh` (two hex digits) in a STRING, `$hhhh` (four) in a WSTRING (`wide`).
pub fn unescape_string(
    body: &str,
    wide: bool,
    out: &mut impl FnMut(StrPiece),
) -> Result<(), LiteralError> {
    let mut it = body.char_indices().peekable();
    while let Some((i, c)) = it.next() {
        if c != '$' {
            out(StrPiece::Char(c));
            continue;
        }
        let Some((_, e)) = it.next() else {
            return Err(LiteralError::EscapeAtEnd { at: i });
        };
        let piece = match e.to_ascii_uppercase() {
            '$' => StrPiece::Char('$'),
            '\'' => StrPiece::Char('\''),
            '"' => StrPiece::Char('"'),
            'L' | 'N' => StrPiece::Char('\n'),
            'P' => StrPiece::Char('\x0C'),
            'R' => StrPiece::Char('\r'),
            'T' => StrPiece::Char('\t'),
            h if h.is_ascii_hexdigit() => {
                let n = if wide { 4 } else { 2 };
                let mut v = h.to_digit(16).unwrap_or(0);
                for _ in 1..n {
                    match it.next() {
                        Some((_, d)) if d.is_ascii_hexdigit() => {
                            v = v * 16 + d.to_digit(16).unwrap_or(0);
                        }
                        _ => return Err(LiteralError::HexEscapeDigits { at: i, wide }),
                    }
                }
                StrPiece::Code(v as u16)
            }
            _ => return Err(LiteralError::BadEscape { at: i, escape: e }),
        };
        out(piece);
    }
    Ok(())
}

/// Unescapes a STRING literal body into a `STRING<N>`: characters as UTF-8 bytes, `$hh` as the
/// byte `hh`. The flag is `true` if the value was truncated to the capacity.
pub fn string_literal<const N: usize>(body: &str) -> Result<(STRING<N>, bool), LiteralError> {
    let mut s = STRING::<N>::new();
    let mut truncated = false;
    unescape_string(body, false, &mut |p| {
        let mut b = [0u8; 4];
        truncated |= match p {
            StrPiece::Char(c) => s.push_units(c.encode_utf8(&mut b).as_bytes()),
            StrPiece::Code(v) => s.push_units(&[v as u8]),
        };
    })?;
    Ok((s, truncated))
}

/// Unescapes a WSTRING literal body into a `WSTRING<N>`: characters as UTF-16, `$hhhh` as the
/// code unit `hhhh`. The flag is `true` if the value was truncated to the capacity.
pub fn wstring_literal<const N: usize>(body: &str) -> Result<(WSTRING<N>, bool), LiteralError> {
    let mut s = WSTRING::<N>::new();
    let mut truncated = false;
    unescape_string(body, true, &mut |p| {
        let mut b = [0u16; 2];
        truncated |= match p {
            StrPiece::Char(c) => {
                let enc = c.encode_utf16(&mut b);
                if s.len() + enc.len() > N {
                    true
                } else {
                    s.push_units(enc)
                }
            }
            StrPiece::Code(v) => s.push_units(&[v]),
        };
    })?;
    Ok((s, truncated))
}

#[cfg(test)]
mod tests {
    use super::LiteralError::*;
    use super::*;
    use std::string::ToString;
    use std::vec::Vec;

    #[test]
    fn ints() {
        assert_eq!(parse_int("0"), Ok(0));
        assert_eq!(parse_int("1_000"), Ok(1000));
        assert_eq!(parse_int("-12"), Ok(-12));
        assert_eq!(parse_int("+7"), Ok(7));
        assert_eq!(parse_int("2#1010_1010"), Ok(0xAA));
        assert_eq!(parse_int("8#777"), Ok(511));
        assert_eq!(parse_int("16#ff"), Ok(255));
        assert_eq!(parse_int("16#FFFF_FFFF_FFFF_FFFF"), Ok(u64::MAX as i128));
        assert_eq!(parse_int("-18446744073709551615"), Ok(-(u64::MAX as i128)));
        for (bad, err) in [
            ("", EmptyNumber),
            ("-", EmptyNumber),
            ("16#", EmptyNumber),
            ("_1", BadUnderscore),
            ("1_", BadUnderscore),
            ("1__0", BadUnderscore),
            ("3#12", BadBase),
            ("-3#12", BadBase),
            ("-16#FF", SignedBasedInt),
            ("+2#1", SignedBasedInt),
            (
                "2#102",
                BadDigit {
                    digit: '2',
                    radix: 2,
                },
            ),
            (
                "16#FG",
                BadDigit {
                    digit: 'G',
                    radix: 16,
                },
            ),
            (
                "16#-1",
                BadDigit {
                    digit: '-',
                    radix: 16,
                },
            ),
            (
                "1.0",
                BadDigit {
                    digit: '.',
                    radix: 10,
                },
            ),
            ("18446744073709551616", IntTooLarge),
            ("99999999999999999999999999999999999999999", IntTooLarge),
        ] {
            assert_eq!(parse_int(bad), Err(err), "{bad}");
        }
    }

    #[test]
    fn reals() {
        assert_eq!(parse_real("1.5"), Ok(1.5));
        assert_eq!(parse_real("1.0E-3"), Ok(1.0e-3));
        assert_eq!(parse_real("-1_000.25"), Ok(-1000.25));
        assert_eq!(parse_real("1__0.0"), Err(BadUnderscore));
        assert_eq!(parse_real("1_.5"), Err(BadUnderscore));
        assert_eq!(parse_real("1.0_"), Err(BadUnderscore));
        assert_eq!(parse_real("inf"), Err(BadReal));
        assert_eq!(parse_real("1e"), Err(BadReal));
        // No length limit without `_` (nothing to copy).
        let long = "1.".to_string() + &"0".repeat(300);
        assert_eq!(parse_real(&long), Ok(1.0));
    }

    #[test]
    fn durations() {
        let ms = 1_000_000i64;
        assert_eq!(
            parse_duration("1h_15m_30s_60ms"),
            Ok((3600 + 15 * 60 + 30) * 1000 * ms + 60 * ms)
        );
        assert_eq!(parse_duration("500ms"), Ok(500 * ms));
        assert_eq!(parse_duration("1.5s"), Ok(1500 * ms));
        assert_eq!(parse_duration("-5s"), Ok(-5000 * ms));
        assert_eq!(parse_duration("+5s"), Ok(5000 * ms));
        assert_eq!(parse_duration("1d2h"), Ok((26 * 3600) * 1000 * ms));
        assert_eq!(parse_duration("25h"), Ok(25 * 3600 * 1000 * ms));
        assert_eq!(parse_duration("1_000ms"), Ok(1000 * ms));
        assert_eq!(parse_duration("1S"), Ok(1000 * ms));
        assert_eq!(parse_duration("10US"), Ok(10_000));
        assert_eq!(parse_duration("1m1ms"), Ok(60_001 * ms));
        assert_eq!(parse_duration("10us5ns"), Ok(10_005));
        assert_eq!(parse_duration("0.0000000015s"), Ok(2));
        assert_eq!(parse_duration("12.5ms"), Ok(12_500_000));
        assert_eq!(parse_duration("0s"), Ok(0));
        assert_eq!(
            parse_duration("106751d23h47m16s854ms775us807ns"),
            Ok(i64::MAX)
        );
        assert_eq!(
            parse_duration("-106751d23h47m16s854ms775us808ns"),
            Ok(i64::MIN)
        );
        for (bad, err) in [
            ("", EmptyDuration),
            ("-", EmptyDuration),
            ("5", MissingDurationUnit { start: 0, end: 1 }),
            ("1h2.5", MissingDurationUnit { start: 2, end: 5 }),
            ("5x", BadDurationUnit { start: 1, end: 2 }),
            ("-5mX", BadDurationUnit { start: 2, end: 4 }),
            ("1.5s3ms", FractionNotLast),
            ("1s1h", DurationUnitOrder),
            ("1s1s", DurationUnitOrder),
            ("1s_", TrailingUnderscore),
            ("1.s", MissingFractionDigits),
            ("s", DurationNeedsNumber),
            ("1h_s", DurationNeedsNumber),
            ("5_s", BadUnderscore),
            ("_5s", BadUnderscore),
            ("1__0s", BadUnderscore),
            ("1.5_s", BadUnderscore),
            ("1h__5m", BadUnderscore),
            ("106751d23h47m16s854ms775us808ns", DurationOutOfRange),
            (
                "99999999999999999999999999999999999999999d",
                DurationOutOfRange,
            ),
            ("9999999999999999999999999d", DurationOutOfRange),
        ] {
            assert_eq!(parse_duration(bad), Err(err), "{bad}");
        }
    }

    #[test]
    fn dates_and_times() {
        assert_eq!(
            parse_date("2001-04-09"),
            Ok(DATE::from_ymd(2001, 4, 9).unwrap())
        );
        assert_eq!(parse_date("1970-01-01"), Ok(DATE(0)));
        assert_eq!(parse_date("2000-02-29"), Ok(DATE(11_016)));
        assert_eq!(parse_date("2001-13-09"), Err(MonthOutOfRange { month: 13 }));
        assert_eq!(
            parse_date("2001-02-29"),
            Err(DayOutOfRange {
                year: 2001,
                month: 2,
                day: 29
            })
        );
        assert_eq!(parse_date("2001-04"), Err(BadDateShape));
        assert_eq!(parse_date("2001-04-09-1"), Err(BadDateShape));
        let year = DateField::Year;
        assert_eq!(
            parse_date("-04-09"),
            Err(BadField {
                field: year,
                start: 0,
                end: 0
            })
        );
        assert_eq!(
            parse_date("2001-04-x"),
            Err(BadField {
                field: DateField::Day,
                start: 8,
                end: 9
            })
        );
        // At most 9 digits a field, so that every value fits.
        assert_eq!(
            parse_date("0000002001-01-01"),
            Err(BadField {
                field: year,
                start: 0,
                end: 10
            })
        );
        // The whole range of DT, whose first day starts before i64::MIN ns.
        assert_eq!(
            parse_dt("1677-09-21-00:12:45").map(|d| d.0 / 1_000_000_000),
            Ok(-9_223_372_035)
        );
        assert_eq!(parse_dt("1677-09-21-00:12:43"), Err(DateTimeOutOfRange));
        assert!(parse_dt("2262-04-11-23:47:16").is_ok());
        assert_eq!(parse_dt("2262-04-11-23:47:17"), Err(DateTimeOutOfRange));
        assert_eq!(
            parse_tod("11:36:15.20"),
            Ok(TOD::from_hms_nanos(11, 36, 15, 200_000_000).unwrap())
        );
        assert_eq!(parse_tod("00:00:00"), Ok(TOD(0)));
        assert_eq!(parse_tod("23:59:59.9999999999"), Ok(TOD(NS_PER_DAY - 1)));
        assert_eq!(parse_tod("24:00:00"), Err(HoursOutOfRange { hours: 24 }));
        assert_eq!(
            parse_tod("12:60:00"),
            Err(MinutesOutOfRange { minutes: 60 })
        );
        assert_eq!(
            parse_tod("12:00:60"),
            Err(SecondsOutOfRange { seconds: 60 })
        );
        assert_eq!(parse_tod("12:00"), Err(BadTimeShape));
        assert_eq!(parse_tod("12:00:00:00"), Err(BadTimeShape));
        assert_eq!(parse_tod("12:00:00."), Err(MissingFractionDigits));
        assert_eq!(
            parse_tod("12:00:00.5x"),
            Err(BadFraction { start: 9, end: 11 })
        );
        assert_eq!(
            parse_tod("12:x:00"),
            Err(BadField {
                field: DateField::Minute,
                start: 3,
                end: 4
            })
        );
        assert_eq!(
            parse_dt("2001-04-09-11:36:15.20"),
            Ok(DT::from_parts(2001, 4, 9, 11, 36, 15, 200_000_000).unwrap())
        );
        assert_eq!(parse_dt("2001-04-09"), Err(BadDateTimeShape));
        assert_eq!(
            parse_dt("2001-04-09-25:00:00"),
            Err(HoursOutOfRange { hours: 25 })
        );
        // Offsets of the time part count from the start of the whole text.
        assert_eq!(
            parse_dt("2001-04-09-1x:00:00"),
            Err(BadField {
                field: DateField::Hour,
                start: 11,
                end: 13
            })
        );
    }

    #[test]
    fn strings() {
        let mut v = Vec::new();
        unescape_string("a$$b$'$\"$L$n$P$r$T$41", false, &mut |p| v.push(p)).unwrap();
        use StrPiece::*;
        assert_eq!(
            v,
            [
                Char('a'),
                Char('$'),
                Char('b'),
                Char('\''),
                Char('"'),
                Char('\n'),
                Char('\n'),
                Char('\x0C'),
                Char('\r'),
                Char('\t'),
                Code(0x41)
            ]
        );
        let mut v = Vec::new();
        unescape_string("$20AC!", true, &mut |p| v.push(p)).unwrap();
        assert_eq!(v, [Code(0x20AC), Char('!')]);
        assert_eq!(
            unescape_string("ab$", false, &mut |_| {}),
            Err(EscapeAtEnd { at: 2 })
        );
        assert_eq!(
            unescape_string("$4", false, &mut |_| {}),
            Err(HexEscapeDigits { at: 0, wide: false })
        );
        assert_eq!(
            unescape_string("x$41G", true, &mut |_| {}),
            Err(HexEscapeDigits { at: 1, wide: true })
        );
        assert_eq!(
            unescape_string("é$q", false, &mut |_| {}),
            Err(BadEscape { at: 2, escape: 'q' })
        );
        let (s, t) = string_literal::<10>("é$FF$0A").unwrap();
        assert!(!t);
        assert_eq!(s.as_bytes(), [0xC3, 0xA9, 0xFF, 0x0A]);
        let (s, t) = string_literal::<2>("abc").unwrap();
        assert!(t);
        assert_eq!(s.as_bytes(), b"ab");
        let (w, t) = wstring_literal::<3>("a$20AC😀").unwrap();
        assert!(t);
        assert_eq!(w.as_units(), [0x61, 0x20AC]);
    }

    #[test]
    fn messages() {
        assert_eq!(
            BadDigit {
                digit: 'G',
                radix: 16
            }
            .to_string(),
            "`G` is not a digit in base 16"
        );
        assert_eq!(
            DayOutOfRange {
                year: 2001,
                month: 2,
                day: 29
            }
            .to_string(),
            "day 29 does not exist in month 2 of 2001"
        );
        assert_eq!(
            BadEscape { at: 0, escape: 'q' }.to_string(),
            "`$q` is not a string escape: use $$, $', $\", $L, $N, $P, $R, $T or $ and hex digits"
        );
        assert_eq!(
            HexEscapeDigits { at: 0, wide: true }.to_string(),
            "`$` followed by a hex code needs 4 hex digits here"
        );
        assert_eq!(
            BadField {
                field: DateField::Month,
                start: 0,
                end: 0
            }
            .to_string(),
            "not a valid month"
        );
    }
}
