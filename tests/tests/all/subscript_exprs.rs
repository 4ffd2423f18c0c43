//! Subscript expressions and input operators on elements of arrays of
//! blocks (`plc/subscript_exprs.il`), through build.rs, `il!` and the
//! interpreter, against the trace worked by hand (issue 29, items 1 and 2).

use il_std::{Cycle, FaultKind, TIME};

/// Inputs of each scan: go, k, d.
const SCANS: [(bool, i16, i16); 6] = [
    (true, 0, 1),
    (false, 0, 1),
    (true, 0, 0),
    (true, 1, 2),
    (false, 1, 2),
    (true, 0, 1),
];

/// After each scan: v, q, w, s0, a[0], and the faults of the scan.
///
/// Scan 1 counts ca[0] to 1 (PV 0 then 2: Q falls); scan 3 counts it to 2
/// (Q) and divides by d = 0 in `a[k / d]` (a fault; element 0); scan 4
/// counts ca[1] while `R ca[(k + 1) MOD 2]` holds ca[0]'s reset low; scan 5
/// resets ca[0], so scan 6 reads 0. rsa[0] is set, then reset by `R1` in
/// scan 3 (d = 0), and set again in scan 6. w reads a[3 - k].
type Row = (i16, bool, i16, bool, i16, Vec<FaultKind>);

fn expected() -> Vec<Row> {
    vec![
        (1, false, 10, true, 0, vec![]),
        (1, false, 10, true, 0, vec![]),
        (2, true, 10, false, 0, vec![FaultKind::DivisionByZero]),
        (1, false, 0, false, 1, vec![]),
        (1, false, 0, false, 1, vec![]),
        (0, false, 10, true, 0, vec![]),
    ]
}

fn faults(ctx: &mut Cycle) -> Vec<FaultKind> {
    let f = ctx.faults().map(|f| f.kind).collect();
    ctx.clear_faults();
    f
}

macro_rules! subscript_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::SubscriptExprs;

            #[test]
            fn subscript_expressions_and_element_input_operators() {
                let mut p = SubscriptExprs::default();
                let mut ctx = Cycle::new();
                let mut out = Vec::new();
                for (n, (go, k, d)) in SCANS.into_iter().enumerate() {
                    ctx.set_now(TIME::from_ms(10 * n as i64));
                    (p.go, p.k, p.d) = (go, k, d);
                    p.call(&mut ctx);
                    out.push((p.v, p.q, p.w, p.s0, p.a[0], faults(&mut ctx)));
                }
                assert_eq!(out, expected());
            }
        }
    };
}

subscript_tests!(via_build);
subscript_tests!(via_macro);

#[test]
fn the_interpreter_agrees() {
    use il_codegen::ir::types::Elem;
    use il_interp::{Machine, Value};
    let src = std::fs::read_to_string("plc/subscript_exprs.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("subscript_exprs.il", src);
    let prog = il_interp::load(&file).expect("checks");
    let mut m = Machine::new(&prog, "SubscriptExprs").expect("program");
    let mut ctx = Cycle::new();
    let mut out = Vec::new();
    let int = |m: &Machine, n: &str| m.get(n).expect(n).as_i64() as i16;
    let b = |m: &Machine, n: &str| matches!(m.get(n), Some(Value::Bool(true)));
    for (n, (go, k, d)) in SCANS.into_iter().enumerate() {
        ctx.set_now(TIME::from_ms(10 * n as i64));
        m.set("go", Value::Bool(go)).expect("go");
        m.set("k", il_interp::int(k.into(), Elem::INT)).expect("k");
        m.set("d", il_interp::int(d.into(), Elem::INT)).expect("d");
        m.scan(&mut ctx).expect("runs");
        let a0 = match m.get("a") {
            Some(Value::Array(e)) => e[0].as_i64() as i16,
            other => panic!("a: {other:?}"),
        };
        out.push((
            int(&m, "v"),
            b(&m, "q"),
            int(&m, "w"),
            b(&m, "s0"),
            a0,
            faults(&mut ctx),
        ));
    }
    assert_eq!(out, expected());
}
