//! Configuration forms (`plc/cfg_forms.il`): a PROGRAM's VAR_IN_OUT bound to
//! a global where the configuration instantiates it, and TASK inputs from a
//! TIME global (INTERVAL), a BOOL global and a bit address (SINGLE, rising
//! edges), through build.rs, `il!` and the interpreter, which must agree.

use il_std::{Area, Cycle, TIME};

/// One step of the host: the time, the SINGLE global and the input bit.
type Step = (i64, bool, bool);

/// A run of 0..=100 ms in 5 ms steps: `trigger` rises at 15 and 40, %IX0.1
/// at 25 and 70; `period` changes from 20 ms to 30 ms at 50 ms.
fn steps() -> Vec<Step> {
    (0..=100)
        .step_by(5)
        .map(|ms| {
            let trigger = (15..30).contains(&ms) || (40..45).contains(&ms);
            let input = (25..35).contains(&ms) || ms >= 70;
            (ms, trigger, input)
        })
        .collect()
}

/// What one run leaves: (timed, edges, wired, pair_a, pair_b, seen) and
/// the trace of (ms, task, program).
type Outcome = ([i32; 6], Vec<(i64, String, String)>);

macro_rules! cfg_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{CfBump, CfgForms};

            fn run() -> Outcome {
                let mut ctx = Cycle::new();
                let mut c = CfgForms::default();
                let mut log = Vec::new();
                for (ms, trigger, input) in steps() {
                    ctx.set_now(TIME::from_ms(ms));
                    c.trigger = trigger;
                    ctx.io.set_bit(Area::Input, 0, 1, input);
                    if ms == 50 {
                        c.period = TIME::from_ms(30);
                    }
                    c.run_traced(&mut ctx, |t, p| {
                        log.push((ms, t.to_string(), p.to_string()))
                    });
                }
                ([c.timed, c.edges, c.wired, c.pair_a, c.pair_b, c.seen], log)
            }

            #[test]
            fn a_program_in_out_is_the_bound_global() {
                let (g, log) = run();
                let p2 = log.iter().filter(|e| e.2 == "P2").count() as i32;
                assert_eq!(p2, 21);
                // P2 adds 1 to b each run; `seen` is a + b before the last one.
                assert_eq!((g[3], g[4], g[5]), (10, 1 + p2, 10 + p2));
                // Each CfBump instance counts its own runs in its own global.
                let timed = log.iter().filter(|e| e.2 == "T1").count() as i32;
                assert_eq!(g[0], timed);
            }

            #[test]
            fn a_program_with_in_outs_is_called_with_references() {
                let mut ctx = Cycle::new();
                let mut p = CfBump::default();
                let mut n = 5;
                p.step = 2;
                p.call(&mut ctx, &mut n);
                p.call(&mut ctx, &mut n);
                assert_eq!((n, p.runs), (9, 2));
            }

            #[test]
            fn interval_from_a_global_and_single_from_a_global_and_an_address() {
                let (g, log) = run();
                let at = |prog: &str| -> Vec<i64> {
                    log.iter().filter(|e| e.2 == prog).map(|e| e.0).collect()
                };
                // 20 ms while period is T#20ms; from 50 the next release
                // (60, decided at 40) is followed by releases 30 ms apart.
                assert_eq!(at("T1"), [0, 20, 40, 60, 90]);
                // SINGLE: once per rising edge of `trigger` and of %IX0.1.
                assert_eq!(at("E1"), [15, 40]);
                assert_eq!(at("W1"), [25, 70]);
                assert_eq!((g[1], g[2]), (20, 200));
                assert_eq!(CfgForms::TASKS[0].interval_from, Some("period"));
                assert_eq!(CfgForms::TASKS[1].single, Some("trigger"));
                assert_eq!(CfgForms::TASKS[2].single, Some("%IX0.1"));
            }

            #[test]
            fn the_interpreter_runs_the_configuration_alike() {
                assert_eq!(super::interpreted(), run());
            }
        }
    };
}

