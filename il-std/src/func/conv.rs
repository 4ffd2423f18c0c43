//! Type conversions `*_TO_*`, `*_TRUNC_*` and BCD conversions, generated from the shared list
//! in `conv_list.rs` (which also feeds the signature table).
//!
//! Rules (documented on each function):
//! * integer/bit string → integer/bit string: two's complement truncation or extension
//!   (`DINT_TO_INT(70000) = 4464`, `INT_TO_WORD(-1) = 16#FFFF`);
//! * integer → real: nearest representable value;
//! * real → integer/bit string: rounded to nearest, **ties to even** (`REAL_TO_INT(2.5) = 2`,
//!   `REAL_TO_INT(3.5) = 4`); out of range saturates, NaN gives 0 (see
//!   [`conv::real_to_int_checked`](crate::conv::real_to_int_checked) for the fault flag);
//! * `BOOL` → number: 0 or 1; number → `BOOL`: `TRUE` if not zero;
//! * `TIME` ↔ number: **milliseconds** (`TIME_TO_DINT(T#1.5s) = 1500`, truncated toward zero;
//!   `TIME_TO_REAL` keeps the fraction of a millisecond); `LTIME` ↔ number: **nanoseconds**;
//! * `*_TRUNC_*`: real → integer truncated toward zero;
//! * BCD: `BCD_TO_*` decode packed BCD (an invalid digit gives 0), `*_TO_BCD` encode (a
//!   negative value or one with too many digits gives 0); see
//!   [`conv::bcd_decode_checked`](crate::conv::bcd_decode_checked);
//! * `*_TO_STRING`: the IEC literal text without type prefix for numbers (`TRUE`, `-12`,
//!   `1.5`), with prefix for durations and dates (`T#1s500ms`, `D#2001-04-09`); results are
//!   `STRING` of the default length 80;
//! * `STRING_TO_*`: parse the same forms (surrounding blanks ignored; integers may use `2#`,
//!   `8#`, `16#` and `_`; durations and dates with or without their `T#`/`D#`/`TOD#`/`DT#`
//!   prefix); an unparsable or out-of-range string gives the type's default (0).

#![allow(clippy::unnecessary_cast)]

use super::conv_list::conversions;
use crate::literal;
use crate::string::{STRING, WSTRING};
use crate::time::{DATE, DT, LTIME, TIME, TOD};
use crate::types::*;
use core::fmt::Write;

fn trim(s: &[u8]) -> &str {
    core::str::from_utf8(s).unwrap_or("").trim()
}

fn strip_prefix_ci<'a>(s: &'a str, prefixes: &[&str]) -> &'a str {
    for p in prefixes {
        if s.len() >= p.len() && s.is_char_boundary(p.len()) && s[..p.len()].eq_ignore_ascii_case(p)
        {
            return &s[p.len()..];
        }
    }
    s
}

fn parse_int_str<const N: usize>(s: STRING<N>) -> Result<i128, literal::LiteralError> {
    let t = trim(s.as_bytes());
    // Accept an optional type prefix such as `INT#`.
    let t = match t.split_once('#') {
        Some((pre, rest)) if pre.chars().all(|c| c.is_ascii_alphabetic()) => rest,
        _ => t,
    };
    literal::parse_int(t)
}

fn parse_dur<const N: usize>(s: STRING<N>) -> i64 {
    let t = strip_prefix_ci(trim(s.as_bytes()), &["LTIME#", "TIME#", "LT#", "T#"]);
    literal::parse_duration(t).unwrap_or(0)
}

fn to_str<T: core::fmt::Display>(v: T) -> STRING {
    let mut s = STRING::new();
    let _ = write!(s, "{v}");
    s
}

fn real_to_str<T: core::fmt::Debug>(v: T) -> STRING {
    let mut s = STRING::new();
    let _ = write!(s, "{v:?}");
    s
}

