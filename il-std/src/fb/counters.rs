//! Counters CTU, CTD, CTUD and their typed variants (_INT, _DINT, _LINT, _UDINT, _ULINT).
//!
//! `CU`/`CD` are declared `R_EDGE` by the standard: the block itself detects their rising edge
//! (its edge memory starts FALSE, so a TRUE `CU` on the first call counts). Counting stops at the
//! bounds of the counter's type (no wrap), which is the standard's `PVmax`/`PVmin`.

use crate::cycle::Cycle;

/// `v <= 0` for signed and unsigned counter types alike.
fn le_zero<T: Default + PartialOrd>(v: T) -> bool {
    v <= T::default()
}

macro_rules! counters {
    ($ctu:ident, $ctd:ident, $ctud:ident, $t:ty, $tn:literal) => {
        #[doc = concat!("`", stringify!($ctu), "`: up counter with `PV`/`CV` of type `", $tn, "`.")]
        ///
        /// Body: if `R` then `CV := 0`, else on a rising edge of `CU` `CV := CV + 1` while `CV` is
        /// below the type's maximum; then `Q := CV >= PV`. IL input operators: `CU`, `R`, `PV`.
        ///
        /// ```
        #[doc = concat!("use il_std::{Cycle, ", stringify!($ctu), "};")]
        /// let mut ctx = Cycle::new();
        #[doc = concat!("let mut c = ", stringify!($ctu), "::new();")]
        /// c.PV = 2;
        /// for cu in [true, false, true] { c.CU = cu; c.call(&mut ctx); }
        /// assert_eq!((c.CV, c.Q), (2, true));
        /// ```
        #[derive(Clone, Debug, Default, PartialEq)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub struct $ctu {
            /// Input: count up on its rising edge.
            pub CU: bool,
            /// Input: reset `CV` to 0 (has priority over counting).
            pub R: bool,
            /// Input: preset value compared with `CV`.
            pub PV: $t,
            /// Output: `CV >= PV`.
            pub Q: bool,
            /// Output: the current count.
            pub CV: $t,
            cu_m: bool,
        }

        impl $ctu {
            /// A fresh instance: all inputs, outputs and memory zero/FALSE (same as `Default`).
            pub const fn new() -> Self {
                Self { CU: false, R: false, PV: 0, Q: false, CV: 0, cu_m: false }
            }
            /// Runs the block body once.
            pub fn call(&mut self, _ctx: &mut Cycle) {
                let cu = self.CU && !self.cu_m;
                self.cu_m = self.CU;
                if self.R {
                    self.CV = 0;
                } else if cu && self.CV < <$t>::MAX {
                    self.CV = self.CV.wrapping_add(1);
                }
                self.Q = self.CV >= self.PV;
            }
        }

        #[doc = concat!("`", stringify!($ctd), "`: down counter with `PV`/`CV` of type `", $tn, "`.")]
        ///
        /// Body: if `LD` then `CV := PV`, else on a rising edge of `CD` `CV := CV - 1` while `CV`
        /// is above the type's minimum; then `Q := CV <= 0`. IL input operators: `CD`, `LD`, `PV`.
        ///
        /// ```
        #[doc = concat!("use il_std::{Cycle, ", stringify!($ctd), "};")]
        /// let mut ctx = Cycle::new();
        #[doc = concat!("let mut c = ", stringify!($ctd), "::new();")]
        /// c.PV = 1;
        /// c.LD = true;
        /// c.call(&mut ctx);              // loads CV := 1
        /// c.LD = false; c.CD = true;
        /// c.call(&mut ctx);              // counts down to 0
        /// assert_eq!((c.CV, c.Q), (0, true));
        /// ```
        #[derive(Clone, Debug, Default, PartialEq)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub struct $ctd {
            /// Input: count down on its rising edge.
            pub CD: bool,
            /// Input: load `CV := PV` (has priority over counting).
            pub LD: bool,
            /// Input: preset value loaded by `LD`.
            pub PV: $t,
            /// Output: `CV <= 0`.
            pub Q: bool,
            /// Output: the current count.
            pub CV: $t,
            cd_m: bool,
        }

        impl $ctd {
            /// A fresh instance: all inputs, outputs and memory zero/FALSE (same as `Default`).
            pub const fn new() -> Self {
                Self { CD: false, LD: false, PV: 0, Q: false, CV: 0, cd_m: false }
            }
            /// Runs the block body once.
            pub fn call(&mut self, _ctx: &mut Cycle) {
                let cd = self.CD && !self.cd_m;
                self.cd_m = self.CD;
                if self.LD {
                    self.CV = self.PV;
                } else if cd && self.CV > <$t>::MIN {
                    self.CV = self.CV.wrapping_sub(1);
                }
                self.Q = le_zero(self.CV);
            }
        }

        #[doc = concat!("`", stringify!($ctud), "`: up-down counter with `PV`/`CV` of type `", $tn, "`.")]
        ///
        /// Body, by priority: if `R` then `CV := 0`; else if `LD` then `CV := PV`; else, unless
        /// `CU` and `CD` rise in the same call (then nothing counts), a rising `CU` increments `CV`
        /// below the type's maximum, or a rising `CD` decrements it above the type's minimum.
        /// Then `QU := CV >= PV` and `QD := CV <= 0`. IL input operators: `CU`, `CD`, `R`, `LD`,
        /// `PV`.
        ///
        /// ```
        #[doc = concat!("use il_std::{Cycle, ", stringify!($ctud), "};")]
        /// let mut ctx = Cycle::new();
        #[doc = concat!("let mut c = ", stringify!($ctud), "::new();")]
        /// c.PV = 1;
        /// c.CU = true;
        /// c.call(&mut ctx);
        /// assert_eq!((c.CV, c.QU, c.QD), (1, true, false));
        /// ```
        #[derive(Clone, Debug, Default, PartialEq)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub struct $ctud {
            /// Input: count up on its rising edge.
            pub CU: bool,
            /// Input: count down on its rising edge.
            pub CD: bool,
            /// Input: reset `CV := 0` (highest priority).
            pub R: bool,
            /// Input: load `CV := PV` (priority over counting).
            pub LD: bool,
            /// Input: preset value.
            pub PV: $t,
            /// Output: `CV >= PV`.
            pub QU: bool,
            /// Output: `CV <= 0`.
            pub QD: bool,
            /// Output: the current count.
            pub CV: $t,
            cu_m: bool,
            cd_m: bool,
        }

        impl $ctud {
            /// A fresh instance: all inputs, outputs and memory zero/FALSE (same as `Default`).
            pub const fn new() -> Self {
                Self {
                    CU: false, CD: false, R: false, LD: false, PV: 0,
                    QU: false, QD: false, CV: 0, cu_m: false, cd_m: false,
                }
            }
            /// Runs the block body once.
            pub fn call(&mut self, _ctx: &mut Cycle) {
                let cu = self.CU && !self.cu_m;
                let cd = self.CD && !self.cd_m;
                self.cu_m = self.CU;
                self.cd_m = self.CD;
                if self.R {
                    self.CV = 0;
                } else if self.LD {
                    self.CV = self.PV;
                } else if !(cu && cd) {
                    if cu && self.CV < <$t>::MAX {
                        self.CV = self.CV.wrapping_add(1);
                    } else if cd && self.CV > <$t>::MIN {
                        self.CV = self.CV.wrapping_sub(1);
                    }
                }
                self.QU = self.CV >= self.PV;
                self.QD = le_zero(self.CV);
            }
        }
    };
}

