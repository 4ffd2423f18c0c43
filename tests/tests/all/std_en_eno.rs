//! EN/ENO on standard functions, and inputs left out of a formal call
//! taking their declared initial values (plc/std_en_eno.il).

use il_std::Cycle;

macro_rules! std_en_eno_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::StdEnEno;

            fn run(go: bool, x: i16, r: f32) -> StdEnEno {
                let mut ctx = Cycle::new();
                let mut p = StdEnEno {
                    go,
                    x,
                    r,
                    ..Default::default()
                };
                p.call(&mut ctx);
                p
            }

            #[test]
            fn en_false_skips_the_call_gives_the_default_and_eno_false() {
                let p = run(false, 20, 2.5);
                assert_eq!((p.limited, p.ok, p.not_ok), (0, false, true));
                assert_eq!((p.rounded, p.conv_ok), (0, false));
            }

            #[test]
            fn en_true_calls_and_sets_eno() {
                let p = run(true, 20, 2.5);
                assert_eq!((p.limited, p.ok, p.not_ok), (9, true, false));
                assert_eq!((p.rounded, p.conv_ok), (2, true), "round half to even");
                let p = run(true, -4, -3.5);
                assert_eq!((p.limited, p.rounded), (0, -4));
            }

            #[test]
            fn an_input_left_out_takes_its_declared_initial_value() {
                let p = run(false, 20, 0.0);
                assert_eq!(p.sum, 23, "b := 3 as declared, c the default 0");
                assert_eq!(p.sum_all, 22);
            }
        }
    };
}

std_en_eno_tests!(via_build);
std_en_eno_tests!(via_macro);
