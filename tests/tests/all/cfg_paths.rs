//! VAR_ACCESS paths through array elements and members
//! (`plc/cfg_paths.il`): elements of an INT array, of a 2-D array, of an
//! array of FB instances and of an array of TONs, members of a structure in
//! a program and in a global, through build.rs, `il!` and the interpreter,
//! which must agree step by step.

use il_std::{Cycle, TIME};

/// The access paths after one run: A2, M23, Cell1Q, Cell2Total, Py3, T2Q,
/// Gx, H3, H2.
type Row = (i16, i16, bool, i16, i16, bool, i16, i16, i16);

/// The host's writes: Gx := 5 at 10 ms, H3 := 4 at 20 ms, Cell2Total :=
/// -100 at 40 ms, each before that run.
const WRITES: [(i64, &str, i16); 3] = [(10, "Gx", 5), (20, "H3", 4), (40, "Cell2Total", -100)];

/// What the program computes (n is the run count, from 1): A2 = n, M23 =
/// 2n, Py3 = g.x + n, H2 = n; cells[1] adds 3 per run (Q above 10: from
/// run 4), cells[2] adds h[3]; t[2] gets IN from run 2 (10 ms) with PT 20
/// ms, so Q from 30 ms.
fn expected() -> Vec<Row> {
    vec![
        (1, 2, false, 0, 1, false, 0, 0, 1),
        (2, 4, false, 0, 7, false, 5, 0, 2),
        (3, 6, false, 4, 8, false, 5, 4, 3),
        (4, 8, true, 8, 9, true, 5, 4, 4),
        (5, 10, true, -96, 10, true, 5, 4, 5),
        (6, 12, true, -92, 11, true, 5, 4, 6),
    ]
}

macro_rules! paths_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::CfgPaths;

            fn run() -> Vec<Row> {
                let mut c = CfgPaths::default();
                let mut ctx = Cycle::new();
                let mut out = Vec::new();
                for ms in (0..=50).step_by(10) {
                    ctx.set_now(TIME::from_ms(ms));
                    for (at, name, v) in WRITES {
                        match (at == ms, name) {
                            (true, "Gx") => c.set_access_Gx(v),
                            (true, "H3") => c.set_access_H3(v),
                            (true, _) => c.set_access_Cell2Total(v),
                            _ => {}
                        }
                    }
                    c.run(&mut ctx);
                    // The getters read the fields the paths name.
                    assert_eq!(c.access_A2(), c.RES1.P1.a[2]);
                    assert_eq!(c.access_M23(), c.RES1.P1.m[1][2]);
                    assert_eq!(c.access_Gx(), c.g.x);
                    out.push((
                        c.access_A2(),
                        c.access_M23(),
                        c.access_Cell1Q(),
                        c.access_Cell2Total(),
                        c.access_Py3(),
                        c.access_T2Q(),
                        c.access_Gx(),
                        c.access_H3(),
                        c.access_H2(),
                    ));
                }
                out
            }

            #[test]
            fn access_paths_read_and_write_elements_and_members() {
                assert_eq!(run(), expected());
            }

            #[test]
            fn a_write_outside_a_subrange_is_refused_and_the_place_kept() {
                use il_std::FaultKind::SubrangeViolation;
                let mut c = CfgPaths::default();
                // Unwritten subrange places start at their lower limits.
                assert_eq!(
                    (c.access_Level(), c.access_Step2(), c.access_Gz()),
                    (0, 1, -10)
                );
                assert_eq!(c.set_access_Level(100), Ok(()));
                assert_eq!(c.set_access_Level(101), Err(SubrangeViolation));
                assert_eq!(c.set_access_Level(-1), Err(SubrangeViolation));
                assert_eq!(c.set_access_Step2(0), Err(SubrangeViolation));
                assert_eq!(c.set_access_Step2(9), Ok(()));
                assert_eq!(c.set_access_Step2(10), Err(SubrangeViolation));
                assert_eq!(c.set_access_Gz(-11), Err(SubrangeViolation));
                assert_eq!(c.set_access_Gz(-10), Ok(()));
                assert_eq!(
                    (c.access_Level(), c.access_Step2(), c.access_Gz()),
                    (100, 9, -10)
                );
                assert_eq!((c.RES1.P1.level, c.RES1.P1.steps[1], c.g.z), (100, 9, -10));
                // A place without a subrange takes any value of its type.
                c.set_access_H3(i16::MIN);
                assert_eq!(c.access_H3(), i16::MIN);
            }
        }
    };
}

paths_tests!(via_build);
paths_tests!(via_macro);

/// plc/cfg_paths.il, checked, for the interpreter.
fn checked() -> il_codegen::ir::Program {
    let src = std::fs::read_to_string("plc/cfg_paths.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("cfg_paths.il", src);
    il_interp::load(&file).expect("checks")
}

#[test]
fn the_interpreter_refuses_a_write_outside_a_subrange() {
    use il_interp::ConfigMachine;
    let prog = checked();
    let mut c = ConfigMachine::new(&prog, "CfgPaths").expect("configuration");
    let int = |v: i128| il_interp::int(v, il_codegen::ir::types::Elem::INT);
    let usint = |v: i128| il_interp::int(v, il_codegen::ir::types::Elem::USINT);
    c.set_access("Level", int(100)).expect("inside");
    let e = c.set_access("Level", int(101)).unwrap_err();
    assert!(e.contains("outside the subrange 0..100"), "{e}");
    assert!(c.set_access("Step2", usint(0)).is_err());
    c.set_access("Step2", usint(9)).expect("inside");
    assert!(c.set_access("Gz", int(11)).is_err());
    let get = |c: &ConfigMachine, n: &str| c.access(n).expect("access path").as_i64();
    assert_eq!(
        (get(&c, "Level"), get(&c, "Step2"), get(&c, "Gz")),
        (100, 9, -10)
    );
}

#[test]
fn the_interpreter_reads_and_writes_the_same_places() {
    use il_interp::{ConfigMachine, Value};
    let prog = checked();
    let mut c = ConfigMachine::new(&prog, "CfgPaths").expect("configuration");
    let int = |v: i16| il_interp::int(v as i128, il_codegen::ir::types::Elem::INT);
    assert!(
        c.set_access("A2", int(1))
            .unwrap_err()
            .contains("READ_ONLY")
    );
    let mut ctx = Cycle::new();
    let mut out = Vec::new();
    for ms in (0..=50).step_by(10) {
        ctx.set_now(TIME::from_ms(ms));
        for (at, name, v) in WRITES {
            if at == ms {
                c.set_access(name, int(v)).expect("READ_WRITE");
            }
        }
        c.run(&mut ctx).expect("runs");
        let get = |n: &str| c.access(n).expect("access path");
        let i = |n: &str| get(n).as_i64() as i16;
        let b = |n: &str| matches!(get(n), Value::Bool(true));
        out.push((
            i("A2"),
            i("M23"),
            b("Cell1Q"),
            i("Cell2Total"),
            i("Py3"),
            b("T2Q"),
            i("Gx"),
            i("H3"),
            i("H2"),
        ));
    }
    assert_eq!(out, expected());
}