counters!(CTU, CTD, CTUD, i16, "INT");
// The 3rd edition names the INT counters too; they are CTU/CTD/CTUD under
// their own names (own types, so that each name is one table row).
counters!(CTU_INT, CTD_INT, CTUD_INT, i16, "INT");
counters!(CTU_DINT, CTD_DINT, CTUD_DINT, i32, "DINT");
counters!(CTU_LINT, CTD_LINT, CTUD_LINT, i64, "LINT");
counters!(CTU_UDINT, CTD_UDINT, CTUD_UDINT, u32, "UDINT");
counters!(CTU_ULINT, CTD_ULINT, CTUD_ULINT, u64, "ULINT");

#[cfg(test)]
mod tests {
    use super::*;

    fn pulse_ctu(c: &mut CTU, ctx: &mut Cycle, n: usize) {
        for _ in 0..n {
            c.CU = true;
            c.call(ctx);
            c.CU = false;
            c.call(ctx);
        }
    }

    #[test]
    fn ctu_counts_edges_only() {
        let mut ctx = Cycle::new();
        let mut c = CTU {
            PV: 3,
            ..Default::default()
        };
        c.CU = true;
        c.call(&mut ctx); // first call with CU TRUE is an edge
        assert_eq!((c.CV, c.Q), (1, false));
        c.call(&mut ctx); // held: no count
        c.call(&mut ctx);
        assert_eq!(c.CV, 1);
        c.CU = false;
        c.call(&mut ctx);
        pulse_ctu(&mut c, &mut ctx, 2);
        assert_eq!((c.CV, c.Q), (3, true));
        pulse_ctu(&mut c, &mut ctx, 2); // counts past PV
        assert_eq!((c.CV, c.Q), (5, true));
        c.R = true;
        c.CU = true;
        c.call(&mut ctx); // reset has priority over an edge
        assert_eq!((c.CV, c.Q), (0, false));
        c.R = false;
        c.call(&mut ctx); // CU still TRUE: the edge was consumed while R was TRUE
        assert_eq!(c.CV, 0);
    }

