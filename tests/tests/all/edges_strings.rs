//! F_EDGE inputs, STRING/REAL comparisons, CTU near the INT limit
//! (plc/edges_strings.il).

use il_std::{Cycle, STRING};

macro_rules! es_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{FEDGEFB, StrRealCmp};

            #[test]
            fn f_edge_input_counts_falling_edges_only() {
                // IEC 61131-3 2.5.2.2: `trig : BOOL F_EDGE` is TRUE inside the
                // block only on a falling edge of the caller's value.
                let mut ctx = Cycle::new();
                let mut f = FEDGEFB::default();
                for v in [true, true, false, false, true, false] {
                    f.trig = v;
                    f.call(&mut ctx);
                }
                assert_eq!(f.n, 2);
            }

            #[test]
            fn string_and_real_comparisons() {
                let mut ctx = Cycle::new();
                let mut f = StrRealCmp::default();
                f.s1 = STRING::from_str_truncating("abd").0;
                f.s2 = STRING::from_str_truncating("abc").0;
                f.x = 0.5;
                f.call(&mut ctx);
                assert!(f.s_gt, "'abd' > 'abc'");
                assert!(f.r_eq);
                f.s1 = STRING::from_str_truncating("ab").0;
                f.x = 0.25;
                f.call(&mut ctx);
                assert!(!f.s_gt, "'ab' < 'abc'");
                assert!(!f.r_eq);
            }

            #[test]
            fn ctu_stops_at_the_type_maximum() {
                let mut ctx = Cycle::new();
                let mut f = StrRealCmp::default();
                f.c.CV = 32766;
                for _ in 0..3 {
                    f.cu = true;
                    f.call(&mut ctx);
                    f.cu = false;
                    f.call(&mut ctx);
                }
                assert_eq!(f.cv, 32767, "no wrap past INT's maximum");
                assert!(f.q);
            }
        }
    };
}

es_tests!(via_build);
es_tests!(via_macro);
