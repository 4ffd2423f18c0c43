//! `cargo run -p il-examples --example trace_motor [FILE]`: the README's motor
//! recorded as a VCD waveform (default `target/motor.vcd`); open it with
//! `gtkwave target/motor.vcd` or `surfer target/motor.vcd`.

use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let path = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/motor.vcd"));
    if let Err(e) = il_examples::trace_motor::write(&path) {
        eprintln!("error: {}: {e}", path.display());
        return ExitCode::FAILURE;
    }
    // The same run's time-line.
    print!("{}", il_examples::trace_motor::run());
    println!("wrote {}", path.display());
    ExitCode::SUCCESS
}
