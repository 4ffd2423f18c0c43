//! Complements of the BOOL arrays a long rung network reads negated.
//!
//! In a fenced network (see `PouEmitter::seq`) every operand is a load from
//! `self`, which x86 folds into the `or`/`and` that uses it; a negated
//! operand (`ANDN x[3]`) cannot be folded: load, `not`, `and`. An array
//! the body never writes has the same complement all through the call, so
//! the emitter computes it once on entry (64 BOOLs: four vector loads,
//! `xor`s and stores) and reads the complement: `and` from memory, two
//! instructions fewer per negated operand (`interlock`: 9 to 7 per rung).
//!
//! The copy is reached through `&mut *black_box(&mut copy)`: memory LLVM
//! cannot see into, so the fences make each rung load from it as from
//! `self`. Through a shared reference (or a plain local) LLVM keeps all 64
//! values in registers and spills them, as it did with `self` before the
//! fences.

use super::PouEmitter;
use super::text::Out;
use crate::ir::types::{Elem, Ty};
use crate::ir::{CheckedPou, Const, Expr, Op, PathElem, Place, Root, Storage, Value};

/// Fewest negated reads of an array for its complement to pay for the copy.
const MIN_NEGATED_READS: usize = 8;

/// The variables whose complement the body reads (`out[i]`): BOOL arrays
/// of one dimension in `self`, never stored by the body, read negated with
/// a literal subscript at least [`MIN_NEGATED_READS`] times, in a body
/// whose rungs are fenced (`fenced`).
pub(crate) fn complemented(pou: &CheckedPou, fenced: bool) -> Vec<bool> {
    let n = pou.vars.len();
    let mut out = vec![false; n];
    if !fenced {
        return out;
    }
    let mut negated = vec![0usize; n];
    let mut stored = vec![false; n];
    for s in &pou.body {
        super::writeback::stores(pou, s, &mut |i| {
            if let Some(w) = stored.get_mut(i) {
                *w = true
            }
        });
        let v = match &s.op {
            Op::SetCr {
                expr: Expr::Not(v), ..
            }
            | Op::SetCr {
                expr:
                    Expr::Bin {
                        rhs: v,
                        negate_rhs: true,
                        ..
                    },
                ..
            } => v,
            _ => continue,
        };
        if let Some((i, _)) = literal_element(pou, v) {
            negated[i] += 1;
        }
    }
    for (i, v) in pou.vars.iter().enumerate() {
        let one_bool_dim = matches!(&v.ty, Ty::Array(a)
            if a.dims.len() == 1 && a.elem == Ty::Elem(Elem::BOOL));
        out[i] = one_bool_dim
            && v.storage == Storage::Instance
            && !v.heap
            && !stored[i]
            && negated[i] >= MIN_NEGATED_READS
            // The copy (vector xors) costs about an instruction per 8
            // BOOLs; each negated read saves two.
            && array_len(&v.ty) <= 8 * negated[i];
    }
    out
}

/// `v` as an element of a one-dimensional array variable with a literal
/// subscript inside its bounds: the variable and the element's offset.
fn literal_element(pou: &CheckedPou, v: &Value) -> Option<(usize, usize)> {
    let Value::Read(p) = v else { return None };
    let p = pou.place(*p);
    let Place {
        root: Root::Var(i),
        path,
        ..
    } = p
    else {
        return None;
    };
    let [PathElem::Index { dims, subs }] = path.as_slice() else {
        return None;
    };
    let ([(lo, hi)], [Value::Const(Const::Int(n, _))]) = (dims.as_slice(), subs.as_slice()) else {
        return None;
    };
    let n = n.get();
    (*lo as i128 <= n && n <= *hi as i128).then(|| (*i, (n - *lo as i128) as usize))
}

fn array_len(t: &Ty) -> usize {
    match t {
        Ty::Array(a) => a
            .dims
            .iter()
            .map(|(lo, hi)| (hi - lo + 1) as usize)
            .product(),
        _ => 0,
    }
}

fn complement_ident(name: &str) -> String {
    format!("__not_{name}")
}

impl PouEmitter<'_> {
    /// On entry: the complement of each array [`complemented`] chose.
    pub(crate) fn complements(&self, o: &mut Out) {
        for (i, v) in self.pou.vars.iter().enumerate() {
            if !self.complemented.get(i).copied().unwrap_or(false) {
                continue;
            }
            let (id, c) = (super::rust_ident(&v.name), complement_ident(&v.name));
            let ty = super::rust_ty(&v.ty);
            o.code(&format!(
                "let mut __copy{c}: {ty} = self.{id}.map(|__b| !__b); let {c} = &mut *::core::hint::black_box(&mut __copy{c});"
            ));
        }
    }

    /// `!v`, read from a complement where there is one.
    pub(crate) fn negated(&self, v: &Value, line: u32) -> String {
        if let Some((i, k)) = literal_element(self.pou, v)
            && self.complemented.get(i).copied().unwrap_or(false)
        {
            return format!("{}[{k}]", complement_ident(&self.pou.vars[i].name));
        }
        format!("!{}", self.value(v, line))
    }
}
