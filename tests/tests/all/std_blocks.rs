//! Standard function blocks driven from IL over many scans with simulated
//! time (plc/std_blocks.il, plc/std_ld_operator.il).

use il_std::{Cycle, TIME};

macro_rules! std_block_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::*;

            #[test]
            fn sr_via_s1_and_r_operators_set_dominant() {
                let mut ctx = Cycle::new();
                let mut f = UseSR::default();
                let steps = [
                    (false, false, false),
                    (true, false, true),
                    (false, false, true),
                    (false, true, false),
                    (true, true, true), // set dominates
                    // the S1 call of this scan still sees R = TRUE from the last one
                    (false, false, false),
                ];
                for (i, (s, r, q)) in steps.into_iter().enumerate() {
                    f.set = s;
                    f.rst = r;
                    f.call(&mut ctx);
                    assert_eq!(f.q, q, "scan {i}");
                    assert_eq!(
                        f.cr_kept, r,
                        "input operators leave the CR unchanged (scan {i})"
                    );
                }
            }

            #[test]
            fn rs_via_s_and_r1_operators_reset_dominant() {
                let mut ctx = Cycle::new();
                let mut f = UseRS::default();
                for (i, (s, r, q)) in [
                    (true, false, true),
                    (false, false, true),
                    (true, true, false),
                    (false, true, false),
                    (true, false, true),
                ]
                .into_iter()
                .enumerate()
                {
                    f.set = s;
                    f.rst = r;
                    f.call(&mut ctx);
                    assert_eq!(f.q, q, "scan {i}");
                }
            }

            #[test]
            fn r_trig_and_f_trig_via_clk() {
                let mut ctx = Cycle::new();
                let mut f = UseTrig::default();
                let clk = [false, true, true, false, false, true, false];
                let rise = [false, true, false, false, false, true, false];
                // F_TRIG's literal body: Q := NOT CLK AND NOT M; M := NOT CLK, with M
                // initially FALSE, so a FALSE CLK on the first call is an edge.
                let fall = [true, false, false, true, false, false, true];
                for i in 0..clk.len() {
                    f.clk = clk[i];
                    f.call(&mut ctx);
                    assert_eq!(f.rise, rise[i], "R_TRIG scan {i}");
                    assert_eq!(f.fall, fall[i], "F_TRIG scan {i}");
                }
            }

            #[test]
            fn ctu_via_cu_r_pv() {
                let mut ctx = Cycle::new();
                let mut f = UseCTU::default();
                let pulse = |f: &mut UseCTU, ctx: &mut Cycle| {
                    f.cu = true;
                    f.call(ctx);
                    f.cu = false;
                    f.call(ctx);
                };
                pulse(&mut f, &mut ctx);
                pulse(&mut f, &mut ctx);
                assert_eq!((f.cv, f.q), (2, false));
                f.cu = true;
                f.call(&mut ctx);
                f.call(&mut ctx);
                f.call(&mut ctx);
                assert_eq!((f.cv, f.q), (3, true), "only the rising edge counts");
                f.cu = false;
                f.call(&mut ctx);
                pulse(&mut f, &mut ctx);
                assert_eq!((f.cv, f.q), (4, true), "counts beyond PV");
                f.reset = true;
                f.call(&mut ctx);
                assert_eq!((f.cv, f.q), (0, false));
                f.cu = true;
                f.call(&mut ctx);
                assert_eq!(f.cv, 0, "R has priority");
            }

            #[test]
            fn ctd_via_cd_and_stored_ld() {
                let mut ctx = Cycle::new();
                let mut f = UseCTD::default();
                f.call(&mut ctx);
                assert_eq!((f.cv, f.q), (0, true), "CV 0 <= 0");
                f.load = true;
                f.call(&mut ctx);
                assert_eq!((f.cv, f.q), (2, false), "LD loads PV");
                f.load = false;
                for (cv, q) in [(1, false), (0, true), (-1, true)] {
                    f.cd = true;
                    f.call(&mut ctx);
                    f.cd = false;
                    f.call(&mut ctx);
                    assert_eq!((f.cv, f.q), (cv, q));
                }
            }

            #[test]
            fn ctd_ld_input_operator() {
                let mut ctx = Cycle::new();
                let mut f = CtdLdOp::default();
                f.load = true;
                f.call(&mut ctx);
                assert_eq!(
                    (f.cv, f.q),
                    (5, false),
                    "`LD c` on a CTD is the LD input operator"
                );
                f.load = false;
                f.cd = true;
                f.call(&mut ctx);
                assert_eq!(f.cv, 4);
            }

            #[test]
            fn ctud_via_cu_cd_r_pv() {
                let mut ctx = Cycle::new();
                let mut f = UseCTUD::default();
                f.call(&mut ctx);
                assert_eq!((f.cv, f.qu, f.qd), (0, false, true));
                for _ in 0..2 {
                    f.cu = true;
                    f.call(&mut ctx);
                    f.cu = false;
                    f.call(&mut ctx);
                }
                assert_eq!((f.cv, f.qu, f.qd), (2, true, false));
                f.cd = true;
                f.call(&mut ctx);
                f.cd = false;
                f.call(&mut ctx);
                assert_eq!((f.cv, f.qu, f.qd), (1, false, false));
                f.cu = true;
                f.cd = true;
                f.call(&mut ctx);
                assert_eq!(f.cv, 1, "simultaneous CU and CD: no count");
                f.cu = false;
                f.cd = false;
                f.reset = true;
                f.call(&mut ctx);
                assert_eq!((f.cv, f.qu, f.qd), (0, false, true));
                f.reset = false;
                f.load = true;
                f.call(&mut ctx);
                assert_eq!((f.cv, f.qu, f.qd), (2, true, false), "LD loads PV");
            }

            #[test]
            fn ton_q_rises_exactly_at_pt() {
                let mut ctx = Cycle::new();
                let mut f = UseTimers::default();
                f.call(&mut ctx);
                assert!(!f.ton_q);
                f.r#in = true;
                for ms in (0..=150).step_by(10) {
                    ctx.set_now(TIME::from_ms(1000 + ms));
                    f.call(&mut ctx);
                    assert_eq!(f.ton_q, ms >= 100, "TON at {ms} ms");
                    assert_eq!(f.ton_et, TIME::from_ms(ms.min(100)), "TON ET at {ms} ms");
                }
                f.r#in = false;
                f.call(&mut ctx);
                assert!(!f.ton_q);
                assert_eq!(f.ton_et, TIME::ZERO);
            }

            #[test]
            fn tof_holds_q_for_pt_after_falling_in() {
                let mut ctx = Cycle::new();
                let mut f = UseTimers::default();
                f.r#in = true;
                f.call(&mut ctx);
                assert!(f.tof_q, "TOF Q follows a rising IN at once");
                ctx.advance(TIME::from_ms(500));
                f.call(&mut ctx);
                f.r#in = false;
                for ms in (0..=150).step_by(10) {
                    f.call(&mut ctx);
                    assert_eq!(f.tof_q, ms < 100, "TOF at {ms} ms after the fall");
                    ctx.advance(TIME::from_ms(10));
                }
                // a rising IN while timing resets it
                f.r#in = true;
                f.call(&mut ctx);
                f.r#in = false;
                f.call(&mut ctx);
                ctx.advance(TIME::from_ms(50));
                f.r#in = true;
                f.call(&mut ctx);
                assert!(f.tof_q);
                assert_eq!(f.tof_et, TIME::ZERO);
            }

            #[test]
            fn tp_pulse_is_not_retriggerable() {
                let mut ctx = Cycle::new();
                let mut f = UseTimers::default();
                f.r#in = true;
                f.call(&mut ctx);
                assert!(f.tp_q);
                for ms in (10..=150).step_by(10) {
                    ctx.advance(TIME::from_ms(10));
                    // toggle IN during the pulse (rising at 30, 50, 70, 90): no
                    // retrigger. (Each scan calls the TP twice, by `PT t_p` with
                    // the previous IN and by `IN t_p`, so IN stays TRUE from 90.)
                    f.r#in = ms % 20 != 0 || ms >= 90;
                    f.call(&mut ctx);
                    assert_eq!(f.tp_q, ms < 100, "TP at {ms} ms");
                }
                f.r#in = true;
                f.call(&mut ctx);
                assert_eq!(
                    f.tp_et,
                    TIME::from_ms(100),
                    "ET stays at PT while IN is TRUE"
                );
                ctx.advance(TIME::from_ms(200));
                f.call(&mut ctx);
                assert!(!f.tp_q);
                assert_eq!(f.tp_et, TIME::from_ms(100));
                f.r#in = false;
                f.call(&mut ctx);
                assert_eq!(
                    f.tp_et,
                    TIME::ZERO,
                    "ET resets once the pulse is over and IN is FALSE"
                );
                f.r#in = true;
                f.call(&mut ctx);
                assert!(f.tp_q, "a new rising edge starts a new pulse");
            }

            #[test]
            fn table53_forms_1_to_3_count_alike() {
                // IEC 61131-3 Table 53 with a BOOL input `ix10` instead of %IX10.
                let mut ctx = Cycle::new();
                let mut f = Table53::default();
                for i in 1..=15 {
                    f.ix10 = true;
                    f.call(&mut ctx);
                    f.ix10 = false;
                    f.call(&mut ctx);
                    assert_eq!((f.cv1, f.cv2, f.cv3), (i, i, i));
                    assert_eq!(f.q1, i >= 15);
                }
                assert_eq!(f.C12.PV, 15);
            }

            #[test]
            fn ton_formal_call_with_outputs() {
                let mut ctx = Cycle::new();
                let mut f = TonFormal::default();
                f.start = true;
                f.call(&mut ctx);
                assert!(!f.done);
                assert!(f.waiting);
                ctx.advance(TIME::from_ms(999));
                f.call(&mut ctx);
                assert!(!f.done);
                assert_eq!(f.elapsed, TIME::from_ms(999));
                ctx.advance(TIME::from_ms(1));
                f.call(&mut ctx);
                assert!(f.done);
                assert!(!f.waiting);
                assert_eq!(f.big, 1);
            }

            #[test]
            fn int_counters_via_input_operators_and_cal() {
                let mut ctx = Cycle::new();
                let mut f = UseIntCounters::default();
                for (k, ((cu, cd, load), want)) in INT_COUNTER_SCANS.into_iter().enumerate() {
                    (f.cu, f.cd, f.load) = (cu, cd, load);
                    f.call(&mut ctx);
                    let got = (f.up, f.up_q, f.down, f.down_q, f.both, f.qu, f.qd);
                    assert_eq!(got, want, "scan {k}");
                }
            }
        }
    };
}

