// Hosts create a block with Default and then set its inputs, as a PLC does.
#![allow(clippy::field_reassign_with_default)]

//! The IEC 61131-3 Annex F IL programs (CMD_MONITOR, STACK_INT, WEIGH,
//! FWD_REV_MON), compiled by build.rs from ../shared/corpus when present,
//! tested against the standard's descriptions of them.

#[test]
fn corpus_present_or_skipped() {
    if cfg!(il_corpus) {
        println!("Annex F programs compiled from ../shared/corpus");
    } else {
        println!("SKIPPED: ../shared/corpus not found");
    }
}

#[cfg(il_corpus)]
mod cmd_monitor {
    use il_std::{Cycle, TIME};
    use il_tests::annex_f::CMD_MONITOR;

    fn auto_monitor() -> CMD_MONITOR {
        let mut m = CMD_MONITOR::default();
        m.AUTO_MODE = true;
        m.MAN_CMD_CHK = true;
        m.T_CMD_MAX = TIME::from_secs(1);
        m
    }

    #[test]
    fn command_follows_auto_and_manual_modes() {
        let mut ctx = Cycle::new();
        let mut m = auto_monitor();
        m.AUTO_CMD = true;
        m.call(&mut ctx);
        assert!(m.CMD, "AUTO_CMD AND AUTO_MODE");
        m.AUTO_MODE = false;
        m.call(&mut ctx);
        assert!(!m.CMD, "AUTO_CMD ignored in manual mode");
        m.MAN_CMD = true;
        m.MAN_CMD_CHK = false;
        m.call(&mut ctx);
        assert!(m.CMD, "MAN_CMD AND NOT AUTO_MODE AND NOT MAN_CMD_CHK");
        m.MAN_CMD_CHK = true;
        m.call(&mut ctx);
        assert!(!m.CMD, "MAN_CMD_CHK (the debounce contact) blocks it");
    }

    #[test]
    fn alarm_after_t_cmd_max_without_feedback() {
        let mut ctx = Cycle::new();
        let mut m = auto_monitor();
        m.AUTO_CMD = true;
        for ms in (0..=1200).step_by(100) {
            ctx.set_now(TIME::from_ms(ms));
            m.call(&mut ctx);
            assert_eq!(m.ALRM, ms >= 1000, "at {ms} ms");
        }
    }

    #[test]
    fn no_alarm_with_feedback_in_time() {
        let mut ctx = Cycle::new();
        let mut m = auto_monitor();
        m.AUTO_CMD = true;
        m.call(&mut ctx);
        ctx.advance(TIME::from_ms(500));
        m.FDBK = true;
        m.call(&mut ctx);
        ctx.advance(TIME::from_secs(5));
        m.call(&mut ctx);
        assert!(m.CMD);
        assert!(!m.ALRM);
    }

    #[test]
    fn ack_clears_the_alarm_only_when_cmd_is_off() {
        let mut ctx = Cycle::new();
        let mut m = auto_monitor();
        m.AUTO_CMD = true;
        m.call(&mut ctx);
        ctx.advance(TIME::from_secs(2));
        m.call(&mut ctx);
        assert!(m.ALRM);
        m.ACK = true;
        m.call(&mut ctx);
        assert!(m.ALRM, "the S input overrides ACK while the command is on");
        m.ACK = false;
        m.AUTO_CMD = false;
        m.call(&mut ctx);
        assert!(!m.CMD);
        assert!(m.ALRM, "the alarm is latched");
        m.ACK = true;
        m.call(&mut ctx);
        assert!(!m.ALRM, "ACK cancels it once CMD is off");
    }
}

#[cfg(il_corpus)]
mod stack_int {
    use il_std::Cycle;
    use il_tests::annex_f::STACK_INT;

    fn pulse_push(s: &mut STACK_INT, ctx: &mut Cycle, v: i16) {
        s.IN = v;
        s.PUSH = true;
        s.call(ctx);
        s.PUSH = false;
        s.call(ctx);
    }

    fn pulse_pop(s: &mut STACK_INT, ctx: &mut Cycle) {
        s.POP = true;
        s.call(ctx);
        s.POP = false;
        s.call(ctx);
    }

