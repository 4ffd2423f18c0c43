use super::*;

#[test]
fn function_blocks_are_in_the_table() {
    let ton = lookup_fb("ton").unwrap();
    assert_eq!(ton.name, "TON");
    let names = |ps: &[FbParam]| {
        ps.iter()
            .map(|p| (p.name, p.ty))
            .collect::<std::vec::Vec<_>>()
    };
    assert_eq!(names(ton.inputs), [("IN", Elem::BOOL), ("PT", Elem::TIME)]);
    assert_eq!(names(ton.outputs), [("Q", Elem::BOOL), ("ET", Elem::TIME)]);
    assert_eq!(lookup_fb("CTUD_UDINT").unwrap().outputs.len(), 3);
    // 26 IEC blocks and the 7 of the Modicon M221 (`M221_C` ... `M221_SYS`).
    assert_eq!(FB_SIGNATURES.len(), 33);
    assert_eq!(lookup_fb("m221_sbr").unwrap().outputs.len(), 0);
    // The 3rd edition's typed counters, every one of them.
    for fb in ["CTU", "CTD", "CTUD"] {
        for ty in ["", "_INT", "_DINT", "_LINT", "_UDINT", "_ULINT"] {
            let name = std::format!("{fb}{ty}");
            let sig = lookup_fb(&name).unwrap_or_else(|| panic!("{name}"));
            let cv = sig.outputs.iter().find(|p| p.name == "CV").unwrap();
            let want = if ty.is_empty() { "INT" } else { &ty[1..] };
            assert_eq!(cv.ty.name(), want, "{name}");
        }
    }
    assert!(lookup_fb("ADD").is_none());
}

#[test]
fn faults_are_in_the_table() {
    use Elem::*;
    let f = |name: &str, args: &[Elem]| lookup(name).unwrap().fault_for(args);
    assert_eq!(f("DIV", &[INT, INT]), Some(FaultKind::DivisionByZero));
    assert_eq!(f("MOD", &[UDINT, UDINT]), Some(FaultKind::DivisionByZero));
    assert_eq!(f("DIV", &[REAL, REAL]), None, "a REAL divisor never faults");
    assert_eq!(
        f("DIV_TIME", &[TIME, SINT]),
        Some(FaultKind::DivisionByZero)
    );
    assert_eq!(f("DIV_TIME", &[TIME, LREAL]), None);
    assert_eq!(f("MUL_TIME", &[TIME, INT]), None);
    assert_eq!(
        f("REAL_TO_INT", &[REAL]),
        Some(FaultKind::ConversionOutOfRange)
    );
    assert_eq!(
        f("LREAL_TO_WORD", &[LREAL]),
        Some(FaultKind::ConversionOutOfRange)
    );
    assert_eq!(
        f("REAL_TRUNC_UINT", &[REAL]),
        Some(FaultKind::ConversionOutOfRange)
    );
    assert_eq!(f("TRUNC", &[LREAL]), Some(FaultKind::ConversionOutOfRange));
    assert_eq!(f("REAL_TO_BOOL", &[REAL]), None);
    assert_eq!(f("REAL_TO_TIME", &[REAL]), None);
    assert_eq!(f("INT_TO_REAL", &[INT]), None);
    assert_eq!(f("DINT_TO_INT", &[DINT]), None, "integer conversions wrap");
    assert_eq!(
        f("CONCAT", &[STRING, STRING]),
        Some(FaultKind::StringOverflow)
    );
    assert_eq!(f("MUX", &[INT, INT, INT]), Some(FaultKind::InvalidArgument));
    // Exactly these hand-written functions may fault (the conversions are above).
    let faulting: std::vec::Vec<&str> = SIGNATURES
        .iter()
        .filter(|s| s.fault.is_some() && !s.name.contains("_TO_") && !s.name.contains("_TRUNC_"))
        .map(|s| s.name)
        .collect();
    assert_eq!(
        faulting,
        [
            "DIV", "MOD", "TRUNC", "MUX", "CONCAT", "INSERT", "REPLACE", "DIV_TIME"
        ]
    );
}

#[test]
fn lookup_works() {
    assert_eq!(lookup("limit").map(|s| s.params.len()), Some(3));
    let l = lookup("LIMIT").unwrap();
    assert_eq!(
        l.params
            .iter()
            .map(|p| p.name)
            .collect::<std::vec::Vec<_>>(),
        ["MN", "IN", "MX"]
    );
    assert_eq!(lookup("max").unwrap().ext, Ext::Fold);
    assert_eq!(lookup("GT").unwrap().ext, Ext::Chain);
    assert_eq!(lookup("MUX").unwrap().ext, Ext::Mux);
    assert_eq!(
        lookup("int_to_real").unwrap().ret,
        ParamTy::Concrete(Elem::REAL)
    );
    assert_eq!(
        lookup("DATE_AND_TIME_TO_TIME_OF_DAY").unwrap().name,
        "DT_TO_TOD"
    );
    assert_eq!(lookup("date_and_time_to_date").unwrap().name, "DT_TO_DATE");
    assert_eq!(
        lookup("TIME_OF_DAY_TO_STRING").unwrap().name,
        "TOD_TO_STRING"
    );
    assert!(lookup("NO_SUCH").is_none());
    assert!(lookup("").is_none());
    assert!(lookup(&"X".repeat(200)).is_none());
}

