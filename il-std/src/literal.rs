//! Literal parsing shared by the compiler and the runtime (`STRING_TO_*`), so that both read
//! IEC literals the same way. Errors are short human messages.

use crate::string::{STRING, WSTRING};
use crate::time::{
    DATE, DT, NS_PER_DAY, NS_PER_H, NS_PER_MIN, NS_PER_MS, NS_PER_S, NS_PER_US, TOD,
};

/// Digits in `radix` with single `_` between digits (IEC `digit {[_] digit}`), as `i128`;
/// `None` if malformed or above `i128::MAX`.
fn digits(text: &str, radix: u32) -> Option<i128> {
    let mut v: i128 = 0;
    let mut prev_digit = false;
    let mut any = false;
    for c in text.chars() {
        if c == '_' {
            if !prev_digit {
                return None;
            }
            prev_digit = false;
            continue;
        }
        let d = c.to_digit(radix)?;
        v = v
            .checked_mul(i128::from(radix))?
            .checked_add(i128::from(d))?;
        prev_digit = true;
        any = true;
    }
    if any && prev_digit { Some(v) } else { None }
}

/// Parses an IEC integer literal: decimal with an optional sign (`-12`, `+7`, `1_000`) or based
/// `2#1010_1010`, `8#777`, `16#FF` (no sign). `_` may separate digits. `None` if malformed or
/// beyond the `i128` range (the caller range-checks against the target type, e.g. with
/// [`Elem::min_max_i128`](crate::signature::Elem::min_max_i128)).
pub fn parse_int(text: &str) -> Option<i128> {
    if let Some((base, rest)) = text.split_once('#') {
        let radix = match base {
            "2" => 2,
            "8" => 8,
            "16" => 16,
            _ => return None,
        };
        return digits(rest, radix);
    }
    if let Some(rest) = text.strip_prefix('-') {
        // Allow i128::MIN's magnitude by negating through checked arithmetic.
        return digits(rest, 10).map(|v| -v);
    }
    digits(text.strip_prefix('+').unwrap_or(text), 10)
}

/// Parses an IEC real literal such as `1.5`, `-0.5`, `1.0E-3`, `1_000.25`, `3e5`
/// (`_` between digits allowed). `None` if malformed.
pub fn parse_real(text: &str) -> Option<f64> {
    let mut buf = [0u8; 96];
    let mut n = 0;
    let mut prev = 0u8;
    for &b in text.as_bytes() {
        if b == b'_' {
            if !prev.is_ascii_digit() {
                return None;
            }
            prev = b;
            continue;
        }
        if prev == b'_' && !b.is_ascii_digit() {
            return None;
        }
        if !(b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-')) {
            return None;
        }
        *buf.get_mut(n)? = b;
        n += 1;
        prev = b;
    }
    if prev == b'_' {
        return None;
    }
    let s = core::str::from_utf8(buf.get(..n)?).ok()?;
    s.parse::<f64>().ok()
}

