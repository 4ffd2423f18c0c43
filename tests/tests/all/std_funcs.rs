//! Standard functions called from IL (plc/std_funcs.il, plc/string_funcs.il).

use il_std::Cycle;

macro_rules! std_func_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{StdFuncs, StrFuncs};

            fn run(setup: impl FnOnce(&mut StdFuncs)) -> StdFuncs {
                let mut ctx = Cycle::new();
                let mut f = StdFuncs::default();
                setup(&mut f);
                f.call(&mut ctx);
                f
            }

            #[test]
            fn limit_takes_the_cr_as_mn() {
                // docs/semantics.md, "Calling functions": `LIMIT 0, 100` =
                // LIMIT(CR, 0, 100); here
                // LD 10 / LIMIT v, 20 = LIMIT(MN := 10, IN := v, MX := 20).
                for (v, want) in [(5, 10), (15, 15), (25, 20)] {
                    let f = run(|f| f.v = v);
                    assert_eq!(f.lim, want, "v={v}");
                }
            }

            #[test]
            fn limit_formal_and_cal_forms() {
                for (v, want) in [(-3, 1), (50, 50), (300, 128)] {
                    let f = run(|f| f.v = v);
                    assert_eq!(f.lim_formal, want, "LIMIT(MN:=1, IN:={v}, MX:=128)");
                    assert_eq!(f.lim_cal, want, "CAL LIMIT(MN:=1,IN:={v},MX:=128)");
                }
            }

            #[test]
            fn max_min_with_extra_operands() {
                let f = run(|f| {
                    f.a = 3;
                    f.b = -8;
                    f.c = 11;
                    f.d = 7;
                });
                assert_eq!(f.mx, 11);
                assert_eq!(f.mn, -8);
            }

            #[test]
            fn sel_and_mux() {
                let f = run(|f| {
                    f.g = false;
                    f.a = 1;
                    f.b = 2;
                    f.c = 3;
                    f.k = 2;
                });
                assert_eq!(f.sel, 1, "SEL(FALSE, a, b) = a");
                assert_eq!(f.mux, 3, "MUX(2, a, b, c) = c");
                let f = run(|f| {
                    f.g = true;
                    f.a = 1;
                    f.b = 2;
                    f.k = 0;
                });
                assert_eq!(f.sel, 2);
                assert_eq!(f.mux, 1);
            }

            #[test]
            fn conversions_shifts_and_math() {
                let f = run(|f| {
                    f.v = -42;
                    f.r = 2.5;
                    f.w = 0x1234;
                });
                assert_eq!(f.to_real, -42.0);
                assert_eq!(f.to_int, 2, "REAL_TO_INT rounds half to even");
                assert_eq!(f.shl, 0x2340);
                assert_eq!(f.shr, 0x0123);
                assert_eq!(f.rol, 0x2341);
                assert_eq!(f.ror, 0x4123);
                assert_eq!(f.ab, 42);
                assert_eq!(f.sq, 2.5f32.sqrt());
                assert_eq!(f.moved, -42);
                assert_eq!(f.from_bcd, 1234);
                assert_eq!(f.tr, 2);
                let f = run(|f| {
                    f.v = 1234;
                    f.r = -3.7;
                });
                assert_eq!(f.bcd, 0x1234);
                assert_eq!(f.to_int, -4);
                assert_eq!(f.tr, -3);
            }

            #[test]
            fn string_functions_clamp_and_truncate() {
                use il_std::{FaultKind, STRING, WSTRING};
                let st = |x: &str| STRING::<10>::from_str_truncating(x).0;
                let ws = |x: &str| WSTRING::<8>::from_str_truncating(x).0;
                let mut ctx = Cycle::new();
                let mut f = StrFuncs::default();
                f.call(&mut ctx);
                assert_eq!(f.left, st("He"));
                assert_eq!(f.right, st("lo"));
                assert_eq!(f.mid, st("ll"));
                assert_eq!(f.cat, st("HelloWorld"));
                assert_eq!(f.cat3, st("HelloWorld"));
                assert_eq!(f.ins, st("HelWorldlo"));
                assert_eq!(f.del, st("Heo"));
                assert_eq!(f.rep, st("HeWorldo"));
                assert_eq!(f.left_neg, st(""));
                assert_eq!(f.mid_far, st(""));
                assert_eq!(f.del_far, st("Hello"));
                assert_eq!(f.ins_far, st("HelloWorld"));
                assert_eq!((f.find_l, f.find_none, f.find_w), (3, 0, 4));
                assert_eq!(f.wleft, ws("äb"));
                assert_eq!(f.wmid, ws("c€"));
                assert_eq!(f.wcat, ws("äbc€dxyz"));
                assert_eq!(f.wrep, ws("ÖÖÖÖÖbc€"));
                let faults: Vec<_> = ctx.faults().map(|x| (x.kind, x.pou, x.line)).collect();
                assert_eq!(
                    faults,
                    [
                        (FaultKind::StringOverflow, "StrFuncs", 33),
                        (FaultKind::StringOverflow, "StrFuncs", 75),
                    ]
                );
            }
        }
    };
}

std_func_tests!(via_build);
std_func_tests!(via_macro);
