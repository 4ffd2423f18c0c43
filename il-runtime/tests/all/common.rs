//! The tests' configurations and helpers.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use il_runtime::{Options, Runtime};

/// The example's CONFIGURATION `Hmi` (the motor starter over Modbus).
pub mod hmi {
    il_macros::il!(file = "examples/softplc.il", serde);
    il_runtime::plc!(Hmi);
}

/// `Bench`: several tasks, RETAIN in a snapshot and in the image.
pub mod bench {
    il_macros::il!(file = "tests/all/bench.il", serde);

    /// `host_check` of bench.il: panics on 13.
    pub fn host_check(_ctx: &mut il_std::Cycle, v: i16) -> bool {
        assert_ne!(v, 13, "host_check: 13 is out of range");
        true
    }

    il_runtime::plc!(Bench, retain = Bench__Retain);
}

/// A fresh directory for one test's files.
pub fn temp_dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("il-runtime-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Options with Modbus on a free port of 127.0.0.1.
pub fn modbus_opts() -> Options {
    Options {
        modbus: Some("127.0.0.1:0".parse().unwrap()),
        ..Default::default()
    }
}

/// Generous: the machine may be loaded (CI runs several builds at once).
pub const PATIENCE: Duration = Duration::from_secs(10);

/// Polls `f` until it gives `Some`, or panics after [`PATIENCE`] naming `what`.
pub fn eventually<T>(what: &str, mut f: impl FnMut() -> Option<T>) -> T {
    let end = Instant::now() + PATIENCE;
    loop {
        if let Some(v) = f() {
            return v;
        }
        assert!(Instant::now() < end, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// Waits until `n` more scans have published their image.
pub fn scans(rt: &Runtime, n: u64) {
    let start = rt.image().scans();
    eventually("scans", || (rt.image().scans() >= start + n).then_some(()));
}

/// The statistics of task `name` so far.
pub fn task(rt: &Runtime, name: &str) -> il_runtime::TaskStats {
    rt.stats()
        .into_iter()
        .find(|t| t.name == name)
        .expect("a task of that name")
}
