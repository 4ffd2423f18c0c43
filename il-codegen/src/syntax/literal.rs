//! Values of IL literals: integers, reals, durations, dates, strings.
//!
//! Each function takes the literal's text (without the type prefix and `#`)
//! and returns its value or a message in a PLC engineer's words.

/// `123`, `1_000`, `16#FF`, `2#1010_1010`, `8#777`, with an optional sign.
pub fn parse_int(text: &str) -> Result<i128, String> {
    let (neg, body) = split_sign(text);
    let (base, digits) = match body.split_once('#') {
        Some((b, d)) => {
            let base = match b {
                "2" => 2,
                "8" => 8,
                "16" => 16,
                _ => {
                    return Err(format!(
                        "`{b}#` is not a base: IEC integers are written in base 2#, 8#, 10 or 16#"
                    ));
                }
            };
            (base, d)
        }
        None => (10, body),
    };
    if digits.is_empty() {
        return Err("this number has no digits".into());
    }
    if digits.starts_with('_') || digits.ends_with('_') || digits.contains("__") {
        return Err("`_` may only separate digits".into());
    }
    let mut v: i128 = 0;
    for c in digits.chars() {
        if c == '_' {
            continue;
        }
        let d = c
            .to_digit(base)
            .ok_or_else(|| format!("`{c}` is not a digit in base {base}"))?;
        v = v
            .checked_mul(base as i128)
            .and_then(|v| v.checked_add(d as i128))
            .ok_or_else(|| "this number is too large for any IEC integer type".to_string())?;
    }
    if v > u64::MAX as i128 {
        return Err(
            "this number is too large for any IEC integer type (the largest is ULINT)".into(),
        );
    }
    Ok(if neg { -v } else { v })
}

fn split_sign(text: &str) -> (bool, &str) {
    if let Some(r) = text.strip_prefix('-') {
        (true, r)
    } else if let Some(r) = text.strip_prefix('+') {
        (false, r)
    } else {
        (false, text)
    }
}

/// `1.5`, `-1.0E-3`, `1_000.5`: returns the value (the text is kept by the caller).
pub fn parse_real(text: &str) -> Result<f64, String> {
    let cleaned: String = text.chars().filter(|&c| c != '_').collect();
    cleaned
        .parse::<f64>()
        .map_err(|_| format!("`{text}` is not a valid REAL number"))
}

const NS_PER: [(&str, i128); 7] = [
    ("d", 86_400_000_000_000),
    ("h", 3_600_000_000_000),
    ("ms", 1_000_000),
    ("us", 1_000),
    ("ns", 1),
    ("m", 60_000_000_000),
    ("s", 1_000_000_000),
];

/// The text after `T#`: `1h_15m_30s_60ms`, `-5s`, `1.5s`, `500ms`. Nanoseconds.
pub fn parse_duration(text: &str) -> Result<i64, String> {
    let (neg, body) = split_sign(text);
    if body.is_empty() {
        return Err("a duration needs a value and a unit, e.g. `T#500ms`".into());
    }
    let b = body.as_bytes();
    let mut i = 0;
    let mut total: i128 = 0;
    let mut had_fraction = false;
    let mut units = 0;
    while i < b.len() {
        if had_fraction {
            return Err("only the last unit of a duration may have a fraction (`T#1.5s`)".into());
        }
        let start = i;
        while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'_') {
            i += 1;
        }
        let int_part = &body[start..i];
        let mut frac = "";
        if i < b.len() && b[i] == b'.' {
            i += 1;
            let fs = i;
            while i < b.len() && b[i].is_ascii_digit() {
                i += 1;
            }
            frac = &body[fs..i];
            had_fraction = true;
        }
        if int_part.trim_matches('_').is_empty() {
            return Err(format!(
                "`{body}` is not a duration: expected a number before each unit, e.g. `T#1h_30m`"
            ));
        }
        let us = i;
        while i < b.len() && b[i].is_ascii_alphabetic() {
            i += 1;
        }
        let unit = body[us..i].to_ascii_lowercase();
        let Some(&(_, factor)) = NS_PER.iter().find(|(u, _)| *u == unit) else {
            return Err(if unit.is_empty() {
                format!(
                    "`{}` has no unit: write d, h, m, s, ms, us or ns after the number",
                    &body[start..i]
                )
            } else {
                format!("`{unit}` is not a unit of time: use d, h, m, s, ms, us or ns")
            });
        };
        units += 1;
        let n =
            parse_int(int_part.trim_matches('_')).map_err(|e| format!("in this duration: {e}"))?;
        total = total.saturating_add(n.saturating_mul(factor));
        if !frac.is_empty() {
            let digits = frac.len().min(18);
            let f: i128 = frac[..digits].parse().unwrap_or(0);
            let scale = 10i128.pow(digits as u32);
            total = total.saturating_add(f * factor / scale);
        }
        if i < b.len() && b[i] == b'_' {
            i += 1;
        }
    }
    if units == 0 {
        return Err("a duration needs a value and a unit, e.g. `T#500ms`".into());
    }
    let total = if neg { -total } else { total };
    i64::try_from(total)
        .map_err(|_| "this duration is too long (the limit is about 292 years)".to_string())
}

