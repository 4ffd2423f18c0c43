//! The VAR_GLOBAL blocks of a configuration and of its resources, checked
//! like a PROGRAM's VARs.

use crate::ast::{self, PouKind, Span, VarKind};
use crate::ir::{Storage, Var};
use crate::sema::Cx;
use crate::sema::codes::*;
use crate::sema::env::{Env, Names, PouSig};
use crate::sema::interface::pou_sig;

/// The checked VAR_GLOBAL blocks of a configuration or resource, with the
/// span of each name. Declarations are checked like a PROGRAM's VARs.
pub(super) fn globals(
    cx: &mut Cx,
    names: &Names,
    env: &Env,
    owner: &ast::Ident,
    blocks: &[ast::VarBlock],
) -> Vec<(Var, Span)> {
    let mut var_blocks = Vec::new();
    for b in blocks {
        if b.kind != VarKind::Global {
            cx.err(
                BAD_SECTION,
                b.span,
                format!(
                    "{} cannot appear in a CONFIGURATION or RESOURCE: declare VAR_GLOBAL",
                    b.kind.keyword()
                ),
            );
            continue;
        }
        let mut b = ast::VarBlock {
            kind: VarKind::Var,
            ..b.clone()
        };
        crate::sema::partial_address::refuse_in_globals(cx, &mut b);
        var_blocks.push(b);
    }
    let fake = ast::Pou {
        kind: PouKind::Program,
        name: owner.clone(),
        return_type: None,
        var_blocks,
        body: Vec::new(),
        begin_il: false,
        span: owner.span,
        end_span: owner.span,
        host: None,
    };
    let sig: PouSig = pou_sig(cx, names, &env.types, &fake);
    sig.vars
        .into_iter()
        .map(|mut v| {
            v.kind = VarKind::Global;
            v.storage = Storage::of(PouKind::Program, VarKind::Global, v.location.is_some());
            let span = decl_span(&fake.var_blocks, &v.name).unwrap_or(owner.span);
            (v, span)
        })
        .collect()
}

pub(super) fn globals_of_resource(
    cx: &mut Cx,
    names: &Names,
    env: &Env,
    c: &ast::Configuration,
    r: &ast::Resource,
    config: &[(Var, Span)],
) -> Vec<(Var, Span)> {
    let owner = r.name.as_ref().unwrap_or(&c.name);
    let mut g = globals(cx, names, env, owner, &r.globals);
    g.retain(|(v, span)| {
        let clash = config
            .iter()
            .any(|(c, _)| c.name.eq_ignore_ascii_case(&v.name));
        if clash {
            cx.err(
                DUPLICATE_DECL,
                *span,
                format!(
                    "`{}` is already a global of configuration `{}`",
                    v.name, c.name
                ),
            );
        }
        !clash
    });
    g
}

/// The span of `name` among the declarations of `blocks`.
pub(super) fn decl_span(blocks: &[ast::VarBlock], name: &str) -> Option<Span> {
    blocks
        .iter()
        .flat_map(|b| &b.decls)
        .flat_map(|d| &d.names)
        .find(|n| n.is(name))
        .map(|n| n.span)
}
