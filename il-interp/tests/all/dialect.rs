//! The interpreter on the 3rd-edition forms of `tests/plc/dialect.il`
//! (asserting what `tests/tests/all/dialect.rs` asserts for generated code),
//! and the same file refused under the 2nd edition.

use il_codegen::diag::SourceFile;
use il_codegen::ir::types::Elem;
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
        assert_eq!(get(&m, "nw"), int(0xFF, Elem::WORD), "{case}");
        assert_eq!(get(&m, "nb"), int(0, Elem::BYTE), "{case}");
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

#[test]
fn partial_access_reads_and_writes_bits_bytes_and_words() {
    let prog = load(&file()).expect("compiles");
    let mut ctx = Cycle::new();
    let mut m = Machine::new(&prog, "Bits").expect("instance");
    for (w, d, go, k) in [
        (0x8001u16, -2i32, true, 0i16),
        (0x7FFE, 0x1234_5678, false, 3),
        (0xA5C3, i32::MIN, true, 9),
    ] {
        m.set("w", int(w.into(), Elem::WORD)).unwrap();
        m.set("d", int(d.into(), Elem::DINT)).unwrap();
        m.set("go", Value::Bool(go)).unwrap();
        m.set("k", int(k.into(), Elem::INT)).unwrap();
        m.set("st", int(0xF0, Elem::WORD)).unwrap();
        m.set("neg", int(0, Elem::DINT)).unwrap();
        m.set("arr", Value::Array(vec![int(0, Elem::BYTE); 4]))
            .unwrap();
        m.scan(&mut ctx).expect("scan");
        let case = format!("w={w:#x} d={d:#x} go={go} k={k}");
        let b = |x: bool| Value::Bool(x);
        assert_eq!(get(&m, "b0"), b(w & 1 != 0), "{case}");
        assert_eq!(get(&m, "b15"), b(w & 0x8000 != 0), "{case}");
        assert_eq!(get(&m, "sign"), b(d < 0), "{case}");
        assert_eq!(get(&m, "hi"), int((w >> 8).into(), Elem::BYTE), "{case}");
        assert_eq!(
            get(&m, "lo_word"),
            int((d as u16).into(), Elem::WORD),
            "{case}"
        );
        let mut st = 0x00F0u16 & !0b11 | u16::from(go) | (u16::from(!go) << 1);
        if go {
            st |= 0x8000;
            st &= !0b100;
        }
        st = (st & !0x100) | (u16::from(go) << 8);
        assert_eq!(get(&m, "st"), int(st.into(), Elem::WORD), "{case}");
        let neg = i32::from_le_bytes([(w >> 8) as u8, 0, 0, 0xFF]);
        assert_eq!(get(&m, "neg"), int(neg.into(), Elem::DINT), "{case}");
        assert_eq!(get(&m, "inner3"), b(w & 8 != 0), "{case}");
        let mut arr = [0u8; 4];
        if (0..4).contains(&k) {
            assert_eq!(get(&m, "elem"), b(w & 1 != 0), "{case}");
            arr[k as usize] = (w as u8 & 0x7F) | (u8::from(go) << 7);
        } else {
            assert_eq!(get(&m, "elem"), b(false), "{case}");
        }
        let arr = Value::Array(arr.iter().map(|&x| int(x.into(), Elem::BYTE)).collect());
        assert_eq!(get(&m, "arr"), arr, "{case}");
    }
    assert!(
        ctx.faults()
            .any(|f| f.kind == il_std::FaultKind::IndexOutOfRange),
        "k = 9 records the fault"
    );
}

#[test]
fn partial_access_on_a_function_result_and_a_var_in_out() {
    let prog = load(&file()).expect("compiles");
    let mut ctx = Cycle::new();
    let mut m = Machine::new(&prog, "InOutBits").expect("instance");
    for (w, n, want) in [
        (0x8001, false, 0x8001),
        (0, true, 4),
        (0x7FFF, false, 0xFFFB),
    ] {
        let (r, _) = m
            .call_function_named("SetBit", vec![int(w, Elem::WORD), Value::Bool(n)], &mut ctx)
            .expect("call");
        assert_eq!(r, int(want, Elem::WORD), "SetBit({w:#x}, {n})");
    }
    // A VAR_IN_OUT lives only during a call: InOutHost binds it to `w := 2`.
    assert!(m.set("io", int(2, Elem::WORD)).is_err());
    let mut m = Machine::new(&prog, "InOutHost").expect("instance");
    m.scan(&mut ctx).expect("scan");
    assert_eq!(get(&m, "b"), Value::Bool(true));
    // Bit 8 of io was set through the in-out: w became 0x102, and
    // r = SetBit(io, TRUE) = 0x106.
    assert_eq!(get(&m, "w"), int(0x102, Elem::WORD));
    assert_eq!(get(&m, "r"), int(0x106, Elem::WORD));
}
