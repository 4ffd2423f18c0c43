//! The messages of refused literals. The parsing is `il_std::literal`'s (the
//! runtime's `STRING_TO_*` and the compiler read literals the same way); here
//! its [`LiteralError`] becomes a sentence that quotes the source.

use il_std::literal::LiteralError;

const UNITS: &str = "d, h, m, s, ms, us or ns";

/// The diagnostic message for `err`, returned by the `il_std::literal`
/// parser given `text` (the literal without its type prefix and `#`).
pub fn literal_message(err: LiteralError, text: &str) -> String {
    use LiteralError::*;
    // Offsets come from the parser of this very text; `get` keeps a wrong
    // pairing of error and text from panicking.
    let part = |start: usize, end: usize| text.get(start..end).unwrap_or(text);
    match err {
        EmptyNumber | SignedBasedInt | BadDigit { .. } | BadUnderscore | IntTooLarge => {
            format!("`{text}`: {err}")
        }
        BadBase => {
            let base = text.split('#').next().unwrap_or("");
            let base = base.trim_start_matches(['-', '+']);
            format!(
                "`{text}`: `{base}#` is not a base: IEC integers are written in base 2#, 8#, 10 or 16#"
            )
        }
        BadReal => format!("`{text}` is not a valid REAL number"),
        DurationNeedsNumber => format!(
            "`{}` is not a duration: expected a number before each unit, e.g. `T#1h_30m`",
            text.trim_start_matches(['-', '+'])
        ),
        MissingDurationUnit { start, end } => format!(
            "`{}` has no unit: write {UNITS} after the number",
            part(start, end)
        ),
        BadDurationUnit { start, end } => format!(
            "`{}` is not a unit of time: use {UNITS}",
            part(start, end).to_ascii_lowercase()
        ),
        DurationUnitOverflow { start, end, limit } => format!(
            "`{}` in `{text}`: after a larger unit it must be below {limit}; only the first unit may overflow (as in `T#90m`)",
            part(start, end)
        ),
        DurationUnitOrder | TrailingUnderscore | MissingFractionDigits => {
            format!("`{text}`: {err}")
        }
        BadDateShape => {
            format!("`{text}` is not a date: write year-month-day, e.g. `D#2024-01-31`")
        }
        BadTimeShape => {
            // In a DT, the time of day is what follows the date's two `-`.
            let time = text
                .match_indices('-')
                .nth(2)
                .map_or(text, |(i, _)| &text[i + 1..]);
            format!(
                "`{time}` is not a time of day: write hours:minutes:seconds, e.g. `TOD#14:30:00`"
            )
        }
        BadDateTimeShape => format!(
            "`{text}` is not a date and time: write year-month-day-hours:minutes:seconds, e.g. `DT#2024-01-31-14:30:00`"
        ),
        BadField { field, start, end } => {
            format!("`{}` is not a valid {}", part(start, end), field.name())
        }
        BadFraction { start, end } => {
            format!("`{}` is not a fraction of a second", part(start, end))
        }
        // The rest name their values, or need no quote of the text.
        _ => err.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use il_std::literal::{parse_date, parse_dt, parse_duration, parse_int, parse_tod};

    fn msg<T: std::fmt::Debug>(r: Result<T, LiteralError>, text: &str) -> String {
        literal_message(r.unwrap_err(), text)
    }

    #[test]
    fn messages_quote_the_source() {
        let int = |t: &str| msg(parse_int(t), t);
        assert_eq!(int("16#FG"), "`16#FG`: `G` is not a digit in base 16");
        assert_eq!(
            int("-3#12"),
            "`-3#12`: `3#` is not a base: IEC integers are written in base 2#, 8#, 10 or 16#"
        );
        assert_eq!(int("1__0"), "`1__0`: `_` may only separate digits");
        let dur = |t: &str| msg(parse_duration(t), t);
        assert_eq!(
            dur("-5X"),
            "`x` is not a unit of time: use d, h, m, s, ms, us or ns"
        );
        assert_eq!(
            dur("1h5"),
            "`5` has no unit: write d, h, m, s, ms, us or ns after the number"
        );
        assert_eq!(
            dur("-1h_s"),
            "`1h_s` is not a duration: expected a number before each unit, e.g. `T#1h_30m`"
        );
        assert_eq!(
            msg(parse_date("2001-x-01"), "2001-x-01"),
            "`x` is not a valid month"
        );
        assert_eq!(
            msg(parse_tod("12:00:00.5x"), "12:00:00.5x"),
            "`5x` is not a fraction of a second"
        );
        let dt = "2001-01-01-12:00";
        assert_eq!(
            msg(parse_dt(dt), dt),
            "`12:00` is not a time of day: write hours:minutes:seconds, e.g. `TOD#14:30:00`"
        );
        let dt = "2001-01-01-1x:00:00";
        assert_eq!(msg(parse_dt(dt), dt), "`1x` is not a valid hour");
    }
}
