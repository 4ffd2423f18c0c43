//! Jumps, labels and returns (plc/jumps.il) through both front ends.

use il_std::Cycle;

macro_rules! jump_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{
                JumpFwd, JumpJoin, JumpLoop, JumpLoopBottom, RetCnFn, RetFb, RetFn, RetNcFb,
                RetProg,
            };

            #[test]
            fn forward_jumps() {
                let mut ctx = Cycle::new();
                let mut f = JumpFwd::default();
                f.sel = true;
                f.call(&mut ctx);
                assert_eq!(f.via_jmp, 2, "JMP skips");
                assert_eq!(f.via_jmpc, 10, "JMPC taken on TRUE");
                assert_eq!(f.via_jmpcn, 40, "JMPCN not taken on TRUE");
                assert_eq!(f.via_jmpnc, 60, "JMPNC not taken on TRUE");
                let mut f = JumpFwd::default();
                f.sel = false;
                f.call(&mut ctx);
                assert_eq!(f.via_jmp, 2);
                assert_eq!(f.via_jmpc, 20, "JMPC not taken on FALSE");
                assert_eq!(f.via_jmpcn, 30, "JMPCN taken on FALSE");
                assert_eq!(f.via_jmpnc, 50, "JMPNC taken on FALSE");
            }

            #[test]
            fn backward_counting_loop() {
                let mut ctx = Cycle::new();
                let mut f = JumpLoop::default();
                assert_eq!(f.n, 100, "initial value");
                f.call(&mut ctx);
                assert_eq!(f.count, 100);
                assert_eq!(f.sum, 100);
                f.call(&mut ctx);
                assert_eq!(f.count, 100, "the loop restarts each call");
                f.n = 10_000;
                f.call(&mut ctx);
                assert_eq!(f.sum, 10_000);
                f.n = 0;
                f.call(&mut ctx);
                assert_eq!((f.count, f.sum), (0, 0));
            }

            #[test]
            fn loop_tested_at_the_bottom() {
                let mut ctx = Cycle::new();
                let mut f = JumpLoopBottom::default();
                f.call(&mut ctx);
                assert_eq!(f.iterations, 10);
                assert_eq!(f.acc, 1024);
            }

            #[test]
            fn label_reached_from_fall_through_and_two_jumps() {
                let mut ctx = Cycle::new();
                let mut f = JumpJoin::default();
                f.val = 21;
                for (mode, out) in [(1, 21), (2, 42), (3, 0), (0, 0)] {
                    f.mode = mode;
                    f.out = -1;
                    f.call(&mut ctx);
                    assert_eq!(f.out, out, "mode {mode}");
                }
            }

            #[test]
            fn ret_retc_retcn_in_function_block() {
                let mut ctx = Cycle::new();
                let mut f = RetFb::default();
                f.c = true;
                f.call(&mut ctx);
                assert_eq!(f.stage, 1, "RETC returns on TRUE");
                f.c = false;
                f.call(&mut ctx);
                assert_eq!(f.stage, 2, "RETC goes on and RETCN returns on FALSE");
                let mut g = RetNcFb::default();
                g.c = false;
                g.call(&mut ctx);
                assert_eq!(g.stage, 1, "RETNC returns on FALSE");
                g.c = true;
                g.call(&mut ctx);
                assert_eq!(g.stage, 2, "RET returns unconditionally");
            }

            #[test]
            fn ret_in_functions_keeps_the_stored_result() {
                let mut ctx = Cycle::new();
                assert_eq!(RetFn(&mut ctx, true, 5), 5);
                assert_eq!(RetFn(&mut ctx, false, 5), 105);
                assert_eq!(RetCnFn(&mut ctx, false), -1);
                assert_eq!(RetCnFn(&mut ctx, true), 1);
            }

            #[test]
            fn ret_in_program_ends_the_scan() {
                let mut ctx = Cycle::new();
                let mut p = RetProg::default();
                p.call(&mut ctx);
                p.stop_early = true;
                p.call(&mut ctx);
                p.call(&mut ctx);
                p.stop_early = false;
                p.call(&mut ctx);
                assert_eq!(p.scans, 4);
                assert_eq!(p.tail_runs, 2);
            }
        }
    };
}

jump_tests!(via_build);
jump_tests!(via_macro);
