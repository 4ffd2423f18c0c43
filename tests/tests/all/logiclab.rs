//! `logiclab/project.plcprj`, a LogicLab / Arduino PLC IDE project,
//! compiled by build.rs and by `il!`, with the Rust body the crate supplies
//! for its ST block `Scale` (src/lib.rs): the configuration the import makes
//! of its global groups and tasks runs scan by scan as the IL says.

use il_std::{Cycle, TIME};

/// Per scan of 10 ms: (Lamp, Count, Total, Boots, full, late, stamp,
/// scaled), worked out by hand from the IL (the same trace as `ilc run`'s
/// test): Pulse's q on every 3rd call is Lamp (%QX1.0); the library block
/// EdgeCounter counts its rising edges (Count) and stamps sysTimer (the
/// host sets 500, 510, 520 before scans 3, 4, 5); Total += Twice(Count);
/// full := Count >= MaxCount (2); the library's TON (TON_LogicLab) with PT
/// 20 (ms of sysTimer) is late from scan 5; Boot runs once (the single
/// task Init); scaled := Count * 10 * 3 (the crate's body of Scale).
/// One scan's values, in the order of the doc above.
type Scan = (bool, i16, i16, i16, bool, bool, u32, i16);

const TRACE: [Scan; 9] = [
    (false, 0, 0, 1, false, false, 0, 0),
    (false, 0, 0, 1, false, false, 0, 0),
    (true, 1, 2, 1, false, false, 500, 30),
    (false, 1, 4, 1, false, false, 500, 30),
    (false, 1, 6, 1, false, true, 500, 30),
    (true, 2, 10, 1, true, true, 520, 60),
    (false, 2, 14, 1, true, true, 520, 60),
    (false, 2, 18, 1, true, true, 520, 60),
    (true, 3, 24, 1, true, true, 520, 90),
];

macro_rules! scans {
    ($m:ident) => {{
        use il_tests::$m::Project;
        let mut ctx = Cycle::new();
        let mut p = Project::default();
        for (k, want) in TRACE.iter().enumerate() {
            ctx.set_now(TIME::from_ms(10 * k as i64));
            if (2..=4).contains(&k) {
                p.sysTimer = 500 + 10 * (k as u32 - 2);
            }
            p.run(&mut ctx);
            let m = &p.ArduinoOpta.Main;
            let got = (
                Project::io_Lamp(&ctx),
                p.Count,
                p.Total,
                p.Boots,
                m.full,
                m.late,
                m.edges.stamp,
                m.scale.scaled,
            );
            assert_eq!(got, *want, "{} scan {}", stringify!($m), k + 1);
        }
        // Total is the configuration's RETAIN data.
        assert_eq!(p.retain().Total, 24);
    }};
}

#[test]
fn the_project_runs_through_build_rs() {
    scans!(logiclab_build);
}

#[test]
fn the_project_runs_through_il() {
    scans!(logiclab_macro);
}
