//! The standard function blocks of IEC 61131-3 (bistables, edge detection, counters, timers,
//! real-time clock).
//!
//! Every block is a plain struct with its IEC inputs and outputs as `pub` UPPERCASE fields and
//! private internal state, and a `call(&mut self, ctx: &mut Cycle)` that runs its body once.
//! Set the inputs, call, read the outputs — exactly what `CAL` does in IL.

use crate::cycle::Cycle;

mod bistable;
mod counters;
mod edge;
mod timers;

pub use bistable::{RS, SR};
pub use counters::{
    CTD, CTD_DINT, CTD_LINT, CTD_UDINT, CTD_ULINT, CTU, CTU_DINT, CTU_LINT, CTU_UDINT, CTU_ULINT,
    CTUD, CTUD_DINT, CTUD_LINT, CTUD_UDINT, CTUD_ULINT,
};
pub use edge::{F_TRIG, R_TRIG};
pub use timers::{RTC, TOF, TON, TP};

/// A function block: something with state that is invoked once per `CAL`.
pub trait FunctionBlock {
    /// Runs the block's body once with the current inputs; `ctx` supplies the time.
    fn call(&mut self, ctx: &mut Cycle);
}

macro_rules! impl_fb {
    ($($t:ident),* $(,)?) => {
        $(impl FunctionBlock for $t {
            fn call(&mut self, ctx: &mut Cycle) {
                $t::call(self, ctx)
            }
        })*
    };
}
impl_fb!(
    SR, RS, R_TRIG, F_TRIG, CTU, CTU_DINT, CTU_LINT, CTU_UDINT, CTU_ULINT, CTD, CTD_DINT, CTD_LINT,
    CTD_UDINT, CTD_ULINT, CTUD, CTUD_DINT, CTUD_LINT, CTUD_UDINT, CTUD_ULINT, TP, TON, TOF, RTC
);
