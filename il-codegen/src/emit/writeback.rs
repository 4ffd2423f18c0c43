//! Where each cached variable (see [`PouEmitter::cached`]) is written back
//! to `self`.
//!
//! A cached variable lives in a local for the call. Written back only at
//! the end of the call, its local stays live across every later FB call,
//! whose callee LLVM cannot see through: the value is kept in a
//! callee-saved register or spilled around the call, and the store cannot
//! go before the call either (the callee might read `self`, as far as LLVM
//! knows). Written back right after its last store in the body instead, at
//! a point every path through the body crosses, the local dies there.
//! A variable the body never stores is not written back at all: its field
//! still holds the value loaded on entry.

use super::text::Out;
use super::{PouEmitter, names, rust_ident};
use crate::ir::{Expr, Op, Place, Root, Stmt};

/// The body's write-backs: `at[p]` are the variables written back before
/// statement `p` of the body (`p == len`: at the end, after `'__body`).
pub(crate) struct WriteBacks {
    pub(crate) at: Vec<Vec<usize>>,
}

impl WriteBacks {
    /// The write-backs before statement `p` (none past the end).
    pub(crate) fn before(&self, p: usize) -> &[usize] {
        self.at.get(p).map_or(&[], Vec::as_slice)
    }
}

/// The variables `s` stores to (in any way: a store, S/R, an FB output, an
/// in-out binding, a function's `=>` output): `written(i)` is called for each.
pub(crate) fn stores(pou: &crate::ir::CheckedPou, s: &Stmt, written: &mut impl FnMut(usize)) {
    let mut place = |p: &Place| {
        if let Root::Var(i) = p.root {
            written(i)
        }
    };
    match &s.op {
        Op::Store { place: p, .. } | Op::SetIf { place: p, .. } => place(pou.place(*p)),
        Op::CallFb(c) => {
            place(&c.inst);
            c.outputs.iter().for_each(|(_, p, _, _)| place(p));
            c.inouts.iter().for_each(|(_, p)| place(p));
        }
        Op::SetCr {
            expr: Expr::CallUser(c),
            ..
        } => {
            c.outputs.iter().for_each(|(_, p, _, _)| place(p));
            c.inouts.iter().for_each(&mut place);
        }
        _ => {}
    }
}

impl PouEmitter<'_> {
    /// The write-back points of a body emitted with `regions` (`[lo, hi)`
    /// of its labelled blocks and loops; none for straight-line code).
    /// `None` (the dispatcher) and a body with a `RET` (which leaves
    /// `'__body` from anywhere) write every variable back at the end.
    pub(crate) fn write_backs(
        &self,
        stmts: &[Stmt],
        regions: Option<&[(usize, usize)]>,
    ) -> WriteBacks {
        let n = stmts.len();
        let vars = self.pou.vars.len();
        let mut last_store: Vec<Option<usize>> = vec![None; vars];
        for (k, s) in stmts.iter().enumerate() {
            stores(self.pou, s, &mut |i| {
                if i < vars {
                    last_store[i] = Some(k)
                }
            });
        }
        let has_return = stmts.iter().any(|s| matches!(s.op, Op::Return { .. }));
        let mut at = vec![Vec::new(); n + 1];
        for (i, last) in last_store.iter().enumerate() {
            let Some(k) = *last else { continue };
            if !self.cached(i) {
                continue;
            }
            let p = match regions {
                Some(rs) if !has_return => lift(k + 1, rs),
                _ => n,
            };
            at[p].push(i);
        }
        WriteBacks { at }
    }

    /// `self.x = __s_x;` for each of `vars`.
    pub(crate) fn write_back(&self, o: &mut Out, vars: &[usize]) {
        for &i in vars {
            let name = &self.pou.vars[i].name;
            let (id, l) = (rust_ident(name), names::cache_ident(name));
            o.code(&format!("self.{id} = {l};"));
        }
    }
}

/// The first point at or after `p` that lies inside no region (`lo < p <
/// hi`): control passes there only from the statement before it, and every
/// path from the body's start to its end passes there.
fn lift(mut p: usize, regions: &[(usize, usize)]) -> usize {
    while let Some(hi) = regions
        .iter()
        .filter(|&&(lo, hi)| lo < p && p < hi)
        .map(|&(_, hi)| hi)
        .max()
    {
        p = hi;
    }
    p
}

#[cfg(test)]
mod tests {
    use super::lift;

    #[test]
    fn a_point_inside_regions_moves_past_the_outermost() {
        let rs = [(2, 10), (4, 6), (12, 14)];
        assert_eq!(lift(1, &rs), 1);
        assert_eq!(lift(2, &rs), 2);
        assert_eq!(lift(5, &rs), 10);
        assert_eq!(lift(3, &rs), 10);
        assert_eq!(lift(10, &rs), 10);
        assert_eq!(lift(13, &rs), 14);
    }
}
