//! The standard function blocks of IEC 61131-3 (bistables, edge detection, counters, timers,
//! real-time clock), and in [`m221`] the vendor blocks of the Modicon M221.
//!
//! Every block is a plain struct with its IEC inputs and outputs as `pub` UPPERCASE fields and
//! private internal state, and a `call(&mut self, ctx: &mut Cycle)` that runs its body once.
//! Set the inputs, call, read the outputs — exactly what `CAL` does in IL.

use crate::cycle::Cycle;

mod bistable;
mod counters;
mod edge;
pub mod m221;
mod timers;

// Every block of the modules; the crate root re-exports those of the table
// (`std_function_blocks!`), which a test proves all exist.
pub use bistable::*;
pub use counters::*;
pub use edge::*;
pub use m221::*;
pub use timers::*;

/// A function block: something with state that is invoked once per `CAL`.
pub trait FunctionBlock {
    /// Runs the block's body once with the current inputs; `ctx` supplies the time.
    fn call(&mut self, ctx: &mut Cycle);
}

/// `impl FunctionBlock` for every block of the table.
macro_rules! impl_fb {
    ($( $t:ident $inputs:tt -> $outputs:tt; )*) => {
        $(impl FunctionBlock for $t {
            fn call(&mut self, ctx: &mut Cycle) {
                $t::call(self, ctx)
            }
        })*
    };
}
crate::std_function_blocks!(impl_fb);
