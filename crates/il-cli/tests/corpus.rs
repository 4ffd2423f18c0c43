//! `ilc check` over the shared IL corpus (`../shared/corpus` beside the
//! checkout): every file has a stated expected outcome in [`EXPECTED`], taken
//! from the corpus's `SOURCES.txt` notes. A corpus file missing from the table
//! fails the test, so new corpus files are noticed.
//!
//! The expectations are those of `ilc check` as it is today: syntax only.
//! Programs that are well-formed IL but call non-IEC functions (echidna's
//! `dbg`, `piface_write`, `_exit`) or recurse are accepted here; the semantic
//! checker will refuse them later, and this table will say so then.

#[path = "../../il-codegen/tests/common/json.rs"]
mod json;

use std::path::{Path, PathBuf};
use std::process::Command;

use json::{J, get};

#[derive(Debug)]
enum Expect {
    /// `ilc check` exits 0 with no error.
    Accept,
    /// `ilc check` exits 1 and among its errors is one with this code, on this
    /// line, whose message names the non-standard construct `must_mention`
    /// (case-insensitive).
    Refuse {
        code: &'static str,
        line: usize,
        must_mention: &'static str,
    },
}

use Expect::*;

const EXPECTED: &[(&str, Expect)] = &[
    // Tier 1: the standard's own Annex F examples.
    ("beremiz_matiec_cmd_monitor_il.txt", Accept),
    ("beremiz_matiec_fwd_rev_mon_il.txt", Accept),
    // `CAL LIMIT(MN:=1,IN:=N,MX:=128)`: CAL of a function with a one-line formal
    // list; syntactically a CAL; that LIMIT is a function is for the checker.
    ("beremiz_matiec_stack_int_il.txt", Accept),
    ("beremiz_matiec_weigh_il.txt", Accept),
    // Tier 2: parser stress files that also hold Structured Text (and SFC).
    (
        "beremiz_matiec_basic_code.test",
        Refuse {
            code: "IL00??",
            line: 419,
            must_mention: "Structured Text",
        },
    ),
    (
        "beremiz_matiec_identifier_as_variable2.test",
        Refuse {
            code: "IL00??",
            line: 47,
            must_mention: "Structured Text",
        },
    ),
    // Tier 4: small real programs.
    ("Autonomy-Logic_STruCpp_state-display.il", Accept),
    ("eduardojvieira_ZPLC_blinky_2a44dc4.il", Accept),
    ("eduardojvieira_ZPLC_jumps.il", Accept),
    ("eduardojvieira_ZPLC_logic.il", Accept),
    // Tier 4b: echidna. Syntactically IEC; `dbg`, `piface_write`, `_exit` and
    // recursion are semantic matters.
    ("61131_echidna_blink.il", Accept),
    ("61131_echidna_ctu.il", Accept),
    ("61131_echidna_factorial.il", Accept),
    ("61131_echidna_rpiface-updown.il", Accept),
    ("61131_echidna_sine.il", Accept),
    // Tier 5: dialects. `;` starts a comment in both; IEC has only `(* *)`.
    (
        "hiperiondev_il_parser_test2.il",
        Refuse {
            code: "IL00??",
            line: 10,
            must_mention: ";",
        },
    ),
    (
        "kalamara_plcemu_knuth.il",
        Refuse {
            code: "IL00??",
            line: 2,
            must_mention: ";",
        },
    ),
];

fn corpus_dir() -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
}

fn is_corpus_file(p: &Path) -> bool {
    let name = p
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = p
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    p.is_file() && name != "SOURCES.txt" && matches!(ext.as_str(), "il" | "txt" | "test")
}

/// The errors `ilc check --message-format json` reports: (code, line, message, exit status).
fn check(path: &Path) -> (i32, Vec<(String, usize, String)>) {
    let o = Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(["check", "--message-format", "json"])
        .arg(path)
        .output()
        .expect("run ilc");
    let status = o.status.code().expect("ilc exited normally");
    let stdout = String::from_utf8(o.stdout).expect("UTF-8 stdout");
    let mut errors = Vec::new();
    for line in stdout.lines() {
        let v = json::parse(line);
        if get(&v, "severity") != &J::Str("error".into()) {
            continue;
        }
        let (J::Str(code), J::Num(l), J::Str(msg)) =
            (get(&v, "code"), get(&v, "line"), get(&v, "message"))
        else {
            panic!("malformed diagnostic {line}")
        };
        errors.push((code.clone(), *l as usize, msg.clone()));
    }
    (status, errors)
}

#[test]
#[ignore = "needs parser"]
fn corpus_outcomes() {
    let dir = corpus_dir();
    if !dir.is_dir() {
        println!(
            "SKIPPED: ../shared/corpus not found (corpus tests need the shared folder beside the checkout)"
        );
        return;
    }
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| is_corpus_file(p))
        .collect();
    files.sort();
    let mut failures = Vec::new();
    for (name, _) in EXPECTED {
        if !dir.join(name).is_file() {
            failures.push(format!("{name}: in the table but not in the corpus"));
        }
    }
    for path in &files {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let Some((_, expect)) = EXPECTED.iter().find(|(n, _)| *n == name) else {
            failures.push(format!(
                "{name}: new corpus file; add its expected outcome to EXPECTED"
            ));
            continue;
        };
        let (status, errors) = check(path);
        let shown = || {
            errors
                .iter()
                .map(|(c, l, m)| format!("\n    {c} line {l}: {m}"))
                .collect::<String>()
        };
        match expect {
            Accept => {
                if status != 0 || !errors.is_empty() {
                    failures.push(format!(
                        "{name}: expected Accept, got exit {status}{}",
                        shown()
                    ));
                }
            }
            Refuse {
                code,
                line,
                must_mention,
            } => {
                let hit = errors.iter().any(|(c, l, m)| {
                    c == code
                        && l == line
                        && m.to_lowercase().contains(&must_mention.to_lowercase())
                });
                if status != 1 || !hit {
                    failures.push(format!(
                        "{name}: expected {code} on line {line} naming {must_mention:?}, got exit {status}{}",
                        shown()
                    ));
                }
            }
        }
    }
    println!("checked {} corpus files", files.len());
    assert!(
        failures.is_empty(),
        "{} corpus file(s) off:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
