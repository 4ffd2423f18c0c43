//! The reference interpreter on the behaviour-test programs of `tests/plc`,
//! asserting what `tests/tests/*.rs` assert for the generated code.

use il_codegen::diag::SourceFile;
use il_codegen::ir::types::Elem;
use il_interp::{Machine, Value, load};
use il_std::{Cycle, FaultKind, TIME};

fn program(file: &str) -> il_codegen::ir::Program {
    let path = format!("{}/../tests/plc/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("read IL");
    load(&SourceFile::new(file, text)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

fn machine(file: &str, pou: &str) -> Machine {
    Machine::new(&program(file), pou).expect("instance")
}

fn i(v: i128, e: Elem) -> Value {
    il_interp::int(v, e)
}

fn int(m: &Machine, n: &str) -> i128 {
    match m.get(n) {
        Some(Value::Int(v, _)) => v,
        other => panic!("{n}: {other:?}"),
    }
}

fn boolean(m: &Machine, n: &str) -> bool {
    match m.get(n) {
        Some(Value::Bool(b)) => b,
        other => panic!("{n}: {other:?}"),
    }
}

fn time(m: &Machine, n: &str) -> TIME {
    match m.get(n) {
        Some(Value::Time(ns, _)) => TIME(ns),
        other => panic!("{n}: {other:?}"),
    }
}

fn scan(m: &mut Machine, ctx: &mut Cycle) {
    m.scan(ctx).expect("scan");
}

macro_rules! check_int {
    ($fb:literal, $t:ty, $e:ident, $cases:expr) => {{
        let prog = program("ops_arith.il");
        for (a, b) in $cases {
            let (a, b): ($t, $t) = (a, b);
            let mut ctx = Cycle::new();
            let mut f = Machine::new(&prog, $fb).unwrap();
            f.set("a", i(a as i128, Elem::$e)).unwrap();
            f.set("b", i(b as i128, Elem::$e)).unwrap();
            scan(&mut f, &mut ctx);
            let case = format!("{} a={a} b={b}", $fb);
            assert_eq!(int(&f, "r_add"), a.wrapping_add(b) as i128, "ADD {case}");
            assert_eq!(int(&f, "r_sub"), a.wrapping_sub(b) as i128, "SUB {case}");
            assert_eq!(int(&f, "r_mul"), a.wrapping_mul(b) as i128, "MUL {case}");
            let (q, m) = if b == 0 {
                (0, 0)
            } else {
                (a.wrapping_div(b), a.wrapping_rem(b))
            };
            assert_eq!(int(&f, "r_div"), q as i128, "DIV {case}");
            assert_eq!(int(&f, "r_mod"), m as i128, "MOD {case}");
            assert_eq!(boolean(&f, "r_gt"), a > b, "GT {case}");
            assert_eq!(boolean(&f, "r_ge"), a >= b, "GE {case}");
            assert_eq!(boolean(&f, "r_eq"), a == b, "EQ {case}");
            assert_eq!(boolean(&f, "r_ne"), a != b, "NE {case}");
            assert_eq!(boolean(&f, "r_le"), a <= b, "LE {case}");
            assert_eq!(boolean(&f, "r_lt"), a < b, "LT {case}");
            assert_eq!(
                ctx.fault_count(),
                if b == 0 { 2 } else { 0 },
                "faults {case}"
            );
        }
    }};
}

macro_rules! signed_cases {
    ($t:ty) => {
        [
            (7 as $t, 2 as $t),
            (-7, 2),
            (7, -2),
            (-7, -2),
            (<$t>::MAX, 1),
            (<$t>::MIN, 1),
            (<$t>::MIN, -1),
            (<$t>::MAX, 2),
            (5, 5),
            (3, 0),
        ]
    };
}

macro_rules! unsigned_cases {
    ($t:ty) => {
        [
            (7 as $t, 2 as $t),
            (0, 1),
            (<$t>::MAX, 1),
            (<$t>::MAX, 2),
            (5, 5),
            (2, 9),
            (3, 0),
        ]
    };
}

#[test]
fn integer_arithmetic_wraps_on_every_type() {
    check_int!("OpsArithSINT", i8, SINT, signed_cases!(i8));
    check_int!("OpsArithINT", i16, INT, signed_cases!(i16));
    check_int!("OpsArithDINT", i32, DINT, signed_cases!(i32));
    check_int!("OpsArithLINT", i64, LINT, signed_cases!(i64));
    check_int!("OpsArithUSINT", u8, USINT, unsigned_cases!(u8));
    check_int!("OpsArithUINT", u16, UINT, unsigned_cases!(u16));
    check_int!("OpsArithUDINT", u32, UDINT, unsigned_cases!(u32));
    check_int!("OpsArithULINT", u64, ULINT, unsigned_cases!(u64));
}

#[test]
fn real_is_32_bit_ieee() {
    let mut ctx = Cycle::new();
    let mut f = machine("ops_arith.il", "OpsArithREAL");
    let real = |m: &Machine, n: &str| match m.get(n) {
        Some(Value::Real(x)) => x,
        other => panic!("{other:?}"),
    };
    f.set("a", Value::Real(0.1)).unwrap();
    f.set("b", Value::Real(0.2)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!(real(&f, "r_add"), 0.1f32 + 0.2f32);
    f.set("a", Value::Real(1.0)).unwrap();
    f.set("b", Value::Real(0.0)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!(real(&f, "r_div"), f32::INFINITY);
    assert_eq!(ctx.fault_count(), 0);
}

#[test]
fn div_by_zero_records_pou_and_line() {
    let mut ctx = Cycle::new();
    let mut f = machine("ops_misc.il", "DivZero");
    f.set("a", i(17, Elem::INT)).unwrap();
    f.set("b", i(0, Elem::INT)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "q"), int(&f, "m")), (0, 0));
    let faults: Vec<_> = ctx.faults().copied().collect();
    assert_eq!(faults.len(), 2);
    assert_eq!(
        (faults[0].kind, faults[0].pou, faults[0].line),
        (FaultKind::DivisionByZero, "DivZero", 13)
    );
    assert_eq!(faults[1].line, 16);
    f.set("b", i(5, Elem::INT)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "q"), int(&f, "m")), (3, 2));
    assert_eq!(ctx.fault_count(), 2);
}

#[test]
fn literal_operands_and_time_arithmetic() {
    let mut ctx = Cycle::new();
    let mut f = machine("ops_misc.il", "LitOps");
    scan(&mut f, &mut ctx);
    assert_eq!(int(&f, "wrap_add"), -32768);
    assert_eq!(int(&f, "wrap_sub"), 127);
    assert_eq!(int(&f, "wrap_mul"), 0);
    assert_eq!(int(&f, "wrap_u"), 65535);
    assert_eq!(int(&f, "div_neg"), -3);
    assert_eq!(int(&f, "mod_neg"), -1);
    assert_eq!(int(&f, "mod_neg2"), 1);
    assert_eq!(f.get("real_div"), Some(Value::Real(0.25)));
    assert_eq!(f.get("lreal_mul"), Some(Value::LReal(0.1f64 * 3.0)));
    assert_eq!(ctx.fault_count(), 0);

    let mut t = machine("ops_misc.il", "TimeOps");
    let tv = |ms: i64| Value::Time(TIME::from_ms(ms).0, Elem::TIME);
    t.set("t1", tv(1500)).unwrap();
    t.set("t2", tv(250)).unwrap();
    t.set("k", t.parse_value("k", "3").unwrap()).unwrap();
    t.set("kd", t.parse_value("kd", "-2").unwrap()).unwrap();
    scan(&mut t, &mut ctx);
    assert_eq!(time(&t, "t_add"), TIME::from_ms(1750));
    assert_eq!(time(&t, "t_sub"), TIME::from_ms(1250));
    assert_eq!(time(&t, "t_mul"), TIME::from_ms(4500));
    assert_eq!(time(&t, "t_div"), TIME::from_ms(500));
    assert_eq!(time(&t, "t_muld"), TIME::from_ms(-3000));
    assert!(boolean(&t, "t_gt") && !boolean(&t, "t_eq"));
    assert_eq!(time(&t, "t_lit"), TIME::from_ms(91_500));
    t.set("t1", tv(1000)).unwrap();
    t.set("k", t.parse_value("k", "0").unwrap()).unwrap();
    scan(&mut t, &mut ctx);
    assert!(boolean(&t, "t_eq"));
    assert_eq!(time(&t, "t_div"), TIME::ZERO);
    assert_eq!(
        ctx.last_fault().map(|x| x.kind),
        Some(FaultKind::DivisionByZero)
    );
}

#[test]
fn jumps_forward_backward_and_returns() {
    let prog = program("jumps.il");
    let mut ctx = Cycle::new();
    for (sel, v) in [(true, [2, 10, 40, 60]), (false, [2, 20, 30, 50])] {
        let mut f = Machine::new(&prog, "JumpFwd").unwrap();
        f.set("sel", Value::Bool(sel)).unwrap();
        scan(&mut f, &mut ctx);
        let got = ["via_jmp", "via_jmpc", "via_jmpcn", "via_jmpnc"].map(|n| int(&f, n));
        assert_eq!(got, v, "sel={sel}");
    }

    let mut f = Machine::new(&prog, "JumpLoop").unwrap();
    assert_eq!(int(&f, "n"), 100);
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "count"), int(&f, "sum")), (100, 100));
    f.set("n", f.parse_value("n", "10000").unwrap()).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!(int(&f, "sum"), 10_000);
    f.set("n", f.parse_value("n", "0").unwrap()).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "count"), int(&f, "sum")), (0, 0));

    let mut f = Machine::new(&prog, "JumpLoopBottom").unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "iterations"), int(&f, "acc")), (10, 1024));

    let mut f = Machine::new(&prog, "JumpJoin").unwrap();
    f.set("val", f.parse_value("val", "21").unwrap()).unwrap();
    for (mode, out) in [(1, 21), (2, 42), (3, 0), (0, 0)] {
        f.set("mode", f.parse_value("mode", &mode.to_string()).unwrap())
            .unwrap();
        f.set("out", f.parse_value("out", "-1").unwrap()).unwrap();
        scan(&mut f, &mut ctx);
        assert_eq!(int(&f, "out"), out, "mode {mode}");
    }

    let mut f = Machine::new(&prog, "RetFb").unwrap();
    f.set("c", Value::Bool(true)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!(int(&f, "stage"), 1);
    f.set("c", Value::Bool(false)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!(int(&f, "stage"), 2);

    let mut p = Machine::new(&prog, "RetProg").unwrap();
    scan(&mut p, &mut ctx);
    p.set("stop_early", Value::Bool(true)).unwrap();
    scan(&mut p, &mut ctx);
    scan(&mut p, &mut ctx);
    p.set("stop_early", Value::Bool(false)).unwrap();
    scan(&mut p, &mut ctx);
    assert_eq!((int(&p, "scans"), int(&p, "tail_runs")), (4, 2));

    let (r, _) = p
        .call_function_named("RetFn", vec![Value::Bool(true), i(5, Elem::INT)], &mut ctx)
        .unwrap();
    assert_eq!(r, i(5, Elem::INT));
    let (r, _) = p
        .call_function_named("RetFn", vec![Value::Bool(false), i(5, Elem::INT)], &mut ctx)
        .unwrap();
    assert_eq!(r, i(105, Elem::INT));
}

#[test]
fn deferred_parentheses() {
    let prog = program("parens.il");
    let mut ctx = Cycle::new();
    for bits in 0..16u8 {
        let (a, b, c, d) = (bits & 1 != 0, bits & 2 != 0, bits & 4 != 0, bits & 8 != 0);
        let mut f = Machine::new(&prog, "ParensBool").unwrap();
        for (n, v) in [("a", a), ("b", b), ("c", c), ("d", d)] {
            f.set(n, Value::Bool(v)).unwrap();
        }
        scan(&mut f, &mut ctx);
        let case = format!("a={a} b={b} c={c} d={d}");
        assert_eq!(boolean(&f, "short_and"), a && (b || c), "{case}");
        assert_eq!(boolean(&f, "long_and"), a && (b || c), "{case}");
        assert_eq!(boolean(&f, "andn_par"), a && !(b || c), "{case}");
        assert_eq!(boolean(&f, "orn_par"), a || !(b && c), "{case}");
        assert_eq!(boolean(&f, "xor_par"), a ^ (b && c), "{case}");
        assert_eq!(boolean(&f, "nested3"), a && (b || (c && !d)), "{case}");
        assert_eq!(
            boolean(&f, "nested3_long"),
            a || (b && (c ^ (d || a))),
            "{case}"
        );
        assert_eq!(boolean(&f, "amp_par"), a && (b ^ c), "{case}");
        assert_eq!(boolean(&f, "xorn_par"), a ^ !(b || c), "{case}");
        assert_eq!(boolean(&f, "ampn_par"), a && !(b && c), "{case}");
    }
    for (x, y, z) in [
        (2i16, 2i16, 3i16),
        (20, 3, 4),
        (-9, 5, -2),
        (7, 7, 0),
        (4, 2, 8),
    ] {
        let mut f = Machine::new(&prog, "ParensArith").unwrap();
        for (n, v) in [("x", x), ("y", y), ("z", z)] {
            f.set(n, i(v as i128, Elem::INT)).unwrap();
        }
        scan(&mut f, &mut ctx);
        let case = format!("x={x} y={y} z={z}");
        let g = |n: &str| int(&f, n) as i16;
        assert_eq!(g("erg_plain"), x * y + z, "{case}");
        assert_eq!(g("erg_par"), x * (y + z), "{case}");
        assert_eq!(g("sub_par"), x - (y - z), "{case}");
        let s = y + z;
        assert_eq!(g("div_par"), if s == 0 { 0 } else { x / s }, "{case}");
        assert_eq!(g("mod_par"), if s == 0 { 0 } else { x % s }, "{case}");
        assert_eq!(g("nest_arith"), x - (y * (z + (x - 1))), "{case}");
        assert_eq!(boolean(&f, "gt_par"), x > y + z, "{case}");
        assert_eq!(boolean(&f, "eq_par"), x == y * z, "{case}");
        assert_eq!(boolean(&f, "le_par"), x <= y - z, "{case}");
        assert_eq!(boolean(&f, "mixed"), x > y && y + z == 10, "{case}");
        assert_eq!(g("long_add"), x + y * z, "{case}");
    }
}

#[test]
fn user_functions_outputs_and_eno() {
    let prog = program("functions.il");
    let mut ctx = Cycle::new();
    let mut f = Machine::new(&prog, "FnCaller").unwrap();
    for (n, v) in [("a", 7), ("b", 2), ("c", 3)] {
        f.set(n, f.parse_value(n, &v.to_string()).unwrap()).unwrap();
    }
    scan(&mut f, &mut ctx);
    assert_eq!(int(&f, "op3"), 7 + 20 + 300);
    assert_eq!(int(&f, "op2"), 5);
    assert_eq!(int(&f, "op1"), 14);
    assert_eq!(int(&f, "chained"), 105);
    assert_eq!(int(&f, "formal_line"), 327);
    assert_eq!(int(&f, "formal_multi"), 327);
    assert_eq!(int(&f, "formal_partial"), 20);

    let mut f = Machine::new(&prog, "FnCaller").unwrap();
    f.set("a", f.parse_value("a", "17").unwrap()).unwrap();
    f.set("b", f.parse_value("b", "5").unwrap()).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "q"), int(&f, "r")), (3, 2));
    assert!(boolean(&f, "nr") && !boolean(&f, "ex"));
    f.set("a", f.parse_value("a", "20").unwrap()).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "q"), int(&f, "r")), (4, 0));
    assert!(!boolean(&f, "nr") && boolean(&f, "ex"));

    let mut f = Machine::new(&prog, "FnCaller").unwrap();
    f.set("a", f.parse_value("a", "12").unwrap()).unwrap();
    f.set("b", f.parse_value("b", "4").unwrap()).unwrap();
    let before = ctx.fault_count();
    scan(&mut f, &mut ctx);
    assert_eq!((int(&f, "safe_ok"), int(&f, "safe_zero")), (3, -1));
    assert_eq!(ctx.fault_count(), before);

    let (r, outs) = f
        .call_function_named("SafeDiv", vec![i(9, Elem::INT), i(0, Elem::INT)], &mut ctx)
        .unwrap();
    assert_eq!(r, i(-1, Elem::INT));
    assert_eq!(outs, vec![Value::Bool(false)]);
    f.call_function_named("DivRem", vec![i(1, Elem::INT), i(0, Elem::INT)], &mut ctx)
        .unwrap();
    let last = ctx.last_fault().copied().unwrap();
    assert_eq!((last.kind, last.pou), (FaultKind::DivisionByZero, "DivRem"));
}

