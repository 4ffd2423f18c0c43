//! Batch weighing (`plc/batch_weigh.il`, through build.rs): a FUNCTION with
//! EN/ENO that shows the net weight in BCD, a filling sequence with a fast
//! and a dribble valve, and a division by zero that is recorded, not a panic.

use crate::plc::BatchWeigher;
use crate::{SCAN, Timeline};
use il_std::Cycle;

/// Put an empty container on the scale, tare, start, fill fast and then
/// slowly to 50.0 kg, settle; take the container off (the display holds
/// its value while NET_BCD's ENO is FALSE), put the next one on and tare;
/// then an
/// operator enters a target of 0.
pub fn run() -> Timeline {
    let mut tl = Timeline::new(
        "batch weighing: weights in 0.1 kg, target 500, dribble below 450; display is BCD",
        &["gross", "tare", "start", "target"],
        &[
            "net", "display", "ok", "%", "fast", "slow", "done", "faults",
        ],
    );
    let mut ctx = Cycle::new();
    let mut w = BatchWeigher::default();
    while ctx.now().as_ms() <= 5_700 {
        let note = match ctx.now().as_ms() {
            0 => "empty scale",
            300 => {
                w.gross = 123;
                "put a 12.3 kg container on the scale"
            }
            600 => {
                w.tare_key = true;
                "TARE"
            }
            700 => {
                w.tare_key = false;
                ""
            }
            1_000 => {
                w.start_key = true;
                "START"
            }
            1_100 => {
                w.start_key = false;
                ""
            }
            4_500 => {
                w.gross = 0;
                "take the full container off: net < 0, ENO = FALSE"
            }
            5_000 => {
                w.gross = 121;
                "put the next empty container on"
            }
            5_200 => {
                w.tare_key = true;
                "TARE"
            }
            5_300 => {
                w.tare_key = false;
                ""
            }
            5_500 => {
                w.target = 0;
                "an operator enters a target of 0"
            }
            _ => "",
        };
        w.call(&mut ctx);
        tl.record(
            ctx.now(),
            &[
                &w.gross,
                &w.tare_key,
                &w.start_key,
                &w.target,
                &w.net,
                &format!("{:04X}", w.display).as_str(),
                &w.display_ok,
                &w.percent,
                &w.fast_valve,
                &w.slow_valve,
                &w.done,
                &ctx.fault_count(),
            ],
            note,
        );
        // The plant: the valves pour 4.0 kg/s (fast) or 0.5 kg/s (dribble).
        if w.fast_valve {
            w.gross += 40;
        } else if w.slow_valve {
            w.gross += 5;
        }
        ctx.advance(SCAN);
    }
    if let Some(f) = ctx.last_fault() {
        tl.footer(format!(
            "{} faults recorded; the last: {f} (the percentage is 0 instead)",
            ctx.fault_count()
        ));
    }
    tl
}
