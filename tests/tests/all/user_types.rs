//! User types (TYPE ... END_TYPE) through both front ends: they become plain
//! Rust enums and structs that the host can use directly.

use il_std::{Cycle, FaultKind};

macro_rules! user_type_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Mode, Point, Tank, TankCtl};

            #[test]
            fn defaults_and_initial_values() {
                let c = TankCtl::default();
                assert_eq!(c.state, Mode::Idle);
                assert_eq!(c.tank.level, 50);
                assert_eq!(c.tank.corner, Point { x: 3, y: 7 });
                assert_eq!(c.tank.name.to_string(), "tank");
                assert_eq!(c.tanks[0].level, 10, "the STRUCT's own initial value");
                assert_eq!(Tank::default().corner.y, 7);
                assert_eq!(Mode::Draining as i32, 5);
            }

            #[test]
            fn enums_structs_arrays_and_subranges() {
                let mut ctx = Cycle::new();
                let mut c = TankCtl::default();
                c.demand = 30;
                c.call(&mut ctx);
                assert_eq!((c.state, c.is_draining), (Mode::Filling, false));
                assert_eq!((c.tank.level, c.tanks[1].level), (30, 30));
                assert_eq!(c.tank.mode, Mode::Filling);
                assert_eq!(c.copy, c.tank.corner);
                c.demand = 80;
                c.call(&mut ctx);
                assert_eq!((c.state, c.is_draining), (Mode::Draining, true));
                assert_eq!(ctx.fault_count(), 0);
                // 150 is outside Percent (0..100): the store is skipped and recorded.
                c.demand = 150;
                c.call(&mut ctx);
                assert_eq!(c.pct, 80);
                let f = ctx.last_fault().copied().unwrap();
                assert_eq!((f.kind, f.pou), (FaultKind::SubrangeViolation, "TankCtl"));
            }
        }
    };
}

user_type_tests!(via_build);
user_type_tests!(via_macro);

macro_rules! fb_array_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_std::TIME;
            use il_tests::$m::TimerBank;

            /// An array of TON instances called by index in a loop.
            #[test]
            fn arrays_of_function_blocks() {
                let mut ctx = Cycle::new();
                let mut b = TimerBank::default();
                b.start = [true, true, true];
                for _ in 0..2 {
                    b.call(&mut ctx);
                    ctx.advance(TIME::from_ms(100));
                }
                // After 200 ms: timers 1 (100 ms) and 2 (200 ms) are done.
                b.call(&mut ctx);
                assert_eq!(b.done, [true, true, false]);
                assert_eq!(b.timers[2].PT, TIME::from_ms(300));
                assert_eq!(ctx.fault_count(), 0);
            }
        }
    };
}

mod fb_arrays {
    use super::*;
    fb_array_tests!(via_build);
    fb_array_tests!(via_macro);
}
