//! ADD SUB MUL DIV MOD and the comparisons on every integer and real type
//! (plc/ops_arith.il, plc/ops_misc.il) through both front ends.

use il_std::{Cycle, FaultKind, TIME};

/// Checks one integer FB type against Rust's wrapping arithmetic: IEC integer
/// arithmetic wraps, DIV truncates toward zero, MOD has the sign of the
/// dividend, DIV/MOD by zero give 0 (and a fault).
macro_rules! check_int {
    ($fb:ty, $t:ty, $cases:expr) => {{
        for (a, b) in $cases {
            let a: $t = a;
            let b: $t = b;
            let mut ctx = Cycle::new();
            let mut f = <$fb>::default();
            f.a = a;
            f.b = b;
            f.call(&mut ctx);
            let case = format!("{} a={a} b={b}", stringify!($fb));
            assert_eq!(f.r_add, a.wrapping_add(b), "ADD {case}");
            assert_eq!(f.r_sub, a.wrapping_sub(b), "SUB {case}");
            assert_eq!(f.r_mul, a.wrapping_mul(b), "MUL {case}");
            let (q, m) = if b == 0 {
                (0, 0)
            } else {
                (a.wrapping_div(b), a.wrapping_rem(b))
            };
            assert_eq!(f.r_div, q, "DIV {case}");
            assert_eq!(f.r_mod, m, "MOD {case}");
            assert_eq!(f.r_gt, a > b, "GT {case}");
            assert_eq!(f.r_ge, a >= b, "GE {case}");
            assert_eq!(f.r_eq, a == b, "EQ {case}");
            assert_eq!(f.r_ne, a != b, "NE {case}");
            assert_eq!(f.r_le, a <= b, "LE {case}");
            assert_eq!(f.r_lt, a < b, "LT {case}");
            assert_eq!(
                ctx.fault_count(),
                if b == 0 { 2 } else { 0 },
                "faults {case}"
            );
        }
    }};
}

macro_rules! signed_cases {
    ($t:ty) => {
        [
            (7 as $t, 2 as $t),
            (-7, 2),
            (7, -2),
            (-7, -2),
            (<$t>::MAX, 1),
            (<$t>::MIN, 1),
            (<$t>::MIN, -1),
            (<$t>::MAX, 2),
            (5, 5),
            (3, 0),
        ]
    };
}

macro_rules! unsigned_cases {
    ($t:ty) => {
        [
            (7 as $t, 2 as $t),
            (0, 1),
            (<$t>::MAX, 1),
            (<$t>::MAX, 2),
            (5, 5),
            (2, 9),
            (3, 0),
        ]
    };
}

