//! Durations: `T#1d2h3m4s5ms`, with a fraction on the last unit.

use super::*;

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
        // What one unit of the next larger kind holds: 24 h, 60 m, 1000 ms ...
        const LIMITS: [u32; 7] = [u32::MAX, 24, 60, 60, 1000, 1000, 1000];
        if last_rank != usize::MAX && int_part >= i128::from(LIMITS[rank]) {
            return Err(LiteralError::DurationUnitOverflow {
                start,
                end: i,
                limit: LIMITS[rank],
            });
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