/// `UseIntCounters` scan by scan: `(cu, cd, load)` in, then `(up, up_q,
/// down, down_q, both, qu, qd)` out (il-interp's plc.rs runs the same).
#[allow(clippy::type_complexity)]
const INT_COUNTER_SCANS: [((bool, bool, bool), (i16, bool, i16, bool, i16, bool, bool)); 13] = [
    ((false, false, true), (0, false, 2, false, 2, true, false)),
    ((true, false, false), (1, false, 2, false, 3, true, false)),
    ((false, true, false), (1, false, 1, false, 2, true, false)),
    ((true, false, false), (2, false, 1, false, 3, true, false)),
    ((false, true, false), (2, false, 0, true, 2, true, false)),
    ((true, false, false), (3, true, 0, true, 3, true, false)),
    // CU held, CD rises: the CTUD_INT counts down only.
    ((true, true, false), (3, true, -1, true, 2, true, false)),
    ((false, false, false), (3, true, -1, true, 2, true, false)),
    // CU and CD rise together: the CTUD_INT does not count.
    ((true, true, false), (4, true, -2, true, 2, true, false)),
    ((false, false, true), (4, true, 2, false, 2, true, false)),
    ((false, true, false), (4, true, 1, false, 1, false, false)),
    ((false, false, false), (4, true, 1, false, 1, false, false)),
    ((false, true, false), (4, true, 0, true, 0, false, true)),
];

std_block_tests!(via_build);
std_block_tests!(via_macro);
