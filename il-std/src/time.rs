//! Time and date types: `TIME`, `LTIME`, `DATE`, `TIME_OF_DAY`, `DATE_AND_TIME`.
//!
//! All are newtypes over an `i64` count (nanoseconds or days). Arithmetic on them wraps
//! (two's complement) or saturates where documented; nothing here panics.

use core::fmt;

pub(crate) const NS_PER_US: i64 = 1_000;
pub(crate) const NS_PER_MS: i64 = 1_000_000;
pub(crate) const NS_PER_S: i64 = 1_000_000_000;
pub(crate) const NS_PER_MIN: i64 = 60 * NS_PER_S;
pub(crate) const NS_PER_H: i64 = 60 * NS_PER_MIN;
pub(crate) const NS_PER_DAY: i64 = 24 * NS_PER_H;

/// Rounds to the nearest integer, ties to even, and converts to `i64` saturating (NaN → 0).
pub(crate) fn f64_to_i64_round(x: f64) -> i64 {
    crate::math::round_half_even(x) as i64
}

macro_rules! duration_type {
    ($name:ident, $prefix:literal, $doc:literal) => {
        #[doc = $doc]
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub struct $name(
            /// Signed duration in nanoseconds.
            pub i64,
        );

        impl $name {
            /// The zero duration (`T#0s`), the IEC default.
            pub const ZERO: Self = Self(0);
            /// The largest representable duration (about 292 years).
            pub const MAX: Self = Self(i64::MAX);
            /// The smallest (most negative) representable duration.
            pub const MIN: Self = Self(i64::MIN);

            /// Duration of `ns` nanoseconds.
            pub const fn from_nanos(ns: i64) -> Self {
                Self(ns)
            }
            /// Duration of `us` microseconds (saturating at the type's range).
            pub const fn from_us(us: i64) -> Self {
                Self(us.saturating_mul(NS_PER_US))
            }
            /// Duration of `ms` milliseconds (saturating at the type's range).
            pub const fn from_ms(ms: i64) -> Self {
                Self(ms.saturating_mul(NS_PER_MS))
            }
            /// Duration of `s` seconds (saturating at the type's range).
            pub const fn from_secs(s: i64) -> Self {
                Self(s.saturating_mul(NS_PER_S))
            }
            /// Whole milliseconds, truncated toward zero.
            pub const fn as_ms(self) -> i64 {
                self.0 / NS_PER_MS
            }
            /// Whole microseconds, truncated toward zero.
            pub const fn as_us(self) -> i64 {
                self.0 / NS_PER_US
            }
            /// Whole seconds, truncated toward zero.
            pub const fn as_secs(self) -> i64 {
                self.0 / NS_PER_S
            }
            /// Nanoseconds.
            pub const fn as_nanos(self) -> i64 {
                self.0
            }
            /// `self + rhs`, wrapping on overflow.
            pub const fn wrapping_add(self, rhs: Self) -> Self {
                Self(self.0.wrapping_add(rhs.0))
            }
            /// `self - rhs`, wrapping on overflow.
            pub const fn wrapping_sub(self, rhs: Self) -> Self {
                Self(self.0.wrapping_sub(rhs.0))
            }
            /// `self + rhs`, saturating at the type's bounds.
            pub const fn saturating_add(self, rhs: Self) -> Self {
                Self(self.0.saturating_add(rhs.0))
            }
            /// `self * k`, wrapping on overflow.
            pub const fn mul_int(self, k: i64) -> Self {
                Self(self.0.wrapping_mul(k))
            }
            /// `self / k`, truncated toward zero. Division by zero returns zero (the caller
            /// records the fault); `MIN / -1` wraps.
            pub const fn div_int(self, k: i64) -> Self {
                if k == 0 {
                    Self(0)
                } else {
                    Self(self.0.wrapping_div(k))
                }
            }
            /// `self * k` rounded to the nearest nanosecond (ties to even), saturating;
            /// a NaN result gives zero.
            pub fn mul_real(self, k: f64) -> Self {
                Self(f64_to_i64_round(self.0 as f64 * k))
            }
            /// `self / k` rounded to the nearest nanosecond (ties to even), saturating
            /// (division by 0.0 gives `MAX`/`MIN`); a NaN result (including `0 / 0.0`) gives zero.
            pub fn div_real(self, k: f64) -> Self {
                Self(f64_to_i64_round(self.0 as f64 / k))
            }
            /// Absolute value (wrapping: `MIN.abs() == MIN`).
            pub const fn abs(self) -> Self {
                Self(self.0.wrapping_abs())
            }
        }

        impl fmt::Display for $name {
            /// IEC literal form, e.g. `T#1h2m3s4ms`, `T#-5s`, `T#0s`.
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write_duration(f, $prefix, self.0)
            }
        }
    };
}

