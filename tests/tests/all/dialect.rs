//! 3rd-edition and vendor forms accepted by default (plc/dialect.il):
//! pragmas and implicit widening conversions, through build.rs and `il!`.

use il_std::{Cycle, LTIME, TIME};

macro_rules! dialect_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Widening, WideningCalls, WideningStd};

            #[test]
            fn widening_keeps_every_value() {
                let mut ctx = Cycle::new();
                let mut f = Widening::default();
                assert_eq!(f.init, -300, "INT#-300 as a DINT initial value");
                for (s, i) in [(-128i8, 32767i16), (127, -32768), (-1, 1), (0, 0)] {
                    f.s = s;
                    f.i = i;
                    f.u = 65535;
                    f.b = true;
                    f.w = 0x8000;
                    f.r = 1.5e-7;
                    f.t = TIME::from_ms(-2500);
                    f.call(&mut ctx);
                    let case = format!("s={s} i={i}");
                    assert_eq!(f.sum, (s as i16).wrapping_add(i), "INT arithmetic: {case}");
                    assert_eq!(f.d, s as i32, "{case}");
                    assert_eq!(f.du, 65535, "{case}");
                    assert_eq!(f.scaled, 2 * s as i32, "{case}");
                    assert_eq!(f.scaled2, 2 * i as i32, "{case}");
                    assert_eq!(f.l, 2 * i as i64, "=> into a wider variable: {case}");
                    assert_eq!(f.bits, 0x8001, "{case}");
                    assert_eq!(f.lr, 1.5e-7f32 as f64, "REAL → LREAL is exact: {case}");
                    assert_eq!(f.ir, i as f32, "{case}");
                    assert!(!f.gt, "d = s, so d GT s is FALSE: {case}");
                    assert_eq!(f.lt, LTIME(-2_500_000_000), "{case}");
                    assert_eq!(f.nw, 0x00FF, "STN: NOT BYTE#0, then widened: {case}");
                    assert_eq!(f.nb, 0, "STN: NOT TRUE, then widened: {case}");
                }
            }

            #[test]
            fn widening_into_fb_inputs_and_from_fb_outputs() {
                let mut ctx = Cycle::new();
                let mut f = WideningCalls::default();
                f.s = -100;
                f.r = 0.1;
                f.call(&mut ctx);
                assert_eq!(f.sum, -200, "SINT into the INT input, INT output into DINT");
                assert_eq!(f.lr, 0.1f32 as f64);
            }

            #[test]
            fn widening_into_standard_functions() {
                for (s, i, d) in [(-100i8, 50i16, 7i32), (20, -300, 40_000), (100, 200, -5)] {
                    let mut ctx = Cycle::new();
                    let mut f = WideningStd::default();
                    (f.s, f.i, f.d) = (s, i, d);
                    f.call(&mut ctx);
                    let got = (f.lim, f.big, f.small, f.q);
                    let want = (
                        i.clamp(s as i16, 100),
                        d.max(i as i32).max(s as i32),
                        (s as i16).min(i),
                        s <= 1,
                    );
                    assert_eq!(got, want, "s={s} i={i} d={d}");
                    assert_eq!(super::widening_std_interpreted(s, i, d), want);
                }
            }
        }
    };
}

dialect_tests!(via_build);
dialect_tests!(via_macro);

/// `WideningStd` through the interpreter: (lim, big, small, q).
fn widening_std_interpreted(s: i8, i: i16, d: i32) -> (i16, i32, i16, bool) {
    use il_codegen::ir::types::Elem;
    let src = std::fs::read_to_string("plc/dialect.il").expect("read");
    let prog = il_interp::load(&il_codegen::diag::SourceFile::new("dialect.il", src)).unwrap();
    let mut m = il_interp::Machine::new(&prog, "WideningStd").unwrap();
    m.set("s", il_interp::int(s.into(), Elem::SINT)).unwrap();
    m.set("i", il_interp::int(i.into(), Elem::INT)).unwrap();
    m.set("d", il_interp::int(d.into(), Elem::DINT)).unwrap();
    m.scan(&mut Cycle::new()).unwrap();
    let int = |n: &str| m.get(n).unwrap().as_i64();
    (
        int("lim") as i16,
        int("big") as i32,
        int("small") as i16,
        m.get("q").unwrap().as_bool(),
    )
}

