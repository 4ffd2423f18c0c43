//! A motor starter with interlocks (`plc/motor_starter.il`, through
//! build.rs). Its variables are located (`AT %IX0.0` ...), so the host
//! talks to it through the process image `Cycle::io`, as a fieldbus driver
//! would: by the IL variable's name (the generated `io_NAME`/`set_io_NAME`)
//! or by the IEC address (`il_std::addr`), both typed.

use crate::plc::MotorStarter;
use crate::{SCAN, Timeline};
use il_std::Cycle;
use il_std::addr::{ix, mw, qx};

/// The inputs, as bits of input byte 0 (`%IX0.0` .. `%IX0.4`).
#[derive(Clone, Copy, Debug, Default)]
struct Panel {
    start: bool,
    stop_ok: bool,
    overload: bool,
    guard_ok: bool,
    reset: bool,
}

impl Panel {
    fn write(&self, ctx: &mut Cycle) {
        MotorStarter::set_io_start_pb(ctx, self.start); // start_pb AT %IX0.0
        MotorStarter::set_io_stop_pb(ctx, self.stop_ok); // stop_pb AT %IX0.1
        ctx.io.set(ix(0, 2), self.overload); // %IX0.2, by its address
        ctx.io.set(ix(0, 3), self.guard_ok);
        ctx.io.set(ix(0, 4), self.reset);
    }
}

/// Start, stop, an interlock that blocks a held START, an overload trip that
/// RESET cannot clear while it persists, and a restart.
pub fn run() -> Timeline {
    let mut tl = Timeline::new(
        "motor starter with interlocks, through the process image:\n\
         in  %IX0.0 START, %IX0.1 STOP (normally closed), %IX0.2 overload, %IX0.3 guard closed, %IX0.4 RESET\n\
         out %QX0.0 contactor, %QX0.1 fault lamp, %MW2 starts",
        &["START", "STOP", "ovld", "guard", "RESET"],
        &["contactor", "fault", "starts"],
    );
    let mut ctx = Cycle::new();
    let mut prg = MotorStarter::default();
    let mut p = Panel {
        stop_ok: true,
        guard_ok: true,
        ..Panel::default()
    };
    while ctx.now().as_ms() <= 8_000 {
        let note = match ctx.now().as_ms() {
            0 => "power on: STOP released, guard closed",
            500 => {
                p.start = true;
                "press START"
            }
            700 => {
                p.start = false;
                "release START: sealed in"
            }
            1_500 => {
                p.stop_ok = false;
                "press STOP"
            }
            1_700 => {
                p.stop_ok = true;
                "release STOP"
            }
            2_000 => {
                p.guard_ok = false;
                "open the guard door"
            }
            2_200 => {
                p.start = true;
                "press and hold START: interlocked"
            }
            2_600 => {
                p.guard_ok = true;
                "close the guard: no start without a new press"
            }
            3_000 => {
                p.start = false;
                "release START"
            }
            3_400 => {
                p.start = true;
                "press START"
            }
            3_600 => {
                p.start = false;
                ""
            }
            4_000 => {
                p.overload = true;
                "overload trips"
            }
            4_500 => {
                p.reset = true;
                "RESET while still overloaded: no effect"
            }
            4_700 => {
                p.reset = false;
                ""
            }
            5_500 => {
                p.overload = false;
                "overload relay cools down"
            }
            6_000 => {
                p.reset = true;
                "RESET: fault cleared"
            }
            6_200 => {
                p.reset = false;
                ""
            }
            7_000 => {
                p.start = true;
                "press START"
            }
            7_200 => {
                p.start = false;
                ""
            }
            _ => "",
        };
        p.write(&mut ctx);
        prg.call(&mut ctx);
        let contactor = MotorStarter::io_contactor(&ctx); // contactor AT %QX0.0
        let lamp = ctx.io.get(qx(0, 1)); // %QX0.1: a bool
        let starts = ctx.io.get(mw(2).int()); // %MW2 read as an INT: an i16
        tl.record(
            ctx.now(),
            &[
                &p.start,
                &p.stop_ok,
                &p.overload,
                &p.guard_ok,
                &p.reset,
                &contactor,
                &lamp,
                &starts,
            ],
            note,
        );
        ctx.advance(SCAN);
    }
    tl
}
