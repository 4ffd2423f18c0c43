//! Fuzz target `front_end`: see `il_fuzz::front_end` (src/lib.rs) and README.md.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| il_fuzz::front_end(data));