/// Days since 1970-01-01 of a proleptic Gregorian date.
pub fn days_from_civil(y: i64, m: u32, d: u32) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = if y >= 0 { y } else { y - 399 } / 400;
    let yoe = y - era * 400;
    let mp = (m as i64 + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d as i64 - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

fn days_in_month(y: i64, m: u32) -> u32 {
    match m {
        1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
        4 | 6 | 9 | 11 => 30,
        _ if (y % 4 == 0 && y % 100 != 0) || y % 400 == 0 => 29,
        _ => 28,
    }
}

fn num(s: &str, what: &str) -> Result<i64, String> {
    if s.is_empty() || !s.bytes().all(|c| c.is_ascii_digit()) || s.len() > 9 {
        return Err(format!("`{s}` is not a valid {what}"));
    }
    Ok(s.parse().unwrap_or(0))
}

/// `2001-04-09` → days since 1970-01-01.
pub fn parse_date(text: &str) -> Result<i64, String> {
    let parts: Vec<&str> = text.split('-').collect();
    if parts.len() != 3 {
        return Err(format!(
            "`{text}` is not a date: write year-month-day, e.g. `D#2024-01-31`"
        ));
    }
    let y = num(parts[0], "year")?;
    let m = num(parts[1], "month")? as u32;
    let d = num(parts[2], "day")? as u32;
    if !(1..=12).contains(&m) {
        return Err(format!("month {m} does not exist (1 to 12)"));
    }
    if d < 1 || d > days_in_month(y, m) {
        return Err(format!("day {d} does not exist in month {m} of {y}"));
    }
    Ok(days_from_civil(y, m, d))
}

/// `11:36:15.20` → nanoseconds since midnight.
pub fn parse_tod(text: &str) -> Result<i64, String> {
    let parts: Vec<&str> = text.split(':').collect();
    if parts.len() != 3 {
        return Err(format!(
            "`{text}` is not a time of day: write hours:minutes:seconds, e.g. `TOD#14:30:00`"
        ));
    }
    let h = num(parts[0], "hour")?;
    let m = num(parts[1], "minute")?;
    let (s, frac) = match parts[2].split_once('.') {
        Some((s, f)) => (s, f),
        None => (parts[2], ""),
    };
    let s = num(s, "second")?;
    if !frac.is_empty() && !frac.bytes().all(|c| c.is_ascii_digit()) {
        return Err(format!("`{frac}` is not a fraction of a second"));
    }
    if h > 23 {
        return Err(format!("hour {h} does not exist (0 to 23)"));
    }
    if m > 59 {
        return Err(format!("minute {m} does not exist (0 to 59)"));
    }
    if s > 59 {
        return Err(format!("second {s} does not exist (0 to 59)"));
    }
    let mut ns = ((h * 60 + m) * 60 + s) * 1_000_000_000;
    if !frac.is_empty() {
        let f = &frac[..frac.len().min(9)];
        ns += f.parse::<i64>().unwrap_or(0) * 10i64.pow(9 - f.len() as u32);
    }
    Ok(ns)
}

/// `2001-04-09-11:36:15.20` → nanoseconds since 1970-01-01T00:00:00.
pub fn parse_dt(text: &str) -> Result<i64, String> {
    // The date has exactly two '-'; the third separates date and time.
    let mut dashes = text.match_indices('-').map(|(i, _)| i);
    let split = dashes.nth(2).ok_or_else(|| {
        format!("`{text}` is not a date and time: write year-month-day-hours:minutes:seconds, e.g. `DT#2024-01-31-14:30:00`")
    })?;
    let days = parse_date(&text[..split])?;
    let tod = parse_tod(&text[split + 1..])?;
    // In i128: DT's first day starts before i64::MIN ns, its later times fit.
    let ns = i128::from(days) * 86_400_000_000_000 + i128::from(tod);
    i64::try_from(ns).map_err(|_| {
        "this date and time is out of range (DT holds DT#1677-09-21-00:12:44 to DT#2262-04-11-23:47:16)"
            .to_string()
    })
}

/// The contents of a string literal (between the quotes), `$` escapes resolved.
/// `wide`: `"..."` (WSTRING, `$hhhh`) vs `'...'` (STRING, `$hh`).
pub fn unescape(body: &str, wide: bool) -> Result<String, String> {
    let mut out = String::with_capacity(body.len());
    let mut it = body.chars();
    while let Some(c) = it.next() {
        if c != '$' {
            out.push(c);
            continue;
        }
        let Some(e) = it.next() else {
            return Err("a `$` at the end of a string must be written `$$`".into());
        };
        match e {
            '$' => out.push('$'),
            '\'' => out.push('\''),
            '"' => out.push('"'),
            'L' | 'l' | 'N' | 'n' => out.push('\n'),
            'P' | 'p' => out.push('\x0C'),
            'R' | 'r' => out.push('\r'),
            'T' | 't' => out.push('\t'),
            h if h.is_ascii_hexdigit() => {
                let n = if wide { 4 } else { 2 };
                let mut hex = String::from(h);
                for _ in 1..n {
                    match it.next() {
                        Some(x) if x.is_ascii_hexdigit() => hex.push(x),
                        _ => {
                            return Err(format!(
                                "`$` followed by a hex code needs {n} hex digits here"
                            ));
                        }
                    }
                }
                let v = u32::from_str_radix(&hex, 16).unwrap_or(0);
                out.push(char::from_u32(v).unwrap_or('\u{FFFD}'));
            }
            other => {
                return Err(format!(
                    "`${other}` is not a string escape: use $$, $', $\", $L, $N, $P, $R, $T or $ and hex digits"
                ));
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ints() {
        assert_eq!(parse_int("1_000"), Ok(1000));
        assert_eq!(parse_int("-1"), Ok(-1));
        assert_eq!(parse_int("16#FF"), Ok(255));
        assert_eq!(parse_int("16#a5"), Ok(165));
        assert_eq!(parse_int("2#1010_1010"), Ok(170));
        assert_eq!(parse_int("8#17"), Ok(15));
        assert!(parse_int("3#12").is_err());
        assert!(parse_int("2#102").is_err());
        assert!(parse_int("1__0").is_err());
        assert!(parse_int("99999999999999999999999").is_err());
    }

    #[test]
    fn durations() {
        assert_eq!(parse_duration("500ms"), Ok(500_000_000));
        assert_eq!(
            parse_duration("1h_15m_30s_60ms"),
            Ok(((3600 + 15 * 60 + 30) * 1000 + 60) * 1_000_000)
        );
        assert_eq!(parse_duration("-5s"), Ok(-5_000_000_000));
        assert_eq!(parse_duration("1.5s"), Ok(1_500_000_000));
        assert_eq!(parse_duration("1d2h"), Ok(26 * 3_600_000_000_000));
        assert_eq!(parse_duration("10US"), Ok(10_000));
        assert_eq!(parse_duration("3ns"), Ok(3));
        assert!(parse_duration("25x").is_err());
        assert!(parse_duration("1.5s3ms").is_err());
        assert!(parse_duration("").is_err());
        assert!(parse_duration("5").is_err());
        assert!(parse_duration("999999999d").is_err());
    }

    #[test]
    fn dates() {
        assert_eq!(parse_date("1970-01-01"), Ok(0));
        assert_eq!(parse_date("2001-04-09"), Ok(11_421));
        assert_eq!(parse_date("2000-02-29"), Ok(11_016));
        assert!(parse_date("2001-13-40").is_err());
        assert!(parse_date("2001-02-29").is_err());
        assert_eq!(
            parse_tod("11:36:15.20"),
            Ok(((11 * 60 + 36) * 60 + 15) * 1_000_000_000 + 200_000_000)
        );
        assert!(parse_tod("24:00:00").is_err());
        assert_eq!(parse_dt("1970-01-02-00:00:01"), Ok(86_401_000_000_000));
        assert!(parse_dt("2001-04-09").is_err());
    }

    #[test]
    fn strings() {
        assert_eq!(parse_real("1.0E-3"), Ok(0.001));
        assert_eq!(unescape("a$$b$'c$N$41", false), Ok("a$b'c\nA".into()));
        assert_eq!(unescape("$0041", true), Ok("A".into()));
        assert!(unescape("$q", false).is_err());
        assert!(unescape("$", false).is_err());
    }
}
