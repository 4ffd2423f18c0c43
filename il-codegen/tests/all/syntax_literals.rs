//! Every literal and direct-address form of `docs/semantics.md` (sections
//! "Literals" and "Direct addresses and the process image").

use crate::syntax_common::*;

fn kind(text: &str) -> LitKind {
    ld_lit(text).kind
}

fn prefix(text: &str) -> Option<String> {
    ld_lit(text).type_prefix.map(|p| p.name.to_string())
}

#[test]
fn integers() {
    assert_eq!(kind("0"), LitKind::Int(IntValue::new(0)));
    assert_eq!(kind("1_000_000"), LitKind::Int(IntValue::new(1_000_000)));
    assert_eq!(kind("-1"), LitKind::Int(IntValue::new(-1)));
    assert_eq!(kind("+7"), LitKind::Int(IntValue::new(7)));
    assert_eq!(kind("2#1010_1010"), LitKind::Int(IntValue::new(170)));
    assert_eq!(kind("8#777"), LitKind::Int(IntValue::new(511)));
    assert_eq!(kind("16#FF"), LitKind::Int(IntValue::new(255)));
    assert_eq!(kind("16#ff"), LitKind::Int(IntValue::new(255)));
}

#[test]
fn reals() {
    assert!(
        matches!(kind("1.5"), LitKind::Real { value, ref text } if value == 1.5 && &**text == "1.5")
    );
    assert!(matches!(kind("1.0E-3"), LitKind::Real { value, .. } if value == 0.001));
    assert!(matches!(kind("-2.5e+2"), LitKind::Real { value, .. } if value == -250.0));
    assert!(matches!(kind("6.2831854"), LitKind::Real { .. }));
}

#[test]
fn booleans_and_typed_literals() {
    assert_eq!(kind("TRUE"), LitKind::Bool(true));
    assert_eq!(kind("false"), LitKind::Bool(false));
    assert_eq!(kind("INT#-5"), LitKind::Int(IntValue::new(-5)));
    assert_eq!(prefix("INT#-5").as_deref(), Some("INT"));
    assert_eq!(kind("UINT#16#A5"), LitKind::Int(IntValue::new(165)));
    assert_eq!(kind("BOOL#1"), LitKind::Bool(true));
    assert_eq!(kind("BOOL#0"), LitKind::Bool(false));
    assert_eq!(kind("bool#true"), LitKind::Bool(true));
    assert_eq!(prefix("bool#true").as_deref(), Some("bool"));
    assert!(matches!(kind("REAL#1.5"), LitKind::Real { value, .. } if value == 1.5));
    assert!(matches!(kind("LREAL#1"), LitKind::Int(n) if n.get() == 1));
    assert_eq!(
        kind("STRING#'x'"),
        LitKind::String {
            value: "x".into(),
            wide: false
        }
    );
    assert_eq!(prefix("STRING#'x'").as_deref(), Some("STRING"));
}

#[test]
fn durations() {
    let t = |nanos| LitKind::Time { nanos, long: false };
    assert_eq!(kind("T#500ms"), t(500_000_000));
    assert_eq!(kind("t#10ms"), t(10_000_000));
    assert_eq!(
        kind("TIME#1h_15m_30s_60ms"),
        t((4530 * 1000 + 60) * 1_000_000)
    );
    assert_eq!(kind("T#-5s"), t(-5_000_000_000));
    assert_eq!(kind("T#1.5s"), t(1_500_000_000));
    assert_eq!(
        kind("T#1d2h3m4s5ms6us7ns"),
        t(((((26 * 60 + 3) * 60 + 4) * 1000 + 5) * 1000 + 6) * 1000 + 7)
    );
    assert_eq!(
        kind("LT#1s"),
        LitKind::Time {
            nanos: 1_000_000_000,
            long: true
        }
    );
    assert_eq!(
        kind("LTIME#1us"),
        LitKind::Time {
            nanos: 1_000,
            long: true
        }
    );
    assert_eq!(prefix("T#1s"), None);
}

