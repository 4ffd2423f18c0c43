//! A stable, dependency-free mutation driver: runs one fuzz target for N
//! executions on inputs mutated from seed files, without libFuzzer or
//! coverage instrumentation (so it is several times faster per execution,
//! but blind: run-stable.sh's coverage-guided libFuzzer finds more per run).
//!
//!     cargo run --release --bin drive -- TARGET RUNS [SEED] [DIR...]
//!
//! DIRs default to `regressions`, `../tests/plc`, `../tests/plc-hostile` and
//! `../../shared/corpus`.
//! Deterministic for a given SEED and seed files. Every input runs under a
//! time budget (`IL_FUZZ_BUDGET_SECS`, default 2 s: inputs are at most 4 KiB
//! and take milliseconds) and a memory budget (`il_fuzz::memory_budget`: the
//! peak allocation of the run, counted by the allocator installed here, at
//! most max(64 MiB, 2000 x the input)). A finding is saved and the run goes
//! on: a panic in `artifacts/TARGET/drive-crash-<run>`, a run over the time
//! budget in `drive-slow-<run>` (not waited for), one over the memory budget
//! in `drive-big-<run>`; the run stops after 10 findings and exits 1 if there
//! was any. The summary gives the largest peak allocation seen.

use std::path::{Path, PathBuf};

#[global_allocator]
static ALLOC: il_fuzz::Counting = il_fuzz::Counting;

/// xorshift64*: small and good enough for choosing mutations.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }
}

/// IL tokens to insert: keywords, operators, literals, punctuation and the
/// characters that stress the writer and the renderers.
#[rustfmt::skip]
const DICT: &[&str] = &[
    "LD ", "LDN ", "ST ", "STN ", "S ", "R ", "AND ", "ANDN ", "OR ", "XOR ", "NOT", "ADD ", "SUB ",
    "MUL ", "DIV ", "MOD ", "GT ", "GE ", "EQ ", "NE ", "LE ", "LT ", "JMP ", "JMPC ", "JMPCN ",
    "CAL ", "CALC ", "RET", "RETC", "ADD(", "AND(", ")", "(", ":=", "=>", ":", ";", ",", ".", "..",
    "[", "]", "#", "(*", "*)", "'", "\"", "$", "$N", "$'", "\n", "\r\n", "\t", " ", "PROGRAM ",
    "END_PROGRAM", "FUNCTION ", "END_FUNCTION", "FUNCTION_BLOCK ", "END_FUNCTION_BLOCK", "VAR",
    "VAR_INPUT", "VAR_OUTPUT", "VAR_TEMP", "VAR_IN_OUT", "END_VAR", "CONSTANT", "RETAIN", "AT ",
    "TYPE ", "END_TYPE", "STRUCT", "END_STRUCT", "ARRAY[1..3] OF ", "ARRAY[0..1, 0..2] OF ",
    "STRING[5]", "WSTRING[4]", "BOOL", "INT", "DINT", "SINT", "UINT", "LREAL", "REAL", "TIME",
    "BYTE", "WORD", "TON", "CTU", "SR", "R_TRIG", "R_EDGE", "F_EDGE", "TRUE", "FALSE", "0", "1",
    "-1", "32767", "-32768", "65535", "16#FFFF_FFFF", "2#1010", "1.5E3", "T#1s", "T#-5ms",
    "INT#-5", "BOOL#1", "'abc'", "\"wide\"", "%IX0.1", "%QW3", "%MD4", "x", "y", "arr[i]",
    "arr[1, 2]", "fb.Q", "lbl:", "CONCAT ", "LEFT ", "MID ", "FIND ", "LIMIT ", "MUX ", "SEL ",
    "INT_TO_REAL", "REAL_TO_INT", "LEN", "(0..100)", "fn", "match", "self", "Self", "None", "i32",
    "*/", "/*", "//", "r#\"", "\"#", "\\", "\u{202e}", "\u{2028}", "\u{85}", "\u{feff}", "\u{0}",
    "ä", "€", "😀",
];

