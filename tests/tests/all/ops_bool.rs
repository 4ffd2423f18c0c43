//! Every Boolean operator and modifier (plc/ops_bool.il) through both front ends.

use il_std::Cycle;

macro_rules! ops_bool_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{OpsBool, OpsWord, SetReset};

            #[test]
            fn bool_operators_truth_tables() {
                let mut ctx = Cycle::new();
                for a in [false, true] {
                    for b in [false, true] {
                        let mut f = OpsBool::default();
                        f.a = a;
                        f.b = b;
                        f.call(&mut ctx);
                        let case = format!("a={a} b={b}");
                        assert_eq!(f.o_ld, a, "LD {case}");
                        assert_eq!(f.o_ldn, !a, "LDN {case}");
                        assert_eq!(f.o_stn, !a, "STN {case}");
                        assert_eq!(f.o_and, a && b, "AND {case}");
                        assert_eq!(f.o_andn, a && !b, "ANDN {case}");
                        assert_eq!(f.o_amp, a && b, "& {case}");
                        assert_eq!(f.o_ampn, a && !b, "&N {case}");
                        assert_eq!(f.o_or, a || b, "OR {case}");
                        assert_eq!(f.o_orn, a || !b, "ORN {case}");
                        assert_eq!(f.o_xor, a ^ b, "XOR {case}");
                        assert_eq!(f.o_xorn, a ^ !b, "XORN {case}");
                        assert_eq!(f.o_not, !a, "NOT {case}");
                        assert_eq!(f.o_eq, a == b, "EQ {case}");
                        assert_eq!(f.o_ne, a != b, "NE {case}");
                        assert_eq!(f.o_gt, a & !b, "GT (TRUE > FALSE) {case}");
                        assert_eq!(f.o_lt, !a & b, "LT {case}");
                    }
                }
                assert_eq!(ctx.fault_count(), 0);
            }

            #[test]
            fn s_and_r_only_act_when_cr_true_and_keep_cr() {
                let mut ctx = Cycle::new();
                let mut f = SetReset::default();
                f.call(&mut ctx);
                assert!(!f.latch);
                assert!(!f.cr_after_s);
                f.set_cond = true;
                f.call(&mut ctx);
                assert!(f.latch, "S with CR TRUE sets");
                assert!(f.cr_after_s, "S leaves the CR unchanged");
                f.set_cond = false;
                f.call(&mut ctx);
                assert!(f.latch, "S with CR FALSE leaves the operand alone");
                f.reset_cond = true;
                f.call(&mut ctx);
                assert!(!f.latch, "R with CR TRUE resets");
                assert!(f.cr_after_r, "R leaves the CR unchanged");
                f.reset_cond = false;
                f.latch = true;
                f.call(&mut ctx);
                assert!(f.latch, "R with CR FALSE leaves the operand alone");
                f.set_cond = true;
                f.reset_cond = true;
                f.call(&mut ctx);
                assert!(!f.latch, "R after S in the same scan wins");
            }

            #[test]
            fn bitwise_on_bit_strings() {
                let mut ctx = Cycle::new();
                let mut f = OpsWord::default();
                f.w1 = 0xF0F0;
                f.w2 = 0xFF00;
                f.b1 = 0b1010_0101;
                f.b2 = 0b0000_1111;
                f.d1 = 0x1234_5678;
                f.l1 = 0x0123_4567_89AB_CDEF;
                f.call(&mut ctx);
                assert_eq!(f.w_and, 0xF000);
                assert_eq!(f.w_andn, 0x00F0);
                assert_eq!(f.w_amp, 0xF000);
                assert_eq!(f.w_or, 0xFFF0);
                assert_eq!(f.w_orn, 0xF0FF);
                assert_eq!(f.w_xor, 0x0FF0);
                assert_eq!(f.w_xorn, 0xF00F);
                assert_eq!(f.w_not, 0x0F0F);
                assert_eq!(f.w_ldn, 0x0F0F);
                assert_eq!(f.w_stn, 0x0F0F);
                assert!(!f.w_eq);
                assert!(!f.w_gt, "16#F0F0 > 16#FF00 is false");
                assert_eq!(f.b_and, 0b0000_0101);
                assert_eq!(f.b_or, 0b1010_1111);
                assert_eq!(f.b_xor, 0b0101_1010);
                assert_eq!(f.b_not, 0b0101_1010);
                assert_eq!(f.d_not, !0x1234_5678u32);
                assert_eq!(f.d_and, 0x0000_5678);
                assert_eq!(f.l_xor, 0x0123_4567_89AB_CDEF ^ 0xFFFF_FFFF_0000_0000);
            }
        }
    };
}

ops_bool_tests!(via_build);
ops_bool_tests!(via_macro);