macro_rules! conv_fn {
    (cast, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: converts `", stringify!($s), "` to `", stringify!($d),
            "` (integers: two's complement truncation/extension; to real: nearest value).")]
        pub fn $name(IN: $s) -> $d { IN as $d }
    };
    (round, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: converts `", stringify!($s), "` to `", stringify!($d),
            "`, rounding to nearest with ties to even; out of range saturates, NaN gives 0.")]
        pub fn $name(IN: $s) -> $d { crate::conv::real_to_int::<$d>(IN as f64) }
    };
    (trunc, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: `", stringify!($s), "` to `", stringify!($d),
            "` truncated toward zero; out of range saturates, NaN gives 0.")]
        pub fn $name(IN: $s) -> $d { crate::conv::trunc_to_int_checked::<$d>(IN as f64).0 }
    };
    (from_bool, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: `FALSE` → 0, `TRUE` → 1.")]
        pub fn $name(IN: $s) -> $d { (IN as u8) as $d }
    };
    (to_bool, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: `TRUE` if `IN` is not zero.")]
        pub fn $name(IN: $s) -> $d { IN != (0 as $s) }
    };
    (time_to_int, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the duration in whole milliseconds (truncated toward zero), then two's complement truncation to `", stringify!($d), "`.")]
        pub fn $name(IN: $s) -> $d { IN.as_ms() as $d }
    };
    (time_to_real, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the duration in milliseconds, with fraction.")]
        pub fn $name(IN: $s) -> $d { (IN.0 as f64 / 1e6) as $d }
    };
    (int_to_time, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: `IN` milliseconds (saturating at the `TIME` range).")]
        pub fn $name(IN: $s) -> $d { TIME::from_ms(IN as i64) }
    };
    (real_to_time, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: `IN` milliseconds, rounded to the nearest nanosecond (saturating, NaN gives `T#0s`).")]
        pub fn $name(IN: $s) -> $d { TIME(crate::time::f64_to_i64_round(IN as f64 * 1e6)) }
    };
    (ltime_to_int, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the duration in nanoseconds, two's complement truncation to `", stringify!($d), "`.")]
        pub fn $name(IN: $s) -> $d { IN.0 as $d }
    };
    (ltime_to_real, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the duration in nanoseconds.")]
        pub fn $name(IN: $s) -> $d { IN.0 as $d }
    };
    (int_to_ltime, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: `IN` nanoseconds (`ULINT` above `LINT`'s range wraps).")]
        pub fn $name(IN: $s) -> $d { LTIME(IN as i64) }
    };
    (real_to_ltime, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: `IN` nanoseconds, rounded (saturating, NaN gives 0).")]
        pub fn $name(IN: $s) -> $d { LTIME(crate::time::f64_to_i64_round(IN as f64)) }
    };
    (dur_dur, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the same duration.")]
        pub fn $name(IN: $s) -> $d { $d(IN.0) }
    };
    (dt_tod, $name:ident, $s:ident, $d:ident) => {
        /// `DT_TO_TOD`: the time-of-day part of a date and time.
        pub fn $name(IN: $s) -> $d { IN.tod() }
    };
    (dt_date, $name:ident, $s:ident, $d:ident) => {
        /// `DT_TO_DATE`: the date part of a date and time.
        pub fn $name(IN: $s) -> $d { IN.date() }
    };
    (bits_to_real, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the bits of `IN` as an IEEE 754 number (no conversion of the value: a vendor's view of two memory words as a float).")]
        pub fn $name(IN: $s) -> $d { <$d>::from_bits(IN) }
    };
    (real_to_bits, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the IEEE 754 bits of `IN` (no conversion of the value).")]
        pub fn $name(IN: $s) -> $d { IN.to_bits() }
    };
    (bcd_to, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: decodes packed BCD (`16#1234` → 1234); an invalid digit gives 0.")]
        pub fn $name(IN: $s) -> $d { crate::conv::bcd_decode_checked(IN as u64).0 as $d }
    };
    (to_bcd, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: encodes as packed BCD (1234 → `16#1234`); a negative value or one with too many digits gives 0.")]
        pub fn $name(IN: $s) -> $d {
            crate::conv::bcd_encode_checked(IN as i128, <$d>::BITS / 4).0 as $d
        }
    };
    (to_string, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the value as text (IEC literal form).")]
        pub fn $name(IN: $s) -> $d { to_str(IN) }
    };
    (real_to_string, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: the value as text (`1.5`, `1.0`, `1e-7`, `NaN`, `inf`).")]
        pub fn $name(IN: $s) -> $d { real_to_str(IN) }
    };
    (bool_to_string, $name:ident, $s:ident, $d:ident) => {
        /// `BOOL_TO_STRING`: `'TRUE'` or `'FALSE'`.
        pub fn $name(IN: $s) -> $d { STRING::from_bytes_truncating(if IN { b"TRUE" } else { b"FALSE" }).0 }
    };
    (str_to_int, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: parses an integer literal (`-12`, `16#FF`); 0 if malformed or out of range.")]
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d {
            parse_int_str(IN).ok().and_then(|v| <$d>::try_from(v).ok()).unwrap_or(0)
        }
    };
    (str_to_real, $name:ident, $s:ident, $d:ident) => {
        #[doc = concat!("`", stringify!($name), "`: parses a real literal (`1.5`, `-1.0E-3`); 0.0 if malformed.")]
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d {
            literal::parse_real(trim(IN.as_bytes())).unwrap_or(0.0) as $d
        }
    };
    (str_to_bool, $name:ident, $s:ident, $d:ident) => {
        /// `STRING_TO_BOOL`: `TRUE` for `'TRUE'` (any case) or a non-zero integer, else `FALSE`.
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d {
            let t = trim(IN.as_bytes());
            // An integer too large to parse is still not zero.
            t.eq_ignore_ascii_case("TRUE")
                || parse_int_str(IN).map_or_else(|e| e == literal::LiteralError::IntTooLarge, |v| v != 0)
        }
    };
    (str_to_time, $name:ident, $s:ident, $d:ident) => {
        /// `STRING_TO_TIME`: parses `T#1s500ms` (prefix optional); `T#0s` if malformed.
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d { TIME(parse_dur(IN)) }
    };
    (str_to_ltime, $name:ident, $s:ident, $d:ident) => {
        /// `STRING_TO_LTIME`: parses `LTIME#1s` (prefix optional); 0 if malformed.
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d { LTIME(parse_dur(IN)) }
    };
    (str_to_date, $name:ident, $s:ident, $d:ident) => {
        /// `STRING_TO_DATE`: parses `D#2001-04-09` (prefix optional); `D#1970-01-01` if malformed.
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d {
            literal::parse_date(strip_prefix_ci(trim(IN.as_bytes()), &["DATE#", "D#"])).unwrap_or_default()
        }
    };
    (str_to_tod, $name:ident, $s:ident, $d:ident) => {
        /// `STRING_TO_TOD`: parses `TOD#11:36:15.2` (prefix optional); midnight if malformed.
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d {
            literal::parse_tod(strip_prefix_ci(trim(IN.as_bytes()), &["TIME_OF_DAY#", "TOD#"])).unwrap_or_default()
        }
    };
    (str_to_dt, $name:ident, $s:ident, $d:ident) => {
        /// `STRING_TO_DT`: parses `DT#2001-04-09-11:36:15.2` (prefix optional); the epoch if malformed.
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d {
            literal::parse_dt(strip_prefix_ci(trim(IN.as_bytes()), &["DATE_AND_TIME#", "DT#"])).unwrap_or_default()
        }
    };
    (str_wstr, $name:ident, $s:ident, $d:ident) => {
        /// `STRING_TO_WSTRING`: each byte as the character of the same code (Latin-1).
        pub fn $name<const N: usize>(IN: STRING<N>) -> $d {
            let mut w = WSTRING::new();
            for &b in IN.as_bytes() {
                w.push_units(&[u16::from(b)]);
            }
            w
        }
    };
    (wstr_str, $name:ident, $s:ident, $d:ident) => {
        /// `WSTRING_TO_STRING`: characters up to U+00FF as that byte (Latin-1), others as `?`.
        pub fn $name<const N: usize>(IN: WSTRING<N>) -> $d {
            let mut s = STRING::new();
            for &u in IN.as_units() {
                s.push_units(&[u8::try_from(u).unwrap_or(b'?')]);
            }
            s
        }
    };
}

macro_rules! define_conversions {
    ([] $($name:ident : $s:ident => $d:ident, $kind:ident;)*) => {
        $( conv_fn!($kind, $name, $s, $d); )*
    };
}

conversions!(define_conversions);

// Keep the imports used whatever the list holds.
const _: Option<(DATE, DT, TOD, BOOL)> = None;

#[cfg(test)]
mod tests {
    use super::*;

    fn st(s: &str) -> STRING {
        STRING::from_str_truncating(s).0
    }

    #[test]
    fn bits_views_keep_the_bits() {
        assert_eq!(DWORD_AS_REAL(0x3F80_0000), 1.0);
        assert_eq!(REAL_AS_DWORD(-2.0), 0xC000_0000);
        assert_eq!(LWORD_AS_LREAL(0x3FF0_0000_0000_0000), 1.0);
        assert_eq!(LREAL_AS_LWORD(0.5), 0x3FE0_0000_0000_0000);
        assert!(DWORD_AS_REAL(0x7FC0_0000).is_nan());
    }

    #[test]
    fn numeric() {
        assert_eq!(DINT_TO_INT(70000), 4464);
        assert_eq!(INT_TO_WORD(-1), 0xFFFF);
        assert_eq!(INT_TO_UINT(-1), 65535);
        assert_eq!(UINT_TO_INT(65535), -1);
        assert_eq!(SINT_TO_LINT(-5), -5);
        assert_eq!(BYTE_TO_SINT(0xFF), -1);
        assert_eq!(ULINT_TO_LREAL(u64::MAX), 1.8446744073709552e19);
        assert_eq!(LREAL_TO_REAL(1e300), f32::INFINITY);
        assert_eq!(REAL_TO_LREAL(1.5), 1.5);
        assert_eq!(REAL_TO_INT(2.5), 2);
        assert_eq!(REAL_TO_INT(3.5), 4);
        assert_eq!(REAL_TO_INT(-2.5), -2);
        assert_eq!(REAL_TO_INT(1e10), i16::MAX);
        assert_eq!(REAL_TO_INT(-1e10), i16::MIN);
        assert_eq!(REAL_TO_INT(f32::NAN), 0);
        assert_eq!(LREAL_TO_UDINT(-1.0), 0);
        assert_eq!(LREAL_TO_ULINT(1e30), u64::MAX);
        assert_eq!(REAL_TO_WORD(65535.4), 65535);
        assert_eq!(LREAL_TO_LINT(-9.5), -10);
        assert_eq!(REAL_TRUNC_INT(-2.9), -2);
        assert_eq!(LREAL_TRUNC_USINT(300.0), 255);
        assert!(INT_TO_BOOL(-3) && !INT_TO_BOOL(0));
        assert!(REAL_TO_BOOL(0.1) && !LREAL_TO_BOOL(0.0));
        assert!(REAL_TO_BOOL(f32::NAN));
        assert_eq!(BOOL_TO_INT(true), 1);
        assert_eq!(BOOL_TO_LREAL(true), 1.0);
        assert_eq!(BOOL_TO_BYTE(false), 0);
    }

    #[test]
    fn times() {
        assert_eq!(TIME_TO_DINT(TIME::from_ms(1500)), 1500);
        assert_eq!(TIME_TO_DINT(TIME(1_999_999)), 1);
        assert_eq!(TIME_TO_DINT(TIME(-1_999_999)), -1);
        assert_eq!(TIME_TO_REAL(TIME(1_500_000)), 1.5);
        assert_eq!(DINT_TO_TIME(1500), TIME::from_ms(1500));
        assert_eq!(LINT_TO_TIME(i64::MAX), TIME::MAX);
        assert_eq!(REAL_TO_TIME(1.5), TIME(1_500_000));
        assert_eq!(LREAL_TO_TIME(f64::NAN), TIME(0));
        assert_eq!(LREAL_TO_TIME(1e300), TIME::MAX);
        assert_eq!(LTIME_TO_LINT(LTIME(5)), 5);
        assert_eq!(LINT_TO_LTIME(5), LTIME(5));
        assert_eq!(LREAL_TO_LTIME(2.5), LTIME(2));
        assert_eq!(TIME_TO_LTIME(TIME(7)), LTIME(7));
        assert_eq!(LTIME_TO_TIME(LTIME(7)), TIME(7));
        let dt = DT::from_parts(2001, 4, 9, 11, 36, 15, 0).unwrap();
        assert_eq!(DT_TO_TOD(dt), TOD::from_hms(11, 36, 15).unwrap());
        assert_eq!(DT_TO_DATE(dt), DATE::from_ymd(2001, 4, 9).unwrap());
        let before = DT::from_parts(1969, 12, 31, 23, 0, 0, 0).unwrap();
        assert_eq!(DT_TO_TOD(before), TOD::from_hms(23, 0, 0).unwrap());
        assert_eq!(DT_TO_DATE(before), DATE(-1));
    }

    #[test]
    fn bcd() {
        assert_eq!(BCD_TO_INT(0x1234), 1234);
        assert_eq!(BCD_TO_INT(0x9999), 9999);
        assert_eq!(BCD_TO_INT(0x12A4), 0);
        assert_eq!(BCD_TO_USINT(0x99), 99);
        assert_eq!(BCD_TO_LINT(0x9999_9999_9999_9999), 9_999_999_999_999_999);
        assert_eq!(BYTE_BCD_TO_USINT(0x42), 42);
        assert_eq!(WORD_BCD_TO_UINT(0x0042), 42);
        assert_eq!(DWORD_BCD_TO_UDINT(0x12345678), 12_345_678);
        assert_eq!(INT_TO_BCD(1234), 0x1234);
        assert_eq!(INT_TO_BCD(-1), 0);
        assert_eq!(INT_TO_BCD(10000), 0);
        assert_eq!(USINT_TO_BCD(99), 0x99);
        assert_eq!(USINT_TO_BCD(100), 0);
        assert_eq!(UINT_TO_BCD_WORD(9999), 0x9999);
        assert_eq!(
            ULINT_TO_BCD_LWORD(9_999_999_999_999_999),
            0x9999_9999_9999_9999
        );
        assert_eq!(ULINT_TO_BCD(u64::MAX), 0);
    }

    #[test]
    fn strings() {
        assert_eq!(INT_TO_STRING(-12).as_bytes(), b"-12");
        assert_eq!(BOOL_TO_STRING(true).as_bytes(), b"TRUE");
        assert_eq!(REAL_TO_STRING(1.5).as_bytes(), b"1.5");
        assert_eq!(LREAL_TO_STRING(1.0).as_bytes(), b"1.0");
        assert_eq!(LREAL_TO_STRING(1e300).as_bytes(), b"1e300");
        assert_eq!(TIME_TO_STRING(TIME::from_ms(1500)).as_bytes(), b"T#1s500ms");
        assert_eq!(DATE_TO_STRING(DATE(0)).as_bytes(), b"D#1970-01-01");
        assert_eq!(STRING_TO_INT(st(" -12 ")), -12);
        assert_eq!(STRING_TO_INT(st("16#7FFF")), 32767);
        assert_eq!(STRING_TO_INT(st("INT#5")), 5);
        assert_eq!(STRING_TO_INT(st("40000")), 0);
        assert_eq!(STRING_TO_UINT(st("40000")), 40000);
        assert_eq!(STRING_TO_BYTE(st("2#1010")), 10);
        assert_eq!(STRING_TO_INT(st("x")), 0);
        assert_eq!(STRING_TO_REAL(st("1.5E3")), 1500.0);
        assert_eq!(STRING_TO_LREAL(st("nope")), 0.0);
        assert!(STRING_TO_BOOL(st("true")) && STRING_TO_BOOL(st("1")) && !STRING_TO_BOOL(st("0")));
        // Too large for any integer type, but not zero.
        assert!(STRING_TO_BOOL(st("99999999999999999999999")));
        assert!(!STRING_TO_BOOL(st("-16#1")));
        assert_eq!(STRING_TO_TIME(st("T#1s500ms")), TIME::from_ms(1500));
        assert_eq!(STRING_TO_TIME(st("time#2s")), TIME::from_secs(2));
        assert_eq!(STRING_TO_TIME(st("250ms")), TIME::from_ms(250));
        assert_eq!(STRING_TO_LTIME(st("LTIME#5ns")), LTIME(5));
        assert_eq!(
            STRING_TO_DATE(st("D#2001-04-09")),
            DATE::from_ymd(2001, 4, 9).unwrap()
        );
        assert_eq!(
            STRING_TO_TOD(st("TOD#11:36:15.2")),
            TOD::from_hms_nanos(11, 36, 15, 200_000_000).unwrap()
        );
        assert_eq!(
            STRING_TO_DT(st("DT#2001-04-09-11:36:15")),
            DT::from_parts(2001, 4, 9, 11, 36, 15, 0).unwrap()
        );
        assert_eq!(STRING_TO_DATE(st("garbage")), DATE(0));
        // Round trips through text.
        for v in [i64::MIN, -1, 0, 1, i64::MAX] {
            assert_eq!(STRING_TO_LINT(LINT_TO_STRING(v)), v);
        }
        for v in [TIME::MIN.0 + 1, -1_500_000, 0, 86_400_000_000_123] {
            assert_eq!(STRING_TO_TIME(TIME_TO_STRING(TIME(v))), TIME(v));
        }
        let w = STRING_TO_WSTRING(STRING::<4>::from_bytes_truncating(&[0x41, 0xE9]).0);
        assert_eq!(w.as_units(), [0x41, 0xE9]);
        assert_eq!(
            WSTRING_TO_STRING(WSTRING::<4>::from_str_truncating("é€").0).as_bytes(),
            [0xE9, b'?']
        );
    }
}
