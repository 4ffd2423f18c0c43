//! `gen_il <lines> [seed] [--labels | --matiec]`: prints the front-end
//! benchmark's generated POU to stdout (`il_bench::generator::big_pou`, or
//! with `--labels` the MATIEC-style `big_pou_labels` with a label every ~45
//! lines, or with `--matiec` `matiec_program`: the same rungs in POUs of 400
//! lines, in forms MATIEC's iec2c translates), to measure what the release `ilc check` / `ilc emit` make of it
//! (time, peak memory, bytes of Rust per IL line, release build time).

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let labels = args.iter().any(|a| a == "--labels");
    let matiec = args.iter().any(|a| a == "--matiec");
    let mut nums = args.iter().filter(|a| !a.starts_with("--"));
    let lines = nums.next().and_then(|a| a.parse().ok());
    let seed = nums.next().and_then(|a| a.parse().ok()).unwrap_or(1);
    let Some(lines) = lines else {
        eprintln!("usage: gen_il <lines> [seed] [--labels | --matiec]");
        std::process::exit(2);
    };
    if matiec {
        print!("{}", il_bench::generator::matiec_program(lines, seed));
    } else if labels {
        print!("{}", il_bench::generator::big_pou_labels(lines, seed));
    } else {
        print!("{}", il_bench::generator::big_pou(lines, seed));
    }
}
