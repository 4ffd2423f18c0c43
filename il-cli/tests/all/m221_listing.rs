//! Modicon M221 / TwidoSuite text listings through `ilc --dialect m221`:
//! `tests/m221/listing.il` (blank-line and comment rungs, printed line
//! numbers, a label, a timer and a counter configured in `(*@ ... *)`
//! comments, an operation and a comparison block, edges, two subroutines,
//! one called TwidoSuite's way, `RETC` in a subroutine, `ENDC`) run scan by
//! scan against a trace worked by hand, with the names as the listing
//! writes them (`%I0.3`, `%C0.V`); refusals located in the listing.

use super::run::{ilc, text};
use std::path::{Path, PathBuf};

fn listing() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/m221/listing.il")
        .display()
        .to_string()
}

/// The inputs of `il-cli/tests/all/m221.rs`, scan by scan (scan k at
/// (k-1) * 10 ms): I0.0 1 1 1 0 0 0, I0.1 0 0 1 1 1 1, I0.2 0 0 0 0 1 1,
/// I0.3 0 0 0 1 1 1, I0.4 0 1 1 0 1 1, I0.5 1 ..., I0.6 0 0 0 0 0 1,
/// I0.7 0 1 0 1 0 0; written as the listing names them.
const INPUTS: &[&str] = &[
    "%I0.0=TRUE",
    "%I0.0=FALSE@4",
    "%I0.1=TRUE@3",
    "%I0.2=TRUE@5",
    "%I0.3=TRUE@4",
    "%I0.4=TRUE@2",
    "%I0.4=FALSE@4",
    "%I0.4=TRUE@5",
    "%I0.5=TRUE",
    "%I0.6=TRUE@6",
    "%I0.7=TRUE@2",
    "%I0.7=FALSE@3",
    "%I0.7=TRUE@4",
    "%I0.7=FALSE@5",
];

fn run(watch: &str) -> String {
    let f = listing();
    let mut args = vec!["run", "--dialect", "m221", f.as_str(), "--cycles", "6"];
    for s in INPUTS {
        args.push("--set");
        args.push(s);
    }
    args.extend(["--watch", watch]);
    let o = ilc(&args);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    text(&o.stdout)
}

#[test]
fn the_listing_checks_clean_with_the_dialect() {
    let o = ilc(&["check", "--dialect", "m221", &listing()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stderr), "");
    // Read as IEC IL it is no program: the switch is what reads it.
    let o = ilc(&["check", &listing()]);
    assert_eq!(o.status.code(), Some(1));
}

#[test]
fn rungs_blocks_and_jumps_follow_the_hand_trace() {
    // Q0.0 := I0.0 AND (I0.1 OR I0.2). %TM0: TON 3 x 10 ms on I0.5 (from
    // 0 ms): Q at 30 ms. %C0 (preset 2): CU = I0.7's rises at scans 2 and
    // 4, D at V = 2, R = I0.6 at scan 6. LDR/LDF %I0.4 set and reset M0
    // (rises at 2 and 5, falls at 4). JMPC %L1 skips M1 := I0.1 while I0.0
    // is 1 (scans 1-3); Q0.7 := M1 after the label.
    let want = "\
cycle  time  %Q0.0  %Q0.4  %C0.V  %Q0.5  %M0    %M1    %Q0.7
    1  0s    FALSE  FALSE      0  FALSE  FALSE  FALSE  FALSE
    2  10ms  FALSE  FALSE      1  FALSE  TRUE   FALSE  FALSE
    3  20ms  TRUE   FALSE      1  FALSE  TRUE   FALSE  FALSE
    4  30ms  FALSE  TRUE       2  TRUE   FALSE  TRUE   TRUE
    5  40ms  FALSE  TRUE       2  TRUE   TRUE   TRUE   TRUE
    6  50ms  FALSE  TRUE       0  FALSE  TRUE   TRUE   TRUE
";
    assert_eq!(run("%Q0.0,%Q0.4,%C0.V,%Q0.5,%M0,%M1,%Q0.7"), want);
}

#[test]
fn subroutines_and_the_end_of_the_scan_follow_the_hand_trace() {
    // `LD %I0.3 / CAL SR1`: SR1 adds 1 to MW0 in the scans where I0.3 is 1
    // (4, 5, 6). Q0.6 := MW0 >= KW0 (2). `LD %I0.4 / SR2` (TwidoSuite's
    // call): SR2 returns at its `RETC` when I0.1 is 1, else adds 1 to MW1:
    // only scan 2 (I0.4 1, I0.1 0). `LD %I0.2 / ENDC` ends the scan from
    // scan 5, before MW2 := MW2 + 1.
    let want = "\
cycle  time  %MW0  %Q0.6  %MW1  %MW2
    1  0s       0  FALSE     0     1
    2  10ms     0  FALSE     1     2
    3  20ms     0  FALSE     1     3
    4  30ms     1  FALSE     1     4
    5  40ms     2  TRUE      1     4
    6  50ms     3  TRUE      1     4
";
    assert_eq!(run("%MW0,%Q0.6,%MW1,%MW2"), want);
    // The mangled IL names are the same objects.
    let values = |t: &str| -> Vec<Vec<String>> {
        t.lines()
            .skip(1)
            .map(|l| l.split_whitespace().map(String::from).collect())
            .collect()
    };
    assert_eq!(values(&run("MW0,Q0_6,MW1,MW2")), values(want));
}

