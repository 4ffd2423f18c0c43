//! Group 4, memory: `size_of` of every il-std block and of the generated
//! FB/PROGRAM structs against the sum of their fields' sizes (the rest is
//! padding), and the peak memory (VmHWM) of compiling the 100k-line POU.
//!
//! `cargo bench -p il-bench --bench memory`
//!
//! The field lists of the il-std blocks mirror their declarations in
//! `il-std/src/fb` (private state included); `size_of` is measured.

use il_bench::{generated as g, generator};
use il_std::*;
use std::mem::{size_of, size_of_val};

const B: usize = size_of::<bool>();
const T: usize = size_of::<TIME>();
const D: usize = size_of::<DT>();

fn row(name: &str, size: usize, fields: usize) {
    println!("{name:<14} {size:>6} {fields:>6} {:>8}", size - fields);
}

fn main() {
    if std::env::args().any(|a| a == "--list" || a == "--test") {
        return;
    }
    println!("il-std blocks: size_of, sum of field sizes, padding (bytes)");
    println!(
        "{:<14} {:>6} {:>6} {:>8}",
        "block", "size", "fields", "padding"
    );
    row("SR", size_of::<SR>(), 3 * B);
    row("RS", size_of::<RS>(), 3 * B);
    row("R_TRIG", size_of::<R_TRIG>(), 3 * B);
    row("F_TRIG", size_of::<F_TRIG>(), 3 * B);
    macro_rules! counters {
        ($($ctu:ident $ctd:ident $ctud:ident $t:ty),*) => {$(
            row(stringify!($ctu), size_of::<$ctu>(), 4 * B + 2 * size_of::<$t>());
            row(stringify!($ctd), size_of::<$ctd>(), 4 * B + 2 * size_of::<$t>());
            row(stringify!($ctud), size_of::<$ctud>(), 8 * B + 2 * size_of::<$t>());
        )*};
    }
    counters!(CTU CTD CTUD i16, CTU_INT CTD_INT CTUD_INT i16, CTU_DINT CTD_DINT CTUD_DINT i32,
        CTU_LINT CTD_LINT CTUD_LINT i64, CTU_UDINT CTD_UDINT CTUD_UDINT u32,
        CTU_ULINT CTD_ULINT CTUD_ULINT u64);
    // TP: IN PT Q ET in_m state(1-byte enum) acc last
    row("TP", size_of::<TP>(), 3 * B + 1 + 4 * T);
    // TON: IN PT Q ET running acc last
    row("TON", size_of::<TON>(), 3 * B + 4 * T);
    // TOF: IN PT Q ET in_m timing acc last
    row("TOF", size_of::<TOF>(), 4 * B + 4 * T);
    // RTC: IN PDT Q CDT in_m base acc last
    row("RTC", size_of::<RTC>(), 3 * B + 3 * D + 2 * T);
    println!(
        "(the host's Cycle context, not a block: {} bytes)",
        size_of::<Cycle>()
    );

    println!("\ngenerated structs (plc/*.il): size_of, sum of field sizes, padding (bytes)");
    println!(
        "{:<14} {:>6} {:>6} {:>8}",
        "struct", "size", "fields", "padding"
    );
    macro_rules! fields {
        ($v:expr; $($f:ident),*) => { 0 $(+ size_of_val(&$v.$f))* };
    }
    let s = g::Station::default();
    row(
        "Station",
        size_of_val(&s),
        fields!(s; go, reset, done, count, t, e, c),
    );
    let b = g::Blocks::default();
    row(
        "Blocks",
        size_of_val(&b),
        fields!(b; go, reset, done, count) + generator::STATIONS * size_of::<g::Station>(),
    );
    let i = g::Interlock::default();
    row("Interlock", size_of_val(&i), fields!(i; x, m));
    let a = g::ArithLoop::default();
    row("ArithLoop", size_of_val(&a), fields!(a; n, seed, acc, x, i));
    let p = g::ArrayProc::default();
    row(
        "ArrayProc",
        size_of_val(&p),
        fields!(p; samples, gain, filtered, peak, i, acc),
    );

    // Peak resident memory of the whole front end on the 100k-line POU.
    let file = il_codegen::diag::SourceFile::new("big.il", generator::big_pou(100_000, 1));
    let before = vm_hwm_kib();
    let program = il_codegen::Program::new().il(file.clone());
    let checked = program.check();
    let opts = il_codegen::EmitOptions {
        line_markers: true,
        ..Default::default()
    };
    let c = checked.emit(opts).expect("compiles").remove(0);
    let after = vm_hwm_kib();
    let text = c.file_text();
    let with_file = vm_hwm_kib();
    println!(
        "\npeak memory (VmHWM), 100k-line POU ({} KiB of IL): before compile {before} KiB, after compile {after} KiB (+{} KiB), after formatting the .rs ({} KiB) {with_file} KiB",
        file.text.len() / 1024,
        after.saturating_sub(before),
        text.len() / 1024
    );
}

fn vm_hwm_kib() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse().ok())
        })
        .unwrap_or(0)
}
