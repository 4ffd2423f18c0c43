//! Beremiz's first_steps PLCopen project from the shared corpus: its
//! `CounterIL` run by the reference interpreter. Skipped (with a message)
//! when ../shared is absent.

use il_codegen::diag::SourceFile;
use il_codegen::plcopen::Import;
use il_interp::{Machine, Value, load};
use il_std::Cycle;

const FILE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../shared/corpus/beremiz_beremiz_first_steps_plc.xml"
);

fn read() -> Option<SourceFile> {
    match std::fs::read_to_string(FILE) {
        Ok(t) => Some(SourceFile::new("first_steps.xml", t)),
        Err(_) => {
            eprintln!("SKIPPED: ../shared/corpus/beremiz_beremiz_first_steps_plc.xml not found");
            None
        }
    }
}

#[test]
fn counter_il_counts_in_the_interpreter() {
    let Some(xml) = read() else { return };
    let imp = Import::new(xml);
    let prog = load(&imp.il).unwrap_or_else(|e| panic!("{e}\n{}", imp.il.text));
    let mut m = Machine::new(&prog, "CounterIL").expect("instance");
    let mut ctx = Cycle::new();
    let int = |m: &Machine, n: &str| match m.get(n) {
        Some(Value::Int(v, _)) => v,
        other => panic!("{n}: {other:?}"),
    };
    for n in 1..=3 {
        m.scan(&mut ctx).expect("scan");
        assert_eq!((int(&m, "Cnt"), int(&m, "OUT")), (n, n));
    }
    m.set("Reset", Value::Bool(true)).unwrap();
    m.scan(&mut ctx).expect("scan");
    // ResetCounterValue: the configuration's VAR_GLOBAL CONSTANT, 17.
    assert_eq!(int(&m, "OUT"), 17);
    m.set("Reset", Value::Bool(false)).unwrap();
    m.scan(&mut ctx).expect("scan");
    assert_eq!(int(&m, "OUT"), 18);
}
