//! Bistable elements SR (set dominant) and RS (reset dominant).

use crate::cycle::Cycle;

/// `SR`: set-dominant bistable. `Q1 := S1 OR (NOT R AND Q1)`.
///
/// When `S1` and `R` are both TRUE, `Q1` becomes TRUE (set wins). IL input operators: `S1`, `R`.
///
/// ```
/// use il_std::{Cycle, SR};
/// let mut ctx = Cycle::new();
/// let mut sr = SR::new();
/// sr.S1 = true;
/// sr.R = true;
/// sr.call(&mut ctx);
/// assert!(sr.Q1);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SR {
    /// Input: set (dominant).
    pub S1: bool,
    /// Input: reset.
    pub R: bool,
    /// Output: the stored bit.
    pub Q1: bool,
}

impl SR {
    /// A fresh instance: everything FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            S1: false,
            R: false,
            Q1: false,
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        self.Q1 = self.S1 || (!self.R && self.Q1);
    }
}

/// `RS`: reset-dominant bistable. `Q1 := NOT R1 AND (S OR Q1)`.
///
/// When `S` and `R1` are both TRUE, `Q1` becomes FALSE (reset wins). IL input operators: `S`, `R1`.
///
/// ```
/// use il_std::{Cycle, RS};
/// let mut ctx = Cycle::new();
/// let mut rs = RS::new();
/// rs.S = true;
/// rs.R1 = true;
/// rs.call(&mut ctx);
/// assert!(!rs.Q1);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RS {
    /// Input: set.
    pub S: bool,
    /// Input: reset (dominant).
    pub R1: bool,
    /// Output: the stored bit.
    pub Q1: bool,
}

impl RS {
    /// A fresh instance: everything FALSE (same as `Default`).
    pub const fn new() -> Self {
        Self {
            S: false,
            R1: false,
            Q1: false,
        }
    }

    /// Runs the block body once.
    pub fn call(&mut self, _ctx: &mut Cycle) {
        self.Q1 = !self.R1 && (self.S || self.Q1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sr_truth_table() {
        let mut c = Cycle::new();
        let mut b = SR::default();
        // (S1, R, expected Q1) in sequence, starting from Q1 = FALSE.
        for (s, r, q) in [
            (false, false, false),
            (false, true, false),
            (true, false, true),
            (false, false, true), // holds
            (true, true, true),   // set dominates
            (false, true, false),
            (false, false, false),
            (true, true, true),
        ] {
            b.S1 = s;
            b.R = r;
            b.call(&mut c);
            assert_eq!(b.Q1, q, "S1={s} R={r}");
        }
    }

    #[test]
    fn rs_truth_table() {
        let mut c = Cycle::new();
        let mut b = RS::default();
        for (s, r, q) in [
            (false, false, false),
            (true, false, true),
            (false, false, true), // holds
            (true, true, false),  // reset dominates
            (true, false, true),
            (false, true, false),
            (false, false, false),
        ] {
            b.S = s;
            b.R1 = r;
            b.call(&mut c);
            assert_eq!(b.Q1, q, "S={s} R1={r}");
        }
    }
}
