//! Runtime faults through generated code (plc/runtime_faults.il), in debug
//! builds (`cargo test`) and release builds (`.ci/run` runs this file with
//! `cargo test --release -p il-tests --test all runtime_faults`): integer
//! overflow wraps without a fault; DIV/MOD by zero give 0; array reads out of
//! range give the default value and stores out of range are skipped (one and
//! two dimensions); a store outside a subrange is skipped; CONCAT beyond the
//! capacity is truncated; DIV, MOD and DIV_TIME called as functions fault as
//! the operators do. None of them panics, each but the wrap is recorded in the
//! `Cycle` with its POU and exact IL line, and the rest of the scan runs.
//! `limits`: an instance larger than a thread's stack (plc/big_instance.il)
//! and the deepest nesting the checker accepts (plc/deep_nesting.il) are
//! created and run without aborting.

use il_std::{Cycle, FaultKind, STRING, TIME};

/// Every fault of one scan of RtFaults with the default inputs, in order.
const EXPECTED: &[(FaultKind, &str, u32)] = &[
    (FaultKind::DivisionByZero, "RtFaults", 69),
    (FaultKind::DivisionByZero, "RtFaults", 72),
    (FaultKind::DivisionByZero, "RtDiv", 11),
    (FaultKind::IndexOutOfRange, "RtFaults", 77),
    (FaultKind::IndexOutOfRange, "RtFaults", 80),
    (FaultKind::IndexOutOfRange, "RtFaults", 81),
    (FaultKind::IndexOutOfRange, "RtFaults", 84),
    (FaultKind::SubrangeViolation, "RtFaults", 86),
    (FaultKind::StringOverflow, "RtFaults", 88),
    (FaultKind::IndexOutOfRange, "RtGrid", 19),
    (FaultKind::IndexOutOfRange, "RtGrid", 22),
];

fn s(text: &str) -> STRING<5> {
    STRING::from_str_truncating(text).0
}