/// Parses the part of a duration literal after `T#`/`TIME#`/`LTIME#`, giving nanoseconds.
///
/// Units `d h m s ms us ns` (any case), from largest to smallest, each at most once, optionally
/// separated by `_`; a fraction only on the last unit; a leading `-` (e.g. `1h_15m_30s_60ms`,
/// `500ms`, `1.5s`, `-5s`, `1d2h`). The first unit may exceed its usual range (`25h`, `90s`).
/// A fraction finer than a nanosecond is rounded to the nearest nanosecond.
pub fn parse_duration(text: &str) -> Result<i64, &'static str> {
    let (neg, mut s) = match text.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, text.strip_prefix('+').unwrap_or(text)),
    };
    if s.is_empty() {
        return Err("empty duration");
    }
    let mut total: i128 = 0;
    let mut last_rank = usize::MAX;
    let mut had_fraction = false;
    while !s.is_empty() {
        if had_fraction {
            return Err("a fraction is only allowed on the last unit");
        }
        // Number: digits with single '_' between digits, then an optional fraction.
        let num_end = s
            .char_indices()
            .find(|&(i, c)| {
                !(c.is_ascii_digit()
                    || (c == '_' && s[i + 1..].starts_with(|n: char| n.is_ascii_digit())))
            })
            .map_or(s.len(), |(i, _)| i);
        let int_part = digits(&s[..num_end], 10).ok_or("expected a number before the unit")?;
        s = &s[num_end..];
        let mut frac: i128 = 0;
        let mut frac_scale: i128 = 1;
        if let Some(r) = s.strip_prefix('.') {
            let end = r.find(|c: char| !c.is_ascii_digit()).unwrap_or(r.len());
            if end == 0 {
                return Err("expected digits after the decimal point");
            }
            for c in r[..end].chars().take(20) {
                frac = frac * 10 + i128::from(c.to_digit(10).unwrap_or(0));
                frac_scale *= 10;
            }
            had_fraction = true;
            s = &r[end..];
        }
        let unit_end = s
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(s.len());
        let unit = &s[..unit_end];
        const UNITS: [(&str, i64); 7] = [
            ("d", NS_PER_DAY),
            ("h", NS_PER_H),
            ("m", NS_PER_MIN),
            ("s", NS_PER_S),
            ("ms", NS_PER_MS),
            ("us", NS_PER_US),
            ("ns", 1),
        ];
        let (rank, ns) = UNITS
            .iter()
            .enumerate()
            .find(|(_, (name, _))| name.eq_ignore_ascii_case(unit))
            .map(|(i, &(_, ns))| (i, ns))
            .ok_or(if unit.is_empty() {
                "missing unit (d, h, m, s, ms, us or ns)"
            } else {
                "unknown unit (expected d, h, m, s, ms, us or ns)"
            })?;
        if last_rank != usize::MAX && rank <= last_rank {
            return Err("units must go from days down to nanoseconds, each at most once");
        }
        last_rank = rank;
        let ns = i128::from(ns);
        let frac_ns = (frac * ns * 2 + frac_scale) / (2 * frac_scale); // rounded half up
        total = int_part
            .checked_mul(ns)
            .and_then(|v| v.checked_add(frac_ns))
            .and_then(|v| total.checked_add(v))
            .ok_or("duration out of range")?;
        s = &s[unit_end..];
        if let Some(r) = s.strip_prefix('_') {
            if r.is_empty() {
                return Err("a duration cannot end with '_'");
            }
            s = r;
        }
    }
    let total = if neg { -total } else { total };
    i64::try_from(total).map_err(|_| "duration out of range")
}

fn field(s: &str) -> Option<u32> {
    if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

/// Parses the part of a date literal after `D#`/`DATE#`: `2001-04-09`.
pub fn parse_date(text: &str) -> Result<DATE, &'static str> {
    let mut it = text.splitn(3, '-');
    let (y, m, d) = match (it.next(), it.next(), it.next()) {
        (Some(y), Some(m), Some(d)) => (y, m, d),
        _ => return Err("expected a date as YYYY-MM-DD"),
    };
    let (y, m, d) = match (field(y), field(m), field(d)) {
        (Some(y), Some(m), Some(d)) => (y, m, d),
        _ => return Err("expected a date as YYYY-MM-DD"),
    };
    let y = i32::try_from(y).map_err(|_| "year out of range")?;
    if !(1..=12).contains(&m) {
        return Err("month must be 1..12");
    }
    DATE::from_ymd(y, m, d).ok_or("day out of range for the month")
}

/// Parses the part of a time-of-day literal after `TOD#`/`TIME_OF_DAY#`: `11:36:15.20`
/// (fraction of a second optional, up to nanoseconds; further digits are ignored).
pub fn parse_tod(text: &str) -> Result<TOD, &'static str> {
    let mut it = text.splitn(3, ':');
    let (h, m, s) = match (it.next(), it.next(), it.next()) {
        (Some(h), Some(m), Some(s)) => (h, m, s),
        _ => return Err("expected a time of day as HH:MM:SS"),
    };
    let (s, frac) = s.split_once('.').unwrap_or((s, ""));
    let (h, m, s) = match (field(h), field(m), field(s)) {
        (Some(h), Some(m), Some(s)) => (h, m, s),
        _ => return Err("expected a time of day as HH:MM:SS"),
    };
    if text.contains('.') && frac.is_empty() {
        return Err("expected digits after the decimal point");
    }
    if !frac.bytes().all(|b| b.is_ascii_digit()) {
        return Err("expected digits after the decimal point");
    }
    let mut ns: u32 = 0;
    for i in 0..9 {
        let d = frac.as_bytes().get(i).map_or(0, |b| u32::from(b - b'0'));
        ns = ns * 10 + d;
    }
    if h > 23 {
        return Err("hours must be 0..23");
    }
    if m > 59 {
        return Err("minutes must be 0..59");
    }
    if s > 59 {
        return Err("seconds must be 0..59");
    }
    TOD::from_hms_nanos(h, m, s, ns).ok_or("invalid time of day")
}

