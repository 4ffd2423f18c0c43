//! Fuzz target `front_end`: see `il_fuzz::front_end` (src/lib.rs) and README.md.
#![no_main]

// Peak allocation per input is counted: over `memory_budget` is a finding.
#[global_allocator]
static ALLOC: il_fuzz::Counting = il_fuzz::Counting;

libfuzzer_sys::fuzz_target!(|data: &[u8]| il_fuzz::within_memory(il_fuzz::front_end, data));
