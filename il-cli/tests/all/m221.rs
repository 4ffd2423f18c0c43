//! Modicon M221 projects (`.smbp`) through `ilc`: the project written for
//! the tests (`tests/m221/groups.smbp`, one rung per instruction group) run
//! scan by scan against traces worked out by hand; the eight real projects
//! of `../shared/corpus/m221` (skipped when absent); refusals and malformed
//! XML with located errors.

use super::run::{ilc, text};
use std::path::{Path, PathBuf};

fn groups() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/m221/groups.smbp")
        .display()
        .to_string()
}

/// The inputs of the traces, scan by scan (cycle k runs at (k-1) * 10 ms):
/// I0.0 1 1 1 0 0 0, I0.1 0 0 1 1 1 1, I0.2 0 0 0 0 1 1, I0.3 0 0 0 1 1 1,
/// I0.4 0 1 1 0 1 1, I0.5 1 ..., I0.6 0 0 0 0 0 1, I0.7 0 1 0 1 0 0.
const INPUTS: &[&str] = &[
    "I0_0=TRUE",
    "I0_0=FALSE@4",
    "I0_1=TRUE@3",
    "I0_2=TRUE@5",
    "I0_3=TRUE@4",
    "I0_4=TRUE@2",
    "I0_4=FALSE@4",
    "I0_4=TRUE@5",
    "%IX0.5=TRUE",
    "I0_6=TRUE@6",
    "I0_7=TRUE@2",
    "I0_7=FALSE@3",
    "I0_7=TRUE@4",
    "I0_7=FALSE@5",
];

fn run(watch: &str) -> String {
    let f = groups();
    let mut args = vec!["run", f.as_str(), "--cycles", "6"];
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
fn the_written_project_checks_clean() {
    let o = ilc(&["check", &groups()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stderr), "");
}

#[test]
fn bit_logic_parentheses_and_jumps_follow_the_hand_trace() {
    // Rung 1: Q0.0 := I0.0 AND (I0.1 OR I0.2) AND NOT I0.3.
    // Rung 11 jumps over rung 12 (M1 := I0.1) while I0.0 is 1, to the
    // rung labelled %L1 (Q0.7 := M1): M1 follows I0.1 from scan 4 only.
    let want = "\
cycle  time  Q0_0   M1     Q0_7
    1  0s    FALSE  FALSE  FALSE
    2  10ms  FALSE  FALSE  FALSE
    3  20ms  TRUE   FALSE  FALSE
    4  30ms  FALSE  TRUE   TRUE
    5  40ms  FALSE  TRUE   TRUE
    6  50ms  FALSE  TRUE   TRUE
";
    assert_eq!(run("Q0_0,M1,Q0_7"), want);
}

#[test]
fn edges_and_the_stack_follow_the_hand_trace() {
    // LDR %I0.4 / S %M0 and LDF %I0.4 / R %M0: M0 rises with I0.4's rising
    // edges (scans 2 and 5) and falls with its falling edge (scan 4), not
    // with its level. MPS/MRD/MPP fan M0 out: Q0.1 := M0 AND I0.1,
    // Q0.2 := M0 AND NOT I0.1, Q0.3 := M0 XOR I0.2.
    let want = "\
cycle  time  M0     Q0_1   Q0_2   Q0_3
    1  0s    FALSE  FALSE  FALSE  FALSE
    2  10ms  TRUE   FALSE  TRUE   TRUE
    3  20ms  TRUE   TRUE   FALSE  TRUE
    4  30ms  FALSE  FALSE  FALSE  FALSE
    5  40ms  TRUE   TRUE   FALSE  FALSE
    6  50ms  TRUE   TRUE   FALSE  FALSE
";
    assert_eq!(run("M0,Q0_1,Q0_2,Q0_3"), want);
}

#[test]
fn timer_counter_and_operation_blocks_follow_the_hand_trace() {
    // %TM0: TON, base 10 ms, preset 3 (30 ms), IN = I0.5 from scan 1 (0 ms):
    // Q at 30 ms. %C0: preset 2, R = I0.6, CU = I0.7 (edges at scans 2, 4):
    // D at V = 2, the reset at scan 6 clears it. MW0 += 1 while I0.7 is 1;
    // MW1 := MW0 * 3 - 1 every scan; Q0.6 := MW1 >= 5;
    // MF10 := INT_TO_REAL(MW1) / 2.0.
    let want = "\
cycle  time  Q0_4   TM0.ET  C0.V  Q0_5   MW0  MW1  Q0_6   MF10
    1  0s    FALSE  T#0s       0  FALSE    0   -1  FALSE  -0.5
    2  10ms  FALSE  T#10ms     1  FALSE    1    2  FALSE   1.0
    3  20ms  FALSE  T#20ms     1  FALSE    1    2  FALSE   1.0
    4  30ms  TRUE   T#30ms     2  TRUE     2    5  TRUE    2.5
    5  40ms  TRUE   T#30ms     2  TRUE     2    5  TRUE    2.5
    6  50ms  TRUE   T#30ms     0  FALSE    2    5  TRUE    2.5
";
    assert_eq!(run("Q0_4,TM0.ET,C0.V,Q0_5,MW0,MW1,Q0_6,MF10"), want);
}

fn temp(name: &str, body: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ilc-m221-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, body).unwrap();
    p
}