    #[test]
    fn ctu_stops_at_type_max() {
        let mut ctx = Cycle::new();
        let mut c = CTU {
            PV: i16::MAX,
            CV: i16::MAX - 1,
            ..Default::default()
        };
        pulse_ctu(&mut c, &mut ctx, 3);
        assert_eq!((c.CV, c.Q), (i16::MAX, true));
        let mut u = CTU_ULINT {
            CV: u64::MAX,
            PV: 0,
            CU: true,
            ..Default::default()
        };
        u.call(&mut ctx);
        assert_eq!((u.CV, u.Q), (u64::MAX, true));
        let mut d = CTU_DINT {
            CV: i32::MAX,
            CU: true,
            ..Default::default()
        };
        d.call(&mut ctx);
        assert_eq!(d.CV, i32::MAX);
        let mut l = CTU_LINT {
            CV: i64::MAX,
            CU: true,
            ..Default::default()
        };
        l.call(&mut ctx);
        assert_eq!(l.CV, i64::MAX);
        let mut ud = CTU_UDINT {
            CV: u32::MAX,
            CU: true,
            ..Default::default()
        };
        ud.call(&mut ctx);
        assert_eq!(ud.CV, u32::MAX);
    }

    #[test]
    fn ctu_pv_zero_and_negative() {
        let mut ctx = Cycle::new();
        let mut c = CTU::default();
        c.call(&mut ctx);
        assert!(c.Q); // CV 0 >= PV 0
        c.PV = -5;
        c.call(&mut ctx);
        assert!(c.Q);
    }

    #[test]
    fn ctd_load_and_count() {
        let mut ctx = Cycle::new();
        let mut c = CTD {
            PV: 2,
            LD: true,
            ..Default::default()
        };
        c.call(&mut ctx);
        assert_eq!((c.CV, c.Q), (2, false));
        c.LD = false;
        for expect in [1, 0, -1, -2] {
            c.CD = true;
            c.call(&mut ctx);
            c.CD = false;
            c.call(&mut ctx);
            assert_eq!((c.CV, c.Q), (expect, expect <= 0));
        }
        // LD has priority over an edge.
        c.LD = true;
        c.CD = true;
        c.call(&mut ctx);
        assert_eq!(c.CV, 2);
    }

    #[test]
    fn ctd_stops_at_type_min() {
        let mut ctx = Cycle::new();
        let mut c = CTD {
            CV: i16::MIN + 1,
            ..Default::default()
        };
        for _ in 0..3 {
            c.CD = true;
            c.call(&mut ctx);
            c.CD = false;
            c.call(&mut ctx);
        }
        assert_eq!((c.CV, c.Q), (i16::MIN, true));
        let mut u = CTD_UDINT {
            CD: true,
            ..Default::default()
        };
        u.call(&mut ctx);
        assert_eq!((u.CV, u.Q), (0, true));
        let mut u = CTD_ULINT {
            CD: true,
            PV: 1,
            ..Default::default()
        };
        u.call(&mut ctx);
        assert_eq!(u.CV, 0);
        let mut l = CTD_LINT {
            CD: true,
            CV: i64::MIN,
            ..Default::default()
        };
        l.call(&mut ctx);
        assert_eq!(l.CV, i64::MIN);
        let mut d = CTD_DINT {
            CD: true,
            CV: i32::MIN,
            ..Default::default()
        };
        d.call(&mut ctx);
        assert_eq!(d.CV, i32::MIN);
    }