fn mutate(rng: &mut Rng, seeds: &[Vec<u8>], data: &mut Vec<u8>) {
    for _ in 0..=rng.below(6) {
        let len = data.len();
        match rng.below(9) {
            0 if len > 0 => {
                let i = rng.below(len);
                data[i] ^= 1 << rng.below(8);
            }
            1 => {
                let i = rng.below(len + 1);
                data.insert(i, rng.next() as u8);
            }
            2 if len > 0 => {
                let i = rng.below(len);
                let n = 1 + rng.below((len - i).min(64));
                data.drain(i..i + n);
            }
            3 if len > 0 => {
                let i = rng.below(len);
                let n = 1 + rng.below((len - i).min(256));
                let copy = data[i..i + n].to_vec();
                let at = rng.below(len + 1);
                data.splice(at..at, copy);
            }
            4..=6 => {
                let t = DICT[rng.below(DICT.len())].as_bytes();
                let at = rng.below(len + 1);
                data.splice(at..at, t.iter().copied());
            }
            7 if !seeds.is_empty() => {
                // A slice of another seed (splicing whole constructs).
                let s = &seeds[rng.below(seeds.len())];
                if !s.is_empty() {
                    let i = rng.below(s.len());
                    let n = 1 + rng.below((s.len() - i).min(512));
                    let at = rng.below(len + 1);
                    data.splice(at..at, s[i..i + n].iter().copied());
                }
            }
            _ if len > 0 => {
                // Replace one line by a line of the same input.
                let lines: Vec<usize> = (0..len).filter(|&i| data[i] == b'\n').collect();
                if lines.len() > 2 {
                    let a = lines[rng.below(lines.len() - 1)];
                    let b = lines[rng.below(lines.len() - 1)];
                    let end = |at: usize| {
                        data[at + 1..]
                            .iter()
                            .position(|&c| c == b'\n')
                            .map_or(len, |p| at + 1 + p)
                    };
                    let (end_a, end_b) = (end(a), end(b));
                    let src = data[b..end_b].to_vec();
                    data.splice(a..end_a, src);
                }
            }
            _ => {}
        }
    }
    data.truncate(4096);
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: drive TARGET RUNS [SEED] [DIR...]";
    let name = args.get(1).expect(usage);
    let runs: u64 = args.get(2).and_then(|s| s.parse().ok()).expect(usage);
    let seed: u64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1);
    let target = il_fuzz::TARGETS
        .iter()
        .find(|(n, _)| n == name)
        .map(|(_, f)| *f)
        .unwrap_or_else(|| panic!("unknown target {name}"));
    let dirs: Vec<PathBuf> = if args.len() > 4 {
        args[4..].iter().map(PathBuf::from).collect()
    } else {
        [
            "regressions",
            "../tests/plc",
            "../tests/plc-hostile",
            "../../shared/corpus",
        ]
        .iter()
        .map(PathBuf::from)
        .collect()
    };
    let mut seeds = Vec::new();
    for d in &dirs {
        let Ok(rd) = std::fs::read_dir(d) else {
            continue;
        };
        let mut files: Vec<PathBuf> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
        files.sort();
        for f in files {
            if let Ok(b) = std::fs::read(&f) {
                seeds.push(b);
            }
        }
    }
    assert!(!seeds.is_empty(), "no seed files");
    let budget = il_fuzz::budget(2);
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let start = std::time::Instant::now();
    let mut data = Vec::new();
    let mut findings = 0;
    let mut max_peak = (0usize, 0usize);
    let mut done = 0;
    for run in 0..runs {
        // Mostly mutate the previous input further; restart from a seed often.
        if run % 8 == 0 {
            data = seeds[rng.below(seeds.len())].clone();
            if data.len() > 4096 {
                let i = rng.below(data.len() - 4096);
                data = data[i..i + 4096].to_vec();
            }
        }
        mutate(&mut rng, &seeds, &mut data);
        let input = data.clone();
        let (outcome, peak) = il_fuzz::run_measured(target, input.clone(), budget);
        done = run + 1;
        if peak > max_peak.0 {
            max_peak = (peak, input.len());
        }
        if outcome != il_fuzz::Outcome::Ok {
            let what = match outcome {
                il_fuzz::Outcome::TooSlow => "slow",
                il_fuzz::Outcome::TooBig { .. } => "big",
                _ => "crash",
            };
            let dir = Path::new("artifacts").join(name);
            let _ = std::fs::create_dir_all(&dir);
            let path = dir.join(format!("drive-{what}-{run}"));
            let _ = std::fs::write(&path, &input);
            eprintln!(
                "{what} at run {run} ({outcome:?}, time budget {budget:?}): input in {}",
                path.display()
            );
            findings += 1;
            if findings >= 10 {
                break;
            }
            // Restart from a seed rather than mutate the finding further.
            data = seeds[rng.below(seeds.len())].clone();
            data.truncate(4096);
        }
        if run > 0 && run % 100_000 == 0 {
            eprintln!("{run} runs, {:.0} s", start.elapsed().as_secs_f64());
        }
    }
    println!(
        "{name}: {done} runs, seed {seed}, {} seed files, {:.1} s, {findings} findings, \
         largest peak allocation {:.1} MiB (input of {} bytes)",
        seeds.len(),
        start.elapsed().as_secs_f64(),
        max_peak.0 as f64 / (1 << 20) as f64,
        max_peak.1
    );
    if findings > 0 {
        std::process::exit(1);
    }
}
