//! Instructions executed, counted by valgrind (cachegrind), for scaling
//! tests: il-codegen's step counter sees only the loops it counts, so a
//! quadratic loop made of library calls (a `str::matches` rescan per line,
//! a `Vec::contains` per name) passes it; the instruction count sees every
//! loop, and like the step counter it does not depend on the machine's load.
//!
//! A scaling test names each input class (`what`) and calls
//! [`assert_linear`] after its own checks; that runs the test again in a
//! child process, the same test binary under cachegrind with only that test
//! selected and `IL_SCALE_PROBE=<class>|<size>` set, three times: the class
//! at n, at 8n, and not at all (`none`: the process, the harness and the
//! test's own set-up, subtracted from the other two). In the child, the test
//! calls [`run_child`] first, which runs only that size of that class. Without
//! valgrind on the machine the comparison is skipped with a message.

use std::process::Command;

/// Names the class and size a child process runs.
const PROBE: &str = "IL_SCALE_PROBE";

/// Whether this process is a child counting instructions: a test skips
/// the set-up and checks that are not part of the work it measures.
pub fn in_child() -> bool {
    std::env::var_os(PROBE).is_some()
}

/// In a child process counting instructions, runs what it asked for class
/// `what` (`small`, `large`, or nothing for the baseline `none` or another
/// class) and returns true: the test returns then. In the test run itself,
/// false.
pub fn run_child(what: &str, small: impl FnOnce(), large: impl FnOnce()) -> bool {
    let Ok(v) = std::env::var(PROBE) else {
        return false;
    };
    match v.rsplit_once('|') {
        Some((class, "small")) if class == what => small(),
        Some((class, "large")) if class == what => large(),
        _ => {}
    }
    true
}

/// Instructions the child executes for `what` at `size`, or why not.
fn count(test: &str, what: &str, size: &str) -> Result<u64, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = Command::new("valgrind")
        .args([
            "--tool=cachegrind",
            "--cache-sim=no",
            "--cachegrind-out-file=/dev/null",
        ])
        .arg(&exe)
        .args(["--exact", test, "--test-threads=1"])
        .env(PROBE, format!("{what}|{size}"))
        .output()
        .map_err(|e| format!("valgrind did not start: {e}"))?;
    let err = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        return Err(format!("the child run failed ({}):\n{err}", out.status));
    }
    // `==pid== I   refs:      496,814,537`
    err.lines()
        .find_map(|l| {
            l.split_once("I   refs:")
                .map(|(_, n)| n.trim().replace(',', ""))
        })
        .and_then(|n| n.parse().ok())
        .ok_or_else(|| format!("no instruction count in valgrind's output:\n{err}"))
}

/// Fails when the instructions the class takes grow more than 12x from n
/// to 8n (linear is 8x; quadratic 64x). The bound is the step counter's.
pub fn assert_linear(what: &str) {
    if Command::new("valgrind").arg("--version").output().is_err() {
        println!("{what}: instruction counts skipped: valgrind is not installed");
        return;
    }
    let test = std::thread::current()
        .name()
        .expect("libtest names each test's thread after the test")
        .to_string();
    let run = |size| count(&test, what, size).unwrap_or_else(|e| panic!("{what}: {e}"));
    let (none, small, large) = (run("none"), run("small"), run("large"));
    let (i1, i8) = (small.saturating_sub(none), large.saturating_sub(none));
    let ratio = i8 as f64 / i1.max(1) as f64;
    println!("{what}: 8x input → {ratio:.1}x instructions ({i1} → {i8}, the process alone {none})");
    assert!(
        ratio < 12.0,
        "{what}: 8x the input took {ratio:.1}x the instructions ({i1} → {i8}; the process alone {none})"
    );
}