macro_rules! fault_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{RtDiv, RtDivForms, RtFaults, RtGrid, RtParens};

            fn faults(ctx: &Cycle) -> Vec<(FaultKind, &'static str, u32)> {
                ctx.faults().map(|f| (f.kind, f.pou, f.line)).collect()
            }

            #[test]
            fn every_fault_is_recorded_with_pou_and_line_and_the_scan_goes_on() {
                let mut ctx = Cycle::new();
                ctx.advance(TIME::from_ms(250));
                let mut p = RtFaults::default();
                p.call(&mut ctx);
                assert_eq!(faults(&ctx), EXPECTED);
                assert_eq!(ctx.fault_count(), EXPECTED.len() as u64);
                assert!(ctx.faults().all(|f| f.time == TIME::from_ms(250)));

                // Integer overflow wraps (and is not a fault).
                assert_eq!(p.sum_wrap, -32768, "INT 32767 + 1");
                assert_eq!(p.mul_wrap, 0, "DINT 65536 * 65536");
                assert_eq!(p.neg_wrap, 127, "SINT -128 - 1");
                assert_eq!(p.udiff, 65535, "UINT 0 - 1");
                // DIV/MOD by zero give 0, in the program and in a FUNCTION.
                assert_eq!((p.q, p.m, p.fq), (0, 0, 0));
                // Out-of-range reads give the default value; stores are skipped.
                assert_eq!(p.read_bad, 0);
                assert_eq!(p.arr, [10, 11, 12, 13]);
                assert_eq!(p.m2_bad, 0);
                assert_eq!(p.m2, [[1, 2, 3], [4, 5, 6]]);
                assert_eq!(p.blk_got, 0);
                assert_eq!(p.blk.grid, [[1, 2, 3], [4, 5, 6]]);
                // The subrange store is skipped, the string truncated.
                assert_eq!(p.pct, 42);
                assert_eq!(p.s2, s("abcde"));
                // The rest of the scan ran.
                assert!(p.reached);
                assert_eq!(p.after, 1);

                // The next scan faults again, the same way.
                ctx.advance(TIME::from_ms(10));
                p.call(&mut ctx);
                assert_eq!(ctx.fault_count(), 2 * EXPECTED.len() as u64);
                assert_eq!(
                    ctx.last_fault().map(|f| (f.kind, f.pou, f.line, f.time)),
                    Some((FaultKind::IndexOutOfRange, "RtGrid", 22, TIME::from_ms(260)))
                );
                assert_eq!(p.after, 2);
            }

            #[test]
            fn valid_inputs_give_no_fault() {
                let mut ctx = Cycle::new();
                let mut p = RtFaults::default();
                p.zero = 5;
                p.dzero = 2;
                p.idx = 1;
                p.pct_in = 100;
                p.tail = s("c");
                p.bi = 2;
                p.bj = 1;
                p.call(&mut ctx);
                assert_eq!(faults(&ctx), []);
                assert_eq!((p.q, p.m, p.fq), (3, 2, 2));
                assert_eq!(p.read_bad, 11);
                assert_eq!(p.arr, [10, 77, 12, 13]);
                assert_eq!(p.m2_bad, 4);
                assert_eq!(p.m2, [[88, 2, 3], [4, 5, 6]]);
                assert_eq!(p.pct, 100);
                assert_eq!(p.s2, s("abc"));
                assert_eq!(p.blk_got, 5);
                assert_eq!(p.blk.grid[0][2], 99);
                assert!(p.reached);
            }

            #[test]
            fn div_mod_and_div_time_as_functions_record_the_fault() {
                let mut ctx = Cycle::new();
                let mut p = RtDivForms::default();
                p.call(&mut ctx);
                assert_eq!(
                    faults(&ctx),
                    [
                        (FaultKind::DivisionByZero, "RtDivForms", 115),
                        (FaultKind::DivisionByZero, "RtDivForms", 117),
                        (FaultKind::DivisionByZero, "RtDivForms", 119),
                    ],
                    "a REAL divisor of 0 records no fault"
                );
                assert_eq!((p.r, p.m, p.tq), (0, 0, TIME::from_ms(0)));
                assert!(p.xq.is_infinite());
                p.zero = 2;
                p.rz = 4.0;
                p.call(&mut ctx);
                assert_eq!(ctx.fault_count(), 3, "no fault with a divisor");
                assert_eq!((p.r, p.m, p.tq), (3, 1, TIME::from_ms(500)));
                assert_eq!(p.tr, TIME::from_ms(250));
            }

            #[test]
            fn a_fault_inside_parentheses_names_its_own_line() {
                let mut ctx = Cycle::new();
                let mut p = RtParens::default();
                p.call(&mut ctx);
                assert_eq!((p.q, p.m), (5, 0));
                assert_eq!(faults(&ctx), PARENS);
            }

            #[test]
            fn a_function_and_a_block_record_their_own_pou() {
                let mut ctx = Cycle::new();
                assert_eq!(RtDiv(&mut ctx, 7, 0), 0);
                assert_eq!(RtDiv(&mut ctx, i32::MIN, -1), i32::MIN, "wraps");
                let mut g = RtGrid::default();
                g.i = 2;
                g.j = -1;
                g.call(&mut ctx);
                assert_eq!(g.got, 0);
                assert_eq!(
                    faults(&ctx),
                    [
                        (FaultKind::DivisionByZero, "RtDiv", 11),
                        (FaultKind::IndexOutOfRange, "RtGrid", 19),
                        (FaultKind::IndexOutOfRange, "RtGrid", 22),
                    ]
                );
                assert_eq!(g.grid, [[1, 2, 3], [4, 5, 6]]);
                g.j = 1;
                g.call(&mut ctx);
                assert_eq!(g.got, 5);
                assert_eq!(g.grid[0][2], 99, "grid[1, 2] := 99");
                assert_eq!(ctx.fault_count(), 3);
            }
        }
    };
}