#[test]
fn dates_and_times_of_day() {
    assert_eq!(kind("D#1970-01-01"), LitKind::Date(0));
    assert_eq!(kind("DATE#2001-04-09"), LitKind::Date(11_421));
    assert_eq!(
        kind("TOD#11:36:15.20"),
        LitKind::Tod(((11 * 60 + 36) * 60 + 15) * 1_000_000_000 + 200_000_000)
    );
    assert_eq!(kind("TIME_OF_DAY#00:00:01"), LitKind::Tod(1_000_000_000));
    assert_eq!(
        kind("DT#1970-01-02-00:00:00"),
        LitKind::Dt(86_400_000_000_000)
    );
    assert_eq!(
        kind("DATE_AND_TIME#2001-04-09-11:36:15.20"),
        LitKind::Dt(11_421 * 86_400_000_000_000 + 41_775_200_000_000)
    );
}

#[test]
fn date_and_time_covers_the_whole_range_of_dt() {
    // DT counts i64 nanoseconds from 1970: its first day starts before
    // i64::MIN, but its later times of day fit and are accepted.
    assert_eq!(
        kind("DT#1677-09-21-00:12:45"),
        LitKind::Dt((-106_752i128 * 86_400_000_000_000 + 765_000_000_000) as i64)
    );
    assert_eq!(
        kind("DT#2262-04-11-23:47:16"),
        LitKind::Dt(106_751 * 86_400_000_000_000 + 85_636_000_000_000)
    );
    for out in ["DT#1677-09-21-00:12:43", "DT#2262-04-11-23:47:17"] {
        let m = err1(
            &format!("PROGRAM p\n  LD {out}\nEND_PROGRAM\n"),
            "IL0020",
            2,
            6,
        );
        assert!(
            m.contains("out of range") && m.contains("DT#1677-09-21-00:12:44"),
            "{m}"
        );
    }
}

#[test]
fn strings() {
    assert_eq!(
        kind("'abc'"),
        LitKind::String {
            value: "abc".into(),
            wide: false
        }
    );
    assert_eq!(
        kind("''"),
        LitKind::String {
            value: "".into(),
            wide: false
        }
    );
    assert_eq!(
        kind("'a$$b$'c$N$R$T$L$P$41'"),
        LitKind::String {
            value: "a$b'c\n\r\t\n\x0cA".into(),
            wide: false
        }
    );
    assert_eq!(
        kind("\"wide $\"q$\" $0041\""),
        LitKind::String {
            value: "wide \"q\" A".into(),
            wide: true
        }
    );
    assert_eq!(
        kind("'(* not a comment *)'"),
        LitKind::String {
            value: "(* not a comment *)".into(),
            wide: false
        }
    );
}