#[test]
fn standard_blocks_with_time() {
    let prog = program("std_blocks.il");
    let mut ctx = Cycle::new();
    let mut f = Machine::new(&prog, "UseSR").unwrap();
    let steps = [
        (false, false, false),
        (true, false, true),
        (false, false, true),
        (false, true, false),
        (true, true, true),
        (false, false, false),
    ];
    for (k, (s, r, q)) in steps.into_iter().enumerate() {
        f.set("set", Value::Bool(s)).unwrap();
        f.set("rst", Value::Bool(r)).unwrap();
        scan(&mut f, &mut ctx);
        assert_eq!(boolean(&f, "q"), q, "scan {k}");
        assert_eq!(boolean(&f, "cr_kept"), r, "scan {k}");
    }

    let mut ctx = Cycle::new();
    let mut f = Machine::new(&prog, "UseTimers").unwrap();
    scan(&mut f, &mut ctx);
    assert!(!boolean(&f, "ton_q"));
    f.set("in", Value::Bool(true)).unwrap();
    for ms in (0..=150).step_by(10) {
        ctx.set_now(TIME::from_ms(1000 + ms));
        scan(&mut f, &mut ctx);
        assert_eq!(boolean(&f, "ton_q"), ms >= 100, "TON at {ms} ms");
        assert_eq!(time(&f, "ton_et"), TIME::from_ms(ms.min(100)));
    }
    f.set("in", Value::Bool(false)).unwrap();
    scan(&mut f, &mut ctx);
    assert!(!boolean(&f, "ton_q"));
    assert_eq!(time(&f, "ton_et"), TIME::ZERO);

    let mut ctx = Cycle::new();
    let mut f = Machine::new(&prog, "UseTimers").unwrap();
    f.set("in", Value::Bool(true)).unwrap();
    scan(&mut f, &mut ctx);
    assert!(boolean(&f, "tp_q"));
    for ms in (10..=150).step_by(10) {
        ctx.advance(TIME::from_ms(10));
        f.set("in", Value::Bool(ms % 20 != 0 || ms >= 90)).unwrap();
        scan(&mut f, &mut ctx);
        assert_eq!(boolean(&f, "tp_q"), ms < 100, "TP at {ms} ms");
    }
    assert_eq!(
        f.get("t_p.PT"),
        Some(Value::Time(TIME::from_ms(100).0, Elem::TIME))
    );
}

