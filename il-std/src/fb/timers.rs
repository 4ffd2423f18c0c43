//! Timers TP, TON, TOF and the real-time clock RTC.
//!
//! Each call samples [`Cycle::now`] once and computes its outputs from that instant. Elapsed time
//! is accumulated call by call from `now − previous now` computed with wrapping subtraction, so
//! a clock that wraps around the end of the `TIME` range (near `i64::MAX` ns) is handled; a clock
//! that goes backwards adds nothing (elapsed time never decreases); the accumulated time
//! saturates instead of overflowing. A negative `PT` behaves like `T#0s`.

use crate::cycle::Cycle;
use crate::time::{DT, TIME};

/// Elapsed time since the previous call, never negative.
fn delta(last: TIME, now: TIME) -> TIME {
    TIME(now.0.wrapping_sub(last.0).max(0))
}

/// `TP`: pulse timer.
///
/// A rising edge of `IN` starts a pulse: `Q` is TRUE for the time `PT` while `ET` counts up from
/// `T#0s`. The pulse is **not retriggerable**: edges of `IN` during the pulse are ignored. When
/// the pulse ends, `ET` stays at `PT` as long as `IN` is still TRUE, and returns to `T#0s` when
/// `IN` is FALSE (immediately at the end of the pulse if `IN` is already FALSE). With `PT = T#0s`
/// no pulse is produced. IL input operators: `IN`, `PT`.
///
/// ```text
///  IN  _/‾‾‾‾‾‾‾‾‾‾‾\___/‾\______     PT = 3 time units, one call per unit
///  Q   _/‾‾‾‾‾\_________/‾‾‾‾‾\__
///  ET   0 1 2 3 3 3 3 0 0 1 2 3 0
/// ```
///
/// ```
/// use il_std::{Cycle, TIME, TP};
/// let mut ctx = Cycle::new();
/// let mut tp = TP::new();
/// tp.PT = TIME::from_ms(30);
/// let mut trace = Vec::new();
/// for in_ in [true, true, false, true, true, true, false] {
///     tp.IN = in_;
///     tp.call(&mut ctx);
///     trace.push((tp.Q, tp.ET.as_ms()));
///     ctx.advance(TIME::from_ms(10));
/// }
/// assert_eq!(trace, [(true, 0), (true, 10), (true, 20), (false, 30), (false, 30), (false, 30), (false, 0)]);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TP {
    /// Input: a rising edge starts the pulse.
    pub IN: bool,
    /// Input: pulse length.
    pub PT: TIME,
    /// Output: TRUE during the pulse.
    pub Q: bool,
    /// Output: elapsed pulse time.
    pub ET: TIME,
    in_m: bool,
    state: PulseState,
    acc: TIME,
    last: TIME,
}

#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
enum PulseState {
    #[default]
    Idle,
    Pulse,
    Done,
}

impl TP {
    /// A fresh instance: everything zero/FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            IN: false,
            PT: TIME(0),
            Q: false,
            ET: TIME(0),
            in_m: false,
            state: PulseState::Idle,
            acc: TIME(0),
            last: TIME(0),
        }
    }

    /// Runs the block body once at time `ctx.now()`.
    pub fn call(&mut self, ctx: &mut Cycle) {
        let now = ctx.now();
        let rising = self.IN && !self.in_m;
        self.in_m = self.IN;
        let pt = TIME(self.PT.0.max(0));
        let timing = match self.state {
            PulseState::Idle if rising => {
                self.acc = TIME(0);
                true
            }
            PulseState::Idle => {
                self.Q = false;
                self.ET = TIME(0);
                false
            }
            PulseState::Pulse => {
                self.acc = self.acc.saturating_add(delta(self.last, now));
                true
            }
            PulseState::Done => {
                self.Q = false;
                if !self.IN {
                    self.state = PulseState::Idle;
                    self.ET = TIME(0);
                }
                false
            }
        };
        if timing {
            if self.acc >= pt {
                self.Q = false;
                if self.IN {
                    self.state = PulseState::Done;
                    self.ET = pt;
                } else {
                    self.state = PulseState::Idle;
                    self.ET = TIME(0);
                }
            } else {
                self.state = PulseState::Pulse;
                self.Q = true;
                self.ET = self.acc;
            }
        }
        self.last = now;
    }
}

