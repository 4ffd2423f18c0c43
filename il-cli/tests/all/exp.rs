//! CODESYS 2.3 `.EXP` projects through `ilc`: the Windows-1252 project
//! written for the tests (`tests/exp/project.EXP`) checked with its one
//! warning and run scan by scan against a trace worked out by hand; a
//! project of several files given as a folder; the OWEN project of
//! `../shared/corpus/exp` (skipped, visibly, without it).

use super::run::{ilc, text};
use std::path::{Path, PathBuf};

fn project() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/exp/project.EXP")
        .display()
        .to_string()
}

#[test]
fn check_passes_with_one_warning_for_the_st_block() {
    let f = project();
    let o = ilc(&["--encoding", "windows-1252", "check", &f]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let err = text(&o.stderr);
    let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning[")).collect();
    assert_eq!(
        warnings,
        [
            "warning[IL0401]: FUNCTION_BLOCK `Scale` is in Structured Text: its interface is compiled, its body is not (host-provided)"
        ],
        "{err}"
    );
    assert!(err.contains(&format!("--> {f}:80:1")), "{err}");
    assert!(err.ends_with("warning: 1 warning emitted\n"), "{err}");
}

#[test]
fn run_gives_the_values_the_il_computes_scan_by_scan() {
    let f = project();
    let o = ilc(&[
        "--encoding",
        "windows-1252",
        "run",
        &f,
        "--cycles",
        "6",
        "--watch",
        "c.n,total,lamp,scaled",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    // By hand: each scan CAL c(inc := TRUE) counts c.n up; total := Twice(c.n);
    // lamp := c.n >= LIMIT_N (3); at c.n >= SLOTS (4) CALC c.Reset (the IL
    // ACTION) sets it back to 0 after lamp was stored. Scale is ST: run as
    // its interface, so `scaled` stays 0.
    let want = "\
cycle  time  c.n  total  lamp   scaled
    1  0s      1      2  FALSE       0
    2  10ms    2      4  FALSE       0
    3  20ms    3      6  TRUE        0
    4  30ms    0      8  TRUE        0
    5  40ms    1      2  FALSE       0
    6  50ms    2      4  FALSE       0
";
    assert_eq!(text(&o.stdout), want);
    let err = text(&o.stderr);
    assert!(
        err.contains("note: `Scale` is a host FUNCTION_BLOCK"),
        "{err}"
    );
}

const GVL: &str = "(* @NESTEDCOMMENTS := 'Yes' *)\r\n(* @GLOBAL_VARIABLE_LIST := 'G' *)\r\n(* @PATH := '' *)\r\nVAR_GLOBAL\r\n\tcount : INT;\r\nEND_VAR\r\nVAR_GLOBAL CONSTANT\r\n\tN : INT := 2;\r\nEND_VAR\r\n(* @OBJECT_END := 'G' *)\r\n";
const FB: &str = "(* @NESTEDCOMMENTS := 'Yes' *)\r\n(* @PATH := '' *)\r\nFUNCTION_BLOCK Inc\r\nVAR_OUTPUT\r\n\tq : BOOL;\r\nEND_VAR\r\n(* @END_DECLARATION := '0' *)\r\nLD count\r\nADD 1\r\nST count\r\nGE N\r\nST q\r\nEND_FUNCTION_BLOCK\r\n";
const PRG: &str = "(* @NESTEDCOMMENTS := 'Yes' *)\r\n(* @PATH := '' *)\r\nPROGRAM Main\r\nVAR\r\n\tinc : Inc;\r\nEND_VAR\r\n(* @END_DECLARATION := '0' *)\r\nCAL inc\r\nEND_PROGRAM\r\n";
const TASKS: &str = "\r\nRESOURCE\r\n\r\nTASK Slow (PRIORITY := 1, INTERVAL := T#20ms);\r\nMain();\r\n{Additional_info : 1,0,0,0,1,4294967295}\r\nEND_TASK\r\nEND_RESOURCE\r\n";

const LIBRARY: &str = "LIBRARY\r\nSTANDARD.LIB 4.10.05 10:14:46\r\n(* @LIBRARYSYMFILEINFO := '0' *)\r\nNumOfPOUs: 1\r\nTON: 0\r\nNumOfGVLs: 0\r\nEND_LIBRARY\r\n";

#[test]
fn a_folder_of_exports_is_one_project_and_its_tasks_run() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc_exp_folder");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (name, t) in [
        ("G.EXP", GVL),
        ("INC.EXP", FB),
        ("MAIN.EXP", PRG),
        ("TASK CONFIGURATION.EXP", TASKS),
        ("STANDARD.LIB.EXP", LIBRARY),
    ] {
        std::fs::write(dir.join(name), t).unwrap();
    }
    let d = dir.display().to_string();
    let o = ilc(&["check", &d]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stderr), "");
    // --verbose lists what was not compiled, one note each.
    let o = ilc(&["check", "--verbose", &d]);
    assert_eq!(
        text(&o.stderr),
        format!(
            "note: {d}/STANDARD.LIB.EXP:1: skipped a library reference `STANDARD.LIB 4.10.05 10:14:46`\n"
        )
    );
    // The task runs Main every 20 ms: every other 10 ms scan.
    let o = ilc(&["run", &d, "--cycles", "4", "--watch", "count"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        "cycle  time  count\n    1  0s        1\n    2  10ms      1\n    3  20ms      2\n    4  30ms      2\n"
    );
}

#[test]
fn the_owen_project_checks_with_no_error() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus/exp/kaapyth0n_OWEN");
    if !dir.is_dir() {
        eprintln!(
            "SKIPPED: {} not found: the OWEN project is not checked",
            dir.display()
        );
        return;
    }
    let d = dir.display().to_string();
    let o = ilc(&["--encoding", "windows-1251", "check", &d]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(!err.contains("error"), "{err}");
    assert!(err.contains("warning[IL0401]: PROGRAM `PLC_PRG` is in Structured Text"));
    // Its task configuration runs (the ST programs as interfaces).
    let o = ilc(&[
        "--encoding",
        "windows-1251",
        "run",
        &d,
        "--cycles",
        "2",
        "--watch",
        "K14UZSPumpSpeed",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        "cycle  time  K14UZSPumpSpeed\n    1  0s                100\n    2  10ms              100\n"
    );
}

/// A PROGRAM with an action that another POU calls (`CAL Aux.Reset`) and
/// reads (`Aux.n`), and that a task runs too.
const CALLED: &str = "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @GLOBAL_VARIABLE_LIST := 'G' *)\nVAR_GLOBAL\n	total : INT;\nEND_VAR\n(* @OBJECT_END := 'G' *)\n\n(* @NESTEDCOMMENTS := 'Yes' *)\nPROGRAM Aux\nVAR_OUTPUT n : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD n\nADD 1\nST n\nADD total\nST total\nEND_PROGRAM\nACTION Reset:\nLD 0\nST n\nEND_ACTION\n\n(* @NESTEDCOMMENTS := 'Yes' *)\nPROGRAM PLC_PRG\nVAR k : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD Aux.n\nST k\nGE 3\nCALC Aux.Reset\nEND_PROGRAM\n\nRESOURCE\nTASK Fast (PRIORITY := 1, INTERVAL := T#10ms);\nAux();\nPLC_PRG();\nEND_TASK\nEND_RESOURCE\n";

#[test]
fn a_program_called_from_another_pou_runs_its_action_there() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc_exp_called");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("called.EXP");
    std::fs::write(&f, CALLED).unwrap();
    let f = f.display().to_string();
    let o = ilc(&["check", &f]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stderr), "");
    // By hand: the task runs Aux (n += 1; total += n), then PLC_PRG
    // (k := Aux.n; at k >= 3 CALC Aux.Reset, which sets n to 0 and does not
    // count): one instance of Aux, as CODESYS has.
    let o = ilc(&[
        "run",
        &f,
        "--cycles",
        "6",
        "--watch",
        "Aux.n,total,PLC.PLC_PRG.k",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        "\
cycle  time  Aux.n  total  PLC.PLC_PRG.k
    1  0s        1      1              1
    2  10ms      2      3              2
    3  20ms      0      6              3
    4  30ms      1      7              1
    5  40ms      2      9              2
    6  50ms      0     12              3
"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