/// The INT counters of the 3rd edition, scan by scan as the generated code
/// runs them (`tests/tests/all/std_blocks.rs`, `INT_COUNTER_SCANS`).
#[test]
fn int_counters_count_as_the_generated_code() {
    let mut ctx = Cycle::new();
    let mut f = machine("std_blocks.il", "UseIntCounters");
    let scans = [
        ((false, false, true), (0, false, 2, false, 2, true, false)),
        ((true, false, false), (1, false, 2, false, 3, true, false)),
        ((false, true, false), (1, false, 1, false, 2, true, false)),
        ((true, false, false), (2, false, 1, false, 3, true, false)),
        ((false, true, false), (2, false, 0, true, 2, true, false)),
        ((true, false, false), (3, true, 0, true, 3, true, false)),
        ((true, true, false), (3, true, -1, true, 2, true, false)),
        ((false, false, false), (3, true, -1, true, 2, true, false)),
        ((true, true, false), (4, true, -2, true, 2, true, false)),
        ((false, false, true), (4, true, 2, false, 2, true, false)),
        ((false, true, false), (4, true, 1, false, 1, false, false)),
        ((false, false, false), (4, true, 1, false, 1, false, false)),
        ((false, true, false), (4, true, 0, true, 0, false, true)),
    ];
    for (k, ((cu, cd, load), want)) in scans.into_iter().enumerate() {
        f.set("cu", Value::Bool(cu)).unwrap();
        f.set("cd", Value::Bool(cd)).unwrap();
        f.set("load", Value::Bool(load)).unwrap();
        scan(&mut f, &mut ctx);
        let got = (
            int(&f, "up"),
            boolean(&f, "up_q"),
            int(&f, "down"),
            boolean(&f, "down_q"),
            int(&f, "both"),
            boolean(&f, "qu"),
            boolean(&f, "qd"),
        );
        assert_eq!(got, want, "scan {k}");
    }
    // The instances are il-std's blocks of those names, with INT members.
    assert_eq!(f.get("c.CV"), Some(i(4, Elem::INT)));
    assert_eq!(f.get("e.PV"), Some(i(2, Elem::INT)));
}

