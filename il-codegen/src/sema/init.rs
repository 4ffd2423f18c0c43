//! Initial values of declarations, checked against their types.

use super::codes::*;
use super::env::*;
use super::ir::{Const, Init};
use super::literals::*;
use super::types::Ty;
use super::{Cx, stdfb};
use crate::ast::{Initializer, LitKind, Literal, Operand};

/// The initial value of a subrange variable or field declared without one:
/// its lower limit (IEC Ed.2 2.3.3.2), decided here for the emitter and the
/// interpreter alike. `None` where that is the type's default (0) anyway.
pub(crate) fn subrange_start(ty: &Ty, range: Option<(i128, i128)>) -> Option<Init> {
    match (ty, range) {
        (Ty::Elem(e), Some((lo, _))) if lo != 0 => Some(Init::Const(Const::Int(lo.into(), *e))),
        _ => None,
    }
}

pub(crate) fn init_value(
    cx: &mut Cx,
    types: &TypeTables,
    init: &Initializer,
    ty: &Ty,
    range: Option<(i128, i128)>,
) -> Option<Init> {
    match (init, ty) {
        (Initializer::Simple(Operand::Lit(lit)), Ty::Elem(_) | Ty::Str { .. }) => {
            let class = lit_class(lit);
            // 3rd edition: a typed literal of a narrower type (`x : DINT := INT#5`).
            let widened = match (&class, ty) {
                (LitClass::Typed(c), Ty::Elem(e)) if c.ty() != *ty => {
                    super::widen::widen_const(c, *e).inspect(|_| {
                        cx.feature(
                            crate::dialect::Feature::Widening {
                                from: c.ty().to_string(),
                                to: ty.to_string(),
                            },
                            lit.span,
                        )
                    })
                }
                _ => None,
            };
            match widened.map_or_else(|| coerce(&class, ty), Ok) {
                Ok(Const::Int(v, e))
                    if range.is_some_and(|(lo, hi)| v.get() < lo || v.get() > hi) =>
                {
                    let (lo, hi) = range.unwrap_or_default();
                    cx.err(
                        BAD_INIT,
                        lit.span,
                        format!("{v} is outside the subrange {lo}..{hi}"),
                    );
                    let _ = e;
                    None
                }
                Ok(c) => Some(Init::Const(c)),
                Err(msg) => {
                    cx.err(BAD_INIT, lit.span, msg);
                    None
                }
            }
        }
        (Initializer::Simple(o), Ty::Enum(name)) => {
            let value = match o {
                Operand::Lit(Literal {
                    kind: LitKind::Enum(e),
                    ..
                }) if e.ty.is(name) => &e.value,
                Operand::Var(v) if v.path.is_empty() => &v.base,
                _ => {
                    cx.err(
                        BAD_INIT,
                        o.span(),
                        format!("expected a value of the enumeration {name}"),
                    );
                    return None;
                }
            };
            let vals = types
                .enums
                .get(&name.to_ascii_uppercase())
                .map_or(&[][..], |(_, v)| v);
            match vals.iter().find(|v| value.is(v)) {
                Some(v) => Some(Init::Const(Const::enum_value(name.clone(), v.clone()))),
                None => {
                    cx.err(
                        BAD_INIT,
                        o.span(),
                        format!("`{value}` is not a value of {name} ({})", vals.join(", ")),
                    );
                    None
                }
            }
        }
        (Initializer::Struct { fields, .. }, Ty::Struct(name)) => {
            let defs = types
                .structs
                .get(&name.to_ascii_uppercase())
                .cloned()
                .unwrap_or_default();
            let mut out = Vec::new();
            for (fname, v) in fields {
                let Some(f) = defs.iter().find(|f| fname.is(&f.name)) else {
                    cx.err(
                        UNKNOWN_MEMBER,
                        fname.span,
                        format!("{name} has no field `{fname}`"),
                    );
                    continue;
                };
                if let Some(i) = init_value(cx, types, v, &f.ty, f.range) {
                    out.push((f.name.clone(), f.ty.clone(), i));
                }
            }
            Some(Init::Struct(out))
        }
        (Initializer::Array { elems, span }, Ty::Array(arr)) => {
            let (dims, elem, elem_range) = (&arr.dims, &arr.elem, &arr.range);
            let total: i64 = dims.iter().map(|(lo, hi)| hi - lo + 1).product();
            let mut out = Vec::new();
            // Each count is at most `total` (16 million): their sum over any
            // source text fits an i64.
            let mut len: i64 = 0;
            for (count, e) in elems {
                let n = match count {
                    None => 1,
                    Some(Literal {
                        kind: LitKind::Int(n),
                        ..
                    }) if (0..=total as i128).contains(&n.get()) => n.get() as i64,
                    Some(l) => {
                        cx.err(
                            BAD_INIT,
                            l.span,
                            "a repeat count must be a small non-negative integer",
                        );
                        return None;
                    }
                };
                // A literal (checked against the element subrange), or a
                // structure initialiser for an array of structures.
                let c = init_value(cx, types, e, elem, *elem_range)?;
                len += n;
                if n > 0 {
                    out.push((n as usize, c));
                }
            }
            if len > total {
                cx.err(
                    BAD_INIT,
                    *span,
                    format!("{len} initial values for an array of {total} elements"),
                );
                return None;
            }
            Some(Init::Array(out))
        }
        (Initializer::Struct { fields, .. }, Ty::Fb(fb)) => {
            let Some(std) = stdfb::lookup(fb) else {
                cx.err(
                    UNSUPPORTED,
                    init.span(),
                    "initial values of user FB instances are not supported yet",
                );
                return None;
            };
            let mut out = Vec::new();
            for (name, v) in fields {
                let Some((i, (iec, e))) =
                    std.inputs.iter().enumerate().find(|(_, (n, _))| name.is(n))
                else {
                    cx.err(
                        UNKNOWN_MEMBER,
                        name.span,
                        format!("{fb} has no input `{name}`"),
                    );
                    continue;
                };
                if let Some(Init::Const(c)) = init_value(cx, types, v, &Ty::Elem(*e), None) {
                    let m = crate::ir::Member {
                        name: (*iec).into(),
                        index: i as u32,
                    };
                    out.push((m, c));
                }
            }
            Some(Init::Fields(out))
        }
        _ => {
            cx.err(
                BAD_INIT,
                init.span(),
                format!("this initial value does not fit type {ty}"),
            );
            None
        }
    }
}
