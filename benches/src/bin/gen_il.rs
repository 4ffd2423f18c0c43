//! `gen_il <lines> [seed]`: prints the front-end benchmark's generated POU
//! (`il_bench::generator::big_pou`) to stdout, to measure what the emitter
//! makes of it (`ilc emit`, bytes of Rust per IL line, release build time).

fn main() {
    let mut args = std::env::args().skip(1);
    let lines = args.next().and_then(|a| a.parse().ok());
    let seed = args.next().and_then(|a| a.parse().ok()).unwrap_or(1);
    let Some(lines) = lines else {
        eprintln!("usage: gen_il <lines> [seed]");
        std::process::exit(2);
    };
    print!("{}", il_bench::generator::big_pou(lines, seed));
}
