//! Benchmarks of il-rs (see `BENCHMARKS.md` at the repository root).
//!
//! - [`generator`] (`src/gen.rs`): deterministic IL generators for the
//!   front-end benchmarks and for the larger benchmark programs.
//! - [`generated`]: the benchmark programs of `plc/*.il`, compiled by
//!   `build.rs` through `il_codegen::Builder`.
//! - [`hand`]: the same logic written by hand in idiomatic Rust, the
//!   baseline the generated scans are compared with.

#[path = "gen.rs"]
pub mod generator; // `gen` is a reserved word in edition 2024

pub mod hand;
pub mod inputs;

/// The scan benchmark programs, generated from `plc/*.il` by `build.rs`.
pub mod generated {
    include!(concat!(env!("OUT_DIR"), "/arith_loop.rs"));
    include!(concat!(env!("OUT_DIR"), "/array_proc.rs"));
    include!(concat!(env!("OUT_DIR"), "/blocks.rs"));
    include!(concat!(env!("OUT_DIR"), "/blocks_loop.rs"));
    include!(concat!(env!("OUT_DIR"), "/interlock.rs"));
    include!(concat!(env!("OUT_DIR"), "/mixed.rs"));
}
