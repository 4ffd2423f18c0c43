//! The body's place table ([`ir::CheckedPou::places`]): reads and stores
//! name their place by index, and a place without subscripts is kept once
//! however often the body uses it.

use super::*;
use crate::sema::ir::{PathElem, Root};

/// What makes two places without subscripts the same place (the root and
/// the steps decide the type and the range too).
#[derive(PartialEq, Eq, Hash)]
pub(super) struct PlaceKey {
    root: RootKey,
    path: Vec<StepKey>,
}

#[derive(PartialEq, Eq, Hash)]
enum RootKey {
    Var(usize),
    Ret,
}

#[derive(PartialEq, Eq, Hash)]
enum StepKey {
    Field(String),
    Part(Elem, u32),
}

impl PlaceKey {
    /// The key of `p`; `None` for a place with subscripts (their values
    /// may differ between uses) or of the process image (rare).
    fn of(p: &Place) -> Option<PlaceKey> {
        let root = match p.root {
            Root::Var(i) => RootKey::Var(i),
            Root::Ret => RootKey::Ret,
            Root::Addr(_) => return None,
        };
        let path = p
            .path
            .iter()
            .map(|e| match e {
                PathElem::Field(f) => Some(StepKey::Field(f.clone())),
                PathElem::Part { part, index, .. } => Some(StepKey::Part(*part, *index)),
                PathElem::Index { .. } => None,
            })
            .collect::<Option<Vec<_>>>()?;
        Some(PlaceKey { root, path })
    }
}

impl Walk<'_, '_> {
    /// The index of `p` in the body's place table, added unless an equal
    /// place without subscripts is there already.
    pub(super) fn place_id(&mut self, p: Place) -> u32 {
        let key = PlaceKey::of(&p);
        if let Some(k) = &key
            && let Some(&i) = self.place_ids.get(k)
        {
            return i;
        }
        // A body has at most a few places per instruction, and a file is
        // far below 4 GiB of instructions.
        let i = self.places.len() as u32;
        self.places.push(p);
        if let Some(k) = key {
            self.place_ids.insert(k, i);
        }
        i
    }
}
