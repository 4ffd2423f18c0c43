//! The standard's corners through both front ends (tests/plc/corners.il):
//! strings of several lengths are one type, cut at the target's capacity
//! with a StringOverflow fault; ANY-typed standard functions on derived
//! types; nested initialisers; subscript expressions.

use il_std::{Cycle, FaultKind};

macro_rules! corner_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{
                AnyDerived, CornColor, CornHolder, CornPt, NestedInit, StrLens, SubExprs,
            };

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
                assert_eq!((p.lit_eq, p.lit_gt), (false, true));
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
                    [(FaultKind::InvalidArgument, "AnyDerived", 153)]
                );
            }

            /// Structure initialisers inside array initialisers and the
            /// reverse, nested; arrays of a subrange start at its lower limit
            /// and their elements are range-checked.
            #[test]
            fn nested_initialisers_and_subrange_arrays() {
                let pt = |x, y| CornPt { x, y };
                let p = NestedInit::default();
                assert_eq!(p.pts, [pt(1, 5), pt(2, 3), pt(0, 5)]);
                assert_eq!(
                    (p.h.pts, p.h.d, p.h.n),
                    ([pt(4, 4), pt(4, 4)], [5, 5, 5], 2)
                );
                let h = CornHolder::default();
                assert_eq!((h.pts, h.d, h.n), ([pt(7, 5), pt(0, 8)], [5, 5, 5], 1));
                assert_eq!((p.hs[0].n, p.hs[0].d, p.hs[1].n), (5, [9, 8, 5], 1));
                assert_eq!((p.digits, p.inl), ([6, 5, 5, 5], [10, 10]));
                let mut ctx = Cycle::new();
                let mut p = p;
                p.call(&mut ctx);
                assert_eq!(
                    (p.digits, p.inl, p.h2.d),
                    ([6, 7, 5, 5], [10, 12], [5, 8, 5])
                );
                assert_eq!(p.hs[1].d, [5, 5, 5]);
                use FaultKind::SubrangeViolation as V;
                assert_eq!(
                    faults(&ctx),
                    [(V, "NestedInit", 180), (V, "NestedInit", 187)]
                );
            }

            /// Subscripts that are expressions: evaluated each scan and
            /// bound-checked like a variable subscript.
            #[test]
            fn subscript_expressions() {
                let mut ctx = Cycle::new();
                let mut p = SubExprs::default();
                p.call(&mut ctx);
                assert_eq!((p.r1, p.r2, p.r3, p.r4, p.r5, p.r6), (30, 31, 10, 30, 0, 7));
                assert_eq!(p.a, [10, 20, 30, 40, 7]);
                p.call(&mut ctx);
                assert_eq!((p.r1, p.r2, p.r3, p.r4, p.i), (40, 0, 20, 10, 4));
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
        }
    };
}

corner_tests!(via_build);
corner_tests!(via_macro);
