//! 3rd-edition and vendor forms accepted by default (plc/dialect.il):
//! pragmas and implicit widening conversions, through build.rs and `il!`.

use il_std::{Cycle, LTIME, TIME};

macro_rules! dialect_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Widening, WideningCalls};

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
        }
    };
}

dialect_tests!(via_build);
dialect_tests!(via_macro);
