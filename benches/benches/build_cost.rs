//! Group 3, build cost: the `il!` expansion of a 1k-line POU (what the
//! proc macro does inside rustc: parse the literal, compile, return tokens),
//! and of the README's motor. Cold and incremental `cargo build` of user
//! crates are measured by `benches/build_cost.sh` (minutes, so not here).
//!
//! `cargo bench -p il-bench --bench build_cost`

use divan::{Bencher, black_box};
use il_bench::generator;
use il_codegen::expand::Tok;

fn main() {
    divan::main();
}

fn input(il: &str) -> Vec<Tok> {
    vec![Tok::string(il, 0)]
}

#[divan::bench(args = [1_000, 10_000])]
fn il_macro_expand(b: Bencher, lines: usize) {
    let il = generator::big_pou(lines, 1);
    b.with_inputs(|| input(&il))
        .bench_local_values(|t| black_box(il_codegen::expand::expand(&t)));
}

#[divan::bench]
fn il_macro_expand_motor(b: Bencher) {
    let il = include_str!("../../examples/motor.il");
    b.with_inputs(|| input(il))
        .bench_local_values(|t| black_box(il_codegen::expand::expand(&t)));
}
