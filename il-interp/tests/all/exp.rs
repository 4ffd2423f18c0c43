//! The CODESYS export of the tests (`tests/exp/project.EXP`) in the
//! interpreter, with a closure as the body of its ST block `Scale`.

use il_codegen::exp::Import;
use il_codegen::read::{Encoding, decode};
use il_interp::{Machine, Value, load};
use il_std::Cycle;

#[test]
fn a_host_block_runs_its_registered_closure() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/exp/project.EXP");
    let bytes = std::fs::read(path).expect("tests/exp/project.EXP");
    let file = decode(
        "project.EXP",
        bytes,
        Encoding::from_label("windows-1252").unwrap(),
    );
    let imp = Import::new(file);
    let prog = load(&imp.il).unwrap_or_else(|e| panic!("{e}\n{}", imp.il.text));
    let int = |m: &Machine, n: &str| match m.get(n) {
        Some(Value::Int(v, _)) => v,
        other => panic!("{n}: {other:?}"),
    };
    // Without a closure, Scale is its interface: `scaled` stays 0.
    let mut m = Machine::new(&prog, "PLC_PRG").expect("instance");
    let mut ctx = Cycle::new();
    m.scan(&mut ctx).unwrap();
    assert_eq!((int(&m, "c.n"), int(&m, "scaled")), (1, 0));
    // Scale's ST body, `o := i * 10;`, as a closure over its variables
    // (i, o in declaration order).
    let mut m = Machine::new(&prog, "PLC_PRG").expect("instance");
    m.host_function("Scale", |_, vars| {
        if let Value::Int(i, t) = vars[0] {
            vars[1] = Value::Int(i * 10, t);
        }
        Value::Bool(false)
    })
    .unwrap();
    let mut ctx = Cycle::new();
    for (n, want) in [(1, 20), (2, 40), (3, 60), (0, 80), (1, 20)] {
        m.scan(&mut ctx).unwrap();
        assert_eq!((int(&m, "c.n"), int(&m, "scaled")), (n, want));
    }
}