#[test]
fn unknown_names_are_errors_not_panics() {
    let prog = program("jumps.il");
    let e = Machine::new(&prog, "Nope").unwrap_err();
    assert!(e.contains("Nope") && e.contains("JumpFwd"), "{e}");
    let mut m = Machine::new(&prog, "JumpFwd").unwrap();
    assert!(m.set("nothing", Value::Bool(true)).is_err());
    assert!(m.set("sel", i(1, Elem::INT)).is_err(), "wrong type");
    assert!(m.parse_value("sel", "maybe").is_err());
    assert!(
        m.call_function_named("Nope", vec![], &mut Cycle::new())
            .is_err()
    );
}

/// globals_tasks.il: VAR_IN_OUT of a FUNCTION and of an FB (an array element
/// too) and an FB's VAR_EXTERNAL are copied in and out around the call; a
/// PROGRAM run alone keeps its own copy of its globals. Same values as
/// tests/tests/globals_tasks.rs asserts for the generated code.
#[test]
fn in_outs_and_externals() {
    let mut m = machine("globals_tasks.il", "FastLoop");
    m.set("limit", i(2, Elem::DINT)).unwrap();
    let mut ctx = Cycle::new();
    for _ in 0..3 {
        m.scan(&mut ctx).unwrap();
    }
    assert_eq!(
        (int(&m, "ticks"), int(&m, "calls"), int(&m, "seen")),
        (3, 6, 3)
    );
    assert_eq!(int(&m, "sum"), 6);
    let Some(Value::Array(arr)) = m.get("arr") else {
        panic!("arr is an array")
    };
    assert_eq!(arr[1], i(30, Elem::DINT));
    assert_eq!((int(&m, "x"), int(&m, "y")), (3, 3));
    assert!(boolean(&m, "swapped"));
    // lamp is located through the configuration: it is the process image.
    assert!(ctx.io.bit(il_std::Area::Output, 0, 0));
}

