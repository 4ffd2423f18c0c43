//! Host functions (`plc-host/host.il`): `{extern}` FUNCTIONs whose bodies
//! are the crate's Rust functions (`il_tests::host_impl`), called as an
//! operator, with a formal list, EN and an output, and with a VAR_IN_OUT;
//! the generated code (build.rs and `il!`) and the interpreter, given the
//! same functions as closures, agree scan by scan.

use il_codegen::ir::types::Elem;
use il_interp::{Machine, Value};
use il_std::Cycle;

/// The raw inputs of the scans: in range, clipped at either end, negative (EN FALSE).
const RAW: [i16; 7] = [5, 250, 1200, -3, 700, 0, 32767];

/// Per scan: level, limited, was_clipped, calls, ok.
type Row = (i16, i16, bool, i32, bool);

macro_rules! host_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::Station;

            pub(super) fn rows() -> Vec<Row> {
                let mut ctx = Cycle::new();
                let mut s = Station::default();
                RAW.iter()
                    .map(|&raw| {
                        s.raw = raw;
                        s.call(&mut ctx);
                        (s.level, s.limited, s.was_clipped, s.calls, s.ok)
                    })
                    .collect()
            }

            #[test]
            fn host_functions_are_called_in_every_form() {
                let rows = rows();
                // As an operator: clamp_sensor(raw, 0, 1000).
                assert_eq!(rows[2].0, 1000);
                assert_eq!(rows[3].0, 0);
                // Formal call clamp_sensor(raw, 10, 500) with EN := raw >= 0:
                // at -3 it does not run (result 0, `clipped` not written).
                assert_eq!(rows[0].1, 10);
                assert!(rows[0].2);
                assert_eq!(rows[1].1, 250);
                assert!(!rows[1].2);
                assert_eq!(rows[3].1, 0);
                assert_eq!(rows[3].2, rows[2].2, "EN FALSE leaves the output alone");
                // VAR_IN_OUT: one call per scan.
                assert_eq!(rows.last().unwrap().3, RAW.len() as i32);
                assert!(rows.iter().all(|r| r.4));
            }
        }
    };
}

host_tests!(host_build);
host_tests!(host_macro);

fn int(v: &Value) -> i16 {
    v.as_i64() as i16
}

fn interpreted() -> Vec<Row> {
    let src = std::fs::read_to_string("plc-host/host.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("host.il", src);
    let prog = il_interp::load(&file).expect("checks");
    let mut m = Machine::new(&prog, "Station").expect("program");
    assert_eq!(m.host_functions(), ["clamp_sensor", "bump"]);
    // The same bodies as host_impl, on the interpreter's values.
    m.host_function("CLAMP_SENSOR", |_ctx, vars| {
        let (raw, lo, hi) = (int(&vars[0]), int(&vars[1]), int(&vars[2]));
        let v = raw.clamp(lo, hi.max(lo));
        vars[3] = Value::Bool(v != raw);
        Value::Int(v as i128, Elem::INT)
    })
    .unwrap();
    m.host_function("bump", |_ctx, vars| {
        vars[0] = Value::Int(vars[0].as_i64() as i128 + 1, Elem::DINT);
        Value::Bool(true)
    })
    .unwrap();
    let err = m
        .host_function("nothing", |_, _| Value::Bool(true))
        .unwrap_err();
    assert!(err.contains("clamp_sensor, bump"), "{err}");
    let mut ctx = Cycle::new();
    RAW.iter()
        .map(|&raw| {
            m.set("raw", Value::Int(raw as i128, Elem::INT)).unwrap();
            m.scan(&mut ctx).unwrap();
            let g = |n: &str| m.get(n).unwrap();
            (
                int(&g("level")),
                int(&g("limited")),
                g("was_clipped").as_bool(),
                g("calls").as_i64() as i32,
                g("ok").as_bool(),
            )
        })
        .collect()
}

#[test]
fn the_interpreter_runs_host_functions_as_the_generated_code_does() {
    let want = host_build::rows();
    assert_eq!(host_macro::rows(), want);
    assert_eq!(interpreted(), want);
}

#[test]
fn without_an_implementation_the_interpreter_runs_the_interface_only() {
    let src = std::fs::read_to_string("plc-host/host.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("host.il", src);
    let prog = il_interp::load(&file).expect("checks");
    let mut m = Machine::new(&prog, "Station").expect("program");
    m.set("raw", Value::Int(1200, Elem::INT)).unwrap();
    m.scan(&mut Cycle::new()).unwrap();
    // Results are the defaults, the in-out is left as it was.
    assert_eq!(int(&m.get("level").unwrap()), 0);
    assert_eq!(m.get("calls").unwrap().as_i64(), 0);
    assert!(!m.get("ok").unwrap().as_bool());
}

#[test]
fn a_host_closure_of_the_wrong_type_is_an_error() {
    let src = std::fs::read_to_string("plc-host/host.il").expect("read");
    let file = il_codegen::diag::SourceFile::new("host.il", src);
    let prog = il_interp::load(&file).expect("checks");
    let mut m = Machine::new(&prog, "Station").expect("program");
    m.host_function("bump", |_, _| Value::Int(1, Elem::INT))
        .unwrap();
    let e = m.scan(&mut Cycle::new()).unwrap_err();
    assert!(
        e.contains("host function `bump` returned 1, which is no BOOL"),
        "{e}"
    );
}
