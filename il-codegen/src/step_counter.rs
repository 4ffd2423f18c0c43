//! The front end's step counter: how many elementary steps it has taken on
//! this thread, for measuring how its work grows with its input. Compiling
//! never reads it; this crate's scaling tests do (`tests/all/scaling.rs` and
//! the PLCopen limits): they read [`steps`] before and after a run at n and
//! at 8n and compare. Unlike a time ratio the count is the same on a busy
//! machine, and a stage whose work grows faster than its input shows up in
//! it as it would in the time.
//!
//! A step is one of: a lexer step, a column counted, an instruction checked,
//! an edge joined at a label, a suggestion distance, a line of an XML body
//! mapped, a line of a generated file written, a tree step of the emitter's
//! block structure; in the PLCopen import: an XML child visited, an
//! attribute checked, a piece of IL text written (copied or generated), a
//! candidate compared when a POU left out is looked up by name and a piece
//! compared when the span map is searched; a type resolved for the nesting
//! check (once each). Counting is one thread-local add per step (not per
//! byte), below measurement on the front-end benchmarks.

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