#[test]
fn enum_literals() {
    match kind("Color#Red") {
        LitKind::Enum(e) => {
            assert!(e.ty.is("color") && e.value.is("RED"));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn direct_addresses() {
    let addr = |text: &str| match one(&format!("LD {text}")) {
        InstrKind::Load {
            operand: Operand::Addr(a),
            ..
        } => (a.area, a.size, a.path),
        other => panic!("{other:?}"),
    };
    assert_eq!(addr("%IX1.0"), (Area::Input, AddrSize::X, vec![1, 0]));
    assert_eq!(addr("%Q0.0"), (Area::Output, AddrSize::Default, vec![0, 0]));
    assert_eq!(addr("%md4.23"), (Area::Memory, AddrSize::D, vec![4, 23]));
    assert_eq!(addr("%IB7"), (Area::Input, AddrSize::B, vec![7]));
    assert_eq!(addr("%QW5"), (Area::Output, AddrSize::W, vec![5]));
    assert_eq!(addr("%ML2"), (Area::Memory, AddrSize::L, vec![2]));
    assert_eq!(addr("%IX1.2.3"), (Area::Input, AddrSize::X, vec![1, 2, 3]));
    assert_eq!(addr("%i0"), (Area::Input, AddrSize::Default, vec![0]));
}

// ------------------------------------------------------------ refused

fn body_err(line: &str, code: &str, col: usize) -> String {
    err1(&format!("PROGRAM p\n{line}\nEND_PROGRAM"), code, 2, col)
}

#[test]
fn malformed_numbers() {
    let m = body_err("LD -12e-5", "IL0018", 4);
    assert_eq!(
        m,
        "`-12e-5` is not an IEC real literal: a REAL needs a decimal point"
    );
    let f = SourceFile::new("t", "PROGRAM p\nLD -12e-5\nEND_PROGRAM");
    assert_eq!(parse(&f).1[0].help.as_deref(), Some("write -12.0e-5"));
    assert!(body_err("LD 16#FG", "IL0018", 4).contains("is not a digit in base 16"));
    assert!(body_err("LD 3#12", "IL0018", 4).contains("is not a base"));
    assert_eq!(body_err("LD 25x", "IL0018", 4), "`25x` is not a number");
    assert_eq!(
        body_err("LD BOOL#2", "IL0018", 4),
        "a BOOL literal is 0, 1, TRUE or FALSE"
    );
    assert!(body_err("LD 99999999999999999999999", "IL0018", 4).contains("too large"));
}

#[test]
fn malformed_durations_and_dates() {
    assert_eq!(
        body_err("LD T#25x", "IL0019", 4),
        "`x` is not a unit of time: use d, h, m, s, ms, us or ns"
    );
    assert!(body_err("LD T#", "IL0019", 4).contains("needs a value and a unit"));
    assert_eq!(
        body_err("LD D#2001-13-40", "IL0020", 4),
        "month 13 does not exist (1 to 12)"
    );
    assert_eq!(
        body_err("LD D#2001-02-29", "IL0020", 4),
        "day 29 does not exist in month 2 of 2001"
    );
    assert_eq!(
        body_err("LD TOD#25:00:00", "IL0020", 4),
        "hour 25 does not exist (0 to 23)"
    );
    assert!(body_err("LD DT#2001-01-01", "IL0020", 4).contains("is not a date and time"));
}

/// Forms the lexer accepted before it shared the runtime's parser
/// (`il_std::literal`), which follows the IEC grammar: based integers have no
/// sign, `_` only between digits, duration units in descending order.
#[test]
fn forms_outside_the_iec_grammar_are_refused() {
    assert_eq!(
        body_err("LD -16#FF", "IL0018", 4),
        "`-16#FF`: a based integer (`16#FF`) cannot have a sign"
    );
    assert_eq!(
        body_err("LD 1__0.5", "IL0018", 4),
        "`1__0.5`: `_` may only separate digits"
    );
    assert_eq!(
        body_err("LD 1.5_", "IL0018", 4),
        "`1.5_`: `_` may only separate digits"
    );
    assert_eq!(
        body_err("LD T#1s1h", "IL0019", 4),
        "`1s1h`: units must go from days down to nanoseconds, each at most once"
    );
    // Only the most significant unit may overflow (`T#61m` is fine).
    assert_eq!(
        body_err("LD T#1h_61m", "IL0019", 4),
        "`61m` in `1h_61m`: after a larger unit it must be below 60; only the first unit may overflow (as in `T#90m`)"
    );
    assert_eq!(
        body_err("LD T#1d24h", "IL0019", 4),
        "`24h` in `1d24h`: after a larger unit it must be below 24; only the first unit may overflow (as in `T#90m`)"
    );
    assert_eq!(
        body_err("LD T#1s_", "IL0019", 4),
        "`1s_`: a duration cannot end with `_`"
    );
    assert_eq!(
        body_err("LD T#1.s", "IL0019", 4),
        "`1.s`: expected digits after the decimal point"
    );
    assert_eq!(
        body_err("LD T#5_s", "IL0019", 4),
        "`5_s`: `_` may only separate digits"
    );
    assert_eq!(
        body_err("LD TOD#12:00:00.", "IL0020", 4),
        "`12:00:00.`: expected digits after the decimal point"
    );
}

#[test]
fn malformed_strings() {
    assert_eq!(
        body_err("LD 'abc", "IL0021", 4),
        "this string is not closed on its line"
    );
    assert!(body_err("LD 'a$qb'", "IL0021", 4).contains("`$q` is not a string escape"));
}

#[test]
fn malformed_addresses() {
    let m = body_err("LD %MF0", "IL0022", 4);
    assert_eq!(
        m,
        "`F` is not an IEC address size: %IF/%QF/%MF float addresses are a vendor extension"
    );
    assert_eq!(
        body_err("LD %Z1", "IL0022", 4),
        "`%Z1` is not a direct address: the area must be I, Q or M"
    );
    assert_eq!(
        body_err("LD %IX", "IL0022", 4),
        "expected a number in this direct address, e.g. `%IX0.1`"
    );
}