/// `TON`: on-delay timer.
///
/// When `IN` rises, `ET` starts counting; `Q` becomes TRUE once `ET` reaches `PT`, and `ET` then
/// stays at `PT`. When `IN` is FALSE, `Q` is FALSE and `ET` is `T#0s`. `PT` is read on every
/// call, so changing it while timing takes effect at once. With `PT = T#0s`, `Q` is TRUE in the
/// same call in which `IN` rises. IL input operators: `IN`, `PT`.
///
/// ```text
///  IN  _/‾‾‾‾‾‾‾‾‾\__/‾\__      PT = 3 time units, one call per unit
///  Q   _______/‾‾‾\________
///  ET   0 1 2 3 3 0 0 1 0
/// ```
///
/// ```
/// use il_std::{Cycle, TIME, TON};
/// let mut ctx = Cycle::new();
/// let mut ton = TON::new();
/// ton.PT = TIME::from_ms(30);
/// let mut trace = Vec::new();
/// for in_ in [true, true, true, true, true, false] {
///     ton.IN = in_;
///     ton.call(&mut ctx);
///     trace.push((ton.Q, ton.ET.as_ms()));
///     ctx.advance(TIME::from_ms(10));
/// }
/// assert_eq!(trace, [(false, 0), (false, 10), (false, 20), (true, 30), (true, 30), (false, 0)]);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TON {
    /// Input: timing runs while TRUE.
    pub IN: bool,
    /// Input: the delay.
    pub PT: TIME,
    /// Output: TRUE once `IN` has been TRUE for `PT`.
    pub Q: bool,
    /// Output: elapsed time, at most `PT`.
    pub ET: TIME,
    running: bool,
    acc: TIME,
    last: TIME,
}

impl TON {
    /// A fresh instance: everything zero/FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            IN: false,
            PT: TIME(0),
            Q: false,
            ET: TIME(0),
            running: false,
            acc: TIME(0),
            last: TIME(0),
        }
    }

    /// Runs the block body once at time `ctx.now()`.
    pub fn call(&mut self, ctx: &mut Cycle) {
        let now = ctx.now();
        if !self.IN {
            self.running = false;
            self.Q = false;
            self.ET = TIME(0);
        } else {
            if self.running {
                self.acc = self.acc.saturating_add(delta(self.last, now));
            } else {
                self.running = true;
                self.acc = TIME(0);
            }
            let pt = TIME(self.PT.0.max(0));
            if self.acc >= pt {
                self.Q = true;
                self.ET = pt;
            } else {
                self.Q = false;
                self.ET = self.acc;
            }
        }
        self.last = now;
    }
}

/// `TOF`: off-delay timer.
///
/// `Q` is TRUE while `IN` is TRUE. When `IN` falls, `ET` starts counting and `Q` stays TRUE
/// until `ET` reaches `PT`; `ET` then stays at `PT` until `IN` rises again, which resets `ET` to
/// `T#0s` (and sets `Q`). With `PT = T#0s`, `Q` falls in the same call as `IN`.
/// IL input operators: `IN`, `PT`.
///
/// ```text
///  IN  _/‾‾‾\_______/‾\_/‾‾      PT = 3 time units, one call per unit
///  Q   _/‾‾‾‾‾‾‾‾\__/‾‾‾‾‾‾
///  ET   0 0 0 1 2 3 3 0 1 0
/// ```
///
/// ```
/// use il_std::{Cycle, TIME, TOF};
/// let mut ctx = Cycle::new();
/// let mut tof = TOF::new();
/// tof.PT = TIME::from_ms(30);
/// let mut trace = Vec::new();
/// for in_ in [true, false, false, false, false, true] {
///     tof.IN = in_;
///     tof.call(&mut ctx);
///     trace.push((tof.Q, tof.ET.as_ms()));
///     ctx.advance(TIME::from_ms(10));
/// }
/// assert_eq!(trace, [(true, 0), (true, 0), (true, 10), (true, 20), (false, 30), (true, 0)]);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TOF {
    /// Input: a falling edge starts the off delay.
    pub IN: bool,
    /// Input: the delay.
    pub PT: TIME,
    /// Output: TRUE while `IN` is TRUE and for `PT` after it falls.
    pub Q: bool,
    /// Output: elapsed time since `IN` fell, at most `PT`.
    pub ET: TIME,
    in_m: bool,
    timing: bool,
    acc: TIME,
    last: TIME,
}

