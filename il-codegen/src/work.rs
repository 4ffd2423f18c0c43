//! A count of the front end's elementary steps on this thread: lexer steps,
//! columns counted, instructions checked, edges joined at labels,
//! suggestion distances, lines of an XML body mapped, lines of a generated
//! file written, tree steps of the emitter's block structure; in the PLCopen
//! import: XML children visited, attributes checked, pieces of IL text
//! written (copied or generated), candidates compared when a POU left out is
//! looked up by name and pieces compared when the span map is searched;
//! types resolved for the nesting check (once each). The scaling tests (`tests/all/scaling.rs`, the PLCopen limits)
//! compare it at n and 8n: unlike a time ratio it is the same on a busy
//! machine, and a stage whose work grows faster than its input shows up in
//! it as it would in the time. Counting is one thread-local add per step
//! (not per byte), below measurement on the front-end benchmarks.

use std::cell::Cell;

thread_local! {
    static STEPS: Cell<u64> = const { Cell::new(0) };
}

/// Count `n` steps.
#[inline]
pub(crate) fn add(n: u64) {
    STEPS.with(|s| s.set(s.get().wrapping_add(n)));
}

/// The steps counted on this thread so far (compare two readings).
pub fn steps() -> u64 {
    STEPS.with(Cell::get)
}