/// Parses the part of a date-and-time literal after `DT#`/`DATE_AND_TIME#`:
/// `2001-04-09-11:36:15.20`.
pub fn parse_dt(text: &str) -> Result<DT, &'static str> {
    let split = text
        .match_indices('-')
        .nth(2)
        .map(|(i, _)| i)
        .ok_or("expected a date and time as YYYY-MM-DD-HH:MM:SS")?;
    let date = parse_date(&text[..split])?;
    let tod = parse_tod(&text[split + 1..])?;
    DT::checked_from_date_tod(date, tod).ok_or("date and time out of range")
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
/// On error, returns the byte offset of the offending `$` in `body` and a message.
pub fn unescape_string(
    body: &str,
    wide: bool,
    out: &mut impl FnMut(StrPiece),
) -> Result<(), (usize, &'static str)> {
    let mut it = body.char_indices().peekable();
    while let Some((i, c)) = it.next() {
        if c != '$' {
            out(StrPiece::Char(c));
            continue;
        }
        let Some((_, e)) = it.next() else {
            return Err((i, "'$' at the end of a string needs an escape character"));
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
                        _ => {
                            return Err((
                                i,
                                if wide {
                                    "expected 4 hex digits after '$' in a WSTRING"
                                } else {
                                    "expected 2 hex digits after '$' in a STRING"
                                },
                            ));
                        }
                    }
                }
                StrPiece::Code(v as u16)
            }
            _ => {
                return Err((
                    i,
                    "unknown escape after '$' (expected $$ $' $\" $L $N $P $R $T or hex)",
                ));
            }
        };
        out(piece);
    }
    Ok(())
}

