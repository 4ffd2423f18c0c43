//! A configuration of two tasks (`plc/bottling.il`, through build.rs): the
//! host calls `Line::run` every 100 ms of simulated time; the `Fast` task
//! (every 200 ms) runs `Fill`, the `Slow` task (every second, lower
//! priority) runs `Report`. The `ran` column shows which programs ran in
//! each host cycle, in the order they ran.

use crate::plc::Line;
use crate::{SCAN, Timeline};
use il_std::Cycle;

/// Three seconds of the line, stopped for a moment at 1.5 s.
pub fn run() -> Timeline {
    let mut tl = Timeline::new(
        "bottling line: CONFIGURATION Line, task Fast (200 ms) runs Fill, task Slow (1 s) runs Report",
        &["running"],
        &["ran", "bottles", "rate", "valve"],
    );
    let mut ctx = Cycle::new();
    let mut line = Line::default();
    while ctx.now().as_ms() <= 3_000 {
        let note = match ctx.now().as_ms() {
            1_500 => {
                line.running = false;
                "operator stops the line"
            }
            1_900 => {
                line.running = true;
                "line restarts"
            }
            _ => "",
        };
        let mut ran: Vec<String> = Vec::new();
        line.run_traced(&mut ctx, |task, program| {
            ran.push(format!("{task}:{program}"))
        });
        let ran = if ran.is_empty() {
            "-".to_string()
        } else {
            ran.join(" ")
        };
        // The valve is a located global: it lives in the process image.
        let valve = Line::io_valve(&ctx); // valve AT %QX0.0
        tl.record(
            ctx.now(),
            &[
                &line.running,
                &ran.as_str(),
                &line.bottles,
                &line.rate,
                &valve,
            ],
            note,
        );
        ctx.advance(SCAN);
    }
    tl.footer(format!(
        "tasks: {}; overruns per task: {:?}",
        Line::TASKS
            .iter()
            .map(|t| format!("{} every {} (priority {})", t.name, t.interval, t.priority))
            .collect::<Vec<_>>()
            .join(", "),
        line.overruns()
    ));
    tl
}