fn temp(name: &str, body: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ilc-m221-listing-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, body).unwrap();
    p
}

#[test]
fn unconfigured_objects_and_bad_lines_are_named_where_they_are() {
    let p = temp(
        "refused.il",
        "(*@ %TM1 TON BASE=2ms PRESET=5 *)\n\
         LD %I0.0\n\
         ST %Q0.0\n\
         \n\
         BLK %TM0\n\
         LD %I0.1\n\
         IN\n\
         END_BLK\n\
         \n\
         LD %I0.2\n\
         CAL SR4\n\
         \n\
         LD [ %MW0 > %KW2 ]\n\
         ST %Q0.1\n\
         RET\n",
    );
    let o = ilc(&["check", "--dialect", "m221", &p.display().to_string()]);
    assert_eq!(o.status.code(), Some(1));
    let err = text(&o.stderr);
    let f = p.display().to_string();
    for (code, at, what) in [
        (
            "IL0433",
            "1:14",
            "`BASE=2ms` in `%TM1`'s configuration: a time base is 1ms, 10ms, 100ms, 1s or 1min",
        ),
        (
            "IL0436",
            "5:5",
            "`%TM0` has no configuration in this listing: add a line `(*@ %TM0 TON BASE=100ms PRESET=50 *)`",
        ),
        (
            "IL0430",
            "11:5",
            "`SR4` calls no subroutine of this program (no `SR4:`)",
        ),
        (
            "IL0436",
            "13:13",
            "`%KW2` has no configuration in this listing: add a line `(*@ %KW2 VALUE=0 *)`",
        ),
    ] {
        assert!(
            err.contains(&format!("error[{code}]: {what}")),
            "{code} {what}\n{err}"
        );
        assert!(err.contains(&format!("--> {f}:{at}")), "{at}\n{err}");
    }
    assert!(err.contains("rung 2 of POU `refused` is left out"), "{err}");
    assert!(err.ends_with("error: check failed: 4 errors\n"), "{err}");
}

#[test]
fn ret_belongs_in_a_subroutine() {
    let p = temp("ret.il", "LD %I0.0\nST %Q0.0\nRET\n");
    let o = ilc(&["check", "--dialect", "m221", &p.display().to_string()]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("error[IL0430]: `RET` outside a subroutine (`SRn:` ... `RET`)"),
        "{err}"
    );
    assert!(err.contains(&format!("--> {}:3:1", p.display())), "{err}");
}

#[test]
fn system_bits_the_controller_sets_are_simulated() {
    // %S0 and %S13 are 1 in the first scan only; %S6 (1 s) and %S5
    // (100 ms) are 0 in the first half of their period, 1 in the second:
    // with 250 ms scans, %S6 is 1 at 500 and 750 ms, rising at 500 ms and
    // at 1.5 s; %S5 (period 100 ms) is sampled at 0, 250, 500 ... ms: 0
    // at whole tenths, 1 at 250 and 750 ms. %S8 is the host's (IL0434).
    let p = temp(
        "system.il",
        "LD %S0\nST %M0\n\nLD %S13\n[ %MW0 := %MW0 + 1 ]\n\nLDR %S6\n[ %MW1 := %MW1 + 1 ]\n\nLD %S5\nST %Q0.0\n\nLD %S8\nST %Q0.1\n",
    );
    let f = p.display().to_string();
    let o = ilc(&[
        "run",
        "--dialect",
        "m221",
        &f,
        "--cycles",
        "8",
        "--step",
        "250ms",
        "--watch",
        "%M0,%MW0,%S6,%MW1,%Q0.0",
    ]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    let want = "\
cycle  time     %M0    %MW0  %S6    %MW1  %Q0.0
    1  0s       TRUE      1  FALSE     0  FALSE
    2  250ms    FALSE     1  FALSE     0  TRUE
    3  500ms    FALSE     1  TRUE      1  FALSE
    4  750ms    FALSE     1  TRUE      1  TRUE
    5  1s       FALSE     1  FALSE     1  FALSE
    6  1s250ms  FALSE     1  FALSE     1  TRUE
    7  1s500ms  FALSE     1  TRUE      2  FALSE
    8  1s750ms  FALSE     1  TRUE      2  TRUE
";
    assert_eq!(text(&o.stdout), want);
    assert!(
        err.contains("warning[IL0434]: system object: `S8` is a global the host sets"),
        "{err}"
    );
    assert_eq!(err.matches("warning[IL0434]").count(), 1, "{err}");
}

#[test]
fn a_bit_of_a_word_is_watched_through_its_word() {
    let p = temp("bit.il", "LD %I0.0\nST %MW4:X3\n");
    let f = p.display().to_string();
    let run = |watch: &str| {
        ilc(&[
            "run",
            "--dialect",
            "m221",
            &f,
            "--cycles",
            "1",
            "--set",
            "%I0.0=TRUE",
            "--watch",
            watch,
        ])
    };
    let o = run("%MW4:X3");
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        text(&o.stderr),
        "error: --watch %MW4:X3: a bit of a word is not watched on its own; watch the word `%MW4`\n"
    );
    let o = run("%MW4");
    assert_eq!(text(&o.stdout), "cycle  time  %MW4\n    1  0s       8\n");
}
