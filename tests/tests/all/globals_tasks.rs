//! VAR_GLOBAL / VAR_EXTERNAL, VAR_IN_OUT and a CONFIGURATION of two tasks
//! (`plc/globals_tasks.il`), through build.rs and through `il!`.

use il_std::{Area, Cycle, TIME};

macro_rules! globals_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{
                Accumulate, Accumulate__Ext, FastLoop, FastLoop__Ext, Plant, SwapInts,
            };

            #[test]
            fn function_in_outs_change_the_callers_variables() {
                let mut ctx = Cycle::new();
                let (mut a, mut b) = (1i16, 2i16);
                assert!(SwapInts(&mut ctx, &mut a, &mut b));
                assert_eq!((a, b), (2, 1));
            }

            #[test]
            fn fb_in_out_and_external_are_the_callers() {
                let mut ctx = Cycle::new();
                let mut fb = Accumulate::default();
                let (mut total, mut calls) = (40i32, 0i32);
                fb.step = 2;
                fb.call(&mut ctx, &mut total, Accumulate__Ext { calls: &mut calls });
                fb.call(&mut ctx, &mut total, Accumulate__Ext { calls: &mut calls });
                assert_eq!((total, calls, fb.after), (44, 2, 44));
            }

            #[test]
            fn program_uses_globals_through_references() {
                let mut ctx = Cycle::new();
                let mut p = FastLoop::default();
                let (mut ticks, mut calls, limit) = (0i32, 0i32, 2i32);
                for _ in 0..3 {
                    p.call(
                        &mut ctx,
                        FastLoop__Ext {
                            ticks: &mut ticks,
                            calls: &mut calls,
                            limit: &limit,
                        },
                    );
                }
                // Two CALs of the accumulator per scan; sum grows by 2, arr[2] by 10.
                assert_eq!((ticks, calls, p.seen), (3, 6, 3));
                assert_eq!((p.sum, p.arr), (6, [0, 30, 0]));
                // Each scan: x := 3, then SwapInts(x, y). Scan 1: (3, 7) → (7, 3);
                // then y stays 3.
                assert_eq!((p.x, p.y, p.swapped), (3, 3, true));
                // lamp is located at %QX0.0 in the configuration, so the program writes the image.
                assert!(ctx.io.bit(Area::Output, 0, 0));
                assert_eq!(FastLoop::ADDRESSES.len(), 1);
            }

            #[test]
            fn configuration_runs_tasks_by_interval_and_priority() {
                let mut ctx = Cycle::new();
                let mut plant = Plant::default();
                let mut log = Vec::new();
                for ms in (0..=100).step_by(5) {
                    ctx.set_now(TIME::from_ms(ms));
                    plant.run_traced(&mut ctx, |task, prog| log.push((ms, task, prog)));
                }
                let fast: Vec<i64> = log.iter().filter(|e| e.1 == "Fast").map(|e| e.0).collect();
                let slow: Vec<i64> = log.iter().filter(|e| e.1 == "Slow").map(|e| e.0).collect();
                assert_eq!(fast, (0..=100).step_by(10).collect::<Vec<_>>());
                assert_eq!(slow, [0, 50, 100]);
                // At 0, 50 and 100 both are due: Fast (PRIORITY 1) runs first.
                assert_eq!(&log[..2], &[(0, "Fast", "Fast1"), (0, "Slow", "Slow1")]);
                // Globals are shared: ticks counts Fast's runs; Slow copies ticks*100
                // into `scaled` through its output binding.
                assert_eq!(plant.ticks, 11);
                assert_eq!(plant.calls, 22);
                assert_eq!(plant.scaled, 1100);
                assert_eq!(plant.Cpu.Slow1.scale, 100);
                assert_eq!(plant.limit, 5);
                // ticks >= limit: the located global %QX0.0 is on.
                assert!(ctx.io.bit(Area::Output, 0, 0));
                assert_eq!(Plant::TASKS.len(), 2);
                assert_eq!(Plant::TASKS[0].programs, &["Fast1"]);
                assert_eq!(Plant::ADDRESSES[0].address, "%QX0.0");
                assert_eq!(plant.overruns(), [0, 0]);
            }

            #[test]
            fn a_late_host_counts_overruns_and_runs_once() {
                let mut ctx = Cycle::new();
                let mut plant = Plant::default();
                assert_eq!(plant.run(&mut ctx), 2);
                ctx.set_now(TIME::from_ms(35));
                // Fast was due at 10, 20, 30: it runs once, two releases missed.
                assert_eq!(plant.run(&mut ctx), 1);
                assert_eq!(plant.overruns(), [2, 0]);
                assert_eq!(plant.ticks, 2);
            }
        }
    };
}

globals_tests!(via_build);
globals_tests!(via_macro);
