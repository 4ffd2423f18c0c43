//! User FUNCTIONs called from IL and from Rust (plc/functions.il).

use il_std::{Cycle, FaultKind};

macro_rules! function_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Diff2, DivRem, FnCaller, SafeDiv, Twice, Weighted3};

            #[test]
            fn direct_rust_calls() {
                let mut ctx = Cycle::new();
                assert_eq!(Weighted3(&mut ctx, 1, 2, 3), 321);
                assert_eq!(Diff2(&mut ctx, 10, 3), 7);
                assert_eq!(Twice(&mut ctx, 21), 42);
                let (mut rem, mut exact) = (0i16, false);
                assert_eq!(DivRem(&mut ctx, 17, 5, &mut rem, &mut exact), 3);
                assert_eq!((rem, exact), (2, false));
                assert_eq!(DivRem(&mut ctx, 15, 5, &mut rem, &mut exact), 3);
                assert_eq!((rem, exact), (0, true));
                // SafeDiv stores ENO, so ENO is an output (TRUE on entry).
                let mut eno = false;
                assert_eq!(SafeDiv(&mut ctx, 9, 3, &mut eno), 3);
                assert!(eno);
                assert_eq!(SafeDiv(&mut ctx, 9, 0, &mut eno), -1);
                assert!(!eno);
                assert_eq!(ctx.fault_count(), 0);
                DivRem(&mut ctx, 1, 0, &mut rem, &mut exact);
                let f = ctx.last_fault().copied().unwrap();
                assert_eq!((f.kind, f.pou), (FaultKind::DivisionByZero, "DivRem"));
            }

            #[test]
            fn operator_calls_take_the_cr_as_first_argument() {
                let mut ctx = Cycle::new();
                let mut f = FnCaller::default();
                f.a = 7;
                f.b = 2;
                f.c = 3;
                f.call(&mut ctx);
                assert_eq!(f.op3, 7 + 20 + 300, "LD a / Weighted3 b, c");
                assert_eq!(f.op2, 5, "LD a / Diff2 b");
                assert_eq!(f.op1, 14, "LD a / INT_TO_DINT / Twice");
                assert_eq!(
                    f.chained,
                    5 + 100,
                    "result of one call is the CR of the next"
                );
            }

            #[test]
            fn formal_calls() {
                let mut ctx = Cycle::new();
                let mut f = FnCaller::default();
                f.a = 7;
                f.b = 2;
                f.c = 3;
                f.call(&mut ctx);
                assert_eq!(f.formal_line, 327, "one-line formal call");
                assert_eq!(
                    f.formal_multi, 327,
                    "multi-line formal call, inputs in another order"
                );
                assert_eq!(f.formal_partial, 20, "missing inputs default to 0");
            }

            #[test]
            fn function_outputs_with_arrow() {
                let mut ctx = Cycle::new();
                let mut f = FnCaller::default();
                f.a = 17;
                f.b = 5;
                f.call(&mut ctx);
                assert_eq!(f.q, 3);
                assert_eq!(f.r, 2, "rem => r");
                assert!(f.nr, "NOT exact => nr");
                assert!(!f.ex, "exact => ex");
                f.a = 20;
                f.call(&mut ctx);
                assert_eq!((f.q, f.r, f.nr, f.ex), (4, 0, false, true));
            }

            #[test]
            fn function_storing_eno_and_returning_early() {
                let mut ctx = Cycle::new();
                let mut f = FnCaller::default();
                f.a = 12;
                f.b = 4;
                f.call(&mut ctx);
                assert_eq!(f.safe_ok, 3);
                assert_eq!(f.safe_zero, -1);
                assert_eq!(ctx.fault_count(), 0);
            }
        }
    };
}

function_tests!(via_build);
function_tests!(via_macro);
