//! Differential testing: random well-typed IL programs (tests/differential/gen/)
//! run under the reference interpreter and as generated Rust, compared variable
//! by variable after every scan (plus the fault count and the last fault).
//!
//! Values are compared by their canonical text: integers, TIME and dates by
//! their inner integer, strings byte by byte (hex), REAL/LREAL by Rust's
//! shortest round-trip text (`{:?}`), which is NaN-aware equality: exact for
//! every non-NaN value (`-0.0` and `0.0` differ, so do any two bit patterns
//! that are not NaN) and any NaN equal to any NaN (sign and payload of a NaN
//! are not compared: IEEE 754 leaves them open, and LLVM may fold them).
//!
//! Each run prints a coverage table (generated constructs, `gen/coverage.rs`,
//! and how many programs used each) and fails at 500 programs or more when
//! one of them was used by none.
//!
//! All programs of a run are compiled into ONE temporary crate (one build).
//! CI: a fixed seed and 500 programs. The long run:
//!
//! ```sh
//! IL_DIFF_COUNT=10000 IL_DIFF_SEED=7 cargo test -p il-tests --test all differential -- --nocapture
//! ```
//!
//! (`IL_DIFF_BATCH` programs per crate build, default 500.)
//!
//! A mismatch is shrunk by line deletion (each round builds all candidates in
//! one crate) and written to `tests/differential/regressions/seed_N.il` with its
//! inputs in `seed_N.scans`; `regressions_agree` runs every file kept there.
//! `tests/differential/compiler-bugs/` holds reproducers of compiler bugs the
//! generator found (and now avoids).

#[path = "../../differential/gen/mod.rs"]
mod generator;

use generator::{Lit, Program, T};
use il_codegen::diag::SourceFile;
use il_codegen::ir::Loc;
use il_codegen::ir::types::Elem;
use il_interp::{Machine, Value, load};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

// The parts: values and their canonical text, the runner (interpret,
// compile, build one crate, compare), shrinking, the coverage table, and
// the configuration run.
mod config;
mod coverage_table;
mod runner;
mod shrink;
mod values;
use config::{CfgCase, config_case, config_driver, interpret_config};
use coverage_table::*;
use runner::*;
use shrink::*;
use values::*;

fn env_num(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
fn interpreter_agrees_with_generated_rust() {
    let count = env_num("IL_DIFF_COUNT", 500) as usize;
    let base = env_num("IL_DIFF_SEED", 20_261_122);
    let mut cases = Vec::new();
    let mut refused = Vec::new();
    let mut coverage: std::collections::BTreeMap<&str, usize> = Default::default();
    for i in 0..count {
        let seed = base.wrapping_add(i as u64);
        let p = generator::generate(seed);
        for k in &p.kinds {
            *coverage.entry(k).or_default() += 1;
        }
        match prepare(i, seed, p) {
            Ok(c) => cases.push(c),
            Err(e) => refused.push(format!(
                "seed {seed}: {e}\n{}",
                generator::generate(seed).il
            )),
        }
    }
    print_coverage(count, &coverage);
    let mut kinds: Vec<String> = refused
        .iter()
        .filter_map(|r| {
            r.lines()
                .nth(1)
                .map(|l| l.split(" (at line").next().unwrap_or(l).to_string())
        })
        .collect();
    kinds.sort();
    kinds.dedup();
    for k in &kinds {
        eprintln!("refused: {k}");
    }
    assert!(
        refused.is_empty(),
        "{} of {count} generated programs could not be run (generator or compiler bug); first:\n{}",
        refused.len(),
        refused[0]
    );
    // Batches keep each crate to a size rustc handles quickly.
    let mut mismatches = Vec::new();
    let mut first_bad = None;
    let batch = env_num("IL_DIFF_BATCH", 500) as usize;
    for (b, chunk) in cases.chunks(batch).enumerate() {
        let got = build_and_run(&tmp_dir(&format!("differential_{base}_{b}")), chunk);
        for (c, g) in chunk.iter().zip(got) {
            if let Some(d) = first_difference(&c.expected, &g) {
                first_bad.get_or_insert(c.seed);
                mismatches.push(format!("seed {} ({d}):\n{}", c.seed, c.program.il));
            }
        }
    }
    println!(
        "{} programs compared, {} mismatches",
        cases.len(),
        mismatches.len()
    );
    if let Some(seed) = first_bad {
        let p = generator::generate(seed);
        let (il, prog) = shrink(p);
        let path = save_regression(seed, &il, &prog);
        mismatches.insert(
            0,
            format!("shrunk reproducer written to {}:\n{il}", path.display()),
        );
    }
    assert!(
        mismatches.is_empty(),
        "{} mismatches; first: {}",
        mismatches.len(),
        mismatches[0]
    );
    let unused: Vec<&str> = generator::coverage::CONSTRUCTS
        .iter()
        .copied()
        .filter(|k| !coverage.contains_key(k))
        .collect();
    assert!(
        count < 500 || unused.is_empty(),
        "constructs no generated program used: {unused:?}"
    );
}

/// Every kept reproducer still agrees (one crate build for all of them).
#[test]
fn regressions_agree() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("differential/regressions");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    files.retain(|p| p.extension().is_some_and(|e| e == "il"));
    files.sort();
    let mut cases = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let il = std::fs::read_to_string(f).unwrap();
        let scans = std::fs::read_to_string(f.with_extension("scans")).unwrap();
        let mut lines = scans.lines();
        let step_ns: i64 = lines
            .next()
            .and_then(|l| l.strip_prefix("step_ns="))
            .and_then(|n| n.parse().ok())
            .expect("step_ns=N");
        let prog = load(&SourceFile::new(f.display().to_string(), il.clone()))
            .unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let m = Machine::new(&prog, "Main").unwrap();
        let mut inputs: Vec<generator::Var> = Vec::new();
        let mut rows = Vec::new();
        for l in lines.filter(|l| !l.trim().is_empty()) {
            let mut row = Vec::new();
            for cell in l.split_whitespace() {
                let (n, v) = cell.split_once('=').unwrap();
                let val = m.parse_value(n, v).unwrap_or_else(|e| panic!("{e}"));
                if rows.is_empty() {
                    inputs.push(generator::Var {
                        name: n.to_string(),
                        ty: gen_type(&m.type_of(n).unwrap()),
                    });
                }
                row.push(value_lit(&val));
            }
            rows.push(row);
        }
        let p = Program {
            il,
            inputs,
            scans: rows,
            step_ns,
            kinds: Vec::new(),
        };
        cases.push(prepare(i, 0, p).unwrap_or_else(|e| panic!("{}: {e}", f.display())));
    }
    assert!(!cases.is_empty(), "no reproducers in {}", dir.display());
    let got = build_and_run(&tmp_dir("differential_regressions"), &cases);
    for ((c, g), f) in cases.iter().zip(got).zip(&files) {
        if let Some(d) = first_difference(&c.expected, &g) {
            panic!("{}: {d}", f.display());
        }
    }
}
