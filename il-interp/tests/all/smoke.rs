//! Every PROGRAM and FUNCTION_BLOCK of `tests/plc` runs under the interpreter
//! for a few scans without an error (and never panics), and the features
//! not covered by plc.rs give the results the compiled code gives.

use il_codegen::diag::SourceFile;
use il_codegen::ir::types::Elem;
use il_interp::{Machine, Value, load};
use il_std::{Cycle, FaultKind, TIME};

fn prog(name: &str, text: &str) -> il_codegen::ir::Program {
    load(&SourceFile::new(name, text)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn every_plc_program_runs() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/plc");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    files.sort();
    let mut failures = Vec::new();
    let mut ran = 0;
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        let Ok(p) = load(&SourceFile::new(name.clone(), text)) else {
            // Files that use POUs of other files are checked with them by build.rs.
            continue;
        };
        for pou in &p.pous {
            if pou.kind == il_codegen::ir::PouKind::Function {
                continue;
            }
            let mut ctx = Cycle::new();
            match Machine::new(&p, &pou.name) {
                Ok(mut m) => {
                    for _ in 0..3 {
                        if let Err(e) = m.scan(&mut ctx) {
                            failures.push(format!("{name} {}: {e}", pou.name));
                            break;
                        }
                        ctx.advance(TIME::from_ms(10));
                    }
                    ran += 1;
                }
                Err(e) => failures.push(format!("{name} {}: {e}", pou.name)),
            }
        }
    }
    assert!(ran > 40, "only {ran} POUs ran");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn edges_arrays_mux_time_functions_and_the_process_image() {
    let p = prog(
        "misc.il",
        "\
FUNCTION_BLOCK Edges
VAR_INPUT
    up : BOOL R_EDGE;
    down : BOOL F_EDGE;
END_VAR
VAR_OUTPUT
    r : BOOL;
    f : BOOL;
END_VAR
    LD up
    ST r
    LD down
    ST f
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    arr : ARRAY[1..3] OF INT := [10, 20, 30];
    i : INT := 4;
    got : INT := 99;
    k : INT := 7;
    sel : INT;
    t : TIME;
    e : Edges;
    x : BOOL;
END_VAR
    LD arr[i]
    ST got
    LD 5
    ST arr[i]
    LD k
    MUX INT#1, 2, 3
    ST sel
    CAL MUL_TIME(IN1 := T#10ms, IN2 := 3)
    ST t
    LD %IX0.1
    ST x
    ST %QX0.2
    LD x
    CAL e(up := x, down := x)
END_PROGRAM
",
    );
    let mut m = Machine::new(&p, "Main").unwrap();
    let mut ctx = Cycle::new();
    m.scan(&mut ctx).unwrap();
    assert_eq!(
        m.get("got"),
        Some(Value::Int(0, Elem::INT)),
        "default value"
    );
    let kinds: Vec<_> = ctx.faults().map(|f| (f.kind, f.line)).collect();
    assert_eq!(
        kinds,
        [
            (FaultKind::IndexOutOfRange, 27),
            (FaultKind::IndexOutOfRange, 30),
            (FaultKind::InvalidArgument, 32),
        ]
    );
    assert_eq!(
        m.get("sel"),
        Some(Value::Int(1, Elem::INT)),
        "IN0 when K is out of range"
    );
    assert_eq!(
        m.get("t"),
        Some(Value::Time(TIME::from_ms(30).0, Elem::TIME))
    );
    assert_eq!(m.get("e.r"), Some(Value::Bool(false)));
    assert_eq!(
        m.get("e.f"),
        Some(Value::Bool(true)),
        "F_EDGE follows F_TRIG: a FALSE first call is an edge"
    );
    ctx.io.set_bit(il_std::Area::Input, 0, 1, true);
    m.scan(&mut ctx).unwrap();
    assert_eq!(m.get("x"), Some(Value::Bool(true)));
    assert!(ctx.io.bit(il_std::Area::Output, 0, 2));
    assert_eq!(m.get("e.r"), Some(Value::Bool(true)), "rising edge");
    m.scan(&mut ctx).unwrap();
    assert_eq!(m.get("e.r"), Some(Value::Bool(false)), "level, no edge");
    ctx.io.set_bit(il_std::Area::Input, 0, 1, false);
    m.scan(&mut ctx).unwrap();
    assert_eq!(m.get("e.f"), Some(Value::Bool(true)), "falling edge");
}
