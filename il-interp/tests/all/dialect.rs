//! The interpreter on the 3rd-edition forms of `tests/plc/dialect.il`
//! (asserting what `tests/tests/all/dialect.rs` asserts for generated code),
//! and the same file refused under the 2nd edition.

use il_codegen::diag::SourceFile;
use il_codegen::sema::types::Elem;
use il_interp::{Machine, Value, int, load, load_std};
use il_std::Cycle;

fn file() -> SourceFile {
    let path = format!("{}/../tests/plc/dialect.il", env!("CARGO_MANIFEST_DIR"));
    SourceFile::new(
        "dialect.il",
        std::fs::read_to_string(&path).expect("read IL"),
    )
}

fn get(m: &Machine, n: &str) -> Value {
    m.get(n).unwrap_or_else(|| panic!("no {n}"))
}

#[test]
fn widening_keeps_every_value() {
    let prog = load(&file()).expect("compiles");
    let mut ctx = Cycle::new();
    let mut m = Machine::new(&prog, "Widening").expect("instance");
    assert_eq!(get(&m, "init"), int(-300, Elem::DINT));
    for (s, i) in [(-128i8, 32767i16), (127, -32768), (-1, 1), (0, 0)] {
        m.set("s", int(s.into(), Elem::SINT)).unwrap();
        m.set("i", int(i.into(), Elem::INT)).unwrap();
        m.set("u", int(65535, Elem::UINT)).unwrap();
        m.set("b", Value::Bool(true)).unwrap();
        m.set("w", int(0x8000, Elem::WORD)).unwrap();
        m.set("r", Value::Real(1.5e-7)).unwrap();
        m.set("t", Value::Time(-2_500_000_000, Elem::TIME)).unwrap();
        m.scan(&mut ctx).expect("scan");
        let case = format!("s={s} i={i}");
        let sum = (s as i16).wrapping_add(i);
        assert_eq!(get(&m, "sum"), int(sum.into(), Elem::INT), "{case}");
        assert_eq!(get(&m, "d"), int(s.into(), Elem::DINT), "{case}");
        assert_eq!(get(&m, "du"), int(65535, Elem::DINT), "{case}");
        assert_eq!(get(&m, "scaled"), int(2 * s as i128, Elem::DINT), "{case}");
        assert_eq!(get(&m, "scaled2"), int(2 * i as i128, Elem::DINT), "{case}");
        assert_eq!(get(&m, "l"), int(2 * i as i128, Elem::LINT), "{case}");
        assert_eq!(get(&m, "bits"), int(0x8001, Elem::WORD), "{case}");
        assert_eq!(get(&m, "lr"), Value::LReal(1.5e-7f32 as f64), "{case}");
        assert_eq!(get(&m, "ir"), Value::Real(i as f32), "{case}");
        assert_eq!(get(&m, "gt"), Value::Bool(false), "{case}");
        assert_eq!(
            get(&m, "lt"),
            Value::Time(-2_500_000_000, Elem::LTIME),
            "{case}"
        );
    }
}

#[test]
fn widening_into_fb_inputs_and_from_fb_outputs() {
    let prog = load(&file()).expect("compiles");
    let mut ctx = Cycle::new();
    let mut m = Machine::new(&prog, "WideningCalls").expect("instance");
    m.set("s", int(-100, Elem::SINT)).unwrap();
    m.set("r", Value::Real(0.1)).unwrap();
    m.scan(&mut ctx).expect("scan");
    assert_eq!(get(&m, "sum"), int(-200, Elem::DINT));
    assert_eq!(get(&m, "lr"), Value::LReal(0.1f32 as f64));
}

#[test]
fn the_same_file_is_refused_under_iec2003() {
    let e = load_std(&file(), il_codegen::Standard::Iec2003).expect_err("refused");
    assert!(e.contains("IL0301") && e.contains("IL0302"), "{e}");
    assert!(
        e.contains("implicit conversion SINT → INT is a 3rd-edition feature"),
        "{e}"
    );
}
