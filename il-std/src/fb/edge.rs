//! Edge detection: R_TRIG (rising) and F_TRIG (falling).

use crate::cycle::Cycle;

/// `R_TRIG`: rising edge detector. `Q := CLK AND NOT M; M := CLK`.
///
/// `Q` is TRUE for exactly one call after `CLK` goes from FALSE to TRUE. `M` starts FALSE, so a
/// TRUE `CLK` on the very first call counts as an edge.
///
/// ```
/// use il_std::{Cycle, R_TRIG};
/// let mut ctx = Cycle::new();
/// let mut r = R_TRIG::default();
/// r.CLK = true;
/// r.call(&mut ctx);
/// assert!(r.Q);          // first call with CLK TRUE: edge
/// r.call(&mut ctx);
/// assert!(!r.Q);         // CLK still TRUE: no edge
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct R_TRIG {
    /// Input: the signal watched.
    pub CLK: bool,
    /// Output: TRUE for one call on a rising edge of `CLK`.
    pub Q: bool,
    M: bool,
}

impl R_TRIG {
    /// A fresh instance: everything FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            CLK: false,
            Q: false,
            M: false,
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        self.Q = self.CLK && !self.M;
        self.M = self.CLK;
    }
}

/// `F_TRIG`: falling edge detector, the standard's literal body
/// `Q := NOT CLK AND NOT M; M := NOT CLK`.
///
/// `Q` is TRUE for exactly one call after `CLK` goes from TRUE to FALSE. Because `M` starts
/// FALSE, **`Q` is also TRUE on the very first call when `CLK` is FALSE** (the standard's body
/// treats the initial state as if `CLK` had been TRUE before).
///
/// ```
/// use il_std::{Cycle, F_TRIG};
/// let mut ctx = Cycle::new();
/// let mut f = F_TRIG::default();
/// f.call(&mut ctx);
/// assert!(f.Q);          // first call with CLK FALSE: TRUE, as the standard's body says
/// f.call(&mut ctx);
/// assert!(!f.Q);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct F_TRIG {
    /// Input: the signal watched.
    pub CLK: bool,
    /// Output: TRUE for one call on a falling edge of `CLK`.
    pub Q: bool,
    M: bool,
}

impl F_TRIG {
    /// A fresh instance: everything FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            CLK: false,
            Q: false,
            M: false,
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        self.Q = !self.CLK && !self.M;
        self.M = !self.CLK;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run_r(seq: &[bool]) -> std::vec::Vec<bool> {
        let mut c = Cycle::new();
        let mut b = R_TRIG::default();
        seq.iter()
            .map(|&clk| {
                b.CLK = clk;
                b.call(&mut c);
                b.Q
            })
            .collect()
    }
    fn run_f(seq: &[bool]) -> std::vec::Vec<bool> {
        let mut c = Cycle::new();
        let mut b = F_TRIG::default();
        seq.iter()
            .map(|&clk| {
                b.CLK = clk;
                b.call(&mut c);
                b.Q
            })
            .collect()
    }

    #[test]
    fn r_trig() {
        assert_eq!(
            run_r(&[true, true, false, true, false]),
            [true, false, false, true, false]
        );
        assert_eq!(run_r(&[false, false, true]), [false, false, true]);
        // Toggling every call: an edge every other call.
        assert_eq!(
            run_r(&[false, true, false, true]),
            [false, true, false, true]
        );
    }

    #[test]
    fn f_trig() {
        // First call with CLK FALSE: TRUE (literal body of the standard).
        assert_eq!(
            run_f(&[false, false, true, false]),
            [true, false, false, true]
        );
        // First call with CLK TRUE: no edge; then a real falling edge.
        assert_eq!(
            run_f(&[true, true, false, false, true]),
            [false, false, true, false, false]
        );
    }
}