cfg_tests!(via_build);
cfg_tests!(via_macro);

fn interpreted() -> Outcome {
    use il_interp::{ConfigMachine, Value};
    let src = std::fs::read_to_string("plc/cfg_forms.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("cfg_forms.il", src);
    let prog = il_interp::load(&file).expect("checks");
    let mut c = ConfigMachine::new(&prog, "cfgforms").expect("configuration");
    let mut ctx = Cycle::new();
    let mut log = Vec::new();
    for (ms, trigger, input) in steps() {
        ctx.set_now(TIME::from_ms(ms));
        c.set_global("trigger", Value::Bool(trigger)).unwrap();
        ctx.io.set_bit(Area::Input, 0, 1, input);
        if ms == 50 {
            let t = Value::Time(30_000_000, il_codegen::ir::types::Elem::TIME);
            c.set_global("period", t).unwrap();
        }
        c.run_traced(&mut ctx, |t, p| {
            log.push((ms, t.to_string(), p.to_string()))
        })
        .unwrap();
    }
    let g = |n: &str| c.global(n).unwrap().as_i64() as i32;
    (
        [
            g("timed"),
            g("edges"),
            g("wired"),
            g("pair_a"),
            g("pair_b"),
            g("seen"),
        ],
        log,
    )
}

/// The host's steps for `CfgIo`: (ms, %IX2.3, %IW4, new Limit).
const IO_STEPS: [(i64, bool, u16, Option<i16>); 3] = [
    (0, true, 7, None),
    (10, false, 2, Some(2)),
    (20, true, 1, None),
];

/// What `CfgIo` leaves after each step: (%QX1.0, Scans, Hits, Limit).
type IoOutcome = Vec<(bool, i16, i16, i16)>;

macro_rules! io_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{CfIo, CfLatch, CfgIo};

            #[test]
            fn partly_specified_addresses_are_listed_unbound() {
                let names: Vec<(&str, &str, bool)> = CfLatch::ADDRESSES
                    .iter()
                    .map(|l| (l.name, l.address, l.bound))
                    .collect();
                assert_eq!(
                    names,
                    [
                        ("sensor", "%I*", false),
                        ("lamp", "%Q*", false),
                        ("level", "%IW*", false),
                        ("spare", "%M*", false)
                    ]
                );
                assert_eq!(CfIo::ADDRESSES[0].name, "free");
                assert_eq!(CfIo::ADDRESSES[0].ty, "BYTE");
                // An ordinary field the host binds.
                let mut fb = CfLatch::default();
                fb.sensor = true;
                fb.level = 4;
                fb.call(&mut Cycle::new());
                assert!(fb.lamp);
                assert_eq!(fb.hits, 4);
            }

            #[test]
            fn var_config_completes_addresses_and_sets_initial_values() {
                let c = CfgIo::default();
                assert_eq!(c.Cpu.Io.limit, 5);
                let bound: Vec<(&str, &str, bool)> = CfgIo::ADDRESSES
                    .iter()
                    .map(|l| (l.name, l.address, l.bound))
                    .collect();
                assert_eq!(
                    bound,
                    [
                        ("Cpu.Io.latch.sensor", "%IX2.3", true),
                        ("Cpu.Io.latch.lamp", "%QX1.0", true),
                        ("Cpu.Io.latch.level", "%IW4", true)
                    ]
                );
            }

            #[test]
            fn access_paths_read_and_write_through_the_configuration() {
                let mut c = CfgIo::default();
                assert_eq!((c.access_Limit(), c.access_Mode()), (5, 3));
                c.set_access_Mode(4);
                assert_eq!(c.mode, 4);
                assert_eq!(run(), super::io_interpreted());
            }

            fn run() -> IoOutcome {
                let mut c = CfgIo::default();
                let mut ctx = Cycle::new();
                let mut out = Vec::new();
                for (ms, bit, word, limit) in IO_STEPS {
                    ctx.set_now(TIME::from_ms(ms));
                    ctx.io.set_bit(Area::Input, 2, 3, bit);
                    ctx.io.set_word(Area::Input, 8, word);
                    if let Some(l) = limit {
                        c.set_access_Limit(l);
                    }
                    c.run(&mut ctx);
                    out.push((
                        ctx.io.bit(Area::Output, 1, 0),
                        c.access_Scans(),
                        c.access_Hits(),
                        c.access_Limit(),
                    ));
                }
                out
            }

            #[test]
            fn access_paths_and_var_config_reach_into_a_standard_block() {
                let mut c = CfgIo::default();
                // VAR_CONFIG `Cpu.Io.tmr.PT := T#20ms`.
                assert_eq!(c.Cpu.Io.tmr.PT, TIME::from_ms(20));
                let mut ctx = Cycle::new();
                let mut out = Vec::new();
                for ms in [0, 10, 20, 30] {
                    ctx.set_now(TIME::from_ms(ms));
                    if ms == 20 {
                        c.set_access_Delay(TIME::from_ms(30));
                    }
                    c.run(&mut ctx);
                    out.push((c.access_Delay().as_ms(), c.access_Done()));
                }
                assert_eq!(out, super::timer_interpreted());
                assert_eq!(out, [(20, false), (20, false), (30, false), (30, true)]);
            }

            #[test]
            fn the_configured_io_is_copied_around_each_run() {
                // %IW4 is byte 8; %QX1.0 follows %IX2.3 of the same run.
                assert_eq!(run(), [(true, 5, 7, 5), (false, 7, 9, 2), (true, 9, 10, 2)]);
            }
        }
    };
}

