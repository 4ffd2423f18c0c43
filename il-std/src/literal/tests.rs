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
    // Only the most significant unit may overflow.
    assert_eq!(parse_duration("61m"), Ok(61 * 60 * 1000 * ms));
    assert_eq!(
        parse_duration("1h_59m_59s_999ms"),
        Ok(((3600 + 59 * 60 + 59) * 1000 + 999) * ms)
    );
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
        (
            "1h_61m",
            DurationUnitOverflow {
                start: 3,
                end: 6,
                limit: 60,
            },
        ),
        (
            "1d24h",
            DurationUnitOverflow {
                start: 2,
                end: 5,
                limit: 24,
            },
        ),
        (
            "-2m60s",
            DurationUnitOverflow {
                start: 3,
                end: 6,
                limit: 60,
            },
        ),
        (
            "1s1000ms",
            DurationUnitOverflow {
                start: 2,
                end: 8,
                limit: 1000,
            },
        ),
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
