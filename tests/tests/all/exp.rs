//! `exp/project.EXP`, a CODESYS V2.3 project in Windows-1252, compiled by
//! build.rs and by `il!`, with the Rust body the crate supplies for its ST
//! block `Scale` (src/lib.rs): the configuration the import makes of its
//! global list and PLC_PRG runs scan by scan as the IL says.

use il_std::Cycle;

/// Per scan: (c.n, total, lamp, scaled), worked out by hand from the IL:
/// c counts up; total := Twice(c.n); lamp (%QX0.0) := c.n >= LIMIT_N (3);
/// scaled := Scale(total) = total * 10 (the crate's body); at c.n >= SLOTS
/// (4) the IL ACTION c.Reset sets c.n back to 0 after lamp was stored.
const TRACE: [(i16, i16, bool, i16); 6] = [
    (1, 2, false, 20),
    (2, 4, false, 40),
    (3, 6, true, 60),
    (0, 8, true, 80),
    (1, 2, false, 20),
    (2, 4, false, 40),
];

macro_rules! scans {
    ($m:ident) => {{
        use il_tests::$m::Project;
        let mut ctx = Cycle::new();
        let mut p = Project::default();
        for (k, want) in TRACE.iter().enumerate() {
            p.run(&mut ctx);
            let got = (
                p.PLC_PRG.c.n,
                p.total,
                Project::io_lamp(&ctx),
                p.PLC_PRG.scaled,
            );
            assert_eq!(got, *want, "{} scan {}", stringify!($m), k + 1);
        }
        // The selector input of the action is cleared by the action.
        assert!(!p.PLC_PRG.c.Reset);
    }};
}

#[test]
fn the_project_runs_through_build_rs() {
    scans!(exp_build);
}

#[test]
fn the_project_runs_through_il() {
    scans!(exp_macro);
}

#[test]
fn host_blocks_with_in_outs_and_a_host_program() {
    use il_tests::exp_host_build::{Logger, UsesAccumulate};
    let mut ctx = Cycle::new();
    let mut u = UsesAccumulate {
        x: 5,
        ..Default::default()
    };
    for k in 1..=3 {
        u.call(&mut ctx);
        assert_eq!(u.total, 5 * k);
    }
    assert_eq!(u.acc.calls, 3);
    let mut l = Logger::default();
    l.call(&mut ctx);
    l.call(&mut ctx);
    assert_eq!(l.lines, 2);
}