/// A project of one POU whose rungs hold `lines`, one rung per slice.
fn project(rungs: &[&[&str]]) -> String {
    let mut s = String::from(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<ProjectDescriptor>\n<SoftwareConfiguration>\n<Pous><ProgramOrganizationUnits><Name>Main</Name><Rungs>\n",
    );
    for r in rungs {
        s.push_str("<RungEntity><InstructionLines>\n");
        for l in *r {
            s.push_str(&format!(
                "<InstructionLineEntity><InstructionLine>{l}</InstructionLine></InstructionLineEntity>\n"
            ));
        }
        s.push_str("</InstructionLines></RungEntity>\n");
    }
    s.push_str("</Rungs></ProgramOrganizationUnits></Pous>\n</SoftwareConfiguration>\n</ProjectDescriptor>\n");
    s
}

#[test]
fn refusals_name_the_object_the_rung_and_why_with_the_line() {
    let p = temp(
        "refused.smbp",
        &project(&[
            &["LD %I0.0", "ST %Q0.0"],
            &["BLK %FC0", "LD %I0.1", "IN", "END_BLK"],
            &["LD %X0.0", "ST %Q0.1"],
            &["[ %MW3 := 1 ]"],
            &["LD [ %MF2 &gt; 1.5 ]", "ST %Q0.2"],
            &["LD %I0.0", "AND(", "OR %I0.1"],
        ]),
    );
    let o = ilc(&["check", &p.display().to_string()]);
    assert_eq!(o.status.code(), Some(1));
    let err = text(&o.stderr);
    let f = p.display().to_string();
    for (code, at, what) in [
        ("IL0431", "10:45", "`%FC0` is a fast or high-speed counter"),
        ("IL0430", "16:44", "`%X0.0` is not an M221 object"),
        (
            "IL0430",
            "29:41",
            "the rung ends with an `AND(` or `OR(` without its `)`",
        ),
    ] {
        assert!(
            err.contains(&format!("error[{code}]: {what}")),
            "{code} {what}\n{err}"
        );
        assert!(err.contains(&format!("--> {f}:{at}")), "{at}\n{err}");
    }
    assert!(err.contains("rung 2 of POU `Main` is left out"), "{err}");
    // `%MF2` over `%MW2`/`%MW3` beside `%MW3` (rungs 4 and 5) compiles.
    assert!(!err.contains(":23:"), "{err}");
    assert!(err.ends_with("error: check failed: 3 errors\n"), "{err}");
}

