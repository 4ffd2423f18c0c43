//! `ilc run` on a CONFIGURATION: its tasks decide which programs each scan
//! runs; `--set`/`--watch` name globals, access paths, program variables
//! (`Resource.instance.var`), members and elements of each (`g.x`, `h[3]`,
//! `Res.inst.var.field[2]`) and direct addresses.

use crate::run::{file, ilc, rows, text};

const CFG_FORMS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/plc/cfg_forms.il");
const CFG_PATHS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/plc/cfg_paths.il");

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
            "--watch Io.limit: configuration `CfgIo` has no global, access path, resource or program instance `Io`",
        ),
        (
            vec!["--config", "CfgIo", "--watch", "Cpu.Io.nothing"],
            "--watch Cpu.Io.nothing: program `CfIo` (instance `Cpu.Io`) has no variable `nothing`",
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

#[test]
fn members_and_elements_of_globals_access_paths_and_program_variables() {
    let o = ilc(&[
        "run",
        CFG_PATHS,
        "--config",
        "CfgPaths",
        "--cycles",
        "4",
        "--set",
        "g.x=5@2",
        "--set",
        "h[3]=7",
        "--set",
        "RES1.P1.cells[2].total=100@3",
        "--watch",
        "g.x,h[3],RES1.h[2],RES1.P1.p.y[3],RES1.P1.m[2,3],RES1.P1.cells[2].total,RES1.P1.t[2].Q,A2",
    ]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{out}{}", text(&o.stderr));
    // g.x is set before scan 2; p.y[3] is g.x + the run count.
    assert_eq!(column(&out, "g.x"), ["0", "5", "5", "5"]);
    assert_eq!(column(&out, "RES1.P1.p.y[3]"), ["1", "7", "8", "9"]);
    // h[3] is set before scan 1 and read into a[3], which cells[2] adds up.
    assert_eq!(column(&out, "h[3]"), ["7"; 4]);
    assert_eq!(
        column(&out, "RES1.P1.cells[2].total"),
        ["7", "14", "107", "114"]
    );
    // `RES1.h`: the configuration's global seen from the resource.
    assert_eq!(column(&out, "RES1.h[2]"), ["1", "2", "3", "4"]);
    assert_eq!(column(&out, "RES1.P1.m[2,3]"), ["2", "4", "6", "8"]);
    assert_eq!(column(&out, "A2"), ["1", "2", "3", "4"]);
    assert_eq!(
        column(&out, "RES1.P1.t[2].Q"),
        ["FALSE", "FALSE", "FALSE", "TRUE"]
    );
}

#[test]
fn wrong_paths_into_a_configuration_say_what_was_meant() {
    for (watch, want) in [
        (
            "g.xx",
            "`g.xx`: CpPoint has no member `xx`; did you mean `x`?",
        ),
        ("h[5]", "`h[5]`: subscript 5 is outside the bounds 1..4"),
        (
            "gg",
            "configuration `CfgPaths` has no global, access path, resource or program instance `gg`; did you mean `g`?",
        ),
        (
            "RES1.P2.n",
            "resource `RES1` has no global or program instance `P2`; did you mean `P1`?",
        ),
        (
            "RES1.P1.nn",
            "program `CpMain` (instance `RES1.P1`) has no variable `nn`; did you mean `n`?",
        ),
        (
            "RES1.P1.cells[1].QQ",
            "CpCell has no member `QQ`; did you mean `Q`?",
        ),
        ("RES1.P1.a.x", "ARRAY[0..3] OF INT has no members"),
        (
            "RES1.P1",
            "`RES1.P1` names the program instance `RES1.P1`: add one of its variables",
        ),
    ] {
        refused_in_cfg_paths("--watch", watch, want);
    }
}

/// `ilc run` of CfgPaths with `flag value` exits 1 saying `want`.
fn refused_in_cfg_paths(flag: &str, value: &str, want: &str) {
    let o = ilc(&[
        "run", CFG_PATHS, "--config", "CfgPaths", "--cycles", "1", flag, value,
    ]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{flag} {value}: {err}");
    assert!(err.contains(want), "{flag} {value}: {err}");
}

#[test]
fn a_set_outside_a_subrange_is_refused_for_access_paths_and_places() {
    for (set, want) in [
        (
            "Level=101",
            "`101` is outside the subrange 0..100 of `Level`",
        ),
        ("Step2=0", "`0` is outside the subrange 1..9 of `Step2`"),
        ("Gz=11", "`11` is outside the subrange -10..10 of `Gz`"),
        (
            "RES1.P1.level=-1",
            "`-1` is outside the subrange 0..100 of `RES1.P1.level`",
        ),
    ] {
        refused_in_cfg_paths("--set", set, want);
    }
    let o = ilc(&[
        "run",
        CFG_PATHS,
        "--config",
        "CfgPaths",
        "--cycles",
        "1",
        "--set",
        "Level=100",
        "--watch",
        "Level,RES1.P1.level",
    ]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{out}{}", text(&o.stderr));
    assert_eq!(column(&out, "Level"), ["100"]);
    assert_eq!(column(&out, "RES1.P1.level"), ["100"]);
}
