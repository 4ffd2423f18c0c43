//! What the RETAIN snapshot of a FUNCTION_BLOCK or PROGRAM holds.

use crate::ast::{PouKind, VarKind};
use crate::ir::Retained;
use crate::sema::env::{Env, PouSig};
use crate::sema::types::Ty;

/// The variables of an FB/PROGRAM that its RETAIN snapshot holds.
pub(crate) fn retained(env: &Env, sig: &PouSig) -> Vec<(usize, Retained)> {
    if sig.kind == PouKind::Function {
        return Vec::new();
    }
    sig.vars
        .iter()
        .enumerate()
        .filter(|(_, v)| {
            matches!(v.kind, VarKind::Var | VarKind::Input | VarKind::Output)
                && v.location.is_none()
        })
        .filter_map(|(i, v)| {
            if v.retain {
                return Some((i, Retained::Whole));
            }
            let fb = instance_of(&v.ty)?;
            holds_retain(env, fb, 0).then_some((i, Retained::Nested))
        })
        .collect()
}

/// The FB type of an instance variable (or of an array of instances).
fn instance_of(mut t: &Ty) -> Option<&str> {
    while let Ty::Array(a) = t {
        t = &a.elem;
    }
    match t {
        Ty::Fb(fb) => Some(fb),
        _ => None,
    }
}

/// Whether an instance of `fb` holds a RETAIN variable at any depth.
/// Memoised per FB in `env`, so each FB is looked at once however often its
/// instances repeat; a cycle (an FB holding itself, refused elsewhere) and
/// nesting past the depth bound count as holding nothing.
fn holds_retain(env: &Env, fb: &str, depth: u32) -> bool {
    let key = fb.to_ascii_uppercase();
    if let Some(&known) = env.holds_retain.borrow().get(&key) {
        return known;
    }
    let Some(sig) = env.pou(fb) else { return false };
    if sig.kind == PouKind::Function || depth > 256 {
        return false;
    }
    // In progress: a cycle back here adds nothing.
    env.holds_retain.borrow_mut().insert(key.clone(), false);
    let found = sig
        .vars
        .iter()
        .filter(|v| {
            matches!(v.kind, VarKind::Var | VarKind::Input | VarKind::Output)
                && v.location.is_none()
        })
        .any(|v| {
            v.retain || instance_of(&v.ty).is_some_and(|inner| holds_retain(env, inner, depth + 1))
        });
    env.holds_retain.borrow_mut().insert(key, found);
    found
}
