//! `%DRn`, the drum controller of the M221: up to 8 steps, each a pattern of 16 control bits
//! that the project assigns to outputs `%Q` or memory bits `%M`.

use super::rising;
use crate::cycle::Cycle;

/// `M221_DR`: the drum controller `%DRn` of a Modicon M221 / Twido.
///
/// From the manual: `R` at 1 sets the drum to step 0; a rising edge of `U` advances it one
/// step, and past the last configured step it comes back to step 0 (the drum's steps are
/// engaged cyclically); `F` ("full") is 1 while the current step is the last configured one;
/// `S` is the current step, which the program may read and write, a written value taking
/// effect at the block's next execution; the control bits are updated only when the step
/// changes (and at a cold start).
///
/// Configuration (inputs written once from the project): `STEPS`, the number of steps
/// (1 to 8), and `P0` .. `P7`, the control-bit pattern of each step (bit `j` of `Pk` is control
/// bit `j` in step `k`). Outputs: `F`; `CTRL`, the pattern of the current step; `UPD`, TRUE
/// for the one call in which the step changed — the M221 importer copies `CTRL`'s bits to their
/// targets exactly then, so a target the program writes elsewhere keeps that value until the
/// next change of step.
///
/// This crate's choices where the manual is silent: a written `S` outside `0 .. STEPS-1` is
/// ignored (`S` shows the current step again after the call); in one call a written `S` is
/// taken first, then `R` or `U` act on it; the first call of the block counts as a change
/// of step (it stands for the cold start, so step 0's pattern is written then); `STEPS`
/// outside 1 to 8 is taken as the nearest of them.
///
/// ```
/// use il_std::{Cycle, M221_DR};
/// let mut ctx = Cycle::new();
/// let mut d = M221_DR::new();
/// d.STEPS = 3;
/// d.P0 = 0b001; d.P1 = 0b011; d.P2 = 0b100;
/// d.call(&mut ctx);                       // first call: step 0, its pattern to write
/// assert_eq!((d.S, d.CTRL, d.UPD, d.F), (0, 0b001, true, false));
/// d.U = true; d.call(&mut ctx);           // rising edge: step 1
/// assert_eq!((d.S, d.CTRL, d.UPD), (1, 0b011, true));
/// d.call(&mut ctx);                       // U held: no change
/// assert!(!d.UPD);
/// ```
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct M221_DR {
    /// Input: at 1, go to step 0 (priority over `U`).
    pub R: bool,
    /// Input: advance one step on its rising edge.
    pub U: bool,
    /// Input and output: the current step (`%DRn.S`); a value the program writes takes effect
    /// at the next call.
    pub S: i16,
    /// Configuration: the number of steps, 1 to 8.
    pub STEPS: i16,
    /// Configuration: the control bits of step 0.
    pub P0: u16,
    /// Configuration: the control bits of step 1.
    pub P1: u16,
    /// Configuration: the control bits of step 2.
    pub P2: u16,
    /// Configuration: the control bits of step 3.
    pub P3: u16,
    /// Configuration: the control bits of step 4.
    pub P4: u16,
    /// Configuration: the control bits of step 5.
    pub P5: u16,
    /// Configuration: the control bits of step 6.
    pub P6: u16,
    /// Configuration: the control bits of step 7.
    pub P7: u16,
    /// Output: the current step is the last configured one (`%DRn.F`).
    pub F: bool,
    /// Output: the control bits of the current step.
    pub CTRL: u16,
    /// Output: the step changed in this call (or this is the first call): write `CTRL` out.
    pub UPD: bool,
    u_m: bool,
    cur: i16,
    started: bool,
}

impl Default for M221_DR {
    fn default() -> Self {
        Self::new()
    }
}

impl M221_DR {
    /// A fresh drum: step 0, one step, all patterns 0, not yet called.
    pub const fn new() -> Self {
        Self {
            R: false,
            U: false,
            S: 0,
            STEPS: 1,
            P0: 0,
            P1: 0,
            P2: 0,
            P3: 0,
            P4: 0,
            P5: 0,
            P6: 0,
            P7: 0,
            F: false,
            CTRL: 0,
            UPD: false,
            u_m: false,
            cur: 0,
            started: false,
        }
    }

