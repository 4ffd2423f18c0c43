// Hosts create a block with Default and then set its inputs, as a PLC does.
#![allow(clippy::field_reassign_with_default)]

//! `CounterIL` of Beremiz's first_steps PLCopen XML project, compiled by
//! build.rs with `Builder::plcopen_file` from ../shared/corpus when present.

#[test]
fn corpus_present_or_skipped() {
    if cfg!(il_plcopen_corpus) {
        println!("first_steps CounterIL compiled from ../shared/corpus");
    } else {
        eprintln!("SKIPPED: ../shared/corpus/beremiz_beremiz_first_steps_plc.xml not found");
    }
}

#[cfg(il_plcopen_corpus)]
mod counter_il {
    use il_std::Cycle;
    use il_tests::first_steps::CounterIL;

    #[test]
    fn counts_one_per_scan_and_resets_to_the_global_constant() {
        let mut ctx = Cycle::new();
        let mut c = CounterIL::default();
        // ResetCounterValue is the configuration's VAR_GLOBAL CONSTANT (17).
        assert_eq!(c.ResetCounterValue, 17);
        for n in 1..=5 {
            c.call(&mut ctx);
            assert_eq!((c.Cnt, c.OUT), (n, n), "scan {n}");
        }
        c.Reset = true;
        c.call(&mut ctx);
        assert_eq!((c.Cnt, c.OUT), (17, 17), "reset loads ResetCounterValue");
        c.call(&mut ctx);
        assert_eq!(c.OUT, 17, "held while Reset");
        c.Reset = false;
        c.call(&mut ctx);
        assert_eq!((c.Cnt, c.OUT), (18, 18), "counts on from there");
    }

    #[test]
    fn wraps_like_an_int() {
        let mut ctx = Cycle::new();
        let mut c = CounterIL::default();
        c.Cnt = i16::MAX;
        c.call(&mut ctx);
        assert_eq!(c.OUT, i16::MIN);
    }
}
