//! Golden-file snapshots for tests: compare a rendering with a checked-in
//! `.txt`; with `IL_BLESS=1` in the environment, (re)write the file instead.

use std::path::{Path, PathBuf};

/// True when the run should rewrite snapshots (`IL_BLESS=1`).
pub fn blessing() -> bool {
    std::env::var_os("IL_BLESS").is_some_and(|v| v == "1")
}

/// `<crate>/tests/<dir>`, for the crate whose test is running.
pub fn golden_dir(manifest_dir: &str, dir: &str) -> PathBuf {
    Path::new(manifest_dir).join("tests").join(dir)
}

/// Compare `actual` with `dir/name.txt`. Line endings are compared as `\n`.
/// Panics with both texts and the first differing line when they differ.
pub fn assert_golden(dir: &Path, name: &str, actual: &str) {
    let path = dir.join(format!("{name}.txt"));
    if blessing() {
        std::fs::create_dir_all(dir).unwrap();
        std::fs::write(&path, actual).unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
        return;
    }
    let expected = match std::fs::read_to_string(&path) {
        Ok(s) => s.replace("\r\n", "\n"),
        Err(e) => panic!(
            "golden file {} cannot be read ({e}); run with IL_BLESS=1 to create it.\n--- actual ---\n{actual}",
            path.display()
        ),
    };
    if expected != actual {
        let line = expected
            .lines()
            .zip(actual.lines())
            .position(|(a, b)| a != b)
            .map_or_else(
                || expected.lines().count().min(actual.lines().count()) + 1,
                |i| i + 1,
            );
        panic!(
            "{} differs from the output (first at line {line}); run with IL_BLESS=1 to accept.\n--- expected ---\n{expected}\n--- actual ---\n{actual}\n---",
            path.display()
        );
    }
}

/// Assert every snapshot in `dir` was produced by the test (no stale files);
/// `names` are the snapshot names the test wrote or compared.
pub fn assert_no_stale(dir: &Path, names: &[&str]) {
    if blessing() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.extension().is_some_and(|x| x == "txt") {
            let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
            assert!(
                names.contains(&stem.as_str()),
                "stale snapshot {} (no test writes it)",
                p.display()
            );
        }
    }
}