duration_type!(
    TIME,
    "T#",
    "IEC `TIME`: a signed duration with nanosecond resolution (the IEC default is `T#0s`).\n\n\
     Displays as an IEC literal (`T#1h2m3s4ms`, `T#-5s`, `T#0s`)."
);
duration_type!(
    LTIME,
    "LTIME#",
    "IEC `LTIME` (3rd edition): a signed 64-bit duration in nanoseconds (default `LTIME#0s`)."
);

impl From<TIME> for LTIME {
    fn from(t: TIME) -> Self {
        LTIME(t.0)
    }
}
impl From<LTIME> for TIME {
    fn from(t: LTIME) -> Self {
        TIME(t.0)
    }
}

fn write_duration(f: &mut fmt::Formatter<'_>, prefix: &str, ns: i64) -> fmt::Result {
    f.write_str(prefix)?;
    if ns == 0 {
        return f.write_str("0s");
    }
    if ns < 0 {
        f.write_str("-")?;
    }
    let mut rest = ns.unsigned_abs();
    const UNITS: [(u64, &str); 7] = [
        (NS_PER_DAY as u64, "d"),
        (NS_PER_H as u64, "h"),
        (NS_PER_MIN as u64, "m"),
        (NS_PER_S as u64, "s"),
        (NS_PER_MS as u64, "ms"),
        (NS_PER_US as u64, "us"),
        (1, "ns"),
    ];
    for (unit, name) in UNITS {
        let q = rest / unit;
        if q != 0 {
            write!(f, "{q}{name}")?;
        }
        rest %= unit;
    }
    Ok(())
}

/// Days since 1970-01-01 of the proleptic Gregorian date `y-m-d` (no validation).
pub(crate) fn days_from_civil(y: i64, m: u32, d: u32) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y.rem_euclid(400);
    let m = i64::from(m);
    let mp = if m > 2 { m - 3 } else { m + 9 };
    let doy = (153 * mp + 2) / 5 + i64::from(d) - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

/// The proleptic Gregorian date of `days` since 1970-01-01 (any `i64`).
pub(crate) fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = i128::from(days) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let y = yoe + era * 400;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = if m <= 2 { y + 1 } else { y };
    (
        y.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64,
        m,
        d,
    )
}

pub(crate) fn days_in_month(y: i64, m: u32) -> u32 {
    match m {
        1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
        4 | 6 | 9 | 11 => 30,
        2 if (y % 4 == 0 && y % 100 != 0) || y % 400 == 0 => 29,
        2 => 28,
        _ => 0,
    }
}

/// IEC `DATE`: a calendar date, stored as days since 1970-01-01 (default `D#1970-01-01`).
///
/// Displays as `D#2001-04-09`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DATE(
    /// Days since 1970-01-01 (negative before).
    pub i64,
);

impl DATE {
    /// The date `y-m-d` of the proleptic Gregorian calendar, or `None` if it does not exist.
    pub fn from_ymd(y: i32, m: u32, d: u32) -> Option<DATE> {
        if !(1..=12).contains(&m) || d == 0 || d > days_in_month(i64::from(y), m) {
            return None;
        }
        Some(DATE(days_from_civil(i64::from(y), m, d)))
    }
    /// `(year, month 1..=12, day 1..=31)`.
    pub fn ymd(self) -> (i64, u32, u32) {
        civil_from_days(self.0)
    }
}

impl fmt::Display for DATE {
    /// `D#2001-04-09`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (y, m, d) = self.ymd();
        write!(f, "D#{y:04}-{m:02}-{d:02}")
    }
}

/// IEC `TIME_OF_DAY`: nanoseconds since midnight, `0 ..= 24 h − 1 ns` (default `TOD#00:00:00`).
///
/// Displays as `TOD#11:36:15.2`. Values outside one day (only possible by writing the field
/// directly) are displayed modulo 24 h.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TOD(
    /// Nanoseconds since midnight.
    pub i64,
);

