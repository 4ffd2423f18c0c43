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
        let note = match ctx.now().as_ms() {
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
                "press start"
            }
            1_700 => {
                m.start = false;
                ""
            }
            _ => "",
        };
        m.call(&mut ctx);
        tl.record(ctx.now(), &[&m.start, &m.stop, &m.run, &m.starts], note);
        ctx.advance(SCAN);
    }
    tl
}