    fn reset(s: &mut STACK_INT, ctx: &mut Cycle, n: i16) {
        s.N = n;
        s.R1 = true;
        s.call(ctx);
        s.R1 = false;
        s.call(ctx);
    }

    #[test]
    fn initial_state_is_empty() {
        let mut ctx = Cycle::new();
        let mut s = STACK_INT::default();
        assert!(s.EMPTY && !s.OFLO && s.OUT == 0);
        s.call(&mut ctx);
        assert!(s.EMPTY && !s.OFLO && s.OUT == 0);
        pulse_pop(&mut s, &mut ctx);
        assert!(s.EMPTY && s.OUT == 0, "popping an empty stack does nothing");
    }

    #[test]
    fn push_pop_with_depth_n() {
        let mut ctx = Cycle::new();
        let mut s = STACK_INT::default();
        reset(&mut s, &mut ctx, 3);
        assert_eq!(s.NI, 3);
        for v in [10, 20, 30] {
            pulse_push(&mut s, &mut ctx, v);
            assert_eq!(s.OUT, v, "OUT is the top of stack");
            assert!(!s.EMPTY && !s.OFLO);
        }
        pulse_push(&mut s, &mut ctx, 40);
        assert!(s.OFLO, "a 4th push overflows a stack of depth 3");
        assert_eq!(s.OUT, 0, "OUT = 0 on overflow");
        pulse_push(&mut s, &mut ctx, 50);
        assert!(s.OFLO, "no push onto an overflowed stack");
        for v in [30, 20, 10] {
            pulse_pop(&mut s, &mut ctx);
            assert!(!s.OFLO && !s.EMPTY);
            assert_eq!(s.OUT, v);
        }
        pulse_pop(&mut s, &mut ctx);
        assert!(s.EMPTY);
        assert_eq!(s.OUT, 0);
        assert_eq!(ctx.fault_count(), 0, "no index out of range");
    }

    #[test]
    fn reset_limits_n_to_1_to_128() {
        let mut ctx = Cycle::new();
        let mut s = STACK_INT::default();
        reset(&mut s, &mut ctx, 0);
        assert_eq!(s.NI, 1);
        pulse_push(&mut s, &mut ctx, 7);
        assert_eq!(s.OUT, 7);
        pulse_push(&mut s, &mut ctx, 8);
        assert!(s.OFLO);
        reset(&mut s, &mut ctx, 1000);
        assert_eq!(s.NI, 128);
        assert!(s.EMPTY && !s.OFLO && s.OUT == 0);
        for v in 1..=128 {
            pulse_push(&mut s, &mut ctx, v);
        }
        assert!(!s.OFLO);
        assert_eq!(s.OUT, 128);
        pulse_push(&mut s, &mut ctx, 129);
        assert!(s.OFLO);
        assert_eq!(ctx.fault_count(), 0);
    }

    #[test]
    fn push_is_r_edge_held_input_pushes_once() {
        // PUSH, POP : BOOL R_EDGE -- IEC 61131-3 2.5.2.2: the FB sees a
        // rising edge, so holding PUSH TRUE over three calls pushes once.
        let mut ctx = Cycle::new();
        let mut s = STACK_INT::default();
        reset(&mut s, &mut ctx, 5);
        s.IN = 1;
        s.PUSH = true;
        s.call(&mut ctx);
        s.IN = 2;
        s.call(&mut ctx);
        s.IN = 3;
        s.call(&mut ctx);
        assert_eq!(s.PTR, 0, "one push");
        assert_eq!(s.OUT, 1);
    }
}

#[cfg(il_corpus)]
mod weigh {
    use il_std::Cycle;
    use il_tests::annex_f::WEIGH;

    #[test]
    fn bcd_in_tare_subtracted_bcd_out() {
        let mut ctx = Cycle::new();
        let mut eno = false;
        assert_eq!(WEIGH(&mut ctx, true, 0x1234, 34, &mut eno), 0x1200);
        assert!(eno, "implicit ENO: TRUE when the body does not clear it");
        assert_eq!(WEIGH(&mut ctx, true, 0x0500, 1, &mut eno), 0x0499);
        assert_eq!(WEIGH(&mut ctx, true, 0x9999, 0, &mut eno), 0x9999);
        assert_eq!(ctx.fault_count(), 0);
    }