macro_rules! bit_tests {
    ($name:ident, $m:ident) => {
        mod $name {
            use super::*;
            use il_tests::$m::{Bits, BitsInStruct, InOutBits, SetBit};

            #[test]
            fn partial_access_on_a_function_result_and_a_var_in_out() {
                let mut ctx = Cycle::new();
                assert_eq!(SetBit(&mut ctx, 0x8001, false), 0x8001);
                assert_eq!(SetBit(&mut ctx, 0x0000, true), 0x0004);
                assert_eq!(SetBit(&mut ctx, 0x7FFF, false), 0xFFFB);
                let mut f = InOutBits::default();
                let mut io = 2u16;
                f.call(&mut ctx, &mut io);
                assert!(f.b);
                assert_eq!(io, 0x102, "bit 8 set through the reference");
                assert_eq!(f.r, 0x106);
            }

            #[test]
            fn partial_access_on_structure_members() {
                let mut ctx = Cycle::new();
                let mut f = BitsInStruct::default();
                f.go = true;
                f.call(&mut ctx);
                assert_eq!((f.f.word, f.f.dint), (0x10, 1 << 30));
                f.go = false;
                f.call(&mut ctx);
                assert_eq!((f.f.word, f.f.dint), (0, 0));
            }

            #[test]
            fn partial_access_reads_and_writes_bits_bytes_and_words() {
                let mut ctx = Cycle::new();
                let mut f = Bits::default();
                for (w, d, go, k) in [
                    (0x8001u16, -2i32, true, 0i16),
                    (0x7FFE, 0x1234_5678, false, 3),
                    (0xA5C3, i32::MIN, true, 9), // k out of bounds
                ] {
                    f.w = w;
                    f.d = d;
                    f.go = go;
                    f.k = k;
                    f.arr = [0; 4];
                    f.st = 0x00F0;
                    f.neg = 0;
                    f.call(&mut ctx);
                    let case = format!("w={w:#x} d={d:#x} go={go} k={k}");
                    assert_eq!(f.b0, w & 1 != 0, "{case}");
                    assert_eq!(f.b15, w & 0x8000 != 0, "{case}");
                    assert_eq!(f.sign, d < 0, "{case}");
                    assert_eq!(f.hi, (w >> 8) as u8, "{case}");
                    assert_eq!(f.lo_word, d as u16, "{case}");
                    let mut st = 0x00F0u16 & !0b11 | u16::from(go) | (u16::from(!go) << 1);
                    if go {
                        st |= 0x8000;
                        st &= !0b100;
                    }
                    let loc_bit = go;
                    st = (st & !0x100) | (u16::from(loc_bit) << 8);
                    assert_eq!(f.st, st, "{case}");
                    assert_eq!(
                        f.neg,
                        i32::from_le_bytes([(w >> 8) as u8, 0, 0, 0xFF]),
                        "{case}"
                    );
                    assert_eq!(f.inner3, w & 8 != 0, "{case}");
                    if (0..4).contains(&k) {
                        assert_eq!(f.elem, w & 1 != 0, "{case}");
                        let mut arr = [0u8; 4];
                        arr[k as usize] = (w as u8 & 0x7F) | (u8::from(go) << 7);
                        assert_eq!(f.arr, arr, "{case}");
                    } else {
                        assert!(!f.elem, "an element out of bounds reads as 0: {case}");
                        assert_eq!(f.arr, [0; 4], "{case}");
                    }
                }
                assert!(
                    ctx.faults()
                        .any(|f| f.kind == il_std::FaultKind::IndexOutOfRange),
                    "k = 9 records the fault"
                );
            }
        }
    };
}

bit_tests!(bits_via_build, via_build);
bit_tests!(bits_via_macro, via_macro);

/// The build-script `Builder` with `strict(true)` / `standard(..)`.
#[test]
fn builder_strict_refuses_what_the_default_accepts() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("dialect-builder");
    let plc = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("plc/dialect.il");
    let build =
        |b: il_codegen::Builder| b.file(&plc).out_dir(&dir).cargo_directives(false).compile();
    assert!(build(il_codegen::Builder::new()).is_ok());
    assert!(build(il_codegen::Builder::new().strict(false)).is_ok());
    for b in [
        il_codegen::Builder::new().strict(true),
        il_codegen::Builder::new().standard(il_codegen::Standard::Iec2003),
    ] {
        let e = build(b).expect_err("refused").to_string();
        for code in ["IL0301", "IL0302", "IL0303"] {
            assert!(e.contains(&format!("error[{code}]")), "{code} in {e}");
        }
    }
}
