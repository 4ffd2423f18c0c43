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
        ("lit_eq", "FALSE"),
        ("lit_gt", "TRUE"),
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
        [(FaultKind::InvalidArgument, "AnyDerived", 153)]
    );
}

#[test]
fn nested_initialisers_and_subrange_arrays() {
    let mut ctx = Cycle::new();
    let mut m = machine("NestedInit");
    let before = [
        (
            "pts",
            "[(x := 1, y := 5), (x := 2, y := 3), (x := 0, y := 5)]",
        ),
        (
            "h",
            "(pts := [(x := 4, y := 4), (x := 4, y := 4)], d := [5, 5, 5], n := 2)",
        ),
        (
            "h2",
            "(pts := [(x := 7, y := 5), (x := 0, y := 8)], d := [5, 5, 5], n := 1)",
        ),
        ("hs[1].d", "[9, 8, 5]"),
        ("hs[1].n", "5"),
        ("hs[2].n", "1"),
        ("digits", "[6, 5, 5, 5]"),
        ("inl", "[10, 10]"),
    ];
    for (var, want) in before {
        assert_eq!(shown(&m, var), want, "{var}");
    }
    m.scan(&mut ctx).unwrap();
    for (var, want) in [
        ("digits", "[6, 7, 5, 5]"),
        ("inl", "[10, 12]"),
        ("h2.d", "[5, 8, 5]"),
        ("hs[2].d", "[5, 5, 5]"),
    ] {
        assert_eq!(shown(&m, var), want, "{var}");
    }
    use FaultKind::SubrangeViolation as V;
    assert_eq!(
        faults(&ctx),
        [(V, "NestedInit", 180), (V, "NestedInit", 187)]
    );
}

#[test]
fn subscript_expressions() {
    let mut ctx = Cycle::new();
    let mut m = machine("SubExprs");
    m.scan(&mut ctx).unwrap();
    let got = |m: &Machine| {
        ["r1", "r2", "r3", "r4", "r5", "r6", "a"]
            .map(|v| shown(m, v))
            .join(" ")
    };
    assert_eq!(got(&m), "30 31 10 30 0 7 [10, 20, 30, 40, 7]");
    m.scan(&mut ctx).unwrap();
    assert_eq!(got(&m), "40 0 20 10 0 7 [10, 20, 30, 40, 7]");
    use FaultKind::IndexOutOfRange as X;
    let s = "SubExprs";
    assert_eq!(
        faults(&ctx),
        [
            (X, s, 208),
            (X, s, 209),
            (X, s, 201),
            (X, s, 208),
            (X, s, 209)
        ]
    );
}
