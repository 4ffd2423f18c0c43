//! The README's motor (`examples/motor.il`, the file that
//! `cargo run -p il-cli -- emit examples/motor.il` compiles), through
//! `il!(file = ...)`: the path is relative to this crate's `Cargo.toml`.

use crate::{SCAN, Timeline};
use il_std::Cycle;

il_macros::il!(file = "motor.il");

/// Start, seal-in, stop, and a second start; `starts` counts rising edges.
pub fn run() -> Timeline {
    let mut tl = Timeline::new(
        "README motor: seal-in contact, starts counted with R_TRIG",
        &["start", "stop"],
        &["run", "starts"],
    );
    let mut ctx = Cycle::new();
    let mut m = Motor::default();
    while ctx.now().as_ms() <= 2_000 {
        let note = operator(&mut m, ctx.now().as_ms());
        m.call(&mut ctx);
        tl.record(ctx.now(), &[&m.start, &m.stop, &m.run, &m.starts], note);
        ctx.advance(SCAN);
    }
    tl
}

/// What the operator does at `ms` into the run (start, seal-in, stop, a
/// second start), and the note for the time-line: the scenario of [`run`]
/// and of the recorded `trace_motor`.
pub fn operator(m: &mut Motor, ms: i64) -> &'static str {
    match ms {
        200 => {
            m.start = true;
            "press start"
        }
        400 => {
            m.start = false;
            "release: sealed in"
        }
        1_000 => {
            m.stop = true;
            "press stop"
        }
        1_200 => {
            m.stop = false;
            ""
        }
        1_500 => {
            m.start = true;
            "press start again"
        }
        1_700 => {
            m.start = false;
            ""
        }
        _ => "",
    }
}
