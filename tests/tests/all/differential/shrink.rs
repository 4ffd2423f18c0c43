//! Shrinking a mismatch to a small reproducer, and keeping it in
//! `tests/differential/regressions/`.

use super::*;

/// Body lines of the program that may be deleted (instructions and labels).
pub(super) fn body_lines(il: &str) -> Vec<usize> {
    let mut in_var = false;
    let mut out = Vec::new();
    for (k, l) in il.lines().enumerate() {
        let t = l.trim();
        if t.starts_with("VAR") {
            in_var = true;
        } else if t == "END_VAR" {
            in_var = false;
        } else if !in_var
            && !t.is_empty()
            && !t.starts_with("FUNCTION")
            && !t.starts_with("END_")
            && !t.starts_with("PROGRAM")
            && !t.starts_with("(*")
        {
            out.push(k);
        }
    }
    out
}

pub(super) fn without(il: &str, drop: &[usize]) -> String {
    il.lines()
        .enumerate()
        .filter(|(k, _)| !drop.contains(k))
        .map(|(_, l)| format!("{l}\n"))
        .collect()
}

/// Delta debugging by line deletion: each round builds every candidate that
/// still checks into one crate and keeps the smallest that still mismatches.
pub(super) fn shrink(p: Program) -> (String, Program) {
    let mut p = p;
    for _round in 0..40 {
        let lines = body_lines(&p.il);
        let mut candidates = Vec::new();
        for size in [16, 8, 4, 2, 1] {
            if size > lines.len() {
                continue;
            }
            let mut start = 0;
            while start < lines.len() {
                let drop: Vec<usize> = lines[start..(start + size).min(lines.len())].to_vec();
                candidates.push(without(&p.il, &drop));
                start += size;
            }
        }
        let mut cases = Vec::new();
        for (i, il) in candidates.iter().enumerate() {
            let q = Program {
                il: il.clone(),
                inputs: p.inputs.clone(),
                scans: p.scans.clone(),
                step_ns: p.step_ns,
                kinds: p.kinds.clone(),
            };
            if let Ok(c) = prepare(i, 0, q) {
                cases.push(c);
            }
            if cases.len() >= 150 {
                break;
            }
        }
        if cases.is_empty() {
            break;
        }
        let got = build_and_run(&tmp_dir("differential_shrink"), &cases);
        let best = cases
            .into_iter()
            .zip(got)
            .filter(|(c, g)| first_difference(&c.expected, g).is_some())
            .min_by_key(|(c, _)| c.program.il.len());
        match best {
            Some((c, _)) => p = c.program,
            None => break,
        }
    }
    (p.il.clone(), p)
}

/// `regressions/seed_N.il` and `seed_N.scans` (line 1: `step_ns=N`, then one
/// line of `input=value` per scan).
pub(super) fn save_regression(seed: u64, il: &str, p: &Program) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("differential/regressions");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("seed_{seed}.il"));
    std::fs::write(&path, il).unwrap();
    let mut scans = format!("step_ns={}\n", p.step_ns);
    for s in &p.scans {
        let cells: Vec<String> = p
            .inputs
            .iter()
            .zip(s)
            .map(|(v, l)| format!("{}={}", v.name, lit_text(l)))
            .collect();
        scans.push_str(&cells.join(" "));
        scans.push('\n');
    }
    std::fs::write(path.with_extension("scans"), scans).unwrap();
    path
}