#[test]
fn table_is_consistent() {
    let mut names: std::vec::Vec<&str> = SIGNATURES.iter().map(|s| s.name).collect();
    names.sort_unstable();
    let n = names.len();
    names.dedup();
    assert_eq!(names.len(), n, "duplicate names");
    assert!(n > 350);
    for s in SIGNATURES {
        assert!(!s.params.is_empty(), "{}", s.name);
        assert!(!s.doc.is_empty());
        // A T result needs a T parameter to take its type from.
        if let ParamTy::T(c) = s.ret {
            assert!(s.params.iter().any(|p| p.ty == ParamTy::T(c)), "{}", s.name);
        }
        match s.ext {
            Ext::Fold | Ext::Chain => assert_eq!(s.params.len(), 2, "{}", s.name),
            Ext::Mux => assert_eq!(s.params.first().map(|p| p.name), Some("K")),
            Ext::Fixed => {}
        }
    }
    for name in [
        "ADD",
        "SUB",
        "MUL",
        "DIV",
        "MOD",
        "MOVE",
        "ABS",
        "SQRT",
        "LN",
        "LOG",
        "EXP",
        "SIN",
        "COS",
        "TAN",
        "ASIN",
        "ACOS",
        "ATAN",
        "EXPT",
        "TRUNC",
        "SHL",
        "SHR",
        "ROL",
        "ROR",
        "AND",
        "OR",
        "XOR",
        "NOT",
        "SEL",
        "MAX",
        "MIN",
        "LIMIT",
        "MUX",
        "GT",
        "GE",
        "EQ",
        "LE",
        "LT",
        "NE",
        "LEN",
        "LEFT",
        "RIGHT",
        "MID",
        "CONCAT",
        "INSERT",
        "DELETE",
        "REPLACE",
        "FIND",
        "ADD_TIME",
        "SUB_TIME",
        "MUL_TIME",
        "DIV_TIME",
        "ADD_TOD_TIME",
        "ADD_DT_TIME",
        "SUB_DATE_DATE",
        "SUB_TOD_TOD",
        "SUB_DT_DT",
        "CONCAT_DATE_TOD",
        "DT_TO_TOD",
        "DT_TO_DATE",
        "BCD_TO_INT",
        "INT_TO_BCD",
        "REAL_TO_INT",
        "TIME_TO_DINT",
        "STRING_TO_INT",
        "INT_TO_STRING",
        "BOOL_TO_INT",
        "WORD_TO_BOOL",
    ] {
        assert!(lookup(name).is_some(), "{name} missing");
    }
    // Every ordered pair of distinct numeric/bit types has a conversion.
    let num = &Elem::ALL[..15];
    for &a in num {
        for &b in num {
            if a != b {
                let name = std::format!("{}_TO_{}", a.name(), b.name());
                let s = lookup(&name).unwrap_or_else(|| panic!("{name}"));
                assert_eq!(s.params[0].ty, ParamTy::Concrete(a));
                assert_eq!(s.ret, ParamTy::Concrete(b));
            }
        }
    }
}

#[test]
fn elem() {
    for e in Elem::ALL {
        assert_eq!(Elem::from_name(e.name()), Some(e));
        assert!(e.class_member(Class::Any));
    }
    assert_eq!(Elem::from_name("time_of_day"), Some(Elem::TOD));
    assert_eq!(Elem::from_name("Date_And_Time"), Some(Elem::DT));
    assert_eq!(Elem::from_name("int"), Some(Elem::INT));
    assert_eq!(Elem::from_name("FOO"), None);
    assert!(Elem::INT.class_member(Class::AnyNum));
    assert!(!Elem::INT.class_member(Class::AnyBit));
    assert!(Elem::BOOL.class_member(Class::AnyBit));
    assert!(!Elem::BOOL.class_member(Class::AnyBitString));
    assert!(Elem::TIME.class_member(Class::AnyMagnitude));
    assert!(!Elem::TIME.class_member(Class::AnyNum));
    assert!(Elem::TOD.class_member(Class::AnyDate));
    assert!(Elem::WSTRING.class_member(Class::AnyString));
    assert_eq!(Elem::INT.min_max_i128(), Some((-32768, 32767)));
    assert_eq!(Elem::LWORD.min_max_i128(), Some((0, u64::MAX as i128)));
    assert_eq!(Elem::REAL.min_max_i128(), None);
    assert_eq!(Elem::WORD.bits(), Some(16));
    assert_eq!(Elem::STRING.bits(), None);
}

#[test]
fn each_entry_is_the_function_its_func_says() {
    for s in SIGNATURES {
        match s.func {
            Func::Conversion => assert!(s.conversion.is_some(), "{}", s.name),
            f => {
                assert!(s.conversion.is_none(), "{}", s.name);
                assert_eq!(std::format!("{f:?}"), s.name);
            }
        }
    }
}