impl TOF {
    /// A fresh instance: everything zero/FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            IN: false,
            PT: TIME(0),
            Q: false,
            ET: TIME(0),
            in_m: false,
            timing: false,
            acc: TIME(0),
            last: TIME(0),
        }
    }

    /// Runs the block body once at time `ctx.now()`.
    pub fn call(&mut self, ctx: &mut Cycle) {
        let now = ctx.now();
        let falling = !self.IN && self.in_m;
        self.in_m = self.IN;
        if self.IN {
            self.timing = false;
            self.Q = true;
            self.ET = TIME(0);
        } else {
            if falling {
                self.timing = true;
                self.acc = TIME(0);
            } else if self.timing {
                self.acc = self.acc.saturating_add(delta(self.last, now));
            }
            if self.timing {
                let pt = TIME(self.PT.0.max(0));
                if self.acc >= pt {
                    self.timing = false;
                    self.Q = false;
                    self.ET = pt;
                } else {
                    self.Q = true;
                    self.ET = self.acc;
                }
            } else {
                self.Q = false;
            }
        }
        self.last = now;
    }
}

/// `RTC`: real-time clock.
///
/// On a rising edge of `IN` the clock is set to `PDT`; while `IN` is TRUE, `CDT` is `PDT` plus
/// the time elapsed (from the cycle context) since that edge, and `Q` is TRUE. While `IN` is
/// FALSE, `Q` is FALSE and `CDT` keeps its last value (the standard says `CDT` is valid only
/// while `Q` is TRUE). IL input operators: `IN`, `PDT`.
///
/// ```
/// use il_std::{Cycle, DT, RTC, TIME};
/// let mut ctx = Cycle::new();
/// let mut rtc = RTC::new();
/// rtc.IN = true;
/// rtc.PDT = DT::from_parts(2001, 4, 9, 11, 0, 0, 0).unwrap();
/// rtc.call(&mut ctx);
/// ctx.advance(TIME::from_secs(90));
/// rtc.call(&mut ctx);
/// assert_eq!(rtc.CDT.to_string(), "DT#2001-04-09-11:01:30");
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RTC {
    /// Input: the clock runs while TRUE; a rising edge loads `PDT`.
    pub IN: bool,
    /// Input: preset date and time loaded on the rising edge of `IN`.
    pub PDT: DT,
    /// Output: a copy of `IN` (`CDT` is valid).
    pub Q: bool,
    /// Output: current date and time.
    pub CDT: DT,
    in_m: bool,
    base: DT,
    acc: TIME,
    last: TIME,
}

