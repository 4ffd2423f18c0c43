//! User types under the interpreter: enumerations (with `T#Value`
//! literals and explicit values), structures with their declared initial
//! values and nested initialisers, arrays (multi-dimensional, of structures,
//! of function blocks), subranges starting at their lower limit, and member
//! and element paths as a host names them.

use il_codegen::diag::SourceFile;
use il_codegen::ir::types::Elem;
use il_interp::{Machine, Value, load};
use il_std::{Cycle, FaultKind, TIME};

fn machine(name: &str, text: &str, pou: &str) -> Machine {
    let p = load(&SourceFile::new(name, text)).unwrap_or_else(|e| panic!("{name}: {e}"));
    Machine::new(&p, pou).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn plc(file: &str, pou: &str) -> Machine {
    let path = format!("{}/../tests/plc/{file}", env!("CARGO_MANIFEST_DIR"));
    machine(file, &std::fs::read_to_string(path).unwrap(), pou)
}

fn get(m: &Machine, n: &str) -> Value {
    m.get(n).unwrap_or_else(|| panic!("no `{n}`"))
}

fn int(m: &Machine, n: &str) -> i128 {
    match get(m, n) {
        Value::Int(v, _) => v,
        other => panic!("{n}: {other:?}"),
    }
}

fn shown(m: &Machine, n: &str) -> String {
    get(m, n).display()
}

/// tests/plc/user_types.il, asserting what tests/tests/all/user_types.rs
/// asserts for the generated code.
#[test]
fn tank_ctl_defaults_and_initial_values() {
    let m = plc("user_types.il", "TankCtl");
    assert_eq!(shown(&m, "state"), "Mode#Idle");
    assert_eq!(int(&m, "tank.level"), 50);
    assert_eq!(shown(&m, "tank.corner"), "(x := 3, y := 7)");
    assert_eq!(shown(&m, "tank.name"), "'tank'");
    assert_eq!(
        int(&m, "tanks[1].level"),
        10,
        "the STRUCT's own initial value"
    );
    assert_eq!(int(&m, "tanks[3].corner.y"), 7);
    assert_eq!(shown(&m, "tank.mode"), "Mode#Idle");
}

#[test]
fn tank_ctl_enums_structs_arrays_and_subranges() {
    let mut ctx = Cycle::new();
    let mut m = plc("user_types.il", "TankCtl");
    m.set("demand", il_interp::int(30, Elem::INT)).unwrap();
    m.scan(&mut ctx).unwrap();
    assert_eq!(shown(&m, "state"), "Mode#Filling");
    assert_eq!(get(&m, "is_draining"), Value::Bool(false));
    assert_eq!((int(&m, "tank.level"), int(&m, "tanks[2].level")), (30, 30));
    assert_eq!(shown(&m, "tank.mode"), "Mode#Filling");
    assert_eq!(
        get(&m, "copy"),
        get(&m, "tank.corner"),
        "whole structures are copied"
    );
    m.set("demand", il_interp::int(80, Elem::INT)).unwrap();
    m.scan(&mut ctx).unwrap();
    assert_eq!(shown(&m, "state"), "Mode#Draining");
    assert_eq!(get(&m, "is_draining"), Value::Bool(true));
    assert_eq!(ctx.fault_count(), 0);
    // 150 is outside Percent (0..100): the store is skipped and recorded.
    m.set("demand", il_interp::int(150, Elem::INT)).unwrap();
    m.scan(&mut ctx).unwrap();
    assert_eq!(int(&m, "pct"), 80);
    let f = ctx.last_fault().copied().unwrap();
    assert_eq!((f.kind, f.pou), (FaultKind::SubrangeViolation, "TankCtl"));
}

#[test]
fn arrays_of_function_blocks() {
    let mut ctx = Cycle::new();
    let mut m = plc("user_types.il", "TimerBank");
    for k in 1..=3 {
        m.set(&format!("start[{k}]"), Value::Bool(true)).unwrap();
    }
    for _ in 0..2 {
        m.scan(&mut ctx).unwrap();
        ctx.advance(TIME::from_ms(100));
    }
    m.scan(&mut ctx).unwrap();
    assert_eq!(shown(&m, "done"), "[TRUE, TRUE, FALSE]");
    assert_eq!(
        get(&m, "timers[3].PT"),
        Value::Time(300_000_000, Elem::TIME)
    );
    assert_eq!(get(&m, "timers[1].Q"), Value::Bool(true));
    assert_eq!(ctx.fault_count(), 0);
}

const KINDS: &str = "\
TYPE
    Color : (Red, Green := 5, Blue) := Green;
    Small : INT (-5..5);
    Level : SINT (10..20);
    Pair : STRUCT
        a : INT := 1;
        b : Color;
    END_STRUCT;
    Box : STRUCT
        p : Pair := (b := Blue);
        lv : Level;
        row : ARRAY[0..2] OF INT := [7, 8];
    END_STRUCT;
END_TYPE

FUNCTION_BLOCK Mixer
VAR_INPUT c : Color; END_VAR
VAR_OUTPUT is_red : BOOL; END_VAR
    LD c
    EQ Color#Red
    ST is_red
END_FUNCTION_BLOCK

PROGRAM Kinds
VAR
    col : Color;
    first : Color := Red;
    s : Small;
    lv : Level;
    bx : Box;
    boxes : ARRAY[1..2] OF Box;
    grid : ARRAY[1..2, 0..2] OF INT := [1, 2, 3, 4];
    mixers : ARRAY[0..1] OF Mixer;
    i : INT := 1;
    j : INT;
    same : BOOL;
    n : INT;
    seven : INT := 7;
END_VAR
    LD Color#Blue
    ST bx.p.b
    ST mixers[0].c
    LD first
    ST mixers[1].c
    CAL mixers[0]
    CAL mixers[1]
    LD bx.p.b
    NE col
    ST same
    LD grid[2, 0]
    ADD grid[i, j]
    ST n
    ST boxes[i].row[2]
    LD seven
    ST s
    LD 4
    ST s
    LD i
    ADD 1
    ST i
END_PROGRAM
";

#[test]
fn every_kind_of_user_type() {
    let mut m = machine("kinds.il", KINDS, "Kinds");
    // Defaults: the declared default value, lower limits, STRUCT initial values.
    assert_eq!(shown(&m, "col"), "Color#Green");
    assert_eq!(shown(&m, "first"), "Color#Red");
    assert_eq!(int(&m, "s"), -5, "a subrange starts at its lower limit");
    assert_eq!(int(&m, "lv"), 10);
    assert_eq!(int(&m, "bx.lv"), 10, "also as a STRUCT field");
    assert_eq!(shown(&m, "bx.p"), "(a := 1, b := Color#Blue)");
    assert_eq!(shown(&m, "bx.row"), "[7, 8, 0]");
    assert_eq!(int(&m, "boxes[1].lv"), 10);
    assert_eq!(shown(&m, "boxes[2].p"), "(a := 1, b := Color#Blue)");
    assert_eq!(int(&m, "grid[1, 2]"), 3);
    assert_eq!(int(&m, "grid[2, 0]"), 4);
    let mut ctx = Cycle::new();
    m.scan(&mut ctx).unwrap();
    assert_eq!(get(&m, "mixers[0].is_red"), Value::Bool(false));
    assert_eq!(get(&m, "mixers[1].is_red"), Value::Bool(true));
    assert_eq!(get(&m, "same"), Value::Bool(true), "Blue NE Green");
    assert_eq!(int(&m, "n"), 4 + 1);
    assert_eq!(int(&m, "boxes[1].row[2]"), 5);
    // 7 is outside -5..5: skipped and recorded; 4 is stored.
    assert_eq!(int(&m, "s"), 4);
    assert_eq!(
        ctx.last_fault().map(|f| f.kind),
        Some(FaultKind::SubrangeViolation)
    );
    m.scan(&mut ctx).unwrap();
    assert_eq!(
        int(&m, "n"),
        4 + 4,
        "grid[2, 0] read through variable subscripts"
    );
}

#[test]
fn host_paths_values_and_errors() {
    let mut m = machine("kinds.il", KINDS, "Kinds");
    let v = m.parse_value("col", "Color#Blue").unwrap();
    m.set("col", v).unwrap();
    assert_eq!(shown(&m, "col"), "Color#Blue");
    let v = m.parse_value("bx.p.b", "red").unwrap();
    m.set("bx.p.b", v).unwrap();
    assert_eq!(shown(&m, "bx.p.b"), "Color#Red");
    m.set("grid[2,2]", il_interp::int(-3, Elem::INT)).unwrap();
    assert_eq!(int(&m, "grid[2, 2]"), -3);
    let err = |r: Result<Value, String>| r.unwrap_err();
    assert!(err(m.parse_value("col", "Color#Bleu")).contains("did you mean `Blue`"));
    assert!(err(m.parse_value("col", "Pair#a")).contains("value of Pair"));
    assert!(err(m.parse_value("s", "6")).contains("outside the subrange -5..5"));
    assert!(err(m.parse_value("bx", "1")).contains("set its members"));
    assert!(err(m.parse_value("bx.q", "1")).contains("did you mean `p`"));
    assert!(err(m.parse_value("grid[3, 0]", "1")).contains("outside the bounds 1..2"));
    assert!(err(m.parse_value("grid[1]", "1")).contains("1 subscripts for an array of 2"));
    assert!(err(m.parse_value("colr", "1")).contains("did you mean `col`"));
    assert!(
        m.set("col", Value::Bool(true)).is_err(),
        "a value of another type"
    );
}

/// A host store into an element of an array of a subrange keeps to the
/// subrange, in a program and in a configuration's global.
#[test]
fn host_stores_into_subrange_elements_keep_the_bounds() {
    let src = "TYPE Pct : INT (0..100); END_TYPE
PROGRAM Hs
VAR_EXTERNAL gl : ARRAY[1..2] OF Pct; END_VAR
VAR a : ARRAY[1..3] OF Pct; END_VAR
    LD gl[1]
    ST a[1]
END_PROGRAM
CONFIGURATION Hc
VAR_GLOBAL gl : ARRAY[1..2] OF Pct; END_VAR
PROGRAM p : Hs;
END_CONFIGURATION
";
    let prog = load(&SourceFile::new("hs.il", src)).unwrap();
    let mut m = Machine::new(&prog, "Hs").unwrap();
    let mut ctx = Cycle::new();
    let p = m.lookup("a[2]").unwrap();
    m.set_at(&mut ctx, &p, il_interp::int(100, Elem::INT))
        .unwrap();
    let e = m
        .set_at(&mut ctx, &p, il_interp::int(101, Elem::INT))
        .unwrap_err();
    assert_eq!(e, "`a[2]`: 101 is outside its subrange 0..100");
    let mut c = il_interp::ConfigMachine::new(&prog, "Hc").unwrap();
    for (path, v, ok) in [
        ("gl[2]", 7, true),
        ("gl[2]", -1, false),
        ("p.a[3]", 101, false),
    ] {
        let place = c.lookup(path).unwrap();
        let r = c.set_at(&mut ctx, &place, il_interp::int(v, Elem::INT));
        assert_eq!(r.is_ok(), ok, "{path} := {v}: {r:?}");
    }
    let place = c.lookup("gl[2]").unwrap();
    assert_eq!(c.get_at(&ctx, &place), il_interp::int(7, Elem::INT));
}