#[test]
fn malformed_xml_is_a_located_error_not_a_panic() {
    let mut body = project(&[&["LD %I0.0", "ST %Q0.0"]]);
    body = body.replace("</Rungs>", "</Rung>");
    let p = temp("broken.smbp", &body);
    let o = ilc(&["check", &p.display().to_string()]);
    assert_eq!(o.status.code(), Some(1));
    let err = text(&o.stderr);
    assert!(err.contains(&format!("--> {}:", p.display())), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    // A protected project: one error at its root, saying why.
    let p = temp(
        "protected.smbp",
        "\u{feff}<?xml version=\"1.0\"?>\n<CryptedProject><Crypted>AAAA</Crypted></CryptedProject>\n",
    );
    let o = ilc(&["check", &p.display().to_string()]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.starts_with("error[IL0435]: this is a protected Machine Expert Basic project"),
        "{err}"
    );
    assert!(err.contains(&format!("--> {}:2:1", p.display())), "{err}");
    assert_eq!(err.matches("error[").count(), 1, "{err}");
}

#[test]
fn the_eight_corpus_projects_compile_and_run() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/corpus/m221/ss56_somachine-basic-programs");
    if !dir.is_dir() {
        println!(
            "SKIPPED: ../shared/corpus/m221 not found (the corpus test needs the shared folder beside the checkout)"
        );
        return;
    }
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "smbp"))
        .collect();
    files.sort();
    assert_eq!(files.len(), 8, "{files:?}");
    for f in &files {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        let path = f.display().to_string();
        let o = ilc(&["check", &path]);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "{name}: {err}");
        let o = ilc(&["run", &path, "--cycles", "3", "--set", "%IX0.0=TRUE@2"]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", text(&o.stderr));
        assert_eq!(text(&o.stdout).lines().count(), 4, "{name}");
    }
}

#[test]
fn a_corpus_timer_takes_its_configured_preset_and_default_base() {
    let f = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/corpus/m221/ss56_somachine-basic-programs/counter_and_timer.smbp");
    if !f.is_file() {
        println!("SKIPPED: ../shared/corpus/m221 not found");
        return;
    }
    // `<Preset>202</Preset>` without `<Base>`: the editor's default base,
    // one minute, so 202 minutes. The last rung writes %Q0.1 from TM0.Q,
    // after rung 1 wrote I0.0 into it: the timer's FALSE wins.
    let o = ilc(&[
        "run",
        &f.display().to_string(),
        "--cycles",
        "2",
        "--set",
        "I0_0=TRUE",
        "--watch",
        "TM0.PT,Q0_1,C0.V",
    ]);
    let want = "\
cycle  time  TM0.PT   Q0_1   C0.V
    1  0s    T#3h22m  FALSE     0
    2  10ms  T#3h22m  FALSE     0
";
    assert_eq!(text(&o.stdout), want, "{}", text(&o.stderr));
}

#[test]
fn end_of_scan_bits_of_words_and_hex_constants_follow_the_hand_trace() {
    // tests/m221/ends.smbp, POU First: ENDC on I0.0 (scan 3) ends the scan,
    // so nothing after it runs, in First or in Second; MW2 counts the scans
    // First completes, Q0.0 is its bit 1 (`%MW2:X1`). POU Second: MW3
    // counts its scans, MW6 adds #10 (16) each, `%MW4:X0` := I0.1, ENDCN
    // ends the scan while I0.2 is 0 (from scan 5), before MW5 += 1.
    let f = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/m221/ends.smbp")
        .display()
        .to_string();
    let o = ilc(&[
        "run",
        &f,
        "--cycles",
        "6",
        "--set",
        "I0_0=TRUE@3",
        "--set",
        "I0_0=FALSE@4",
        "--set",
        "I0_1=TRUE@2",
        "--set",
        "I0_1=FALSE@4",
        "--set",
        "I0_2=TRUE",
        "--set",
        "I0_2=FALSE@5",
        "--watch",
        "MW2,Q0_0,MW3,MW4,MW5,MW6",
    ]);
    let want = "\
cycle  time  MW2  Q0_0   MW3  MW4  MW5  MW6
    1  0s      1  FALSE    1    0    1   16
    2  10ms    2  TRUE     2    1    2   32
    3  20ms    2  TRUE     2    1    2   32
    4  30ms    3  TRUE     3    0    3   48
    5  40ms    4  FALSE    4    0    3   64
    6  50ms    5  FALSE    5    0    3   80
";
    assert_eq!(text(&o.stdout), want, "{}", text(&o.stderr));
}

