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

fn file(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc_run");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn ilc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run ilc")
}

fn text(b: &[u8]) -> String {
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
        err.contains("cycle 1: fault DivisionByZero in Main at IL line 21"),
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
