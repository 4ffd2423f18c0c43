//! Fuzz target `pipeline`: see `il_fuzz::pipeline` (src/lib.rs) and README.md.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| il_fuzz::pipeline(data));