#[test]
fn shift_bit_register_fifo_step_counter_and_drum_follow_the_hand_trace() {
    // %SBR0: CU = I0.0 (edges at scans 2, 4), R = I0.1 (scan 5); rung 2
    // writes I0.2 into its bit 0 after the shift. %R0 (FIFO): %R0.I := MW0
    // (10, then 20), I = I0.3 (edges at 1, 3), O = I0.4 (edge at 5), MW1 :=
    // %R0.O. %SC0: CU = I0.5 (edges at 2, 4), Q0.0 := %SC0.1. %DR0 (not
    // configured: 8 steps): U = I0.6 (edge at 3).
    let p = temp(
        "objects.smbp",
        &project(&[
            &["BLK %SBR0", "LD %I0.0", "CU", "LD %I0.1", "R", "END_BLK"],
            &["LD %I0.2", "ST %SBR0.0"],
            &["[ %R0.I := %MW0 ]"],
            &["BLK %R0", "LD %I0.3", "I", "LD %I0.4", "O", "END_BLK"],
            &["[ %MW1 := %R0.O ]"],
            &["BLK %SC0", "LD %I0.5", "CU", "END_BLK"],
            &["LD %SC0.1", "ST %Q0.0"],
            &[
                "BLK %DR0", "LD %I0.6", "U", "OUT_BLK", "LD F", "ST %Q0.1", "END_BLK",
            ],
        ]),
    );
    let f = p.display().to_string();
    let mut args = vec!["run", f.as_str(), "--cycles", "6"];
    for s in [
        "I0_0=TRUE@2",
        "I0_0=FALSE@3",
        "I0_0=TRUE@4",
        "I0_1=TRUE@5",
        "I0_2=TRUE",
        "I0_2=FALSE@2",
        "MW0=10",
        "MW0=20@2",
        "I0_3=TRUE",
        "I0_3=FALSE@2",
        "I0_3=TRUE@3",
        "I0_3=FALSE@4",
        "I0_4=TRUE@5",
        "I0_5=TRUE@2",
        "I0_5=FALSE@3",
        "I0_5=TRUE@4",
        "I0_6=TRUE@3",
    ] {
        args.extend(["--set", s]);
    }
    args.extend(["--watch", "SBR0.X,R0.E,MW1,Q0_0,DR0.S,Q0_1"]);
    let o = ilc(&args);
    let want = "\
cycle  time  SBR0.X  R0.E   MW1  Q0_0   DR0.S  Q0_1
    1  0s         1  FALSE    0  FALSE      0  FALSE
    2  10ms       2  FALSE    0  TRUE       0  FALSE
    3  20ms       2  FALSE    0  TRUE       1  FALSE
    4  30ms       4  FALSE    0  FALSE      1  FALSE
    5  40ms       0  FALSE   10  FALSE      1  FALSE
    6  50ms       0  FALSE   10  FALSE      1  FALSE
";
    assert_eq!(text(&o.stdout), want, "{}", text(&o.stderr));
}

#[test]
fn a_timers_value_and_preset_are_words_in_units_of_its_base() {
    // %TM0 is not configured: TON, base one minute, preset 9999. One scan
    // every 30 s; IN = I0.0 from scan 1. MW0 := %TM0.V (ET in minutes);
    // from scan 3, I0.1 sets %TM0.P := 2 (after the timer ran in that scan),
    // so Q (Q0.1) comes at ET = 2 min, scan 5; ET stops there.
    let p = temp(
        "timer_words.smbp",
        &project(&[
            &[
                "BLK %TM0", "LD %I0.0", "IN", "OUT_BLK", "LD Q", "ST %Q0.1", "END_BLK",
            ],
            &["[ %MW0 := %TM0.V ]"],
            &["LD %I0.1", "[ %TM0.P := 2 ]"],
            &["LD [ %TM0.V &gt;= 1 ]", "ST %Q0.0"],
            &["[ %MW1 := %TM0.P ]"],
        ]),
    );
    let o = ilc(&[
        "run",
        &p.display().to_string(),
        "--cycles",
        "6",
        "--step",
        "30s",
        "--set",
        "I0_0=TRUE",
        "--set",
        "I0_1=TRUE@3",
        "--watch",
        "MW0,Q0_0,MW1,Q0_1",
    ]);
    let want = "\
cycle  time   MW0  Q0_0    MW1  Q0_1
    1  0s       0  FALSE  9999  FALSE
    2  30s      0  FALSE  9999  FALSE
    3  1m       1  TRUE      2  FALSE
    4  1m30s    1  TRUE      2  FALSE
    5  2m       2  TRUE      2  TRUE
    6  2m30s    2  TRUE      2  TRUE
";
    assert_eq!(text(&o.stdout), want, "{}", text(&o.stderr));
}

