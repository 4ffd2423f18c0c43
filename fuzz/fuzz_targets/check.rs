//! Fuzz target `check`: see `il_fuzz::check` (src/lib.rs) and README.md.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| il_fuzz::check(data));
