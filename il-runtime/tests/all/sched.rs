//! Task release, statistics, overruns and the watchdog, on `Bench`.

use std::time::Duration;

use il_runtime::{Error, Options, Runtime};
use il_std::addr::{ix, md, mw};

use crate::common::{bench::Bench, eventually, scans, task};

fn opts() -> Options {
    Options {
        tick: Duration::from_millis(2),
        ..Default::default()
    }
}

#[test]
fn periodic_tasks_keep_their_rates() {
    let rt = Runtime::start(Bench::default(), opts()).unwrap();
    eventually("ten Slower scans", || {
        (task(&rt, "Slower").scans >= 10).then_some(())
    });
    let report = rt.stop().unwrap();
    let (fast, slow) = (report.task("Fast").unwrap(), report.task("Slower").unwrap());
    // Releases since the start, run or missed (missed ones under load): the
    // same elapsed time holds five times as many 10 ms releases as 50 ms ones.
    let (f, s) = (fast.scans + fast.missed, slow.scans + slow.missed);
    assert!(f + 4 >= 5 * s && f <= 5 * s + 4, "fast {f}, slow {s}");
    assert!(fast.min <= fast.mean() && fast.mean() <= fast.max);
    assert_eq!(fast.interval, Duration::from_millis(10));
}

#[test]
fn a_single_task_runs_once_per_rising_edge() {
    let rt = Runtime::start(Bench::default(), opts()).unwrap();
    let shots = || rt.image().get(mw(10).int());
    scans(&rt, 5);
    assert_eq!(shots(), 0);
    rt.image().set(ix(0, 0), true).unwrap();
    eventually("one shot", || (shots() == 1).then_some(()));
    scans(&rt, 10);
    assert_eq!(shots(), 1, "TRUE held: no more");
    rt.image().set(ix(0, 0), false).unwrap();
    scans(&rt, 3);
    rt.image().set(ix(0, 0), true).unwrap();
    eventually("a second shot", || (shots() == 2).then_some(()));
    assert_eq!(rt.stop().unwrap().task("OnTrig").unwrap().scans, 2);
}

/// Makes `Heavy`'s scans longer (its loop runs `n` times, 4 times more each
/// round) until `enough` says so: how long an iteration takes depends on the
/// build and the machine, which a fixed count would guess.
fn burn_until(rt: &mut Runtime, mut enough: impl FnMut(&mut Runtime) -> bool) {
    let mut n: i32 = 1_000_000;
    loop {
        rt.image().set(md(8).dint(), n).unwrap();
        let before = task(rt, "Heavy").scans;
        eventually("two Heavy scans", || {
            (rt.wait_timeout(Duration::ZERO) || task(rt, "Heavy").scans >= before + 2).then_some(())
        });
        if enough(rt) {
            return;
        }
        n = n.saturating_mul(4);
    }
}

#[test]
fn a_scan_longer_than_its_interval_is_an_overrun() {
    let mut rt = Runtime::start(Bench::default(), opts()).unwrap();
    // Over two intervals, so that Fast, waiting behind it, misses a release.
    burn_until(&mut rt, |rt| {
        task(rt, "Heavy").max > Duration::from_millis(25)
    });
    rt.image().set(md(8).dint(), 0).unwrap();
    let report = rt.stop().unwrap();
    let heavy = report.task("Heavy").unwrap();
    assert!(heavy.overruns >= 1, "{heavy}");
    let fast = report.task("Fast").unwrap();
    assert!(fast.missed >= 1, "Fast waited behind it: {fast}");
    assert_eq!(fast.overruns, 0, "its own scans are short: {fast}");
}

#[test]
fn the_watchdog_stops_the_runtime_with_a_clear_error() {
    let mut rt = Runtime::start(
        Bench::default(),
        Options {
            watchdog: Some(Duration::from_millis(100)),
            ..opts()
        },
    )
    .unwrap();
    scans(&rt, 3);
    burn_until(&mut rt, |rt| rt.wait_timeout(Duration::ZERO));
    match rt.wait() {
        Err(e @ Error::Watchdog { task: "Heavy", .. }) => {
            let msg = e.to_string();
            assert!(msg.contains("watchdog") && msg.contains("Heavy"), "{msg}");
        }
        other => panic!("expected the watchdog, got {other:?}"),
    }
}

#[test]
fn sigterm_stops_the_runtime_cleanly_and_the_last_state_is_saved() {
    let dir = crate::common::temp_dir("sigterm");
    let opts = Options {
        retain: Some(dir.join("motor.retain")),
        // Longer than the test: only the save on stop can write the 9.
        retain_period: Duration::from_secs(3600),
        signals: true,
        ..opts()
    };
    let rt = Runtime::start(crate::common::hmi::Hmi::default(), opts.clone()).unwrap();
    rt.image().set(mw(0).int(), 9).unwrap();
    scans(&rt, 2);
    // SAFETY: raise() delivers to this thread, whose handler (installed by
    // `signals: true`) sets the runtime's flag; the process is not ended
    // while a runtime listens.
    assert_eq!(unsafe { libc::raise(libc::SIGTERM) }, 0);
    let report = rt.wait().expect("a clean stop");
    assert!(report.retain_saves >= 1);
    let rt = Runtime::start(
        crate::common::hmi::Hmi::default(),
        Options {
            signals: false,
            ..opts
        },
    )
    .unwrap();
    assert_eq!(rt.image().get(mw(0).int()), 9);
    rt.stop().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_panicking_host_function_stops_the_runtime_with_an_error() {
    let dir = crate::common::temp_dir("panic");
    let path = dir.join("bench.retain");
    let opts = Options {
        retain: Some(path.clone()),
        // Longer than the test: only a save on stop could write the file.
        retain_period: Duration::from_secs(3600),
        ..opts()
    };
    let rt = Runtime::start(Bench::default(), opts).unwrap();
    scans(&rt, 2);
    // (The scan thread's panic message shows on stderr: expected.)
    rt.image().set(mw(12).int(), 13).unwrap();
    match rt.wait() {
        Err(e @ Error::Panic { task: "Fast", .. }) => {
            assert!(e.to_string().contains("13 is out of range"), "{e}");
        }
        other => panic!("expected a panic error, got {other:?}"),
    }
    // The scan stopped half way: that state is not saved.
    assert!(!path.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