    fn pattern(&self, step: i16) -> u16 {
        match step {
            0 => self.P0,
            1 => self.P1,
            2 => self.P2,
            3 => self.P3,
            4 => self.P4,
            5 => self.P5,
            6 => self.P6,
            _ => self.P7,
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        let steps = self.STEPS.clamp(1, 8);
        let before = self.cur;
        if self.S != self.cur && (0..steps).contains(&self.S) {
            self.cur = self.S;
        }
        let advance = rising(self.U, &mut self.u_m);
        if self.R {
            self.cur = 0;
        } else if advance {
            self.cur = (self.cur + 1) % steps;
        }
        // STEPS lowered under the current step: the drum cannot stand past its last step.
        if self.cur >= steps {
            self.cur = 0;
        }
        self.UPD = !self.started || self.cur != before;
        self.started = true;
        self.S = self.cur;
        self.F = self.cur == steps - 1;
        self.CTRL = self.pattern(self.cur);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs `(R, U, written S)` per call; returns `(S, F, CTRL, UPD)` after each.
    fn run(
        d: &mut M221_DR,
        seq: &[(bool, bool, Option<i16>)],
    ) -> std::vec::Vec<(i16, bool, u16, bool)> {
        let mut c = Cycle::new();
        seq.iter()
            .map(|&(r, u, s)| {
                d.R = r;
                d.U = u;
                if let Some(s) = s {
                    d.S = s;
                }
                d.call(&mut c);
                (d.S, d.F, d.CTRL, d.UPD)
            })
            .collect()
    }

    fn drum4() -> M221_DR {
        let mut d = M221_DR::new();
        d.STEPS = 4;
        d.P0 = 0x0001;
        d.P1 = 0x0003;
        d.P2 = 0x0006;
        d.P3 = 0x8000;
        d
    }

    #[test]
    fn advances_on_rising_edges_and_wraps_after_the_last_step() {
        let mut d = drum4();
        // U: 0 1 1 0 1 0 1 0 1 — edges at calls 2, 5, 7, 9.
        let got = run(
            &mut d,
            &[
                (false, false, None),
                (false, true, None),
                (false, true, None),
                (false, false, None),
                (false, true, None),
                (false, false, None),
                (false, true, None),
                (false, false, None),
                (false, true, None),
            ],
        );
        assert_eq!(
            got,
            [
                (0, false, 0x0001, true), // first call: cold start writes step 0
                (1, false, 0x0003, true),
                (1, false, 0x0003, false), // U held: no edge
                (1, false, 0x0003, false),
                (2, false, 0x0006, true),
                (2, false, 0x0006, false),
                (3, true, 0x8000, true), // last step: F
                (3, true, 0x8000, false),
                (0, false, 0x0001, true), // past the last step: back to 0
            ]
        );
    }

    #[test]
    fn reset_is_a_level_with_priority_over_u() {
        let mut d = drum4();
        let got = run(
            &mut d,
            &[
                (false, true, None),  // edge on the first call: step 1
                (true, false, None),  // R: step 0
                (true, true, None),   // R held, U rises: still 0, no change
                (false, false, None), // R released
                (false, true, None),  // edge: 1
            ],
        );
        assert_eq!(
            got.iter().map(|g| (g.0, g.3)).collect::<std::vec::Vec<_>>(),
            [(1, true), (0, true), (0, false), (0, false), (1, true)]
        );
    }

    #[test]
    fn a_written_step_takes_effect_at_the_next_call_and_a_bad_one_is_ignored() {
        let mut d = drum4();
        let got = run(
            &mut d,
            &[
                (false, false, None),
                (false, false, Some(3)), // written: step 3, F, its pattern
                (false, false, Some(9)), // outside 0..3: ignored
                (false, true, Some(1)),  // written 1 then U's edge: 2
            ],
        );
        assert_eq!(
            got,
            [
                (0, false, 0x0001, true),
                (3, true, 0x8000, true),
                (3, true, 0x8000, false),
                (2, false, 0x0006, true),
            ]
        );
    }

    #[test]
    fn one_step_drum_is_always_full_and_never_changes() {
        let mut d = M221_DR::new();
        d.P0 = 0x00F0;
        let got = run(&mut d, &[(false, false, None), (false, true, None)]);
        assert_eq!(got, [(0, true, 0x00F0, true), (0, true, 0x00F0, false)]);
    }
}