#[test]
fn logic_on_words_is_bitwise() {
    // AND/OR/XOR/NOT on %MW and %MD words, as the M221 computes them:
    // 16#1234 AND 16#FF = 16#34; NOT 16#1234 = 16#EDCB (-4661 as INT);
    // (16#1234 OR 1) XOR 3 = 16#1236; 1000 AND 255 = 232.
    let p = temp(
        "words.smbp",
        &project(&[
            &["[ %MW1 := %MW2 AND 16#FF ]"],
            &["[ %MW3 := NOT %MW2 ]"],
            &["[ %MW4 := %MW2 OR 1 XOR %MW5 ]"],
            &["LD [ NOT %MW2 = -4661 ]", "ST %Q0.0"],
            &["[ %MD10 := %MD12 AND 255 ]"],
        ]),
    );
    let o = ilc(&[
        "run",
        &p.display().to_string(),
        "--cycles",
        "1",
        "--set",
        "MW2=16#1234",
        "--set",
        "MW5=3",
        "--set",
        "MD12=1000",
        "--watch",
        "MW1,MW3,MW4,Q0_0,MD10",
    ]);
    let want = "\
cycle  time  MW1    MW3   MW4  Q0_0  MD10
    1  0s     52  -4661  4662  TRUE   232
";
    assert_eq!(text(&o.stdout), want, "{}", text(&o.stderr));
}

#[test]
fn double_words_and_floats_are_views_of_two_words_when_they_share_them() {
    // %MF2 shares %MW2 with %MF1 and %MW3 with %MW3: every %MD/%MF is then
    // the words n (low) and n+1. 1.5 is 16#3FC00000: MW1 = 0, MW2 = 16#3FC0
    // (16320). With MW3 = 16#4000, %MF2 is 16#40003FC0, 2.0038909..., > 2.0;
    // copied to %MF20: MW20 = 16320, MW21 = 16384. %MD7 := -2 is
    // 16#FFFFFFFE: MW7 = -2, MW8 = -1; with MW9 = 0, %MD8 is 16#0000FFFF,
    // copied to %MD12: MW12 = -1, MW13 = 0.
    let p = temp(
        "views.smbp",
        &project(&[
            &["[ %MF1 := 1.5 ]"],
            &["[ %MW10 := %MW1 ]"],
            &["[ %MW11 := %MW2 ]"],
            &["[ %MW3 := 16#4000 ]"],
            &["LD [ %MF2 &gt; 2.0 ]", "ST %Q0.0"],
            &["[ %MD7 := -2 ]"],
            &["[ %MW9 := 0 ]"],
            &["[ %MD12 := %MD8 ]"],
            &["[ %MF20 := %MF2 ]"],
        ]),
    );
    let o = ilc(&[
        "run",
        &p.display().to_string(),
        "--cycles",
        "1",
        "--watch",
        "MW10,MW11,Q0_0,MW7,MW8,MW12,MW13,MW20,MW21",
    ]);
    let want = "\
cycle  time  MW10   MW11  Q0_0  MW7  MW8  MW12  MW13   MW20   MW21
    1  0s       0  16320  TRUE   -2   -1    -1     0  16320  16384
";
    assert_eq!(text(&o.stdout), want, "{}", text(&o.stderr));
}

