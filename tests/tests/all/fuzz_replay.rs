//! Replays every fuzz target (`fuzz/src/lib.rs`) over the checked-in seeds
//! and regressions (`fuzz/regressions`), our IL programs (`tests/plc`,
//! `tests/plc-hostile`) and the
//! shared real-world corpus when it is present. A crash found by fuzzing is
//! fixed and its input kept in `fuzz/regressions`, so this test keeps it fixed
//! on stable Rust, in CI, without libFuzzer.
//!
//! Each run has a time budget (`IL_FUZZ_BUDGET_SECS`, default 30 s in this
//! debug build, far above the slowest input): the hang inputs of earlier
//! defects (exponential instance trees and type graphs, many diagnostics on
//! one long line) took minutes, and a run over budget fails the test with its
//! input named instead of hanging CI. And a memory budget
//! (`targets::memory_budget`, max(64 MiB, 2000 x the input)): the peak
//! allocation of each run is counted per thread by the allocator installed
//! here (for this whole test binary: a thread-local add per allocation).

#[path = "../../../fuzz/src/lib.rs"]
#[allow(dead_code)]
mod targets;

#[global_allocator]
static ALLOC: targets::Counting = targets::Counting;

use std::path::{Path, PathBuf};

fn files(dir: &Path) -> Vec<PathBuf> {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut v: Vec<PathBuf> = rd
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .collect();
    v.sort();
    v
}

#[test]
fn every_target_over_the_seed_and_regression_corpus() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let regressions = files(&root.join("fuzz/regressions"));
    assert!(
        regressions.len() >= 10,
        "fuzz/regressions holds the seeds and regressions"
    );
    let mut inputs = regressions;
    inputs.extend(files(&root.join("tests/plc")));
    inputs.extend(files(&root.join("tests/plc-hostile")));
    inputs.extend(files(&root.join("../shared/corpus")));
    let budget = targets::budget(30);
    let mut runs = 0;
    let mut largest = (0, 0, String::new());
    for path in &inputs {
        let data = std::fs::read(path).expect("read a corpus file");
        for (name, target) in targets::TARGETS {
            let (outcome, peak) = targets::run_measured(*target, data.clone(), budget);
            if peak > largest.0 {
                largest = (peak, data.len(), format!("{name} on {}", path.display()));
            }
            assert_eq!(
                outcome,
                targets::Outcome::Ok,
                "target `{name}` on {} (budget {budget:?})",
                path.display()
            );
            runs += 1;
        }
    }
    println!("{runs} runs over {} inputs", inputs.len());
    println!(
        "largest peak allocation: {:.1} MiB, {} (an input of {} bytes)",
        largest.0 as f64 / (1 << 20) as f64,
        largest.2,
        largest.1
    );
}
