//! tests/plc/corners.il under the interpreter, asserting what
//! tests/tests/all/corners.rs asserts for the generated code.

use il_codegen::diag::SourceFile;
use il_interp::{Machine, load};
use il_std::{Cycle, FaultKind};

fn machine(pou: &str) -> Machine {
    let path = format!("{}/../tests/plc/corners.il", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("read IL");
    let p = load(&SourceFile::new("corners.il", text)).unwrap_or_else(|e| panic!("{e}"));
    Machine::new(&p, pou).unwrap_or_else(|e| panic!("{e}"))
}

fn shown(m: &Machine, n: &str) -> String {
    m.get(n).unwrap_or_else(|| panic!("no `{n}`")).display()
}

fn faults(ctx: &Cycle) -> Vec<(FaultKind, &'static str, u32)> {
    ctx.faults().map(|x| (x.kind, x.pou, x.line)).collect()
}

#[test]
fn strings_of_several_lengths() {
    let mut ctx = Cycle::new();
    let mut m = machine("StrLens");
    m.scan(&mut ctx).unwrap();
    for (var, want) in [
        ("short", "'abcde'"),
        ("back", "'abcdefghij'"),
        ("wshort", "\"wxy\""),
        ("eq_cut", "TRUE"),
        ("eq_long", "FALSE"),
        ("lt_short", "TRUE"),
        ("ne_long", "TRUE"),
        ("sink.held", "'abcd'"),
        ("sink.outp", "'abcd'"),
        ("fbout", "'ab'"),
        ("fr", "'abc'"),
        ("fo", "'ab'"),
        ("sel", "'abcdefghij'"),
        ("cat", "'abcdeabcdefghij'"),
        ("ins", "'abcdef'"),
        ("rep", "'aXYZ'"),
    ] {
        assert_eq!(shown(&m, var), want, "{var}");
    }
    use FaultKind::StringOverflow as O;
    assert_eq!(
        faults(&ctx),
        [
            (O, "StrLens", 39),
            (O, "StrLens", 54),
            (O, "StrLens", 55),
            (O, "StrLens", 55),
            (O, "StrLens", 56),
            (O, "StrShort", 18),
            (O, "StrLens", 56),
            (O, "StrLens", 65),
            (O, "StrLens", 68),
        ]
    );
}

#[test]
fn any_typed_functions_on_derived_types() {
    let mut ctx = Cycle::new();
    let mut m = machine("AnyDerived");
    m.scan(&mut ctx).unwrap();
    for (var, want) in [
        ("csel", "CornColor#Blue"),
        ("cmux", "CornColor#Red"),
        ("cmove", "CornColor#Green"),
        ("ceq3", "TRUE"),
        ("cne", "TRUE"),
        ("pmax", "70"),
        ("pmin", "30"),
        ("plim", "50"),
        ("pgt", "TRUE"),
        ("ssel", "(x := 2, y := 3)"),
        ("smux", "(x := 1, y := 5)"),
        ("smove", "(x := 2, y := 3)"),
        ("rsel", "[1, 2, 3]"),
        ("rmux", "[4, 5, 6]"),
        ("rmove", "[4, 5, 6]"),
        ("bigmux[39]", "1"),
    ] {
        assert_eq!(shown(&m, var), want, "{var}");
    }
    assert_eq!(
        faults(&ctx),
        [(FaultKind::InvalidArgument, "AnyDerived", 147)]
    );
}
