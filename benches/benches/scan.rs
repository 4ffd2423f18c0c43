//! Group 2, generated code: one scan of each benchmark program, generated
//! from `plc/*.il` against the hand-written Rust twin (`src/hand`), in the
//! same run. After divan's table, an interleaved A/B loop prints the ratio
//! generated / hand-written per program (medians of alternating rounds, so
//! that load from other processes hits both sides alike).
//!
//! `cargo bench -p il-bench --bench scan`

use divan::{Bencher, black_box};
use il_bench::{generated as g, hand as h};
use il_std::Cycle;
use std::time::{Duration, Instant};

fn main() {
    divan::main();
    if !std::env::args().any(|a| a == "--list" || a == "--test") {
        ratios();
    }
}

use il_bench::inputs::{TICK, go, interlock_x as interlock_inputs, raw, samples};

/// The programs, set up with the same inputs on both sides.
struct Progs {
    ctx: Cycle,
    gi: g::Interlock,
    hi: h::Interlock,
    ga: g::ArithLoop,
    ha: h::ArithLoop,
    gb: g::Blocks,
    hb: h::Blocks,
    gl: g::BlocksLoop,
    gp: g::ArrayProc,
    hp: h::ArrayProc,
    gm: g::Mixed,
    hm: h::Mixed,
}

impl Progs {
    fn new() -> Self {
        let mut p = Progs {
            ctx: Cycle::new(),
            gi: g::Interlock::default(),
            hi: h::Interlock::default(),
            ga: g::ArithLoop::default(),
            ha: h::ArithLoop::default(),
            gb: g::Blocks::default(),
            hb: h::Blocks::default(),
            gl: g::BlocksLoop::default(),
            gp: g::ArrayProc::default(),
            hp: h::ArrayProc::default(),
            gm: g::Mixed::default(),
            hm: h::Mixed::default(),
        };
        p.gi.x = interlock_inputs();
        p.hi.x = p.gi.x;
        p.gb.go = go();
        p.hb.go = p.gb.go;
        p.gl.go = p.gb.go;
        p.gp.samples = samples();
        p.hp.samples = p.gp.samples;
        p.gm.raw = raw();
        p.hm.raw = p.gm.raw;
        p
    }
}

mod interlock {
    use super::*;
    #[divan::bench]
    fn generated(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| black_box(&mut p.gi).call(black_box(&mut p.ctx)));
    }
    #[divan::bench]
    fn hand(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| black_box(&mut p.hi).call());
    }
}

mod arith_loop {
    use super::*;
    #[divan::bench]
    fn generated(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| black_box(&mut p.ga).call(black_box(&mut p.ctx)));
    }
    #[divan::bench]
    fn hand(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| black_box(&mut p.ha).call());
    }
}

mod blocks {
    use super::*;
    #[divan::bench]
    fn generated(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| {
            p.ctx.advance(TICK);
            black_box(&mut p.gb).call(black_box(&mut p.ctx))
        });
    }
    #[divan::bench]
    fn hand(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| {
            p.ctx.advance(TICK);
            black_box(&mut p.hb).call(black_box(&mut p.ctx))
        });
    }
}

mod blocks_loop {
    use super::*;
    #[divan::bench]
    fn generated(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| {
            p.ctx.advance(TICK);
            black_box(&mut p.gl).call(black_box(&mut p.ctx))
        });
    }
    #[divan::bench]
    fn hand(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| {
            p.ctx.advance(TICK);
            black_box(&mut p.hb).call(black_box(&mut p.ctx))
        });
    }
}

mod array_proc {
    use super::*;
    #[divan::bench]
    fn generated(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| black_box(&mut p.gp).call(black_box(&mut p.ctx)));
    }
    #[divan::bench]
    fn hand(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| black_box(&mut p.hp).call());
    }
}

mod mixed {
    use super::*;
    #[divan::bench]
    fn generated(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| {
            p.ctx.advance(TICK);
            black_box(&mut p.gm).call(black_box(&mut p.ctx))
        });
    }
    #[divan::bench]
    fn hand(b: Bencher) {
        let mut p = Progs::new();
        b.bench_local(|| {
            p.ctx.advance(TICK);
            black_box(&mut p.hm).call(black_box(&mut p.ctx))
        });
    }
}

/// Time `scans` calls of `f`.
fn time(scans: u32, mut f: impl FnMut()) -> Duration {
    let t = Instant::now();
    for _ in 0..scans {
        f();
    }
    t.elapsed() / scans
}

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v[v.len() / 2]
}

fn ab(name: &str, scans: u32, mut gen_scan: impl FnMut(), mut hand_scan: impl FnMut()) {
    let (mut tg, mut th) = (Vec::new(), Vec::new());
    for round in 0..41 {
        // Alternate which side goes first.
        if round % 2 == 0 {
            tg.push(time(scans, &mut gen_scan));
            th.push(time(scans, &mut hand_scan));
        } else {
            th.push(time(scans, &mut hand_scan));
            tg.push(time(scans, &mut gen_scan));
        }
    }
    let (mg, mh) = (median(tg), median(th));
    let ratio = mg.as_secs_f64() / mh.as_secs_f64();
    let verdict = if ratio <= 1.05 { "met" } else { "NOT met" };
    println!(
        "{name:<12} {:>12?} {:>12?} {ratio:>8.3}   {verdict}",
        mg, mh
    );
}

fn ratios() {
    let mut p = Progs::new();
    let mut ctx2 = Cycle::new();
    println!("\nscan ratio (interleaved A/B, medians of 41 rounds; target <= 1.05)");
    println!(
        "{:<12} {:>12} {:>12} {:>8}",
        "program", "generated", "hand", "ratio"
    );
    ab(
        "interlock",
        2000,
        || black_box(&mut p.gi).call(black_box(&mut p.ctx)),
        || black_box(&mut p.hi).call(),
    );
    ab(
        "arith_loop",
        50,
        || black_box(&mut p.ga).call(black_box(&mut p.ctx)),
        || black_box(&mut p.ha).call(),
    );
    let mut pb = Progs::new();
    ab(
        "blocks",
        500,
        || {
            pb.ctx.advance(TICK);
            black_box(&mut pb.gb).call(black_box(&mut pb.ctx))
        },
        || {
            ctx2.advance(TICK);
            black_box(&mut pb.hb).call(black_box(&mut ctx2))
        },
    );
    let mut pl = Progs::new();
    let mut ctx3 = Cycle::new();
    ab(
        "blocks_loop",
        500,
        || {
            pl.ctx.advance(TICK);
            black_box(&mut pl.gl).call(black_box(&mut pl.ctx))
        },
        || {
            ctx3.advance(TICK);
            black_box(&mut pl.hb).call(black_box(&mut ctx3))
        },
    );
    ab(
        "array_proc",
        500,
        || black_box(&mut p.gp).call(black_box(&mut p.ctx)),
        || black_box(&mut p.hp).call(),
    );
    let mut pm = Progs::new();
    let mut ctx4 = Cycle::new();
    ab(
        "mixed",
        2000,
        || {
            pm.ctx.advance(TICK);
            black_box(&mut pm.gm).call(black_box(&mut pm.ctx))
        },
        || {
            ctx4.advance(TICK);
            black_box(&mut pm.hm).call(black_box(&mut ctx4))
        },
    );
}