/// plc/string_funcs.il: what tests/std_funcs.rs asserts for the generated code.
#[test]
fn string_functions_clamp_and_truncate() {
    let st = |x: &str| Value::Str {
        units: x.bytes().map(u16::from).collect(),
        wide: false,
    };
    let ws = |x: &str| Value::Str {
        units: x.encode_utf16().collect(),
        wide: true,
    };
    let mut ctx = Cycle::new();
    let mut f = machine("string_funcs.il", "StrFuncs");
    scan(&mut f, &mut ctx);
    for (var, want) in [
        ("left", st("He")),
        ("right", st("lo")),
        ("mid", st("ll")),
        ("cat", st("HelloWorld")),
        ("cat3", st("HelloWorld")),
        ("ins", st("HelWorldlo")),
        ("del", st("Heo")),
        ("rep", st("HeWorldo")),
        ("left_neg", st("")),
        ("mid_far", st("")),
        ("del_far", st("Hello")),
        ("ins_far", st("HelloWorld")),
        ("wleft", ws("äb")),
        ("wmid", ws("c€")),
        ("wcat", ws("äbc€dxyz")),
        ("wrep", ws("ÖÖÖÖÖbc€")),
    ] {
        assert_eq!(f.get(var), Some(want), "{var}");
    }
    assert_eq!(
        (int(&f, "find_l"), int(&f, "find_none"), int(&f, "find_w")),
        (3, 0, 4)
    );
    let faults: Vec<_> = ctx.faults().map(|x| (x.kind, x.pou, x.line)).collect();
    assert_eq!(
        faults,
        [
            (FaultKind::StringOverflow, "StrFuncs", 33),
            (FaultKind::StringOverflow, "StrFuncs", 75),
        ]
    );
    // Lengths and positions from variables, a second scan.
    f.set("n", i(-1, Elem::INT)).unwrap();
    f.set("p", i(0, Elem::INT)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!(f.get("left"), Some(st("")));
    assert_eq!(f.get("mid"), Some(st("")));
    assert_eq!(f.get("ins"), Some(st("WorldHello")));
    assert_eq!(f.get("rep"), Some(st("WorldHello")));
}

/// plc/runtime_faults.il: the interpreter records the faults the generated
/// code records (tests/runtime_faults.rs), at the same lines.
#[test]
fn runtime_faults_as_the_generated_code() {
    let mut ctx = Cycle::new();
    let mut f = machine("runtime_faults.il", "RtFaults");
    scan(&mut f, &mut ctx);
    let faults: Vec<_> = ctx.faults().map(|x| (x.kind, x.pou, x.line)).collect();
    use FaultKind::*;
    assert_eq!(
        faults,
        [
            (DivisionByZero, "RtFaults", 69),
            (DivisionByZero, "RtFaults", 72),
            (DivisionByZero, "RtDiv", 11),
            (IndexOutOfRange, "RtFaults", 77),
            (IndexOutOfRange, "RtFaults", 80),
            (IndexOutOfRange, "RtFaults", 81),
            (IndexOutOfRange, "RtFaults", 84),
            (SubrangeViolation, "RtFaults", 86),
            (StringOverflow, "RtFaults", 88),
            (IndexOutOfRange, "RtGrid", 19),
            (IndexOutOfRange, "RtGrid", 22),
        ]
    );
    assert_eq!(int(&f, "sum_wrap"), -32768);
    assert_eq!(int(&f, "udiff"), 65535);
    assert_eq!(int(&f, "pct"), 42);
    assert_eq!(int(&f, "after"), 1);
    assert!(boolean(&f, "reached"));
}

/// plc/runtime_faults.il, RtDivForms: DIV, MOD and DIV_TIME as functions
/// fault as the operators do (and as the generated code does); a REAL
/// divisor of 0 does not.
#[test]
fn div_mod_and_div_time_as_functions_record_the_fault() {
    let mut ctx = Cycle::new();
    let mut f = machine("runtime_faults.il", "RtDivForms");
    scan(&mut f, &mut ctx);
    let faults: Vec<_> = ctx.faults().map(|x| (x.kind, x.pou, x.line)).collect();
    use FaultKind::*;
    assert_eq!(
        faults,
        [
            (DivisionByZero, "RtDivForms", 115),
            (DivisionByZero, "RtDivForms", 117),
            (DivisionByZero, "RtDivForms", 119),
        ]
    );
    assert_eq!((int(&f, "r"), int(&f, "m")), (0, 0));
    assert_eq!(time(&f, "tq"), TIME::from_ms(0));
    f.set("zero", i(2, Elem::INT)).unwrap();
    f.set("rz", Value::Real(4.0)).unwrap();
    scan(&mut f, &mut ctx);
    assert_eq!(ctx.fault_count(), 3, "no fault with a divisor");
    assert_eq!((int(&f, "r"), int(&f, "m")), (3, 1));
    assert_eq!(time(&f, "tq"), TIME::from_ms(500));
    assert_eq!(time(&f, "tr"), TIME::from_ms(250));
}

/// EN/ENO on standard functions and declared initial values of omitted
/// inputs, as the generated code does (tests/tests/all/std_en_eno.rs).
#[test]
fn std_en_eno_and_declared_defaults() {
    let run = |go: bool| {
        let mut m = machine("std_en_eno.il", "StdEnEno");
        m.set("go", Value::Bool(go)).unwrap();
        m.set("x", i(20, Elem::INT)).unwrap();
        m.set("r", m.parse_value("r", "2.5").unwrap()).unwrap();
        m.scan(&mut Cycle::new()).unwrap();
        (
            [
                int(&m, "limited"),
                int(&m, "rounded"),
                int(&m, "sum"),
                int(&m, "sum_all"),
            ],
            [
                boolean(&m, "ok"),
                boolean(&m, "not_ok"),
                boolean(&m, "conv_ok"),
            ],
        )
    };
    assert_eq!(run(false), ([0, 0, 23, 22], [false, true, false]));
    assert_eq!(run(true), ([9, 2, 23, 22], [true, false, true]));
}