    #[test]
    fn no_weigh_command_returns_default() {
        // "EN input is used to indicate scale ready": without a weigh
        // command, `ST ENO / RET` stores the CR (FALSE) in ENO and leaves the
        // result at its default 0.
        let mut ctx = Cycle::new();
        let mut eno = true;
        assert_eq!(WEIGH(&mut ctx, false, 0x1234, 34, &mut eno), 0);
        assert!(!eno);
    }
}

#[cfg(il_corpus)]
mod fwd_rev_mon {
    use il_std::{Cycle, TIME};
    use il_tests::annex_f::FWD_REV_MON;

    fn mon() -> FWD_REV_MON {
        let mut m = FWD_REV_MON::default();
        m.AUTO = true;
        m.MAN_FWD_CHK = true;
        m.MAN_REV_CHK = true;
        m.T_FWD_MAX = TIME::from_secs(1);
        m.T_REV_MAX = TIME::from_secs(1);
        m
    }

    #[test]
    fn forward_command_and_its_timeout_alarm() {
        let mut ctx = Cycle::new();
        let mut m = mon();
        m.AUTO_FWD = true;
        m.call(&mut ctx);
        assert!(m.FWD_CMD && !m.REV_CMD && !m.KLAXON);
        ctx.advance(TIME::from_secs(1));
        m.call(&mut ctx);
        assert!(m.FWD_ALRM, "T_FWD_MAX without FWD_FDBK");
        assert!(m.KLAXON);
        assert!(!m.FWD_REV_ALRM);
    }

    #[test]
    fn contention_alarm_latches_until_ack() {
        let mut ctx = Cycle::new();
        let mut m = mon();
        m.AUTO_FWD = true;
        m.AUTO_REV = true;
        m.call(&mut ctx);
        assert!(m.FWD_REV_ALRM, "both commands at once");
        assert!(!m.FWD_CMD && !m.REV_CMD, "contention blocks both commands");
        assert!(m.KLAXON);
        m.AUTO_REV = false;
        m.call(&mut ctx);
        assert!(m.FWD_REV_ALRM, "latched after the contention is gone");
        assert!(!m.FWD_CMD, "still blocked while latched");
        m.ACK = true;
        m.call(&mut ctx);
        assert!(!m.FWD_REV_ALRM, "ACK clears it");
        m.ACK = false;
        m.call(&mut ctx);
        assert!(m.FWD_CMD);
        assert!(!m.KLAXON);
    }

    #[test]
    fn ack_does_not_clear_contention_while_it_persists() {
        let mut ctx = Cycle::new();
        let mut m = mon();
        m.AUTO_FWD = true;
        m.AUTO_REV = true;
        m.ACK = true;
        m.call(&mut ctx);
        m.call(&mut ctx);
        assert!(m.FWD_REV_ALRM, "SR: set dominates reset");
    }
}

/// FWD_REV_MON reads `FWD_REV_FF.Q`, but FWD_REV_FF is an SR whose output is
/// `Q1`: the checker refuses it at that line and suggests `Q1`; the corrected
/// copy (made by build.rs) compiles and is tested above.
#[cfg(il_corpus)]
#[test]
fn fwd_rev_mon_as_published_is_refused_with_q1_suggested() {
    use il_codegen::diag::SourceFile;
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus/");
    let read = |n: &str| SourceFile::new(n, std::fs::read_to_string(format!("{dir}{n}")).unwrap());
    let files = [
        read("beremiz_matiec_cmd_monitor_il.txt"),
        read("beremiz_matiec_fwd_rev_mon_il.txt"),
    ];
    let errors =
        il_codegen::compile_all_to_files(&files).expect_err("FWD_REV_FF.Q must be refused");
    let (index, diags) = &errors[0];
    assert_eq!(*index, 1, "the error is in FWD_REV_MON, not CMD_MONITOR");
    let errs: Vec<_> = diags.iter().filter(|d| d.is_error()).collect();
    assert_eq!(errs.len(), 1, "{errs:#?}");
    let d = errs[0];
    assert_eq!(d.code, "IL0112");
    assert_eq!(
        files[1].line_col(d.span.lo).0,
        60,
        "the line of `LD FWD_REV_FF.Q`"
    );
    assert!(d.message.contains("`Q`"), "{}", d.message);
    assert_eq!(d.help.as_deref(), Some("did you mean `Q1`?"));
}
