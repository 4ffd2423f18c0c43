//! The CR at a label: the join of the CRs on every edge into it (the
//! fall-through and each jump), and what tells the user why paths disagree.

use super::{Class, Cr, Why};
use crate::ast::Span;
use crate::sema::literals::{LitClass, coerce};
use crate::sema::types::{Elem, Ty};

/// Add an edge into a label. Most labels have one or two (the fall-through
/// and a jump): a first push of `Vec` reserved room for four, half the
/// checker's memory per label beside the IR (edges are kept across rounds,
/// cleared but not freed).
pub(super) fn push_edge(edges: &mut Vec<(Span, Class, u32)>, e: (Span, Class, u32)) {
    if edges.capacity() == 0 {
        edges.reserve_exact(2);
    }
    edges.push(e);
}

/// The CR after a label, from the CR on every edge into it.
pub(super) fn join(edges: &[(Span, Class, u32)]) -> Cr {
    let Some((_, first, _)) = edges.first() else {
        return Cr::Dead;
    };
    if edges.iter().any(|(_, c, _)| *c == Class::Error) {
        return Cr::Undef(Why::Error);
    }
    let mut ty: Option<Ty> = None;
    let mut lit: Option<Class> = None;
    let mut lits: Vec<&Class> = Vec::new();
    let mut bad = false;
    for (_, c, _) in edges {
        match c {
            Class::Val(t) => match &ty {
                None => ty = Some(t.clone()),
                Some(u) if u == t => {}
                Some(_) => bad = true,
            },
            Class::Undef(_) => bad = true,
            l => {
                // Literals of one kind join (their values may differ).
                match &lit {
                    None => lit = Some(l.clone()),
                    Some(m) if std::mem::discriminant(m) == std::mem::discriminant(l) => {}
                    Some(_) => bad = true,
                }
                lits.push(l);
            }
        }
    }
    if !bad {
        match (ty, lit) {
            (Some(t), None) => return Cr::Val(t),
            (Some(t), Some(_)) if lits.iter().all(|l| lit_fits(l, &t)) => return Cr::Val(t),
            (None, Some(Class::LitInt(_))) => return Cr::Val(Ty::Elem(Elem::DINT)),
            (None, Some(Class::LitReal)) => return Cr::Val(Ty::Elem(Elem::LREAL)),
            (None, Some(Class::LitStr(w))) => {
                return Cr::Val(Ty::Str {
                    wide: w,
                    len: crate::sema::types::DEFAULT_STRING_LEN,
                });
            }
            _ => {}
        }
    }
    let _ = first;
    let paths: Vec<String> = edges
        .iter()
        .map(|(_, c, line)| {
            let what = match c {
                Class::Val(t) => t.to_string(),
                Class::LitInt(v) => format!("the integer literal {v}"),
                Class::LitReal => "a real literal".into(),
                Class::LitStr(_) => "a string literal".into(),
                Class::Undef(why) => format!("undefined ({why})"),
                Class::Error => "an error".into(),
            };
            format!("{what} from line {line}")
        })
        .collect();
    Cr::Undef(Why::Mixed(paths.join(", ")))
}

fn lit_fits(c: &Class, t: &Ty) -> bool {
    match (c, t) {
        // BOOL takes 0 and 1 in a store, but a label joining an integer path
        // with a BOOL path is more likely a mistake: keep them apart.
        (Class::LitInt(v), Ty::Elem(e)) if *e != Elem::BOOL => {
            coerce(&LitClass::Int(*v), t).is_ok()
        }
        (Class::LitReal, Ty::Elem(e)) => e.is_real(),
        (Class::LitStr(w), Ty::Str { wide, .. }) => w == wide,
        _ => false,
    }
}
