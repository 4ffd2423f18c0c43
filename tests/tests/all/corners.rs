//! The standard's corners through both front ends (tests/plc/corners.il):
//! strings of several lengths are one type, cut at the target's capacity
//! with a StringOverflow fault; ANY-typed standard functions on derived
//! types; nested initialisers; subscript expressions.

use il_std::{Cycle, FaultKind};

macro_rules! corner_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{AnyDerived, CornColor, CornPt, StrLens};

            fn faults(ctx: &Cycle) -> Vec<(FaultKind, &'static str, u32)> {
                ctx.faults().map(|x| (x.kind, x.pou, x.line)).collect()
            }

            /// Stores, FB inputs and outputs, function arguments, results and
            /// outputs across STRING lengths; comparisons across lengths;
            /// INSERT and REPLACE results that do not fit.
            #[test]
            fn strings_of_several_lengths() {
                let mut ctx = Cycle::new();
                let mut p = StrLens::default();
                p.call(&mut ctx);
                let s = |v: &dyn std::fmt::Display| v.to_string();
                assert_eq!(s(&p.short), "abcde");
                assert_eq!(s(&p.back), "abcdefghij");
                assert_eq!(s(&p.wshort), "wxy");
                assert_eq!(
                    (p.eq_cut, p.eq_long, p.lt_short, p.ne_long),
                    (true, false, true, true)
                );
                assert_eq!(s(&p.sink.held), "abcd");
                assert_eq!(s(&p.sink.outp), "abcd");
                assert_eq!(s(&p.fbout), "ab");
                assert_eq!((s(&p.fr), s(&p.fo)), ("abc".into(), "ab".into()));
                assert_eq!(s(&p.sel), "abcdefghij");
                assert_eq!(s(&p.cat), "abcdeabcdefghij");
                assert_eq!((s(&p.ins), s(&p.rep)), ("abcdef".into(), "aXYZ".into()));
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

            /// SEL, MUX, MOVE on enumerations, structures and arrays (one of
            /// 40 elements: no `Default` needed); EQ and NE on enumerations;
            /// MIN, MAX, LIMIT and GT on subranges.
            #[test]
            fn any_typed_functions_on_derived_types() {
                let mut ctx = Cycle::new();
                let mut p = AnyDerived::default();
                p.call(&mut ctx);
                assert_eq!(
                    (p.csel, p.cmux, p.cmove),
                    (CornColor::Blue, CornColor::Red, CornColor::Green)
                );
                assert_eq!((p.ceq3, p.cne), (true, true));
                assert_eq!((p.pmax, p.pmin, p.plim, p.pgt), (70, 30, 50, true));
                assert_eq!(p.ssel, CornPt { x: 2, y: 3 });
                assert_eq!(p.smux, CornPt { x: 1, y: 5 });
                assert_eq!(p.smove, CornPt { x: 2, y: 3 });
                assert_eq!((p.rsel, p.rmux, p.rmove), ([1, 2, 3], [4, 5, 6], [4, 5, 6]));
                assert_eq!(p.bigmux, [1; 40]);
                assert_eq!(
                    faults(&ctx),
                    [(FaultKind::InvalidArgument, "AnyDerived", 147)]
                );
            }
        }
    };
}

corner_tests!(via_build);
corner_tests!(via_macro);
