//! `ilc run`: the interpreter's quick look at a program, as a user runs it.

use std::path::PathBuf;
use std::process::{Command, Output};

const COUNTER: &str = "\
PROGRAM Main
VAR
    start : BOOL;
    n : INT;
    big : INT := 32766;
    q : INT;
    d : INT;
    t1 : TON;
    done : BOOL;
END_VAR
    LD start
    JMPCN skip
    LD n
    ADD 1
    ST n
skip:
    LD big
    ADD 1
    ST big
    LD 10
    DIV d
    ST q
    CAL t1(IN := start, PT := T#20ms)
    LD t1.Q
    ST done
END_PROGRAM
";

pub(crate) fn file(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc_run");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    // Tests that share a file name run in parallel: a write in place could
    // be read half-done by another test's ilc, a rename is seen whole.
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = dir.join(format!("{name}.{}.{n}.tmp", std::process::id()));
    std::fs::write(&tmp, text).unwrap();
    std::fs::rename(&tmp, &p).unwrap();
    p.display().to_string()
}

pub(crate) fn ilc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run ilc")
}

pub(crate) fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn prints_an_aligned_table_per_cycle() {
    let f = file("counter.il", COUNTER);
    let o = ilc(&[
        "run",
        &f,
        "--program",
        "Main",
        "--cycles",
        "4",
        "--step",
        "10ms",
        "--set",
        "start=TRUE@2",
        "--set",
        "d=5",
        "--watch",
        "start,n,big,q,t1.ET,done",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let expected = "\
cycle  time  start  n     big  q  t1.ET   done
    1  0s    FALSE  0   32767  2  T#0s    FALSE
    2  10ms  TRUE   1  -32768  2  T#0s    FALSE
    3  20ms  TRUE   2  -32767  2  T#10ms  FALSE
    4  30ms  TRUE   3  -32766  2  T#20ms  TRUE
";
    assert_eq!(out, expected);
    assert_eq!(text(&o.stderr), "");
}

#[test]
fn program_is_found_alone_and_all_variables_are_watched() {
    let f = file("alone.il", COUNTER);
    let o = ilc(&["run", &f, "--cycles", "1", "--set", "d=2"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let head = out.lines().next().unwrap();
    assert_eq!(
        head.split_whitespace().collect::<Vec<_>>(),
        ["cycle", "time", "start", "n", "big", "q", "d", "done"]
    );
    assert_eq!(out.lines().count(), 2);
}

#[test]
fn faults_are_reported_on_stderr() {
    let f = file("faults.il", COUNTER);
    let o = ilc(&["run", &f, "--cycles", "2", "--watch", "q"]);
    assert_eq!(o.status.code(), Some(0));
    let err = text(&o.stderr);
    assert!(
        err.contains("cycle 1: fault DivisionByZero in Main at ") && err.contains("faults.il:21\n"),
        "{err}"
    );
    assert!(err.contains("cycle 2:"), "{err}");
}

#[test]
fn wrong_names_and_values_exit_1() {
    let f = file("names.il", COUNTER);
    for (args, msg) in [
        (
            vec!["--program", "Nope"],
            "no PROGRAM or FUNCTION_BLOCK named `Nope`",
        ),
        (vec!["--set", "nope=1"], "no variable `nope`"),
        (vec!["--set", "n=TRUE"], "`TRUE` is not a valid INT value"),
        (vec!["--set", "n=40000"], "`40000` is not a valid INT value"),
        (vec!["--watch", "n,zz"], "no variable `zz`"),
        (vec!["--watch", "t1"], "function block instance"),
        (vec!["--set", "n=1@99"], "only 10 cycles"),
    ] {
        let mut a = vec!["run", f.as_str()];
        a.extend(args.iter().copied());
        let o = ilc(&a);
        assert_eq!(o.status.code(), Some(1), "{args:?}");
        let err = text(&o.stderr);
        assert!(err.contains(msg), "{args:?}: {err}");
        assert!(text(&o.stdout).is_empty());
    }
    let bad = file(
        "bad.il",
        "PROGRAM P\nVAR a : BOOL; END_VAR\n LD b\n ST a\nEND_PROGRAM\n",
    );
    let o = ilc(&["run", &bad]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o.stderr).contains("nothing was run"));
    let o = ilc(&["run", "/nonexistent/x.il"]);
    assert_eq!(o.status.code(), Some(1));
    let two = file(
        "two.il",
        "PROGRAM A\nVAR x : BOOL; END_VAR\n LD x\n ST x\nEND_PROGRAM\nPROGRAM B\nVAR x : BOOL; END_VAR\n LD x\n ST x\nEND_PROGRAM\n",
    );
    let o = ilc(&["run", &two]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o.stderr).contains("several PROGRAMs (A, B)"));
}

#[test]
fn usage_errors_exit_2() {
    let f = file("usage.il", COUNTER);
    for args in [
        vec!["run"],
        vec!["run", f.as_str(), "--cycles", "many"],
        vec!["run", f.as_str(), "--cycles", "0"],
        vec!["run", f.as_str(), "--step", "soon"],
        vec!["run", f.as_str(), "--set", "n"],
        vec!["run", f.as_str(), "--set", "n=1@0"],
        vec!["run", f.as_str(), "--bogus"],
    ] {
        let o = ilc(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o.stderr));
    }
}

#[test]
fn members_of_standard_blocks_can_be_set_and_watched() {
    let f = file(
        "dotted.il",
        "PROGRAM Main\nVAR\n    go : BOOL;\n    t1 : TON;\n    done : BOOL;\nEND_VAR\n    LD go\n    IN t1\n    LD t1.Q\n    ST done\nEND_PROGRAM\n",
    );
    let o = ilc(&[
        "run",
        &f,
        "--cycles",
        "4",
        "--step",
        "1s",
        "--set",
        "go=TRUE",
        "--set",
        "t1.PT=T#2s",
        "--watch",
        "t1.ET,done",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        "\
cycle  time  t1.ET  done
    1  0s    T#0s   FALSE
    2  1s    T#1s   FALSE
    3  2s    T#2s   TRUE
    4  3s    T#2s   TRUE
"
    );
}

/// The tank controller (enumeration, structures, an array of structures, a
/// subrange, TON, CTU, R_TRIG, a FUNCTION with a VAR_OUTPUT, jumps, located
/// variables and direct addresses).
const TANK: &str = include_str!("tank.il");

/// The table's rows as cells, without the header.
pub(crate) fn rows(out: &str) -> Vec<Vec<String>> {
    out.lines()
        .skip(1)
        .map(|l| l.split_whitespace().map(str::to_string).collect())
        .collect()
}

#[test]
fn a_tank_controller_driven_through_its_inputs() {
    let f = file("tank.il", TANK);
    let o = ilc(&[
        "run",
        &f,
        "--cycles",
        "10",
        "--step",
        "10ms",
        "--set",
        "%IX0.0=TRUE@2",
        "--set",
        "%IW2=900@3",
        "--set",
        "%IX0.2=TRUE@4",
        "--set",
        "raw=50@8",
        "--watch",
        "state,tank.level,%QX0.0,drain,settle.ET,batches.CV,history[1],slot,valves[2].open",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert_eq!(
        out.lines()
            .next()
            .unwrap()
            .split_whitespace()
            .collect::<Vec<_>>(),
        [
            "cycle",
            "time",
            "state",
            "tank.level",
            "%QX0.0",
            "drain",
            "settle.ET",
            "batches.CV",
            "history[1]",
            "slot",
            "valves[2].open"
        ]
    );
    let r = rows(&out);
    let col = |k: usize, c: usize| r[k - 1][c].as_str();
    // Idle until the start button's rising edge at cycle 2: the pump runs.
    assert_eq!((col(1, 2), col(1, 4)), ("TankState#Idle", "FALSE"));
    assert_eq!((col(2, 2), col(2, 4)), ("TankState#Filling", "TRUE"));
    // %IW2 = 900 raw is 90 %, above the high mark: the pump stops, it settles.
    assert_eq!(
        (col(3, 2), col(3, 3), col(3, 4)),
        ("TankState#Settling", "90", "FALSE")
    );
    // The flush button at %IX0.2 opens valve 2 from cycle 4.
    assert_eq!((col(3, 10), col(4, 10)), ("FALSE", "TRUE"));
    // TON of 30 ms: ET grows by the 10 ms step, Q at cycle 6 starts draining.
    assert_eq!(
        (col(4, 6), col(5, 6), col(6, 6)),
        ("T#10ms", "T#20ms", "T#30ms")
    );
    assert_eq!((col(6, 2), col(6, 5)), ("TankState#Draining", "TRUE"));
    assert_eq!(col(5, 5), "FALSE");
    // raw = 50 (the located variable's name) is 5 %: below the low mark, a batch is done.
    assert_eq!(
        (col(8, 2), col(8, 3), col(8, 5)),
        ("TankState#Idle", "5", "FALSE")
    );
    assert_eq!((col(7, 7), col(8, 7), col(10, 7)), ("0", "1", "1"));
    assert_eq!((col(8, 8), col(8, 9)), ("5", "2"));
    assert_eq!(text(&o.stderr), "");
}

#[test]
fn tank_values_of_user_types_members_and_the_default_watch() {
    let f = file("tank_set.il", TANK);
    let o = ilc(&[
        "run",
        &f,
        "--cycles",
        "2",
        "--set",
        "state=TankState#Filling",
        "--set",
        "valves[1].open=TRUE@2",
        "--set",
        "tank.high=50",
        "--set",
        "%IW2=700@2",
        "--watch",
        "state,tank.high,valves[1],%QX0.0,pump,raw,%IW2",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let r = rows(&out);
    assert_eq!(r[0][2], "TankState#Filling");
    assert_eq!(r[0][3], "50");
    assert!(out.contains("(open := FALSE, opened := 0)"), "{out}");
    assert!(out.contains("(open := TRUE, opened := 0)"), "{out}");
    // Filling with the level at 70 % >= 50 %: settling, the pump (%QX0.0) off.
    assert_eq!(r[1][2], "TankState#Settling");
    assert_eq!(&r[1][r[1].len() - 4..], ["FALSE", "FALSE", "700", "700"]);
    assert_eq!(
        (r[0][r[0].len() - 4].as_str(), r[0][r[0].len() - 3].as_str()),
        ("TRUE", "TRUE")
    );

    // Without --watch: every variable but the FB instances, located ones too.
    let o = ilc(&["run", &f, "--cycles", "1"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let head: Vec<&str> = out.lines().next().unwrap().split_whitespace().collect();
    for name in [
        "start", "stop", "raw", "pump", "drain", "state", "tank", "valves",
    ] {
        assert!(head.contains(&name), "{name}: {head:?}");
    }
    for name in ["settle", "batches", "start_edge"] {
        assert!(!head.contains(&name), "{name}: {head:?}");
    }
}

#[test]
fn tank_wrong_names_addresses_and_values() {
    let f = file("tank_bad.il", TANK);
    for (args, msg) in [
        (
            vec!["--watch", "tank.levl"],
            "Tank has no member `levl`; did you mean `level`?",
        ),
        (
            vec!["--watch", "stat"],
            "no variable `stat` in TankCtl; did you mean `state`?",
        ),
        (vec!["--set", "state=Filing"], "did you mean `Filling`?"),
        (vec!["--set", "state=3"], "is not a value of TankState"),
        (vec!["--set", "%IX0.9=TRUE"], "bit 9 does not exist"),
        (vec!["--set", "%IW99999=1"], "outside the process image"),
        (vec!["--set", "%IW2=-5"], "not a valid WORD value"),
        (
            vec!["--set", "valves[3].open=TRUE"],
            "outside the bounds 1..2",
        ),
        (
            vec!["--set", "tank.level=300"],
            "outside the subrange 0..100",
        ),
        (vec!["--set", "tank=1"], "set its members"),
        (vec!["--watch", "settle"], "function block instance"),
        (vec!["--watch", "settle.QQ"], "did you mean `Q`?"),
        (vec!["--watch", "pump.x"], "has no members"),
    ] {
        let mut a = vec!["run", f.as_str(), "--cycles", "1"];
        a.extend(args.iter().copied());
        let o = ilc(&a);
        assert_eq!(o.status.code(), Some(1), "{args:?}");
        let err = text(&o.stderr);
        assert!(err.contains(msg), "{args:?}: {err}");
        assert!(text(&o.stdout).is_empty());
    }
}

/// A host function (`{extern}`) has no body `ilc run` could run: the run goes
/// on with its interface (default result, outputs at their initial values)
/// and says so.
#[test]
fn host_functions_are_run_by_their_interface_and_named() {
    let f = file(
        "host.il",
        "{extern}\nFUNCTION read_sensor : INT\nVAR_INPUT ch : INT; END_VAR\nEND_FUNCTION\nPROGRAM Main\nVAR v : INT; n : INT; END_VAR\n    LD 3\n    read_sensor\n    ADD 1\n    ST v\n    LD n\n    ADD 1\n    ST n\nEND_PROGRAM\n",
    );
    let o = ilc(&["run", &f, "--cycles", "2"]);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert!(o.status.success(), "{out}{err}");
    assert!(
        err.contains("note: `read_sensor` is a host function ({extern})")
            && err.contains("returns the INT default"),
        "{err}"
    );
    let last: Vec<&str> = out.lines().last().unwrap().split_whitespace().collect();
    assert_eq!(last[2..], ["1", "2"], "{out}");
}

/// `--set %IW2=-5`: a WORD has no sign; the error says the two ways that work.
#[test]
fn a_negative_number_into_a_word_address_says_how() {
    let f = file("tank.il", TANK);
    let o = ilc(&["run", &f, "--cycles", "1", "--set", "%IW2=-5"]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let err = text(&o.stderr);
    assert!(err.contains("a WORD has no sign"), "{err}");
    assert!(err.contains("(`--set NAME=-5`)"), "{err}");
    assert!(err.contains("(`--set %IW2=65531`)"), "{err}");
    let o = ilc(&["run", &f, "--cycles", "1", "--set", "%IW2=65531"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
}

/// A PROGRAM run alone from a file whose CONFIGURATION declares the globals
/// it uses: its externals start at their defaults, and the user is told so
/// with the option that runs the configuration (whose values differ).
#[test]
fn a_program_run_alone_says_its_externals_miss_the_globals_values() {
    let f = file(
        "alone_externals.il",
        "PROGRAM Main\nVAR_EXTERNAL g : INT; END_VAR\nVAR x : INT; END_VAR\n  LD g\n  ADD 1\n  ST x\nEND_PROGRAM\n\
         CONFIGURATION Plant\n  VAR_GLOBAL g : INT := 5; END_VAR\n  RESOURCE Cpu ON PLC\n\
         TASK t (INTERVAL := T#10ms, PRIORITY := 1);\n    PROGRAM m WITH t : Main;\n  END_RESOURCE\nEND_CONFIGURATION\n",
    );
    let o = ilc(&["run", &f, "--cycles", "1", "--watch", "x"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert!(
        err.contains("note: PROGRAM `Main` runs alone: its VAR_EXTERNALs (g)")
            && err.contains("--config Plant runs the configuration"),
        "{err}"
    );
    assert!(
        out.lines().nth(1).is_some_and(|l| l.ends_with(" 1")),
        "{out}"
    );
    let o = ilc(&[
        "run", &f, "--cycles", "1", "--config", "Plant", "--watch", "Cpu.m.x",
    ]);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert!(!err.contains("note:"), "{err}");
    assert!(
        out.lines().nth(1).is_some_and(|l| l.ends_with(" 6")),
        "{out}"
    );
    // Named, the program runs alone without the note: the user chose it.
    let o = ilc(&["run", &f, "--cycles", "1", "--program", "Main"]);
    assert!(!text(&o.stderr).contains("note:"), "{}", text(&o.stderr));
}
