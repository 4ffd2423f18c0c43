//! The README's motor example through both front ends.

use il_std::Cycle;

macro_rules! motor_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::Motor;

            #[test]
            fn seal_in_and_stop() {
                let mut ctx = Cycle::new();
                let mut m = Motor::default();
                m.call(&mut ctx);
                assert!(!m.run);
                m.start = true;
                m.call(&mut ctx);
                assert!(m.run);
                m.start = false;
                m.call(&mut ctx);
                assert!(m.run, "sealed in");
                m.stop = true;
                m.call(&mut ctx);
                assert!(!m.run);
                assert_eq!(m.starts, 1);
            }
        }
    };
}

motor_tests!(via_build);
motor_tests!(via_macro);
