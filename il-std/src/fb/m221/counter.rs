//! `%Cn`, the up/down counter of the M221: 0 to 9999 with wrap-around flags, which IEC's
//! `CTUD` (saturating, no preset load) does not model.

use super::rising;
use crate::cycle::Cycle;

/// The largest value of a counter; counting wraps around it.
const MAX: i16 = 9999;

/// `M221_C`: the up/down counter `%Cn` of a Modicon M221 / Twido.
///
/// From the manual (Generic Functions Library Guide, "Counter (%C)"): `R` at 1 sets the
/// current value `V` to 0 and has priority; `S` at 1 loads the preset `P`; a rising edge of
/// `CU` adds 1, of `CD` subtracts 1. Counting up from 9999 gives 0 and sets `F` (overflow);
/// counting down from 0 gives 9999 and sets `E` (underflow); the next count, either way,
/// clears them. `D` (done) is 1 while `V` equals `P`. Rising edges of `CU` and `CD` in the
/// same call cancel (observed on the vendor's simulator, the manual is silent).
///
/// ```
/// use il_std::{Cycle, M221_C};
/// let mut ctx = Cycle::new();
/// let mut c = M221_C::new();
/// c.P = 2;
/// c.CD = true; c.call(&mut ctx);
/// assert_eq!((c.V, c.E), (9999, true));
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct M221_C {
    /// Input: at 1, `V := 0` (priority over everything else).
    pub R: bool,
    /// Input: at 1, `V := P`.
    pub S: bool,
    /// Input: count up on its rising edge.
    pub CU: bool,
    /// Input: count down on its rising edge.
    pub CD: bool,
    /// Input: the preset `%Cn.P` (0 to 9999).
    pub P: i16,
    /// Output: underflow, set when counting down wraps 0 to 9999.
    pub E: bool,
    /// Output: done, `V = P`.
    pub D: bool,
    /// Output: overflow, set when counting up wraps 9999 to 0.
    pub F: bool,
    /// Output: the current value `%Cn.V`.
    pub V: i16,
    cu_m: bool,
    cd_m: bool,
}

impl M221_C {
    /// A counter at 0 (as after a cold start).
    pub const fn new() -> Self {
        Self {
            R: false,
            S: false,
            CU: false,
            CD: false,
            P: 0,
            E: false,
            D: false,
            F: false,
            V: 0,
            cu_m: false,
            cd_m: false,
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        let up = rising(self.CU, &mut self.cu_m);
        let down = rising(self.CD, &mut self.cd_m);
        if self.R {
            self.V = 0;
            self.E = false;
            self.F = false;
        } else if self.S {
            self.V = self.P;
            self.E = false;
            self.F = false;
        } else if up != down {
            // Any count clears the flag of the last wrap.
            self.E = false;
            self.F = false;
            if up {
                self.F = self.V >= MAX;
                self.V = if self.F { 0 } else { self.V.max(-1) + 1 };
            } else {
                self.E = self.V <= 0;
                self.V = if self.E { MAX } else { self.V.min(MAX + 1) - 1 };
            }
        }
        self.D = self.V == self.P;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One call per `(R, S, CU, CD)` with preset `p`; returns `(V, E, D, F)` after each.
    fn run(p: i16, seq: &[(bool, bool, bool, bool)]) -> std::vec::Vec<(i16, bool, bool, bool)> {
        let mut ctx = Cycle::new();
        let mut c = M221_C::new();
        c.P = p;
        seq.iter()
            .map(|&(r, s, u, d)| {
                (c.R, c.S, c.CU, c.CD) = (r, s, u, d);
                c.call(&mut ctx);
                (c.V, c.E, c.D, c.F)
            })
            .collect()
    }

    const UP: (bool, bool, bool, bool) = (false, false, true, false);
    const DOWN: (bool, bool, bool, bool) = (false, false, false, true);
    const IDLE: (bool, bool, bool, bool) = (false, false, false, false);

    #[test]
    fn done_follows_equality_with_the_preset_both_ways() {
        let got = run(2, &[UP, IDLE, UP, UP, IDLE, UP, IDLE, DOWN]);
        let vd: std::vec::Vec<(i16, bool)> = got.iter().map(|x| (x.0, x.2)).collect();
        // The held `UP` (4th call) is no edge.
        assert_eq!(
            vd,
            [
                (1, false),
                (1, false),
                (2, true),
                (2, true),
                (2, true),
                (3, false),
                (3, false),
                (2, true)
            ]
        );
    }

    #[test]
    fn wraps_set_e_and_f_and_the_next_count_clears_them() {
        let got = run(3, &[DOWN, IDLE, DOWN, IDLE, UP, IDLE, UP]);
        assert_eq!(
            got,
            [
                (9999, true, false, false),
                (9999, true, false, false),
                (9998, false, false, false),
                (9998, false, false, false),
                (9999, false, false, false),
                (9999, false, false, false),
                (0, false, false, true),
            ]
        );
    }

    #[test]
    fn reset_wins_over_set_and_set_loads_the_preset() {
        let got = run(3, &[(true, true, true, false), (false, true, false, false)]);
        assert_eq!(got, [(0, false, false, false), (3, false, true, false)]);
    }

    #[test]
    fn both_edges_in_one_call_cancel() {
        let got = run(3, &[(false, false, true, true)]);
        assert_eq!(got, [(0, false, false, false)]);
    }
}
