//! ST chains, literals typed from use, typed literals and case-insensitivity
//! (plc/misc_lang.il).

use il_std::{Cycle, TIME};

macro_rules! misc_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{CaseMix, Literals, StChain};

            #[test]
            fn st_chain_stores_the_unchanged_cr() {
                let mut ctx = Cycle::new();
                let mut f = StChain::default();
                f.x = 9;
                f.call(&mut ctx);
                assert_eq!((f.a, f.b, f.c), (9, 9, 9));
                assert!(f.nb);
                assert!(!f.nc, "STN after ST stores the complement of the same CR");
                f.x = -1;
                f.call(&mut ctx);
                assert_eq!((f.a, f.b, f.c, f.nb, f.nc), (-1, -1, -1, false, true));
            }

            #[test]
            fn literals() {
                let mut ctx = Cycle::new();
                let mut f = Literals::default();
                f.call(&mut ctx);
                assert!(f.boolvar, "LD 1 / ST boolvar");
                assert!(!f.boolfalse, "LD 0 / ST boolvar");
                assert_eq!(f.dintvar, 5);
                assert_eq!(f.neg, -5, "INT#-5");
                assert_eq!(f.hex, 255, "16#FF");
                assert_eq!(f.bin, 10, "2#1010");
                assert_eq!(f.oct, 15, "8#17");
                assert_eq!(f.under, 1_000_000);
                assert_eq!(f.uhex, 0xA5, "UINT#16#A5");
                assert_eq!(f.t1, TIME::from_secs(90), "T#1m30s");
                assert_eq!(f.t2, TIME::from_ms(1500), "T#1.5s");
                assert_eq!(f.t3, TIME::from_secs(2 * 3600 + 180), "TIME#2h_3m");
                assert_eq!(f.t4, TIME::from_ms(-250), "T#-250ms");
                assert_eq!(
                    f.t5,
                    TIME::from_ms(((24 + 2) * 3600 + 3 * 60 + 4) * 1000 + 5),
                    "t#1d2h3m4s5ms"
                );
                assert_eq!(f.r1, 1.5);
                assert_eq!(f.r2, 1.0e-3);
                assert_eq!(f.r3, -2.25);
                assert!(f.btyped);
                assert_eq!(f.big, 9_000_000_000);
                assert_eq!(f.wmax, 0xFFFF);
            }

            #[test]
            fn case_insensitive_keywords_and_names() {
                let mut ctx = Cycle::new();
                let mut f = CaseMix::default();
                f.X = 4;
                f.call(&mut ctx);
                assert_eq!(f.y, 4, "declared X and y, used as x and Y");
                assert!(f.Flag);
            }
        }
    };
}

misc_tests!(via_build);
misc_tests!(via_macro);
