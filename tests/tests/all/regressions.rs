//! Regression tests for compiler bugs found by the behaviour suite (each IL
//! file's header comment describes the original bug).

use il_std::Cycle;

macro_rules! regression_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::*;

            /// fn_en_eno.il: EN/ENO of a user FUNCTION from a formal call.
            #[test]
            fn en_eno_of_user_functions() {
                let mut ctx = Cycle::new();
                let mut c = EnoCaller::default();
                for (x, enable, r, ok) in [
                    (5, true, 5, true),
                    (-3, true, -3, false),
                    (7, false, 0, false),
                ] {
                    c.x = x;
                    c.enable = enable;
                    c.call(&mut ctx);
                    assert_eq!((c.r, c.ok), (r, ok), "x = {x}, EN = {enable}");
                }
            }

            /// array_init_parens.il: array initial values (and no warning).
            #[test]
            fn array_initial_values() {
                let mut ctx = Cycle::new();
                let mut a = ArrInit::default();
                a.call(&mut ctx);
                assert_eq!(a.first, 1);
                assert_eq!(a.arr, [1, 2, 3, 4, 5]);
            }

            /// fb_type_case.il: an instance of a mixed-case user FB.
            #[test]
            fn mixed_case_user_fb_type() {
                let mut ctx = Cycle::new();
                let mut u = UsesCounter1::default();
                u.call(&mut ctx);
                u.call(&mut ctx);
                assert_eq!(u.n, 2);
            }

            /// fn_param_none.il: a FUNCTION input named `None`.
            #[test]
            fn input_named_like_a_prelude_variant() {
                let mut ctx = Cycle::new();
                assert_eq!(ProbeNone(&mut ctx, 42), 42);
            }

            /// pou_named_i16.il: a POU named like a Rust primitive becomes `i16_`.
            #[test]
            fn pou_named_like_a_primitive() {
                let mut ctx = Cycle::new();
                let mut b = i16_::default();
                b.call(&mut ctx);
                let y: i16 = b.y;
                assert_eq!(y, 1);
            }
        }
    };
}

regression_tests!(via_build);
regression_tests!(via_macro);

macro_rules! operand_list_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::AddList;

            /// `ADD b, c` is ADD(CR, b, c); `GT b, c` is CR > b AND b > c.
            #[test]
            fn extensible_functions_with_operand_lists() {
                let mut ctx = Cycle::new();
                let mut f = AddList::default();
                (f.a, f.b, f.c) = (1, 20, 3);
                f.call(&mut ctx);
                assert_eq!(f.sum, 24);
                assert!(f.big, "24 > 20 > 3");
                (f.a, f.b, f.c) = (1, 2, 3);
                f.call(&mut ctx);
                assert_eq!(f.sum, 6);
                assert!(!f.big, "6 > 2 but not 2 > 3");
            }
        }
    };
}

mod operand_lists {
    use super::*;
    operand_list_tests!(via_build);
    operand_list_tests!(via_macro);
}

macro_rules! pending_call_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::MuxLit;

            /// `LD k / MUX 10, 20, 30 / ST mux_out`: the literals take the
            /// type of `mux_out` (INT), as plain literals would.
            #[test]
            fn untyped_literal_arguments_take_their_type_from_use() {
                let mut ctx = Cycle::new();
                let mut m = MuxLit::default();
                for (k, out) in [(0, 10), (1, 20), (2, 30)] {
                    m.k = k;
                    m.call(&mut ctx);
                    assert_eq!(m.mux_out, out);
                }
                assert_eq!(ctx.fault_count(), 0);
                m.k = 7;
                m.call(&mut ctx);
                assert_eq!(m.mux_out, 10, "out of range gives IN0 and a fault");
                assert_eq!(ctx.fault_count(), 1);
            }
        }
    };
}

mod pending_calls {
    use super::*;
    pending_call_tests!(via_build);
    pending_call_tests!(via_macro);
}

macro_rules! conversion_fault_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_std::{FaultKind, STRING};
            use il_tests::$m::ConvFaults;

            /// Out-of-range conversions saturate and record ConversionOutOfRange;
            /// a too-long CONCAT truncates and records StringOverflow.
            #[test]
            fn conversion_and_string_faults_are_recorded() {
                let mut ctx = Cycle::new();
                let mut c = ConvFaults::default();
                c.r = 2.5;
                c.a = STRING::<4>::from_str_truncating("ab").0;
                c.b = STRING::<4>::from_str_truncating("cd").0;
                c.call(&mut ctx);
                assert_eq!((c.i, c.t, c.s.to_string().as_str()), (2, 2, "abcd"));
                assert_eq!(ctx.fault_count(), 0);
                c.r = 1.0e9;
                c.b = STRING::<4>::from_str_truncating("cde").0;
                c.call(&mut ctx);
                assert_eq!(c.i, i16::MAX);
                assert_eq!(c.s.to_string(), "abcd");
                let kinds: Vec<FaultKind> = ctx.faults().map(|f| f.kind).collect();
                assert_eq!(
                    kinds,
                    [FaultKind::ConversionOutOfRange, FaultKind::StringOverflow]
                );
            }
        }
    };
}

mod conversion_faults {
    use super::*;
    conversion_fault_tests!(via_build);
    conversion_fault_tests!(via_macro);
}

macro_rules! differential_regression_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_std::{FaultKind, TIME};
            use il_tests::$m::{DivFnForm, FnArgElement, TimeMulReal, UselessCompare};

            #[test]
            fn div_and_mod_function_forms_record_faults() {
                let mut ctx = Cycle::new();
                let mut p = DivFnForm::default();
                p.call(&mut ctx);
                assert_eq!((p.r, p.m), (0, 0));
                assert_eq!(ctx.fault_count(), 2);
                assert_eq!(
                    ctx.last_fault().map(|f| f.kind),
                    Some(FaultKind::DivisionByZero)
                );
            }

            #[test]
            fn function_arguments_that_index_arrays() {
                let mut ctx = Cycle::new();
                let mut p = FnArgElement::default();
                p.call(&mut ctx);
                assert_eq!(p.r, 8);
                p.k = 9;
                p.call(&mut ctx);
                assert_eq!(p.r, 5, "out of range reads 0");
                assert_eq!(
                    ctx.last_fault().map(|f| f.kind),
                    Some(FaultKind::IndexOutOfRange)
                );
            }

            #[test]
            fn time_times_real_is_one_rule() {
                let mut ctx = Cycle::new();
                let mut p = TimeMulReal::default();
                p.call(&mut ctx);
                assert_eq!(p.by_op, p.by_fn);
                assert_eq!(p.by_op, TIME(2), "1 ns * 1.5 rounds to even: 2 ns");
                let mut q = UselessCompare::default();
                q.call(&mut ctx);
                assert!(q.a && !q.b);
            }
        }
    };
}

mod differential_regressions {
    use super::*;
    differential_regression_tests!(via_build);
    differential_regression_tests!(via_macro);
}
