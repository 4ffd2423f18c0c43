//! Dates, times of day and dates with times.

use super::*;

/// A date or time field at `start..end` of `text`: 1 to 9 decimal digits (so that it fits).
pub(super) fn field(
    text: &str,
    start: usize,
    end: usize,
    field: DateField,
) -> Result<u32, LiteralError> {
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
