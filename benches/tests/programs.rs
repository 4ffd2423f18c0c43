//! The scan benchmarks compare like with like: the generated and the
//! hand-written version of each program compute the same outputs, scan
//! after scan, from the same inputs. Also: the generated benchmark sources
//! are up to date with their generator (`IL_BLESS=1` rewrites them).

use il_bench::generator::{XorShift, blocks_il, interlock_il, interlock_rust};
use il_bench::{generated as g, hand as h};
use il_std::{Cycle, TIME};

fn up_to_date(path: &str, text: String) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    if std::env::var_os("IL_BLESS").is_some() {
        std::fs::write(&path, text).unwrap();
        return;
    }
    let old = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        old == text,
        "{} is stale: run IL_BLESS=1 cargo test -p il-bench",
        path.display()
    );
}

#[test]
fn generated_sources_are_up_to_date() {
    up_to_date("plc/interlock.il", interlock_il());
    up_to_date("plc/blocks.il", blocks_il());
    up_to_date("src/hand/interlock.rs", interlock_rust());
}

#[test]
fn interlock_same_outputs() {
    let mut rng = XorShift::new(5);
    let (mut a, mut b) = (g::Interlock::default(), h::Interlock::default());
    let mut ctx = Cycle::new();
    let mut ones = 0;
    for _ in 0..40 {
        for k in 0..64 {
            let v = rng.below(3) != 0;
            a.x[k] = v;
            b.x[k] = v;
        }
        a.call(&mut ctx);
        b.call();
        assert_eq!(a.m, b.m);
        ones += b.m.iter().filter(|&&m| m).count();
    }
    assert!(ones > 40 * 20, "the network does something: {ones}");
}

#[test]
fn arith_loop_same_outputs() {
    let mut ctx = Cycle::new();
    let (mut a, mut b) = (g::ArithLoop::default(), h::ArithLoop::default());
    for (n, seed) in [(1000, 7), (0, 3), (1, -5), (250, i32::MAX), (1000, -99)] {
        (a.n, a.seed, b.n, b.seed) = (n, seed, n, seed);
        a.call(&mut ctx);
        b.call();
        assert_eq!((a.acc, a.x), (b.acc, b.x), "n={n} seed={seed}");
    }
    assert_eq!(ctx.fault_count(), 0);
}

#[test]
fn array_proc_same_outputs() {
    let mut rng = XorShift::new(9);
    let mut ctx = Cycle::new();
    let (mut a, mut b) = (g::ArrayProc::default(), h::ArrayProc::default());
    for scan in 0..10 {
        for k in 0..256 {
            let v = rng.next_u64() as i16 >> (scan % 8);
            a.samples[k] = v;
            b.samples[k] = v;
        }
        a.call(&mut ctx);
        b.call();
        assert_eq!((a.filtered, a.peak), (b.filtered, b.peak), "scan {scan}");
    }
}

#[test]
fn blocks_same_outputs() {
    let mut rng = XorShift::new(3);
    let (mut ca, mut cb) = (Cycle::new(), Cycle::new());
    let (mut a, mut b) = (g::Blocks::default(), h::Blocks::default());
    let mut counted = 0;
    for scan in 0..300 {
        for k in 0..100 {
            let v = rng.below(4) != 0;
            a.go[k] = v;
            b.go[k] = v;
        }
        a.reset = scan % 97 == 96;
        b.reset = a.reset;
        a.call(&mut ca);
        b.call(&mut cb);
        assert_eq!((a.done, a.count), (b.done, b.count), "scan {scan}");
        counted += b.count.iter().filter(|&&c| c > 0).count();
        ca.advance(TIME::from_ms(10));
        cb.advance(TIME::from_ms(10));
    }
    assert!(counted > 1000, "the counters count: {counted}");
}

#[test]
fn blocks_loop_same_outputs() {
    let mut rng = XorShift::new(3);
    let (mut ca, mut cb) = (Cycle::new(), Cycle::new());
    let (mut a, mut b) = (g::BlocksLoop::default(), h::Blocks::default());
    let mut counted = 0;
    for scan in 0..300 {
        for k in 0..100 {
            let v = rng.below(4) != 0;
            a.go[k] = v;
            b.go[k] = v;
        }
        a.reset = scan % 97 == 96;
        b.reset = a.reset;
        a.call(&mut ca);
        b.call(&mut cb);
        assert_eq!((a.done, a.count), (b.done, b.count), "scan {scan}");
        counted += b.count.iter().filter(|&&c| c > 0).count();
        ca.advance(TIME::from_ms(10));
        cb.advance(TIME::from_ms(10));
    }
    assert!(counted > 1000, "the counters count: {counted}");
}

#[test]
fn mixed_same_outputs() {
    let mut rng = XorShift::new(11);
    let (mut ca, mut cb) = (Cycle::new(), Cycle::new());
    let (mut a, mut b) = (g::Mixed::default(), h::Mixed::default());
    let (mut high, mut moved) = (0, 0.0f32);
    for scan in 0..400 {
        // New samples every 50 scans; the program's phase flips the target
        // every 20 scans, so the axis moves, settles and times out.
        if scan % 50 == 0 {
            for k in 0..32 {
                let v = rng.next_u64() as i16 >> (scan % 7 + 2);
                a.raw[k] = v;
                b.raw[k] = v;
            }
        }
        a.run = scan % 173 < 150;
        b.run = a.run;
        let before = a.pos;
        a.call(&mut ca);
        b.call(&mut cb);
        assert_eq!(
            (
                a.sum.to_bits(),
                a.high,
                a.alarms,
                a.pos.to_bits(),
                a.hist.map(f32::to_bits)
            ),
            (
                b.sum.to_bits(),
                b.high,
                b.alarms,
                b.pos.to_bits(),
                b.hist.map(f32::to_bits)
            ),
            "scan {scan}"
        );
        high += b.high;
        moved += (a.pos - before).abs();
        ca.advance(TIME::from_ms(10));
        cb.advance(TIME::from_ms(10));
    }
    assert!(high > 100, "samples above 100.0 are counted: {high}");
    assert!(moved > 100.0, "the axis moves: {moved}");
    assert!(b.alarms >= 5, "slow moves are counted: {}", b.alarms);
    assert_eq!(ca.fault_count(), 0);
}