/// The IEC long name of [`TOD`].
pub type TIME_OF_DAY = TOD;

impl TOD {
    /// `h:m:s` plus `nanos`, or `None` unless `h < 24`, `m < 60`, `s < 60`, `nanos < 10⁹`.
    pub fn from_hms_nanos(h: u32, m: u32, s: u32, nanos: u32) -> Option<TOD> {
        if h >= 24 || m >= 60 || s >= 60 || nanos >= 1_000_000_000 {
            return None;
        }
        Some(TOD(i64::from(h) * NS_PER_H
            + i64::from(m) * NS_PER_MIN
            + i64::from(s) * NS_PER_S
            + i64::from(nanos)))
    }
    /// `h:m:s` (see [`TOD::from_hms_nanos`]).
    pub fn from_hms(h: u32, m: u32, s: u32) -> Option<TOD> {
        Self::from_hms_nanos(h, m, s, 0)
    }
    /// `(hours, minutes, seconds, nanoseconds)` of the value taken modulo 24 h.
    pub fn hms_nanos(self) -> (u32, u32, u32, u32) {
        let v = self.0.rem_euclid(NS_PER_DAY);
        (
            (v / NS_PER_H) as u32,
            (v % NS_PER_H / NS_PER_MIN) as u32,
            (v % NS_PER_MIN / NS_PER_S) as u32,
            (v % NS_PER_S) as u32,
        )
    }
}

fn write_hms(f: &mut fmt::Formatter<'_>, tod_ns: i64) -> fmt::Result {
    let (h, m, s, ns) = TOD(tod_ns).hms_nanos();
    write!(f, "{h:02}:{m:02}:{s:02}")?;
    if ns != 0 {
        let mut digits = 9;
        let mut frac = ns;
        while frac % 10 == 0 {
            frac /= 10;
            digits -= 1;
        }
        write!(f, ".{frac:0digits$}")?;
    }
    Ok(())
}

impl fmt::Display for TOD {
    /// `TOD#11:36:15.2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("TOD#")?;
        write_hms(f, self.0)
    }
}

/// IEC `DATE_AND_TIME`: nanoseconds since 1970-01-01-00:00:00 (default `DT#1970-01-01-00:00:00`).
///
/// Displays as `DT#2001-04-09-11:36:15.2`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DT(
    /// Nanoseconds since 1970-01-01T00:00:00.
    pub i64,
);

/// The IEC long name of [`DT`].
pub type DATE_AND_TIME = DT;

impl DT {
    /// The date and time `y-mo-d-h:mi:s` plus `nanos`, or `None` if a part is out of range or
    /// the instant is not representable (about years 1678..2261).
    pub fn from_parts(y: i32, mo: u32, d: u32, h: u32, mi: u32, s: u32, nanos: u32) -> Option<DT> {
        let date = DATE::from_ymd(y, mo, d)?;
        let tod = TOD::from_hms_nanos(h, mi, s, nanos)?;
        Self::checked_from_date_tod(date, tod)
    }
    /// `date` at `tod`, or `None` if not representable.
    pub fn checked_from_date_tod(date: DATE, tod: TOD) -> Option<DT> {
        // In i128: the first day of the range starts before `i64::MIN` ns, but
        // its later times of day fit (`DT#1677-09-21-00:12:45`).
        let ns = i128::from(date.0) * i128::from(NS_PER_DAY) + i128::from(tod.0);
        i64::try_from(ns).ok().map(DT)
    }
    /// `date` at `tod`, wrapping if not representable (IEC `CONCAT_DATE_TOD`).
    pub const fn from_date_tod(date: DATE, tod: TOD) -> DT {
        DT(date.0.wrapping_mul(NS_PER_DAY).wrapping_add(tod.0))
    }
    /// The date part (IEC `DT_TO_DATE`).
    pub const fn date(self) -> DATE {
        DATE(self.0.div_euclid(NS_PER_DAY))
    }
    /// The time-of-day part (IEC `DT_TO_TOD`).
    pub const fn tod(self) -> TOD {
        TOD(self.0.rem_euclid(NS_PER_DAY))
    }
}

