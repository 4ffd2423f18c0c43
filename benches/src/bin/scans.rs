//! `scans <program> <gen|hand> <n>`: runs `n` scans of one benchmark program
//! (generated from `plc/<program>.il`, or its hand-written twin) with the
//! inputs of `il_bench::inputs`, then prints the time per scan in ns and a
//! checksum of the outputs. `benches/matiec_compare.sh` runs it next to
//! MATIEC's C (same inputs, same checksum: the two compute the same thing)
//! under callgrind and the clock.

// Set up by assignment: most programs have private fields, which rule out
// `..Default::default()`; one style for all of them.
#![allow(clippy::field_reassign_with_default)]

use il_bench::{generated as g, hand as h, inputs};
use il_std::Cycle;
use std::hint::black_box;
use std::time::Instant;

/// One program: set up, then a closure per scan and a checksum at the end.
trait Prog {
    fn scan(&mut self, ctx: &mut Cycle);
    fn checksum(&self) -> u64;
}

fn bools(v: &[bool]) -> u64 {
    v.iter()
        .enumerate()
        .map(|(k, &b)| (k as u64 + 1) * b as u64)
        .sum()
}

fn ints(v: &[i16]) -> u64 {
    v.iter()
        .map(|&x| x as i64 as u64)
        .fold(0, u64::wrapping_add)
}

macro_rules! prog {
    ($t:ty, |$s:ident| $sum:expr) => {
        impl Prog for $t {
            fn scan(&mut self, ctx: &mut Cycle) {
                self.call(ctx)
            }
            fn checksum(&self) -> u64 {
                let $s = self;
                $sum
            }
        }
    };
}

prog!(g::Interlock, |s| bools(&s.m));
prog!(g::ArithLoop, |s| (s.acc as i64 + s.x as i64) as u64);
prog!(g::ArrayProc, |s| ints(&s.filtered)
    .wrapping_add(s.peak as i64 as u64));
prog!(g::Blocks, |s| ints(&s.count) + 1000 * bools(&s.done));
prog!(g::BlocksLoop, |s| ints(&s.count) + 1000 * bools(&s.done));
prog!(g::Mixed, |s| mixed_sum(s.alarms, s.high, s.sum, s.pos));
prog!(h::Blocks, |s| ints(&s.count) + 1000 * bools(&s.done));
prog!(h::Mixed, |s| mixed_sum(s.alarms, s.high, s.sum, s.pos));

fn mixed_sum(alarms: i16, high: i16, sum: f32, pos: f32) -> u64 {
    (alarms as i64 * 1_000_000 + high as i64) as u64 + sum.to_bits() as u64 + pos.to_bits() as u64
}

/// The hand-written twins without a context parameter.
macro_rules! prog_noctx {
    ($t:ty, |$s:ident| $sum:expr) => {
        impl Prog for $t {
            fn scan(&mut self, _: &mut Cycle) {
                self.call()
            }
            fn checksum(&self) -> u64 {
                let $s = self;
                $sum
            }
        }
    };
}
prog_noctx!(h::Interlock, |s| bools(&s.m));
prog_noctx!(h::ArithLoop, |s| (s.acc as i64 + s.x as i64) as u64);
prog_noctx!(h::ArrayProc, |s| ints(&s.filtered)
    .wrapping_add(s.peak as i64 as u64));

fn program(name: &str, hand: bool) -> Option<Box<dyn Prog>> {
    Some(match (name, hand) {
        ("interlock", false) => {
            let mut p = g::Interlock::default();
            p.x = inputs::interlock_x();
            Box::new(p)
        }
        ("interlock", true) => {
            let mut p = h::Interlock::default();
            p.x = inputs::interlock_x();
            Box::new(p)
        }
        ("arith_loop", false) => Box::new(g::ArithLoop::default()),
        ("arith_loop", true) => Box::new(h::ArithLoop::default()),
        ("array_proc", false) => {
            let mut p = g::ArrayProc::default();
            p.samples = inputs::samples();
            Box::new(p)
        }
        ("array_proc", true) => {
            let mut p = h::ArrayProc::default();
            p.samples = inputs::samples();
            Box::new(p)
        }
        ("blocks", false) => {
            let mut p = g::Blocks::default();
            p.go = inputs::go();
            Box::new(p)
        }
        ("blocks_loop", false) => {
            let mut p = g::BlocksLoop::default();
            p.go = inputs::go();
            Box::new(p)
        }
        ("blocks" | "blocks_loop", true) => {
            let mut p = h::Blocks::default();
            p.go = inputs::go();
            Box::new(p)
        }
        ("mixed", false) => {
            let mut p = g::Mixed::default();
            p.raw = inputs::raw();
            Box::new(p)
        }
        ("mixed", true) => {
            let mut p = h::Mixed::default();
            p.raw = inputs::raw();
            Box::new(p)
        }
        _ => return None,
    })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage =
        "usage: scans <interlock|arith_loop|array_proc|blocks|blocks_loop|mixed> <gen|hand> <n>";
    let (Some(name), Some(side), Some(n)) = (
        args.get(1),
        args.get(2),
        args.get(3).and_then(|n| n.parse::<u32>().ok()),
    ) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let hand = side == "hand";
    let Some(mut p) = program(name, hand).filter(|_| hand || side == "gen") else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let mut ctx = Cycle::new();
    let t = Instant::now();
    for _ in 0..n {
        ctx.advance(inputs::TICK);
        black_box(&mut *p).scan(black_box(&mut ctx));
    }
    let ns = t.elapsed().as_nanos() as f64 / n.max(1) as f64;
    println!("{ns:.1} {}", p.checksum());
}