#[test]
fn edge_blocks_of_the_rung_condition_and_cartridge_channels() {
    // RISING0 / FALLING1 are the ladder's edge blocks on the condition so
    // far (I0.0: rises at scans 2 and 5, falls at 4); MW0 and MW1 count
    // them. %IW0.100 / %QW0.100 are a cartridge's channels, host globals.
    let p = temp(
        "edge_blocks.smbp",
        &project(&[
            &["LD %I0.0", "RISING0", "[ %MW0 := %MW0 + 1 ]"],
            &["LD %I0.0", "FALLING1", "[ %MW1 := %MW1 + 1 ]"],
            &["[ %QW0.100 := %IW0.100 * 2 ]"],
        ]),
    );
    let o = ilc(&[
        "run",
        &p.display().to_string(),
        "--cycles",
        "6",
        "--set",
        "I0_0=TRUE@2",
        "--set",
        "I0_0=FALSE@4",
        "--set",
        "I0_0=TRUE@5",
        "--set",
        "IW0_100=21",
        "--watch",
        "MW0,MW1,QW0_100",
    ]);
    let want = "\
cycle  time  MW0  MW1  QW0_100
    1  0s      0    0       42
    2  10ms    1    0       42
    3  20ms    1    0       42
    4  30ms    1    1       42
    5  40ms    2    1       42
    6  50ms    2    1       42
";
    assert_eq!(text(&o.stdout), want, "{}", text(&o.stderr));
}

#[test]
fn assigning_a_real_to_a_word_says_which_conversion() {
    let p = temp(
        "types.smbp",
        &project(&[&["[ %MW1 := %MF10 * 2.0 ]"], &["[ %MF12 := %MW1 ]"]]),
    );
    let o = ilc(&["check", &p.display().to_string()]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains(
            "error[IL0430]: the value is REAL, the object assigned is INT: convert with REAL_TO_INT"
        ),
        "{err}"
    );
    assert!(
        err.contains(
            "error[IL0430]: the value is INT, the object assigned is REAL: convert with INT_TO_REAL"
        ),
        "{err}"
    );
    assert!(err.contains(&format!("--> {}:6:42", p.display())), "{err}");
    assert!(!err.contains("_x"), "no temporary named: {err}");
}

/// A project whose `<Subroutines>` hold a subroutine as `<Pous>` hold a POU
/// (`<SectionNumber>` its number): `CAL SR0` runs it when the rung's
/// condition is 1.
#[test]
fn a_projects_subroutine_runs_when_called() {
    let mut body = project(&[&["LD %I0.0", "CAL SR0"], &["LD %M0", "ST %Q0.0"]]);
    body = body.replace(
        "</Pous>",
        "</Pous>\n<Subroutines><ProgramOrganizationUnits><Name>Count</Name><SectionNumber>0</SectionNumber><Rungs>\n\
         <RungEntity><InstructionLines>\n\
         <InstructionLineEntity><InstructionLine>LD %I0.1</InstructionLine></InstructionLineEntity>\n\
         <InstructionLineEntity><InstructionLine>RETCN</InstructionLine></InstructionLineEntity>\n\
         <InstructionLineEntity><InstructionLine>[ %MW0 := %MW0 + 1 ]</InstructionLine></InstructionLineEntity>\n\
         <InstructionLineEntity><InstructionLine>LD [ %MW0 &gt;= 2 ]</InstructionLine></InstructionLineEntity>\n\
         <InstructionLineEntity><InstructionLine>ST %M0</InstructionLine></InstructionLineEntity>\n\
         </InstructionLines></RungEntity>\n\
         </Rungs></ProgramOrganizationUnits></Subroutines>",
    );
    let p = temp("sub.smbp", &body);
    let f = p.display().to_string();
    // SR0 runs in scans 2-5 (I0.0); it counts when I0.1 is 1 too (3-5);
    // M0 (MW0 >= 2) from scan 4, Q0.0 after it in the same scan.
    let o = ilc(&[
        "run",
        &f,
        "--cycles",
        "5",
        "--set",
        "%I0.0=TRUE@2",
        "--set",
        "%I0.1=TRUE@3",
        "--watch",
        "%MW0,%M0,%Q0.0",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let want = "\
cycle  time  %MW0  %M0    %Q0.0
    1  0s       0  FALSE  FALSE
    2  10ms     0  FALSE  FALSE
    3  20ms     1  FALSE  FALSE
    4  30ms     2  TRUE   TRUE
    5  40ms     3  TRUE   TRUE
";
    assert_eq!(text(&o.stdout), want);
}
