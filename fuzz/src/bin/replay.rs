//! Replay saved inputs through one fuzz target in a release build, each
//! with its time and peak allocation: is a `drive-slow-N` slow on its own,
//! or was the machine busy when the drive ran it?
//!
//!     cargo run --release --bin replay -- TARGET FILE...

#[global_allocator]
static ALLOC: il_fuzz::Counting = il_fuzz::Counting;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: replay TARGET FILE...";
    let name = args.get(1).expect(usage);
    let target = il_fuzz::TARGETS
        .iter()
        .find(|(n, _)| n == name)
        .map(|(_, f)| *f)
        .unwrap_or_else(|| panic!("unknown target {name}"));
    let budget = il_fuzz::budget(2);
    for f in &args[2..] {
        let data = std::fs::read(f).unwrap_or_else(|e| panic!("{f}: {e}"));
        let t = std::time::Instant::now();
        let (outcome, peak) = il_fuzz::run_measured(target, data, budget);
        println!(
            "{f}: {outcome:?} in {:.3} s, peak allocation {:.1} MiB",
            t.elapsed().as_secs_f64(),
            peak as f64 / (1 << 20) as f64
        );
    }
}
