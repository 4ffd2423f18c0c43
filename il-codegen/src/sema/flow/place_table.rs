//! The body's place table ([`ir::CheckedPou::places`]): reads and stores
//! name their place by index, and a place without subscripts is kept once
//! however often the body uses it.

use super::*;
use std::hash::{Hash, Hasher};

/// A hash of what makes a place without subscripts itself (its root and
/// steps; they decide its type and range), computed without allocating:
/// the lookup runs for every operand of every round. `None` for a place
/// with subscripts (their values may differ between uses) or of the
/// process image (rare): those are not shared.
fn key(p: &Place) -> Option<u64> {
    let mut h = rustc_hash::FxHasher::default();
    match p.root {
        Root::Var(i) => i.hash(&mut h),
        Root::Ret => usize::MAX.hash(&mut h),
        Root::Addr(_) => return None,
    }
    for e in &p.path {
        match e {
            PathElem::Field(f) => f.hash(&mut h),
            PathElem::Part { part, index, .. } => (part, index).hash(&mut h),
            PathElem::Index { .. } => return None,
        }
    }
    Some(h.finish())
}

impl Walk<'_, '_> {
    /// The index of `p` in the body's place table, added unless an equal
    /// place without subscripts is there already.
    pub(super) fn place_id(&mut self, p: Place) -> u32 {
        let key = key(&p);
        if let Some(k) = key
            && let Some(&i) = self.place_ids.get(&k)
            && self.places[i as usize] == p
        {
            return i;
        }
        // A body has at most a few places per instruction, and a file is
        // far below 4 GiB of instructions.
        let i = self.places.len() as u32;
        self.places.push(p);
        // On a collision the first place keeps the entry; the other is
        // only not shared.
        if let Some(k) = key {
            self.place_ids.entry(k).or_insert(i);
        }
        i
    }
}