impl RTC {
    /// A fresh instance: everything zero/FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            IN: false,
            PDT: DT(0),
            Q: false,
            CDT: DT(0),
            in_m: false,
            base: DT(0),
            acc: TIME(0),
            last: TIME(0),
        }
    }

    /// Runs the block body once at time `ctx.now()`.
    pub fn call(&mut self, ctx: &mut Cycle) {
        let now = ctx.now();
        if self.IN {
            if self.in_m {
                self.acc = self.acc.saturating_add(delta(self.last, now));
            } else {
                self.base = self.PDT;
                self.acc = TIME(0);
            }
            self.CDT = DT(self.base.0.wrapping_add(self.acc.0));
        }
        self.Q = self.IN;
        self.in_m = self.IN;
        self.last = now;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    const MS: i64 = 1_000_000;

    /// Runs `fb` once per entry of `ins`, advancing time by `step` ms after each call;
    /// returns (Q, ET in ms) per call.
    fn trace<F: FnMut(&mut Cycle, bool) -> (bool, TIME)>(
        ctx: &mut Cycle,
        ins: &[u8],
        step: i64,
        mut f: F,
    ) -> Vec<(bool, i64)> {
        ins.iter()
            .map(|&i| {
                let (q, et) = f(ctx, i != 0);
                ctx.advance(TIME(step * MS));
                (q, et.0 / MS)
            })
            .collect()
    }

    fn ton(pt: i64) -> impl FnMut(&mut Cycle, bool) -> (bool, TIME) {
        let mut t = TON {
            PT: TIME(pt * MS),
            ..Default::default()
        };
        move |c, i| {
            t.IN = i;
            t.call(c);
            (t.Q, t.ET)
        }
    }
    fn tof(pt: i64) -> impl FnMut(&mut Cycle, bool) -> (bool, TIME) {
        let mut t = TOF {
            PT: TIME(pt * MS),
            ..Default::default()
        };
        move |c, i| {
            t.IN = i;
            t.call(c);
            (t.Q, t.ET)
        }
    }
    fn tp(pt: i64) -> impl FnMut(&mut Cycle, bool) -> (bool, TIME) {
        let mut t = TP {
            PT: TIME(pt * MS),
            ..Default::default()
        };
        move |c, i| {
            t.IN = i;
            t.call(c);
            (t.Q, t.ET)
        }
    }

    fn qs(v: &[(bool, i64)]) -> Vec<u8> {
        v.iter().map(|x| x.0 as u8).collect()
    }
    fn ets(v: &[(bool, i64)]) -> Vec<i64> {
        v.iter().map(|x| x.1).collect()
    }

    #[test]
    fn ton_diagram() {
        let mut c = Cycle::new();
        let r = trace(&mut c, &[0, 1, 1, 1, 1, 1, 0, 1, 1, 0], 10, ton(30));
        assert_eq!(qs(&r), [0, 0, 0, 0, 1, 1, 0, 0, 0, 0]);
        assert_eq!(ets(&r), [0, 0, 10, 20, 30, 30, 0, 0, 10, 0]);
    }

    #[test]
    fn ton_uneven_steps_cross_pt_between_calls() {
        let mut c = Cycle::new();
        let r = trace(&mut c, &[1, 1, 1, 1], 25, ton(30));
        assert_eq!(qs(&r), [0, 0, 1, 1]);
        assert_eq!(ets(&r), [0, 25, 30, 30]);
    }

    #[test]
    fn ton_toggle_every_scan() {
        let mut c = Cycle::new();
        let r = trace(&mut c, &[1, 0, 1, 0, 1, 0, 1, 0], 100, ton(30));
        assert_eq!(qs(&r), [0; 8]);
        assert_eq!(ets(&r), [0; 8]);
        // With PT = 0, Q follows IN in the same call.
        let r = trace(&mut c, &[1, 0, 1, 0], 10, ton(0));
        assert_eq!(qs(&r), [1, 0, 1, 0]);
    }

    #[test]
    fn ton_pt_zero_same_call() {
        let mut c = Cycle::new();
        let r = trace(&mut c, &[0, 1, 1, 0], 0, ton(0));
        assert_eq!(qs(&r), [0, 1, 1, 0]);
        assert_eq!(ets(&r), [0, 0, 0, 0]);
        // Negative PT behaves like zero.
        let r = trace(&mut c, &[1], 0, ton(-5));
        assert_eq!(r, [(true, 0)]);
    }

    #[test]
    fn ton_pt_changed_while_timing() {
        let mut c = Cycle::new();
        let mut t = TON {
            PT: TIME(50 * MS),
            IN: true,
            ..Default::default()
        };
        t.call(&mut c);
        c.advance(TIME(20 * MS));
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (false, TIME(20 * MS)));
        t.PT = TIME(10 * MS); // shortened below elapsed: done at once
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (true, TIME(10 * MS)));
        t.PT = TIME(40 * MS); // lengthened: elapsed (20) is below again
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (false, TIME(20 * MS)));
        c.advance(TIME(20 * MS));
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (true, TIME(40 * MS)));
    }

    #[test]
    fn ton_time_wraps_near_limit() {
        let mut c = Cycle::new();
        c.set_now(TIME(i64::MAX - 15 * MS));
        let r = trace(&mut c, &[1, 1, 1, 1], 10, ton(30));
        assert_eq!(qs(&r), [0, 0, 0, 1]);
        assert_eq!(ets(&r), [0, 10, 20, 30]);
        assert!(c.now().0 < 0, "the clock did wrap");
    }

    #[test]
    fn ton_clock_going_backwards_adds_nothing() {
        let mut c = Cycle::new();
        c.set_now(TIME(100 * MS));
        let mut t = TON {
            PT: TIME(30 * MS),
            IN: true,
            ..Default::default()
        };
        t.call(&mut c);
        c.set_now(TIME(50 * MS));
        t.call(&mut c);
        assert_eq!(t.ET, TIME(0));
        c.advance(TIME(30 * MS));
        t.call(&mut c);
        assert!(t.Q);
    }

    #[test]
    fn ton_huge_elapsed_saturates() {
        let mut c = Cycle::new();
        let mut t = TON {
            PT: TIME::MAX,
            IN: true,
            ..Default::default()
        };
        t.call(&mut c);
        for _ in 0..4 {
            c.advance(TIME(i64::MAX / 2 + 1));
            t.call(&mut c);
        }
        assert_eq!((t.Q, t.ET), (true, TIME::MAX));
    }

    #[test]
    fn tof_diagram() {
        let mut c = Cycle::new();
        let r = trace(&mut c, &[0, 1, 1, 0, 0, 0, 0, 0, 1, 0, 1, 1], 10, tof(30));
        assert_eq!(qs(&r), [0, 1, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1]);
        assert_eq!(ets(&r), [0, 0, 0, 0, 10, 20, 30, 30, 0, 0, 0, 0]);
    }

    #[test]
    fn tof_toggle_every_scan_and_pt_zero() {
        let mut c = Cycle::new();
        let r = trace(&mut c, &[1, 0, 1, 0, 1, 0], 10, tof(30));
        assert_eq!(qs(&r), [1; 6]);
        assert_eq!(ets(&r), [0; 6]);
        let r = trace(&mut c, &[1, 0, 1, 0, 0], 10, tof(0));
        assert_eq!(qs(&r), [1, 0, 1, 0, 0]);
        assert_eq!(ets(&r), [0; 5]);
    }

    #[test]
    fn tof_pt_changed_and_wrap() {
        let mut c = Cycle::new();
        c.set_now(TIME(i64::MAX - 5 * MS));
        let mut t = TOF {
            PT: TIME(100 * MS),
            IN: true,
            ..Default::default()
        };
        t.call(&mut c);
        t.IN = false;
        t.call(&mut c);
        c.advance(TIME(20 * MS));
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (true, TIME(20 * MS)));
        t.PT = TIME(15 * MS);
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (false, TIME(15 * MS)));
        // Once expired, a longer PT does not bring Q back.
        t.PT = TIME(100 * MS);
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (false, TIME(15 * MS)));
    }

    #[test]
    fn tp_diagram_not_retriggerable() {
        let mut c = Cycle::new();
        // IN rises, toggles during the pulse (ignored), stays TRUE after the pulse (ET held at
        // PT), falls (ET resets), then a short IN pulse gives a full Q pulse.
        let r = trace(&mut c, &[0, 1, 0, 1, 1, 1, 1, 0, 1, 0, 0, 0, 0], 10, tp(30));
        assert_eq!(qs(&r), [0, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 0, 0]);
        assert_eq!(ets(&r), [0, 0, 10, 20, 30, 30, 30, 0, 0, 10, 20, 0, 0]);
    }

    #[test]
    fn tp_pt_zero_and_toggle() {
        let mut c = Cycle::new();
        let r = trace(&mut c, &[1, 1, 0, 1], 10, tp(0));
        assert_eq!(qs(&r), [0, 0, 0, 0]);
        assert_eq!(ets(&r), [0, 0, 0, 0]);
        let r = trace(&mut c, &[1, 0, 1, 0, 1, 0, 1, 0], 10, tp(35));
        assert_eq!(qs(&r), [1, 1, 1, 1, 0, 0, 1, 1]);
        assert_eq!(ets(&r), [0, 10, 20, 30, 35, 0, 0, 10]);
    }

    #[test]
    fn tp_pt_changed_while_timing_and_wrap() {
        let mut c = Cycle::new();
        c.set_now(TIME(i64::MAX - MS));
        let mut t = TP {
            PT: TIME(50 * MS),
            IN: true,
            ..Default::default()
        };
        t.call(&mut c);
        c.advance(TIME(20 * MS));
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (true, TIME(20 * MS)));
        t.PT = TIME(10 * MS);
        t.call(&mut c);
        assert_eq!((t.Q, t.ET), (false, TIME(10 * MS)));
    }

    #[test]
    fn rtc() {
        let mut c = Cycle::new();
        c.set_now(TIME(i64::MAX));
        let mut r = RTC {
            PDT: DT(1_000),
            ..Default::default()
        };
        r.call(&mut c);
        assert!(!r.Q);
        r.IN = true;
        r.call(&mut c);
        assert_eq!((r.Q, r.CDT), (true, DT(1_000)));
        c.advance(TIME(500));
        r.PDT = DT(0); // only loaded on the rising edge
        r.call(&mut c);
        assert_eq!(r.CDT, DT(1_500));
        r.IN = false;
        c.advance(TIME(500));
        r.call(&mut c);
        assert_eq!((r.Q, r.CDT), (false, DT(1_500)));
        r.IN = true;
        r.call(&mut c);
        assert_eq!(r.CDT, DT(0));
    }
}
