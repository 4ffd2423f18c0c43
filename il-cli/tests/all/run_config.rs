//! `ilc run` on a CONFIGURATION: its tasks decide which programs each scan
//! runs; `--set`/`--watch` name globals, access paths, program variables
//! (`Resource.instance.var`) and direct addresses.

use crate::run::{file, ilc, rows, text};

const CFG_FORMS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/plc/cfg_forms.il");

/// The column `name` of a table, top to bottom.
fn column(out: &str, name: &str) -> Vec<String> {
    let header: Vec<&str> = out
        .lines()
        .next()
        .unwrap_or("")
        .split_whitespace()
        .collect();
    let i = header
        .iter()
        .position(|h| *h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"));
    rows(out).into_iter().map(|r| r[i].clone()).collect()
}

#[test]
fn tasks_release_their_programs_by_interval_and_edge() {
    let o = ilc(&[
        "run",
        CFG_FORMS,
        "--config",
        "cfgforms",
        "--cycles",
        "5",
        "--set",
        "trigger=TRUE@2",
        "--set",
        "%IX0.1=TRUE@4",
    ]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{out}{}", text(&o.stderr));
    // Timed: INTERVAL 20ms at a 10ms step, so every other scan, from the first.
    assert_eq!(column(&out, "timed"), ["1", "1", "2", "2", "3"]);
    // OnEdge: once, on the rising edge of `trigger` (set before scan 2).
    assert_eq!(column(&out, "edges"), ["0", "10", "10", "10", "10"]);
    // OnInput: on the rising edge of %IX0.1 (before scan 4).
    assert_eq!(column(&out, "wired"), ["0", "0", "0", "100", "100"]);
    // P2 has no task: every scan; its in-out `b` is the global pair_b.
    assert_eq!(column(&out, "pair_b"), ["2", "3", "4", "5", "6"]);
    assert_eq!(column(&out, "seen"), ["11", "12", "13", "14", "15"]);
}

#[test]
fn access_paths_var_config_addresses_and_program_variables() {
    let o = ilc(&[
        "run",
        CFG_FORMS,
        "--config",
        "CfgIo",
        "--cycles",
        "4",
        "--set",
        "%IW4=7",
        "--set",
        "%IX2.3=TRUE@2",
        "--set",
        "Limit=2@3",
        "--set",
        "Cpu.Io.scans=100@4",
        "--watch",
        "mode,Scans,Limit,Hits,Cpu.Io.scans,%QX1.0",
    ]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{out}{}", text(&o.stderr));
    // VAR_CONFIG sets `limit` to 5; the access path Limit writes it at 3.
    assert_eq!(column(&out, "Limit"), ["5", "5", "2", "2"]);
    assert_eq!(column(&out, "Scans"), ["5", "10", "12", "102"]);
    assert_eq!(column(&out, "Cpu.Io.scans"), column(&out, "Scans"));
    // latch.level is %IW4 and latch.lamp is %QX1.0 through VAR_CONFIG.
    assert_eq!(column(&out, "Hits"), ["7", "14", "21", "28"]);
    assert_eq!(column(&out, "%QX1.0"), ["FALSE", "TRUE", "TRUE", "TRUE"]);
    assert_eq!(column(&out, "mode"), ["3"; 4]);
}

#[test]
fn the_default_watch_is_the_globals_and_access_paths() {
    let o = ilc(&["run", CFG_FORMS, "--config", "CfgIo", "--cycles", "1"]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let header: Vec<&str> = out.lines().next().unwrap().split_whitespace().collect();
    // `Mode` is the access path to `mode`: one column.
    assert_eq!(
        header,
        [
            "cycle", "time", "mode", "Scans", "Limit", "Hits", "Delay", "Done"
        ]
    );
}

const ONE: &str = "\
PROGRAM Up
VAR_EXTERNAL n : INT; END_VAR
    LD n
    ADD 1
    ST n
END_PROGRAM
PROGRAM Down
VAR_EXTERNAL n : INT; END_VAR
VAR runs : INT; END_VAR
    LD runs
    ADD 1
    ST runs
END_PROGRAM
CONFIGURATION Only
VAR_GLOBAL n : INT := 10; END_VAR
TASK slow (INTERVAL := T#30ms);
PROGRAM u WITH slow : Up;
PROGRAM d : Down;
END_CONFIGURATION
";

#[test]
fn the_only_configuration_runs_when_no_program_is_named() {
    let f = file("only_config.il", ONE);
    let o = ilc(&["run", &f, "--cycles", "4", "--watch", "n,d.runs"]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{out}{}", text(&o.stderr));
    assert_eq!(column(&out, "n"), ["11", "11", "11", "12"]);
    assert_eq!(column(&out, "d.runs"), ["1", "2", "3", "4"]);
    // --program still runs one program alone.
    let o = ilc(&[
        "run",
        &f,
        "--program",
        "Down",
        "--cycles",
        "2",
        "--watch",
        "runs",
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert_eq!(column(&text(&o.stdout), "runs"), ["1", "2"]);
}

#[test]
fn wrong_configuration_names_exit_1() {
    for (args, want) in [
        (
            vec!["--cycles", "1"],
            "has several PROGRAMs (CfBump, CfTwo, CfIo); choose one with --program, or a CONFIGURATION (CfgForms, CfgIo) with --config",
        ),
        (
            vec!["--config", "Nope"],
            "no CONFIGURATION named `Nope` (there is CfgForms, CfgIo)",
        ),
        (
            vec!["--config", "CfgIo", "--program", "CfIo"],
            "give --program or --config, not both",
        ),
        (
            vec!["--config", "CfgIo", "--set", "Scans=3"],
            "--set Scans=3: the access path `Scans` is READ_ONLY",
        ),
        (
            vec!["--config", "CfgIo", "--set", "Limit=TRUE"],
            "--set Limit=TRUE: `TRUE` is not a valid INT value (for `Limit`)",
        ),
        (
            vec!["--config", "CfgIo", "--watch", "Io.limit"],
            "--watch Io.limit: configuration `CfgIo` has no global, access path or program variable `Io.limit`",
        ),
        (
            vec!["--config", "CfgIo", "--watch", "Cpu.Io.nothing"],
            "--watch Cpu.Io.nothing: program `CfIo` has no variable `nothing`",
        ),
    ] {
        let mut all = vec!["run", CFG_FORMS];
        all.extend(&args);
        let o = ilc(&all);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}
