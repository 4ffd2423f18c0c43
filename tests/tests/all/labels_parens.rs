//! A UTF-8 comment, forward FB reference, deep parentheses, consecutive labels
//! (plc/labels_parens.il) and a CRLF source file (plc/crlf.il).

use il_std::Cycle;

macro_rules! lp_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{CrLf, UsesLater};

            #[test]
            fn forward_fb_reference_deep_parens_and_labels() {
                let mut ctx = Cycle::new();
                let mut f = UsesLater::default();
                f.call(&mut ctx);
                assert_eq!(f.o, 7, "output initial value of an FB declared later");
                assert_eq!(f.deep, 10, "1 + (1 + (1 + ... 9 deep");
                assert!(f.o2, "CR kept across JMP and two labels, then JMPC");
            }

            #[test]
            fn crlf_source() {
                let mut ctx = Cycle::new();
                let mut f = CrLf::default();
                f.a = 41;
                f.call(&mut ctx);
                assert_eq!(f.b, 42);
            }
        }
    };
}

lp_tests!(via_build);
lp_tests!(via_macro);
