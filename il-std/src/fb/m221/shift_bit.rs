//! `%SBRn`, the shift bit register of the M221: 16 bits shifted left or right one place per
//! edge.

use super::rising;
use crate::cycle::Cycle;

/// `M221_SBR`: the shift bit register `%SBRn` of a Modicon M221 / Twido.
///
/// From the manual: `R` at 1 sets register bits 0 to 15 (`%SBRn.0` .. `%SBRn.15`) to 0; a
/// rising edge of `CU` shifts the register one bit to the left (bit `j` moves to `j+1`), a
/// rising edge of `CD` one bit to the right (bit `j` moves to `j-1`); the program may read
/// and write each bit.
///
/// The register is the word `X`, bit `j` being `%SBRn.j`. A shift brings in a 0 and loses the
/// bit shifted out (bit 15 to the left, bit 0 to the right), as a shift of a word does; the
/// manual does not name the incoming bit, and its example diagram shows the vacated bit at 0.
/// This crate's choice where the manual is silent: when `CU` and `CD` rise in the same call,
/// nothing shifts (as IEC's `CTUD` does not count).
///
/// ```
/// use il_std::{Cycle, M221_SBR};
/// let mut ctx = Cycle::new();
/// let mut s = M221_SBR::new();
/// s.X = 0b0110;
/// s.CU = true; s.call(&mut ctx);
/// assert_eq!(s.X, 0b1100);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct M221_SBR {
    /// Input: at 1, clear the 16 bits (priority over shifting).
    pub R: bool,
    /// Input: shift left on its rising edge.
    pub CU: bool,
    /// Input: shift right on its rising edge.
    pub CD: bool,
    /// Input and output: the register; bit `j` is `%SBRn.j`.
    pub X: u16,
    cu_m: bool,
    cd_m: bool,
}

impl M221_SBR {
    /// A cleared register (as after a cold start).
    pub const fn new() -> Self {
        Self {
            R: false,
            CU: false,
            CD: false,
            X: 0,
            cu_m: false,
            cd_m: false,
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        let up = rising(self.CU, &mut self.cu_m);
        let down = rising(self.CD, &mut self.cd_m);
        if self.R {
            self.X = 0;
        } else if up && !down {
            self.X <<= 1;
        } else if down && !up {
            self.X >>= 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One call per `(R, CU, CD)` from `x`; returns `X` after each.
    fn run(x: u16, seq: &[(bool, bool, bool)]) -> std::vec::Vec<u16> {
        let mut c = Cycle::new();
        let mut s = M221_SBR::new();
        s.X = x;
        seq.iter()
            .map(|&(r, u, d)| {
                s.R = r;
                s.CU = u;
                s.CD = d;
                s.call(&mut c);
                s.X
            })
            .collect()
    }

    #[test]
    fn shifts_once_per_edge_and_loses_the_bit_shifted_out() {
        let seq = [
            (false, true, false), // left
            (false, true, false), // held: nothing
            (false, false, false),
            (false, true, false), // left: bit 15 lost
            (false, false, true), // right
            (false, false, false),
            (false, false, true), // right: bit 0 lost
        ];
        assert_eq!(
            run(0x4001, &seq),
            [0x8002, 0x8002, 0x8002, 0x0004, 0x0002, 0x0002, 0x0001]
        );
    }

    #[test]
    fn reset_clears_and_wins_over_an_edge() {
        assert_eq!(
            run(0xFFFF, &[(true, true, false), (false, false, false)]),
            [0, 0]
        );
    }

    #[test]
    fn both_edges_in_one_call_shift_nothing() {
        assert_eq!(run(0x0180, &[(false, true, true)]), [0x0180]);
    }
}
