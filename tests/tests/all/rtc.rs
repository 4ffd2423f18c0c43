//! RTC through IL: CDT starts at PDT when IN rises and runs with the
//! cycle context's time.

use il_std::{Cycle, DT, TIME};

macro_rules! rtc_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::UseRTC;

            #[test]
            fn rtc_runs_from_preset() {
                let mut ctx = Cycle::new();
                let mut r = UseRTC::default();
                r.call(&mut ctx);
                assert!(!r.valid);
                r.set = true;
                ctx.advance(TIME::from_ms(250));
                r.call(&mut ctx);
                assert!(r.valid);
                let preset = DT::from_parts(2024, 1, 31, 23, 59, 59, 0).unwrap();
                assert_eq!(r.now, preset);
                ctx.advance(TIME::from_ms(1500));
                r.call(&mut ctx);
                assert_eq!(r.now.0 - preset.0, 1_500_000_000, "1.5 s later");
                assert_eq!(r.now.to_string(), "DT#2024-02-01-00:00:00.5");
            }
        }
    };
}

rtc_tests!(via_build);
rtc_tests!(via_macro);
