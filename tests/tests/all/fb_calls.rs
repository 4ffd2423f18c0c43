//! User function block invocation in all forms (plc/fb_calls.il).

use il_std::Cycle;

macro_rules! fb_call_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{CalForms, Outer};

            #[test]
            fn cal_with_one_line_formal_list_and_outputs() {
                let mut ctx = Cycle::new();
                let mut f = CalForms::default();
                f.step = 4;
                f.call(&mut ctx);
                assert_eq!(f.t1, 4);
                assert!(!f.big1);
                assert!(f.small1, "NOT big => small1");
                f.call(&mut ctx);
                f.call(&mut ctx);
                assert_eq!(f.t1, 12);
                assert!(f.big1);
                assert!(!f.small1);
                assert_eq!(f.acc1.calls, 3);
            }

            #[test]
            fn cal_after_load_store_of_inputs() {
                let mut ctx = Cycle::new();
                let mut f = CalForms::default();
                f.step = 5;
                f.call(&mut ctx);
                f.call(&mut ctx);
                assert_eq!(f.t2, 10);
                assert_eq!(f.acc2.inc, 5, "the stored input stays in the instance");
                assert!(f.acc2.big);
            }

            #[test]
            fn calc_and_calcn() {
                let mut ctx = Cycle::new();
                let mut f = CalForms::default();
                f.step = 1;
                f.go = true;
                f.call(&mut ctx);
                f.call(&mut ctx);
                assert_eq!((f.t3, f.n3), (2, 2), "CALC calls on TRUE");
                assert_eq!((f.t4, f.n4), (0, 0), "CALCN does not call on TRUE");
                assert_eq!(f.acc5.calls, 0, "CALNC does not call on TRUE");
                f.go = false;
                f.call(&mut ctx);
                assert_eq!((f.t3, f.n3), (2, 2), "CALC does not call on FALSE");
                assert_eq!((f.t4, f.n4), (1, 1), "CALCN calls on FALSE");
                assert_eq!(
                    (f.t5, f.n5),
                    (1, 1),
                    "CALNC with a multi-line formal list calls on FALSE"
                );
            }

            #[test]
            fn nested_user_fbs_keep_their_own_state() {
                let mut ctx = Cycle::new();
                let mut o = Outer::default();
                o.x = 3;
                o.call(&mut ctx);
                assert_eq!(o.y, 6, "(3 + 0) * 2");
                o.x = 10;
                o.call(&mut ctx);
                assert_eq!(o.y, 26, "(10 + 3) * 2");
                assert_eq!(o.mid.inn.y, 13);
            }
        }
    };
}

fb_call_tests!(via_build);
fb_call_tests!(via_macro);