    #[test]
    fn ctud_priorities_and_simultaneous_edges() {
        let mut ctx = Cycle::new();
        let mut c = CTUD {
            PV: 2,
            ..Default::default()
        };
        c.call(&mut ctx);
        assert_eq!((c.CV, c.QU, c.QD), (0, false, true));
        // CU and CD rise together: nothing counts.
        c.CU = true;
        c.CD = true;
        c.call(&mut ctx);
        assert_eq!(c.CV, 0);
        // CD falls and CU stays high: no new edge on CU, nothing counts.
        c.CD = false;
        c.call(&mut ctx);
        assert_eq!(c.CV, 0);
        c.CU = false;
        c.call(&mut ctx);
        c.CU = true;
        c.call(&mut ctx);
        assert_eq!((c.CV, c.QU, c.QD), (1, false, false));
        c.CU = false;
        c.call(&mut ctx);
        c.CU = true;
        c.call(&mut ctx);
        assert_eq!((c.CV, c.QU, c.QD), (2, true, false));
        c.CU = false;
        c.CD = true;
        c.call(&mut ctx);
        assert_eq!(c.CV, 1);
        // R beats LD.
        c.R = true;
        c.LD = true;
        c.call(&mut ctx);
        assert_eq!(c.CV, 0);
        c.R = false;
        c.call(&mut ctx);
        assert_eq!((c.CV, c.QU), (2, true));
        // LD beats counting.
        c.CD = false;
        c.call(&mut ctx);
        c.CD = true;
        c.call(&mut ctx);
        assert_eq!(c.CV, 2);
    }

    #[test]
    fn int_counters_are_ctu_ctd_ctud_under_their_3rd_edition_names() {
        let mut ctx = Cycle::new();
        let (mut a, mut b) = (CTU::new(), CTU_INT::new());
        let (mut c, mut d) = (CTD::new(), CTD_INT::new());
        let (mut e, mut f) = (CTUD::new(), CTUD_INT::new());
        (a.PV, b.PV, c.PV, d.PV, e.PV, f.PV) = (2, 2, 1, 1, 2, 2);
        (a.CV, b.CV) = (i16::MAX - 1, i16::MAX - 1);
        for k in 0..8 {
            let edge = k % 2 == 0;
            (a.CU, b.CU, e.CU, f.CU) = (edge, edge, edge, edge);
            (c.LD, d.LD) = (k == 0, k == 0);
            (c.CD, d.CD, e.CD, f.CD) = (edge, edge, k > 4, k > 4);
            for x in [
                &mut a as &mut dyn crate::FunctionBlock,
                &mut b,
                &mut c,
                &mut d,
                &mut e,
                &mut f,
            ] {
                x.call(&mut ctx);
            }
            assert_eq!((a.CV, a.Q), (b.CV, b.Q));
            assert_eq!((c.CV, c.Q), (d.CV, d.Q));
            assert_eq!((e.CV, e.QU, e.QD), (f.CV, f.QU, f.QD));
        }
        assert_eq!(b.CV, i16::MAX);
        assert_eq!(d.CV, -2);
    }

    #[test]
    fn ctud_bounds() {
        let mut ctx = Cycle::new();
        let mut c = CTUD_UDINT {
            CD: true,
            ..Default::default()
        };
        c.call(&mut ctx);
        assert_eq!((c.CV, c.QD), (0, true));
        let mut c = CTUD {
            CU: true,
            CV: i16::MAX,
            ..Default::default()
        };
        c.call(&mut ctx);
        assert_eq!(c.CV, i16::MAX);
        let mut c = CTUD_LINT {
            CD: true,
            CV: i64::MIN,
            ..Default::default()
        };
        c.call(&mut ctx);
        assert_eq!(c.CV, i64::MIN);
        let mut c = CTUD_ULINT {
            CU: true,
            CV: u64::MAX,
            PV: u64::MAX,
            ..Default::default()
        };
        c.call(&mut ctx);
        assert_eq!((c.CV, c.QU), (u64::MAX, true));
        let mut c = CTUD_DINT {
            CU: true,
            ..Default::default()
        };
        c.call(&mut ctx);
        assert_eq!(c.CV, 1);
    }
}
