//! The rows measured against MATIEC (issue 14): scan time of each benchmark
//! program against iec2c's C at gcc -O2 (`benches/matiec_compare.sh`) and the
//! release build of the 10k-line program's output against gcc on iec2c's C
//! (`benches/matiec_build.sh`). MATIEC is built outside this repository, so
//! the rows run only when `IEC2C` (its `iec2c` binary) and `MATIEC_LIB` (its
//! `lib` directory) are set; otherwise this says so and does nothing.
//!
//! `IEC2C=... MATIEC_LIB=... cargo bench -p il-bench --bench matiec`

use std::process::{Command, ExitCode};

fn main() -> ExitCode {
    if std::env::var_os("IEC2C").is_none() || std::env::var_os("MATIEC_LIB").is_none() {
        println!(
            "matiec: skipped (set IEC2C to MATIEC's iec2c and MATIEC_LIB to its lib directory; \
             see benches/matiec_compare.sh)"
        );
        return ExitCode::SUCCESS;
    }
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/");
    for script in ["matiec_compare.sh", "matiec_build.sh"] {
        println!("== {script}");
        // The scripts print their tables; a failure (iec2c refusing a program,
        // checksums that differ) fails the bench.
        match Command::new("bash").arg(format!("{dir}{script}")).status() {
            Ok(s) if s.success() => {}
            Ok(s) => {
                eprintln!("matiec: {script} failed ({s})");
                return ExitCode::FAILURE;
            }
            Err(e) => {
                eprintln!("matiec: cannot run bash for {script}: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}
