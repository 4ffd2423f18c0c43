//! Edge cases (plc/edge_cases.il) and more call forms (plc/more_calls.il).

use il_std::{Cycle, FaultKind, TIME};

macro_rules! edge_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{EdgeMisc, KwParams, MoreCalls};

            #[test]
            fn rust_keywords_as_parameter_names() {
                let mut ctx = Cycle::new();
                assert_eq!(KwParams(&mut ctx, 3, 4), 7, "inputs `loop` and `match`");
            }

            #[test]
            fn operator_names_as_variables() {
                let mut ctx = Cycle::new();
                let mut f = EdgeMisc::default();
                f.S = true;
                f.PV = 2;
                f.call(&mut ctx);
                assert!(f.R, "LD S / ST R with variables named S and R");
                f.S = false;
                f.call(&mut ctx);
                f.S = true;
                f.call(&mut ctx);
                assert_eq!(f.x1.CV, 2, "x1, x2 : CTU declared together");
                assert_eq!(f.x2.CV, 2);
                assert!(f.x2.Q);
            }

            #[test]
            fn arrays_with_negative_lower_bound_and_bad_index() {
                let mut ctx = Cycle::new();
                let mut f = EdgeMisc::default();
                f.arr = [1, 2, 3, 4, 5];
                f.call(&mut ctx);
                assert_eq!(f.arr_sum, 6, "arr[-2] + arr[2]");
                assert_eq!(f.arr_bad, 0, "arr[3] is out of range: default value");
                let fl = ctx.last_fault().copied().expect("a fault");
                assert_eq!(
                    (fl.kind, fl.pou, fl.line),
                    (FaultKind::IndexOutOfRange, "EdgeMisc", 50)
                );
            }

            #[test]
            fn var_temp_starts_fresh_each_call() {
                let mut ctx = Cycle::new();
                let mut f = EdgeMisc::default();
                f.a = 9;
                f.call(&mut ctx);
                f.call(&mut ctx);
                assert_eq!(f.temp_seen, 0);
            }

            #[test]
            fn function_call_and_st_inside_parentheses() {
                let mut ctx = Cycle::new();
                let mut f = EdgeMisc::default();
                f.a = 5;
                f.S = true;
                f.call(&mut ctx);
                assert_eq!(f.fn_in_par, 5 + (5 + 1), "ADD( a / KwParams 1 / )");
                assert!(f.keep, "ST inside parentheses stores the inner CR");
                assert!(f.st_in_par);
                f.S = false;
                f.call(&mut ctx);
                assert!(!f.keep && !f.st_in_par);
            }

            #[test]
            fn function_without_inputs_and_bool_function_feeding_jmpc() {
                let mut ctx = Cycle::new();
                let mut f = MoreCalls::default();
                f.v = 150;
                f.call(&mut ctx);
                assert_eq!(f.no_in, 42);
                assert_eq!(f.big_jump, 2);
                assert_eq!(f.early, 0, "RET before ST: the default result");
                f.v = 5;
                f.call(&mut ctx);
                assert_eq!(f.big_jump, 1);
            }

            #[test]
            fn fb_inputs_left_out_keep_their_values() {
                let mut ctx = Cycle::new();
                let mut f = MoreCalls::default();
                f.call(&mut ctx);
                assert_eq!(f.partial1, 15);
                assert_eq!(f.partial2, 6, "q keeps 5 from the first CAL");
                assert_eq!(f.empty_call, 6, "CAL kin()");
            }

            #[test]
            fn mux_out_of_range_faults() {
                let mut ctx = Cycle::new();
                let mut f = MoreCalls::default();
                f.k = 1;
                f.call(&mut ctx);
                assert_eq!(f.mux_out, 20);
                assert_eq!(ctx.fault_count(), 0);
                f.k = 5;
                f.call(&mut ctx);
                assert_eq!(
                    ctx.last_fault().map(|x| x.kind),
                    Some(FaultKind::InvalidArgument)
                );
            }

            #[test]
            fn shift_time_real_string_and_ton_zero() {
                let mut ctx = Cycle::new();
                let mut f = MoreCalls::default();
                f.w = 0xFFFF;
                f.t = TIME::from_secs(1);
                f.r = 1.5;
                f.call(&mut ctx);
                assert_eq!(f.shl_wide, 0, "SHL by more than the width");
                assert_eq!(f.t_real, TIME::from_ms(1500), "T#1s * 1.5");
                assert_eq!(f.str.as_str(), Some("abc"));
                assert_eq!(f.str_len, 3);
                assert!(f.str_eq);
                assert_eq!(f.cat.as_str(), Some("abcdefg"));
                assert!(f.ton0, "TON with PT = T#0s: Q in the same call");
            }
        }
    };
}

edge_tests!(via_build);
edge_tests!(via_macro);