impl fmt::Display for DT {
    /// `DT#2001-04-09-11:36:15.2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (y, m, d) = self.date().ymd();
        write!(f, "DT#{y:04}-{m:02}-{d:02}-")?;
        write_hms(f, self.tod().0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::format;

    #[test]
    fn time_display() {
        assert_eq!(format!("{}", TIME::ZERO), "T#0s");
        assert_eq!(format!("{}", TIME::from_secs(-5)), "T#-5s");
        let t = TIME(NS_PER_H + 2 * NS_PER_MIN + 3 * NS_PER_S + 4 * NS_PER_MS);
        assert_eq!(format!("{t}"), "T#1h2m3s4ms");
        assert_eq!(format!("{}", TIME(NS_PER_DAY + 1_001)), "T#1d1us1ns");
        assert_eq!(format!("{}", LTIME::from_ms(1500)), "LTIME#1s500ms");
        assert_eq!(
            format!("{}", TIME::MIN),
            "T#-106751d23h47m16s854ms775us808ns"
        );
    }

    #[test]
    fn time_arith_never_panics() {
        assert_eq!(TIME::MAX.wrapping_add(TIME(1)), TIME::MIN);
        assert_eq!(TIME::MIN.div_int(-1), TIME::MIN);
        assert_eq!(TIME::from_secs(1).div_int(0), TIME(0));
        assert_eq!(TIME::from_secs(1).mul_int(3), TIME::from_secs(3));
        assert_eq!(TIME::from_secs(1).mul_real(1.5), TIME::from_ms(1500));
        assert_eq!(TIME::from_secs(1).mul_real(f64::NAN), TIME(0));
        assert_eq!(TIME::from_secs(1).mul_real(1e30), TIME::MAX);
        assert_eq!(TIME::from_secs(1).div_real(0.0), TIME::MAX);
        assert_eq!(TIME::from_secs(-1).div_real(0.0), TIME::MIN);
        assert_eq!(TIME(0).div_real(0.0), TIME(0));
        assert_eq!(TIME::from_secs(3).div_real(2.0), TIME::from_ms(1500));
        assert_eq!(TIME::from_ms(i64::MAX), TIME::MAX);
        assert_eq!(TIME::from_ms(1234).as_ms(), 1234);
        assert_eq!(TIME::MIN.abs(), TIME::MIN);
    }

    #[test]
    fn dates() {
        assert_eq!(DATE::from_ymd(1970, 1, 1), Some(DATE(0)));
        let d = DATE::from_ymd(2001, 4, 9).unwrap();
        assert_eq!(format!("{d}"), "D#2001-04-09");
        assert_eq!(d.ymd(), (2001, 4, 9));
        assert_eq!(
            DATE::from_ymd(2000, 2, 29).map(|d| d.ymd()),
            Some((2000, 2, 29))
        );
        assert_eq!(DATE::from_ymd(1900, 2, 29), None);
        assert_eq!(DATE::from_ymd(2001, 13, 1), None);
        assert_eq!(DATE::from_ymd(2001, 4, 31), None);
        assert_eq!(DATE::from_ymd(1969, 12, 31), Some(DATE(-1)));
        // Round trip over a wide range of days.
        for days in (-800_000..800_000).step_by(997) {
            let (y, m, dd) = DATE(days).ymd();
            assert_eq!(DATE::from_ymd(y as i32, m, dd), Some(DATE(days)));
        }
        let _ = format!("{}", DATE(i64::MAX));
        let _ = format!("{}", DATE(i64::MIN));
    }

    #[test]
    fn tod_and_dt() {
        let t = TOD::from_hms_nanos(11, 36, 15, 200_000_000).unwrap();
        assert_eq!(format!("{t}"), "TOD#11:36:15.2");
        assert_eq!(format!("{}", TOD::default()), "TOD#00:00:00");
        assert_eq!(TOD::from_hms(24, 0, 0), None);
        let dt = DT::from_parts(2001, 4, 9, 11, 36, 15, 200_000_000).unwrap();
        assert_eq!(format!("{dt}"), "DT#2001-04-09-11:36:15.2");
        assert_eq!(dt.date(), DATE::from_ymd(2001, 4, 9).unwrap());
        assert_eq!(dt.tod(), t);
        assert_eq!(DT::from_date_tod(dt.date(), dt.tod()), dt);
        let before = DT::from_parts(1969, 12, 31, 23, 0, 0, 0).unwrap();
        assert_eq!(format!("{before}"), "DT#1969-12-31-23:00:00");
        assert_eq!(DT::from_parts(3000, 1, 1, 0, 0, 0, 0), None);
        let _ = format!("{}", DT(i64::MIN));
    }
}
