//! Waveforms of the README's motor: the host records the variables the
//! generated `Motor` offers (`Motor::visit`, including its R_TRIG `edge`)
//! with [`il_trace::Recorder`] once per scan, as a VCD file for GTKWave or
//! Surfer. `cargo run -p il-examples --example trace_motor` writes
//! `target/motor.vcd`.

use std::io::{self, Write};

use crate::readme_motor::{Motor, operator};
use crate::{SCAN, Timeline};
use il_std::Cycle;
use il_trace::Recorder;

/// Run the motor over 2 s (start, seal-in, stop, restart), recording every
/// scan to `out`; the time-line shows what was recorded.
pub fn record(out: &mut dyn Write) -> io::Result<Timeline> {
    let mut tl = Timeline::new(
        "README motor, recorded as VCD: every variable of Motor and of its R_TRIG",
        &["start", "stop"],
        &["run", "starts", "edge.Q"],
    );
    let mut rec = Recorder::new(out, "motor", SCAN)?;
    let mut ctx = Cycle::new();
    let mut m = Motor::default();
    while ctx.now().as_ms() <= 2_000 {
        let note = operator(&mut m, ctx.now().as_ms());
        m.call(&mut ctx);
        // After the scan: what a logic analyser on the PLC would see.
        rec.sample(ctx.now(), &m)?;
        tl.record(
            ctx.now(),
            &[&m.start, &m.stop, &m.run, &m.starts, &m.edge.Q],
            note,
        );
        ctx.advance(SCAN);
    }
    rec.finish()?;
    Ok(tl)
}

/// [`record`] to the file `path`, written under a temporary name and
/// renamed at the end: an error never leaves half a file.
pub fn write(path: &std::path::Path) -> io::Result<()> {
    let mut f = il_trace::AtomicFile::create(path)?;
    record(&mut f)?;
    f.commit()
}

/// [`record`] to nowhere: the time-line alone (for [`crate::ALL`]).
pub fn run() -> Timeline {
    match record(&mut io::sink()) {
        Ok(tl) => tl,
        // A sink never fails; say so rather than panic if it ever did.
        Err(e) => Timeline::new(&format!("recording failed: {e}"), &[], &[]),
    }
}
