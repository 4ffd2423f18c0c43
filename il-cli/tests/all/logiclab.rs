//! LogicLab / Arduino PLC IDE projects through `ilc`: the project written
//! for the tests (`tests/logiclab/project.plcprj`) checked with its
//! warnings and run scan by scan, its tasks scheduling its programs, against
//! a trace worked out by hand.

use super::run::{ilc, text};
use std::path::Path;

fn project() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/logiclab/project.plcprj")
        .display()
        .to_string()
}

#[test]
fn check_passes_with_a_warning_for_each_thing_not_compiled_as_written() {
    let f = project();
    let o = ilc(&["check", &f]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let err = text(&o.stderr);
    let codes: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("warning["))
        .map(|l| &l[8..14])
        .collect();
    assert_eq!(codes, ["IL0424", "IL0420", "IL0423", "IL0425"], "{err}");
    assert!(err.contains(&format!("--> {f}:108:26")), "{err}");
    assert!(err.ends_with("warning: 4 warnings emitted\n"), "{err}");
}

#[test]
fn run_schedules_the_tasks_and_gives_the_values_the_il_computes() {
    let f = project();
    let o = ilc(&[
        "run",
        &f,
        "--cycles",
        "9",
        "--set",
        "sysTimer=500@3",
        "--set",
        "sysTimer=510@4",
        "--set",
        "sysTimer=520@5",
        "--watch",
        "Lamp,Count,Total,Boots,ArduinoOpta.Main.full,ArduinoOpta.Main.late,ArduinoOpta.Main.t.ET,ArduinoOpta.Main.edges.stamp,ArduinoOpta.Main.scale.scaled",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    // By hand, one scan every 10 ms (the Fast task's interval):
    // - Pulse counts its calls: q on the 3rd, 6th, 9th; Lamp := q.
    // - EdgeCounter (a library block) counts Lamp's rising edges: Count,
    //   and stamps sysTimer (the target's milliseconds, which the host
    //   sets: 500, 510, 520 before scans 3, 4, 5) at each edge.
    // - Total (RETAIN) += Twice(Count): 0 0 2 4 6 10 14 18 24.
    // - full := Count >= MaxCount (a global CONSTANT, 2).
    // - t is the library's TON (compiled as TON_LogicLab): ET is sysTimer
    //   minus its value when IN rose (0 until sysTimer is 500: "not
    //   started"), Q at ET >= PT (20): from scan 5.
    // - Boot runs once, in the single task Init.
    // - Scale is Structured Text: its interface runs, `scaled` stays 0.
    let want = "\
cycle  time  Lamp   Count  Total  Boots  ArduinoOpta.Main.full  ArduinoOpta.Main.late  ArduinoOpta.Main.t.ET  ArduinoOpta.Main.edges.stamp  ArduinoOpta.Main.scale.scaled
    1  0s    FALSE      0      0      1  FALSE                  FALSE                                      0                             0                              0
    2  10ms  FALSE      0      0      1  FALSE                  FALSE                                      0                             0                              0
    3  20ms  TRUE       1      2      1  FALSE                  FALSE                                      0                           500                              0
    4  30ms  FALSE      1      4      1  FALSE                  FALSE                                     10                           500                              0
    5  40ms  FALSE      1      6      1  FALSE                  TRUE                                      20                           500                              0
    6  50ms  TRUE       2     10      1  TRUE                   TRUE                                      20                           520                              0
    7  60ms  FALSE      2     14      1  TRUE                   TRUE                                      20                           520                              0
    8  70ms  FALSE      2     18      1  TRUE                   TRUE                                      20                           520                              0
    9  80ms  TRUE       3     24      1  TRUE                   TRUE                                      20                           520                              0
";
    assert_eq!(text(&o.stdout), want);
}
