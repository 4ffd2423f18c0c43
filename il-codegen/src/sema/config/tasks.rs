//! TASK declarations of a resource: INTERVAL, PRIORITY and SINGLE, each
//! from any data source Ed.2 2.7.2 allows (a literal, a global of the
//! configuration, a direct address), decided once into a [`TaskSource`].

use super::lookup::{lookup, unknown_global};
use crate::ast::{self, LitKind, Operand};
use crate::ir::{ConfigDef, TaskDef, TaskSource};
use crate::sema::Cx;
use crate::sema::codes::*;
use crate::sema::resolve::resolve_addr;
use crate::sema::types::{Elem, Ty};

pub(crate) fn tasks(cx: &mut Cx, def: &ConfigDef, res: usize, r: &ast::Resource) -> Vec<TaskDef> {
    let mut out: Vec<TaskDef> = Vec::new();
    for t in &r.tasks {
        if out.iter().any(|o| t.name.is(&o.name)) {
            cx.err(
                DUPLICATE_DECL,
                t.name.span,
                format!("task `{}` is declared twice", t.name),
            );
            continue;
        }
        let interval = match &t.interval {
            None => TaskSource::Fixed(0),
            Some(o) => interval(cx, def, res, o),
        };
        let priority = match &t.priority {
            None => 0,
            Some(ast::Literal {
                kind: LitKind::Int(n),
                ..
            }) if u32::try_from(n.get()).is_ok() => n.get() as u32,
            Some(l) => {
                cx.err(
                    BAD_CONFIG,
                    l.span,
                    "PRIORITY must be a non-negative integer (0 is the highest)",
                );
                0
            }
        };
        let single = t.single.as_ref().and_then(|o| single(cx, def, res, o));
        out.push(TaskDef {
            name: t.name.name.to_string(),
            interval,
            priority,
            single,
        });
    }
    out
}

/// `INTERVAL :=` a TIME literal (not negative) or a TIME global. A direct
/// address holds no TIME (only bit strings, integers and reals can be
/// located), so it is refused with that reason.
fn interval(cx: &mut Cx, def: &ConfigDef, res: usize, o: &Operand) -> TaskSource<i64> {
    match o {
        Operand::Lit(ast::Literal {
            kind: LitKind::Time { nanos, long: false },
            ..
        }) if *nanos >= 0 => TaskSource::Fixed(*nanos),
        Operand::Var(v) if v.path.is_empty() => match lookup(def, res, &v.base.name) {
            Some((g, var)) if var.ty == Ty::Elem(Elem::TIME) => TaskSource::Global(g),
            Some((_, var)) => {
                cx.err(
                    BAD_CONFIG,
                    v.span(),
                    format!("INTERVAL needs a TIME global; `{}` is {}", v.base, var.ty),
                );
                TaskSource::Fixed(0)
            }
            None => {
                unknown_global(cx, def, res, &v.base, "INTERVAL");
                TaskSource::Fixed(0)
            }
        },
        Operand::Addr(_) => {
            cx.err(
                BAD_CONFIG,
                o.span(),
                "INTERVAL needs a TIME, and a direct address holds no TIME: use a TIME global",
            );
            TaskSource::Fixed(0)
        }
        _ => {
            cx.err(
                BAD_CONFIG,
                o.span(),
                "INTERVAL must be a non-negative TIME literal such as T#10ms, or a TIME global",
            );
            TaskSource::Fixed(0)
        }
    }
}

/// `SINGLE :=` a BOOL global, a bit address or a BOOL literal.
fn single(cx: &mut Cx, def: &ConfigDef, res: usize, o: &Operand) -> Option<TaskSource<bool>> {
    match o {
        Operand::Lit(ast::Literal {
            kind: LitKind::Bool(b),
            ..
        }) => Some(TaskSource::Fixed(*b)),
        Operand::Var(v) if v.path.is_empty() => match lookup(def, res, &v.base.name) {
            Some((g, var)) if var.ty == Ty::BOOL => Some(TaskSource::Global(g)),
            Some((_, var)) => {
                cx.err(
                    BAD_CONFIG,
                    v.span(),
                    format!("SINGLE needs a BOOL global; `{}` is {}", v.base, var.ty),
                );
                None
            }
            None => {
                unknown_global(cx, def, res, &v.base, "SINGLE");
                None
            }
        },
        Operand::Addr(a) => resolve_addr(cx, a, Some(&Ty::BOOL)).map(TaskSource::Addr),
        _ => {
            cx.err(
                BAD_CONFIG,
                o.span(),
                "SINGLE must be a BOOL global, a bit address (%IX0.0) or TRUE/FALSE",
            );
            None
        }
    }
}
