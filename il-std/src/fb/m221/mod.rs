//! Function-block objects of Schneider's Modicon M221 (Machine Expert Basic / SoMachine Basic)
//! and Twido controllers that have no IEC 61131-3 counterpart: the drum `%DRn`, the FIFO/LIFO
//! registers `%Rn`, the shift bit register `%SBRn` and the step counter `%SCn`; and the
//! system bits the controller sets (`%S0`, the clocks `%S4` .. `%S7`, `%S13`): `M221_SYS`.
//!
//! They are vendor blocks, kept apart from the standard ones by their `M221_` prefix: an IEC
//! program can still declare them, which is how the M221 importer uses them (one instance per
//! object, its configuration written into the instance's configuration inputs). Each module
//! says which of its rules are the manual's and which are this crate's choice where the manual
//! is silent (docs/semantics.md, "Modicon M221 dialect", lists the same).
//!
//! Conventions shared by the four: the inputs the manual calls edge inputs (`U`, `I`, `O`,
//! `CU`, `CD`) act on a rising edge the block detects itself, with its edge memory starting
//! FALSE (a TRUE input on the first call is an edge, as for IEC's `R_TRIG`); the reset `R` is a
//! level and has priority over everything else in the same call. An object member the manual
//! lets the program write (`%DRn.S`, `%Rn.I`, `%Rn.O`, `%SBRn.j`, `%SCn.j`) is an *input* field
//! that the block also updates, so the checker lets the program store to it.

mod counter;
mod drum;
mod register;
mod shift_bit;
mod step_counter;
mod system;

pub use counter::M221_C;
pub use drum::M221_DR;
pub use register::{M221_FIFO, M221_LIFO};
pub use shift_bit::M221_SBR;
pub use step_counter::M221_SC;
pub use system::M221_SYS;

/// `true` once per rising edge of `input`, with `mem` the previous value.
fn rising(input: bool, mem: &mut bool) -> bool {
    let r = input && !*mem;
    *mem = input;
    r
}