/// RtParens: the DIV inside `MUL(` ... `)` on its own line, the `MOD(`
/// operator itself on its line.
const PARENS: &[(FaultKind, &str, u32)] = &[
    (FaultKind::DivisionByZero, "RtParens", 137),
    (FaultKind::DivisionByZero, "RtParens", 142),
];

fault_tests!(via_build);
fault_tests!(via_macro);

/// The interpreter records the same lines (from the same checked IR).
#[test]
fn the_interpreter_names_the_line_inside_parentheses() {
    let text = std::fs::read_to_string("plc/runtime_faults.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("runtime_faults.il", text);
    let prog = il_interp::load(&file).expect("checks");
    let mut m = il_interp::Machine::new(&prog, "RtParens").expect("instance");
    let mut ctx = Cycle::new();
    m.scan(&mut ctx).expect("scans");
    let got: Vec<_> = ctx.faults().map(|f| (f.kind, f.pou, f.line)).collect();
    assert_eq!(got, PARENS);
}

/// Resource limits: generated code must not abort either.
macro_rules! limit_tests {
    ($m:ident) => {
        mod $m {
            use il_std::Cycle;
            use il_tests::$m::{BigProg, DeepMain, DeepPlant};

            /// plc/big_instance.il: 16 MB of LREAL, a 16 MB initialised 2-D
            /// array, 100,000 RETAIN blocks... used to overflow the stack in
            /// `Default::default()` (debug and release). The large arrays are
            /// on the heap: created, run, cloned, compared, snapshot and
            /// restored in a thread with a 2 MiB stack (the test default).
            #[test]
            fn an_instance_larger_than_the_stack_is_created_and_run() {
                let run = || {
                    let mut ctx = Cycle::new();
                    let mut p = BigProg::default();
                    assert_eq!(p.samples.len(), 2_000_000);
                    assert_eq!(
                        (p.grid[0][2], p.grid[1][0], p.grid[62_499][31]),
                        (1.5, 0.0, 2.5)
                    );
                    p.n = 2_000_000;
                    p.call(&mut ctx);
                    assert_eq!(ctx.fault_count(), 0);
                    assert_eq!(p.sum, 1_999_999.0 * 2_000_000.0 / 2.0);
                    assert_eq!(p.samples[1_234_567], 1_234_567.0);
                    assert_eq!((p.last, p.got, p.cell), (2.5, 1_999_999.0, 7));
                    assert_eq!(p.inner.buf[99_999], 1_999_999.0);
                    let copy = p.clone();
                    assert!(copy == p);
                    let saved = p.retain();
                    let mut warm = BigProg::default();
                    warm.restore(&saved);
                    assert_eq!((warm.cells[99_999].total, warm.kept[199_999]), (7, 7));
                    assert_eq!(
                        (warm.more[5].total, warm.more[5].out),
                        (3, 0),
                        "total is RETAIN"
                    );
                    assert_eq!(warm.samples[1_234_567], 0.0, "not RETAIN");
                    // An index past the end is a fault, not a panic.
                    p.n = 2_000_001;
                    p.call(&mut ctx);
                    assert_eq!(ctx.fault_count(), 1);
                };
                std::thread::Builder::new()
                    .stack_size(2 << 20)
                    .spawn(run)
                    .unwrap()
                    .join()
                    .unwrap();
            }

            /// plc/deep_nesting.il: the deepest nesting the checker accepts
            /// (120 levels, IL0133) compiles and runs.
            #[test]
            fn the_deepest_accepted_nesting_runs() {
                let mut ctx = Cycle::new();
                let mut m = Box::new(DeepMain::default());
                m.call(&mut ctx);
                assert_eq!(m.count, 116);
                let mut plant = Box::new(DeepPlant::default());
                plant.run(&mut ctx);
                assert_eq!(plant.cpu.main.count, 116);
                assert_eq!(plant.cpu.structs.x, 118);
                let saved = plant.retain();
                let mut warm = Box::new(DeepPlant::default());
                warm.restore(&saved);
                assert!(warm.retain() == saved);
            }
        }
    };
}

mod limits {
    limit_tests!(via_build);
    limit_tests!(via_macro);
}
