//! Benchmarks of il-rs (see `BENCHMARKS.md` at the repository root).
//!
//! - [`generator`] (`src/gen.rs`): deterministic IL generators for the front-end benchmarks.
//! - [`generated`]: the benchmark programs of `plc/*.il`, compiled by
//!   `build.rs` through `il_codegen::Builder`.
//! - [`hand`]: the same logic written by hand in idiomatic Rust, the
//!   baseline the generated scans are compared with.

#[path = "gen.rs"]
pub mod generator; // `gen` is a reserved word in edition 2024