macro_rules! arith_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::*;

            #[test]
            fn sint() {
                check_int!(OpsArithSINT, i8, signed_cases!(i8));
            }
            #[test]
            fn int() {
                check_int!(OpsArithINT, i16, signed_cases!(i16));
            }
            #[test]
            fn dint() {
                check_int!(OpsArithDINT, i32, signed_cases!(i32));
            }
            #[test]
            fn lint() {
                check_int!(OpsArithLINT, i64, signed_cases!(i64));
            }
            #[test]
            fn usint() {
                check_int!(OpsArithUSINT, u8, unsigned_cases!(u8));
            }
            #[test]
            fn uint() {
                check_int!(OpsArithUINT, u16, unsigned_cases!(u16));
            }
            #[test]
            fn udint() {
                check_int!(OpsArithUDINT, u32, unsigned_cases!(u32));
            }
            #[test]
            fn ulint() {
                check_int!(OpsArithULINT, u64, unsigned_cases!(u64));
            }

            #[test]
            fn real_is_32_bit_ieee() {
                let mut ctx = Cycle::new();
                let mut f = OpsArithREAL::default();
                f.a = 1.5;
                f.b = 0.25;
                f.call(&mut ctx);
                assert_eq!(f.r_add, 1.75f32);
                assert_eq!(f.r_sub, 1.25f32);
                assert_eq!(f.r_mul, 0.375f32);
                assert_eq!(f.r_div, 6.0f32);
                assert!(f.r_gt && f.r_ge && f.r_ne && !f.r_eq && !f.r_le && !f.r_lt);
                // 0.1 + 0.2 in f32, not f64
                f.a = 0.1;
                f.b = 0.2;
                f.call(&mut ctx);
                assert_eq!(f.r_add, 0.1f32 + 0.2f32);
                // REAL division by zero follows IEEE 754 and records no fault
                f.a = 1.0;
                f.b = 0.0;
                f.call(&mut ctx);
                assert_eq!(f.r_div, f32::INFINITY);
                f.a = -1.0;
                f.call(&mut ctx);
                assert_eq!(f.r_div, f32::NEG_INFINITY);
                f.a = 0.0;
                f.call(&mut ctx);
                assert!(f.r_div.is_nan());
                assert!(!f.r_eq || f.a == f.b);
                assert_eq!(ctx.fault_count(), 0);
            }

            #[test]
            fn lreal_is_64_bit() {
                let mut ctx = Cycle::new();
                let mut f = OpsArithLREAL::default();
                f.a = 0.1;
                f.b = 0.2;
                f.call(&mut ctx);
                assert_eq!(f.r_add, 0.1f64 + 0.2f64);
                assert_eq!(f.r_mul, 0.1f64 * 0.2f64);
                assert_eq!(f.r_div, 0.5f64);
                assert!(f.r_lt && f.r_le && f.r_ne);
                f.b = 0.0;
                f.call(&mut ctx);
                assert_eq!(f.r_div, f64::INFINITY);
                assert_eq!(ctx.fault_count(), 0);
            }

            #[test]
            fn div_by_zero_records_pou_and_line() {
                let mut ctx = Cycle::new();
                let mut f = DivZero::default();
                f.a = 17;
                f.b = 0;
                f.call(&mut ctx);
                assert_eq!(f.q, 0);
                assert_eq!(f.m, 0);
                assert_eq!(ctx.fault_count(), 2);
                let faults: Vec<_> = ctx.faults().copied().collect();
                assert_eq!(faults[0].kind, FaultKind::DivisionByZero);
                assert_eq!(faults[0].pou, "DivZero");
                assert_eq!(faults[0].line, 13, "the DIV line of plc/ops_misc.il");
                let last = ctx.last_fault().unwrap();
                assert_eq!(
                    (last.kind, last.pou, last.line),
                    (FaultKind::DivisionByZero, "DivZero", 16)
                );
                f.b = 5;
                f.call(&mut ctx);
                assert_eq!((f.q, f.m), (3, 2));
                assert_eq!(ctx.fault_count(), 2, "no new fault");
            }

            #[test]
            fn literal_operands_wrap_and_truncate() {
                let mut ctx = Cycle::new();
                let mut f = LitOps::default();
                f.call(&mut ctx);
                assert_eq!(f.wrap_add, -32768, "INT 32767 + 1");
                assert_eq!(f.wrap_sub, 127, "SINT -128 - 1");
                assert_eq!(f.wrap_mul, 0, "DINT 65536 * 65536");
                assert_eq!(f.wrap_u, 65535, "UINT 0 - 1");
                assert_eq!(f.div_neg, -3, "-7 / 2 truncates toward zero");
                assert_eq!(f.mod_neg, -1, "-7 MOD 2 has the dividend's sign");
                assert_eq!(f.mod_neg2, 1, "7 MOD -2 has the dividend's sign");
                assert_eq!(f.real_div, 0.25f32);
                assert_eq!(f.lreal_mul, 0.1f64 * 3.0);
                assert_eq!(ctx.fault_count(), 0);
            }

            #[test]
            fn time_arithmetic() {
                let mut ctx = Cycle::new();
                let mut f = TimeOps::default();
                f.t1 = TIME::from_ms(1500);
                f.t2 = TIME::from_ms(250);
                f.k = 3;
                f.kd = -2;
                f.call(&mut ctx);
                assert_eq!(f.t_add, TIME::from_ms(1750));
                assert_eq!(f.t_sub, TIME::from_ms(1250));
                assert_eq!(f.t_mul, TIME::from_ms(4500));
                assert_eq!(f.t_div, TIME::from_ms(500));
                assert_eq!(f.t_muld, TIME::from_ms(-3000));
                assert!(f.t_gt);
                assert!(!f.t_eq);
                assert_eq!(f.t_lit, TIME::from_ms(91_500), "T#1m30s + T#1.5s");
                f.t1 = TIME::from_secs(1);
                f.k = 0;
                f.call(&mut ctx);
                assert!(f.t_eq);
                assert_eq!(f.t_div, TIME::ZERO, "TIME / 0 gives 0");
                assert_eq!(
                    ctx.last_fault().map(|x| x.kind),
                    Some(FaultKind::DivisionByZero)
                );
            }
        }
    };
}

arith_tests!(via_build);
arith_tests!(via_macro);
