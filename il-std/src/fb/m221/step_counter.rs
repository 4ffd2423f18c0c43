//! `%SCn`, the step counter of the M221: 256 step bits `%SCn.0` .. `%SCn.255`, of which the
//! counter moves the active one up or down a step per edge.

use super::rising;
use crate::cycle::Cycle;

/// `M221_SC`: the step counter `%SCn` of a Modicon M221 / Twido.
///
/// From the manual: a step counter provides a series of 256 steps; the bit of the active step
/// (`%SCn.j`) is 1, and only one step is active at a time; `R` at 1 resets the counter; a
/// rising edge of `CU` moves it one step up, of `CD` one step down; the program may read and
/// write the step bits.
///
/// The 256 bits are the sixteen words `X0` .. `X15`: step `j` is bit `j mod 16` of word
/// `X(j / 16)`. This crate's choices where the manual is silent: the reset and the cold start
/// make step 0 the active one; counting is circular (up from step 255 is step 0, down from
/// step 0 is step 255); a step moves all 256 bits one place, so a bit the program set beside
/// the active one moves with it; when `CU` and `CD` rise in the same call nothing moves.
///
/// ```
/// use il_std::{Cycle, M221_SC};
/// let mut ctx = Cycle::new();
/// let mut s = M221_SC::new();
/// assert_eq!(s.X0, 1);                 // step 0 active
/// s.CD = true; s.call(&mut ctx);        // down from step 0: step 255
/// assert_eq!((s.X0, s.X15), (0, 0x8000));
/// ```
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct M221_SC {
    /// Input: at 1, make step 0 the only active step (priority over counting).
    pub R: bool,
    /// Input: one step up on its rising edge.
    pub CU: bool,
    /// Input: one step down on its rising edge.
    pub CD: bool,
    /// Input and output: step bits 0 .. 15.
    pub X0: u16,
    /// Input and output: step bits 16 .. 31.
    pub X1: u16,
    /// Input and output: step bits 32 .. 47.
    pub X2: u16,
    /// Input and output: step bits 48 .. 63.
    pub X3: u16,
    /// Input and output: step bits 64 .. 79.
    pub X4: u16,
    /// Input and output: step bits 80 .. 95.
    pub X5: u16,
    /// Input and output: step bits 96 .. 111.
    pub X6: u16,
    /// Input and output: step bits 112 .. 127.
    pub X7: u16,
    /// Input and output: step bits 128 .. 143.
    pub X8: u16,
    /// Input and output: step bits 144 .. 159.
    pub X9: u16,
    /// Input and output: step bits 160 .. 175.
    pub X10: u16,
    /// Input and output: step bits 176 .. 191.
    pub X11: u16,
    /// Input and output: step bits 192 .. 207.
    pub X12: u16,
    /// Input and output: step bits 208 .. 223.
    pub X13: u16,
    /// Input and output: step bits 224 .. 239.
    pub X14: u16,
    /// Input and output: step bits 240 .. 255.
    pub X15: u16,
    cu_m: bool,
    cd_m: bool,
}

impl Default for M221_SC {
    fn default() -> Self {
        Self::new()
    }
}

impl M221_SC {
    /// A counter at step 0 (as after a cold start).
    pub const fn new() -> Self {
        Self {
            R: false,
            CU: false,
            CD: false,
            X0: 1,
            X1: 0,
            X2: 0,
            X3: 0,
            X4: 0,
            X5: 0,
            X6: 0,
            X7: 0,
            X8: 0,
            X9: 0,
            X10: 0,
            X11: 0,
            X12: 0,
            X13: 0,
            X14: 0,
            X15: 0,
            cu_m: false,
            cd_m: false,
        }
    }

    fn words(&mut self) -> [&mut u16; 16] {
        [
            &mut self.X0,
            &mut self.X1,
            &mut self.X2,
            &mut self.X3,
            &mut self.X4,
            &mut self.X5,
            &mut self.X6,
            &mut self.X7,
            &mut self.X8,
            &mut self.X9,
            &mut self.X10,
            &mut self.X11,
            &mut self.X12,
            &mut self.X13,
            &mut self.X14,
            &mut self.X15,
        ]
    }

    /// Moves every step bit one place up (`up`) or down, circularly over the 256.
    fn step(&mut self, up: bool) {
        let mut w = self.words();
        if up {
            // Bit 15 of each word carries into bit 0 of the next; step 255 into step 0.
            let mut carry = *w[15] >> 15;
            for x in w.iter_mut() {
                let out = **x >> 15;
                **x = (**x << 1) | carry;
                carry = out;
            }
        } else {
            let mut carry = *w[0] & 1;
            for x in w.iter_mut().rev() {
                let out = **x & 1;
                **x = (**x >> 1) | (carry << 15);
                carry = out;
            }
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        let up = rising(self.CU, &mut self.cu_m);
        let down = rising(self.CD, &mut self.cd_m);
        if self.R {
            for (k, x) in self.words().into_iter().enumerate() {
                *x = u16::from(k == 0);
            }
        } else if up != down {
            self.step(up);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// The active steps, in order.
    fn active(s: &mut M221_SC) -> Vec<usize> {
        let words: Vec<u16> = s.words().iter().map(|x| **x).collect();
        (0..256)
            .filter(|j| words[j / 16] >> (j % 16) & 1 == 1)
            .collect()
    }

    fn call(s: &mut M221_SC, r: bool, cu: bool, cd: bool) -> Vec<usize> {
        s.R = r;
        s.CU = cu;
        s.CD = cd;
        s.call(&mut Cycle::new());
        active(s)
    }

    #[test]
    fn counts_up_and_down_one_step_per_edge_across_words() {
        let mut s = M221_SC::new();
        assert_eq!(active(&mut s), [0]);
        for _ in 0..15 {
            call(&mut s, false, true, false);
            call(&mut s, false, false, false);
        }
        assert_eq!(active(&mut s), [15]);
        assert_eq!(call(&mut s, false, true, false), [16]); // into X1
        assert_eq!(call(&mut s, false, true, false), [16]); // held
        assert_eq!(call(&mut s, false, false, true), [15]); // down, back into X0
        assert_eq!((s.X0, s.X1), (0x8000, 0));
    }

    #[test]
    fn counting_is_circular_over_256_steps() {
        let mut s = M221_SC::new();
        assert_eq!(call(&mut s, false, false, true), [255]); // down from 0
        assert_eq!(call(&mut s, false, true, false), [0]); // up from 255
        call(&mut s, false, false, false);
        assert_eq!(call(&mut s, false, true, false), [1]);
    }

    #[test]
    fn reset_makes_step_0_the_only_active_one() {
        let mut s = M221_SC::new();
        s.X7 = 0x0101;
        assert_eq!(call(&mut s, true, true, false), [0]);
    }

    #[test]
    fn a_bit_written_beside_the_active_one_moves_with_it() {
        let mut s = M221_SC::new();
        s.X0 |= 1 << 4; // steps 0 and 4
        assert_eq!(call(&mut s, false, true, false), [1, 5]);
    }

    #[test]
    fn both_edges_in_one_call_move_nothing() {
        let mut s = M221_SC::new();
        assert_eq!(call(&mut s, false, true, true), [0]);
    }
}