/// Unescapes a STRING literal body into a `STRING<N>`: characters as UTF-8 bytes, `$hh` as the
/// byte `hh`. The flag is `true` if the value was truncated to the capacity.
pub fn string_literal<const N: usize>(
    body: &str,
) -> Result<(STRING<N>, bool), (usize, &'static str)> {
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
pub fn wstring_literal<const N: usize>(
    body: &str,
) -> Result<(WSTRING<N>, bool), (usize, &'static str)> {
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
    use super::*;
    use std::vec::Vec;

    #[test]
    fn ints() {
        assert_eq!(parse_int("0"), Some(0));
        assert_eq!(parse_int("1_000"), Some(1000));
        assert_eq!(parse_int("-12"), Some(-12));
        assert_eq!(parse_int("+7"), Some(7));
        assert_eq!(parse_int("2#1010_1010"), Some(0xAA));
        assert_eq!(parse_int("8#777"), Some(511));
        assert_eq!(parse_int("16#ff"), Some(255));
        assert_eq!(parse_int("16#FFFF_FFFF_FFFF_FFFF"), Some(u64::MAX as i128));
        for bad in [
            "", "_1", "1_", "1__0", "3#12", "2#102", "16#", "-", "16#-1", "1.0", "12a",
        ] {
            assert_eq!(parse_int(bad), None, "{bad}");
        }
        assert_eq!(
            parse_int("170141183460469231731687303715884105727"),
            Some(i128::MAX)
        );
        assert_eq!(parse_int("170141183460469231731687303715884105728"), None);
    }

    #[test]
    fn reals() {
        assert_eq!(parse_real("1.5"), Some(1.5));
        assert_eq!(parse_real("1.0E-3"), Some(1.0e-3));
        assert_eq!(parse_real("-1_000.25"), Some(-1000.25));
        assert_eq!(parse_real("1__0.0"), None);
        assert_eq!(parse_real("1.0_"), None);
        assert_eq!(parse_real("inf"), None);
        assert_eq!(parse_real("abc"), None);
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
        assert_eq!(parse_duration("1d2h"), Ok((26 * 3600) * 1000 * ms));
        assert_eq!(parse_duration("25h"), Ok(25 * 3600 * 1000 * ms));
        assert_eq!(parse_duration("1_000ms"), Ok(1000 * ms));
        assert_eq!(parse_duration("1S"), Ok(1000 * ms));
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
        for (bad, msg) in [
            ("", "empty duration"),
            ("5", "missing unit (d, h, m, s, ms, us or ns)"),
            ("5x", "unknown unit (expected d, h, m, s, ms, us or ns)"),
            ("1.5s3ms", "a fraction is only allowed on the last unit"),
            (
                "1s1h",
                "units must go from days down to nanoseconds, each at most once",
            ),
            (
                "1s1s",
                "units must go from days down to nanoseconds, each at most once",
            ),
            ("1s_", "a duration cannot end with '_'"),
            ("1.s", "expected digits after the decimal point"),
            ("s", "expected a number before the unit"),
            ("106751d23h47m16s854ms775us808ns", "duration out of range"),
            (
                "99999999999999999999999999999999999999999d",
                "expected a number before the unit",
            ),
            ("9999999999999999999999999d", "duration out of range"),
        ] {
            assert_eq!(parse_duration(bad), Err(msg), "{bad}");
        }
    }

    #[test]
    fn dates_and_times() {
        assert_eq!(
            parse_date("2001-04-09"),
            Ok(DATE::from_ymd(2001, 4, 9).unwrap())
        );
        assert_eq!(parse_date("2001-13-09"), Err("month must be 1..12"));
        // The whole range of DT, whose first day starts before i64::MIN ns.
        assert_eq!(
            parse_dt("1677-09-21-00:12:45").map(|d| d.0 / 1_000_000_000),
            Ok(-9_223_372_035)
        );
        assert_eq!(
            parse_dt("1677-09-21-00:12:43"),
            Err("date and time out of range")
        );
        assert!(parse_dt("2262-04-11-23:47:16").is_ok());
        assert_eq!(
            parse_dt("2262-04-11-23:47:17"),
            Err("date and time out of range")
        );
        assert_eq!(
            parse_date("2001-02-29"),
            Err("day out of range for the month")
        );
        assert_eq!(parse_date("2001-04"), Err("expected a date as YYYY-MM-DD"));
        assert_eq!(
            parse_date("2001-04-x"),
            Err("expected a date as YYYY-MM-DD")
        );
        assert_eq!(
            parse_tod("11:36:15.20"),
            Ok(TOD::from_hms_nanos(11, 36, 15, 200_000_000).unwrap())
        );
        assert_eq!(parse_tod("00:00:00"), Ok(TOD(0)));
        assert_eq!(parse_tod("23:59:59.999999999"), Ok(TOD(NS_PER_DAY - 1)));
        assert_eq!(parse_tod("24:00:00"), Err("hours must be 0..23"));
        assert_eq!(parse_tod("12:60:00"), Err("minutes must be 0..59"));
        assert_eq!(parse_tod("12:00:60"), Err("seconds must be 0..59"));
        assert_eq!(
            parse_tod("12:00"),
            Err("expected a time of day as HH:MM:SS")
        );
        assert_eq!(
            parse_tod("12:00:00."),
            Err("expected digits after the decimal point")
        );
        assert_eq!(
            parse_dt("2001-04-09-11:36:15.20"),
            Ok(DT::from_parts(2001, 4, 9, 11, 36, 15, 200_000_000).unwrap())
        );
        assert_eq!(
            parse_dt("2001-04-09"),
            Err("expected a date and time as YYYY-MM-DD-HH:MM:SS")
        );
        assert_eq!(parse_dt("2001-04-09-25:00:00"), Err("hours must be 0..23"));
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
            Err((2, "'$' at the end of a string needs an escape character"))
        );
        assert_eq!(
            unescape_string("$4", false, &mut |_| {}),
            Err((0, "expected 2 hex digits after '$' in a STRING"))
        );
        assert_eq!(
            unescape_string("x$41G", true, &mut |_| {}),
            Err((1, "expected 4 hex digits after '$' in a WSTRING"))
        );
        assert!(unescape_string("$Q", false, &mut |_| {}).is_err());
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
}
