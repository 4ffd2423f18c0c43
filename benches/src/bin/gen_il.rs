//! `gen_il <lines> [seed] [--labels]`: prints the front-end benchmark's
//! generated POU to stdout (`il_bench::generator::big_pou`, or with
//! `--labels` the MATIEC-style `big_pou_labels` with a label every ~45
//! lines), to measure what the release `ilc check` / `ilc emit` make of it
//! (time, peak memory, bytes of Rust per IL line, release build time).

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let labels = args.iter().any(|a| a == "--labels");
    let mut nums = args.iter().filter(|a| *a != "--labels");
    let lines = nums.next().and_then(|a| a.parse().ok());
    let seed = nums.next().and_then(|a| a.parse().ok()).unwrap_or(1);
    let Some(lines) = lines else {
        eprintln!("usage: gen_il <lines> [seed] [--labels]");
        std::process::exit(2);
    };
    if labels {
        print!("{}", il_bench::generator::big_pou_labels(lines, seed));
    } else {
        print!("{}", il_bench::generator::big_pou(lines, seed));
    }
}