mod io {
    use super::*;
    io_tests!(via_build);
    io_tests!(via_macro);
}

fn io_interpreted() -> IoOutcome {
    use il_codegen::ir::types::Elem;
    use il_interp::{ConfigMachine, Value};
    let src = std::fs::read_to_string("plc/cfg_forms.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("cfg_forms.il", src);
    let prog = il_interp::load(&file).expect("checks");
    let mut c = ConfigMachine::new(&prog, "CfgIo").expect("configuration");
    assert!(
        c.set_access("Scans", il_interp::int(1, Elem::INT))
            .unwrap_err()
            .contains("READ_ONLY")
    );
    let mut ctx = Cycle::new();
    let mut out = Vec::new();
    let int = |v: Option<Value>| v.expect("access path").as_i64() as i16;
    for (ms, bit, word, limit) in IO_STEPS {
        ctx.set_now(TIME::from_ms(ms));
        ctx.io.set_bit(Area::Input, 2, 3, bit);
        ctx.io.set_word(Area::Input, 8, word);
        if let Some(l) = limit {
            c.set_access("Limit", il_interp::int(l as i128, Elem::INT))
                .unwrap();
        }
        c.run(&mut ctx).unwrap();
        out.push((
            ctx.io.bit(Area::Output, 1, 0),
            int(c.access("Scans")),
            int(c.access("Hits")),
            int(c.access("Limit")),
        ));
    }
    out
}

/// `timer` of `io_tests` through the interpreter's access paths.
fn timer_interpreted() -> Vec<(i64, bool)> {
    use il_interp::{ConfigMachine, Value};
    let src = std::fs::read_to_string("plc/cfg_forms.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("cfg_forms.il", src);
    let prog = il_interp::load(&file).expect("checks");
    let mut c = ConfigMachine::new(&prog, "CfgIo").expect("configuration");
    let mut ctx = Cycle::new();
    let mut out = Vec::new();
    for ms in [0, 10, 20, 30] {
        ctx.set_now(TIME::from_ms(ms));
        if ms == 20 {
            let v = Value::Time(30_000_000, il_codegen::ir::types::Elem::TIME);
            c.set_access("Delay", v).unwrap();
        }
        c.run(&mut ctx).unwrap();
        let delay = c.access("Delay").expect("Delay").as_i64() / 1_000_000;
        out.push((delay, c.access("Done").expect("Done").as_bool()));
    }
    out
}
