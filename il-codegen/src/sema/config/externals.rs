//! The VAR_EXTERNALs of programs and function blocks, bound to the globals
//! by name.

use super::globals::decl_span;
use crate::ast::{self, Span, VarKind};
use crate::ir::{Loc, Storage, Var};
use crate::sema::Cx;
use crate::sema::codes::*;
use crate::sema::env::Env;
use crate::sema::types::Ty;

/// Every VAR_EXTERNAL named like the located global `g` becomes located there.
pub(super) fn bind_located(cx: &mut Cx, env: &mut Env, g: &Var, l: &Loc, span: Span) {
    for sig in env.pous.values_mut() {
        let Some(i) = sig.index.get(&g.name) else {
            continue;
        };
        let v = &mut sig.vars[i];
        if v.kind != VarKind::External {
            continue;
        }
        if v.ty != g.ty {
            cx.err(
                BAD_GLOBAL,
                span,
                format!(
                    "`{}` is {} here, but {} declares VAR_EXTERNAL `{}` : {}",
                    g.name, g.ty, sig.name, v.name, v.ty
                ),
            );
            continue;
        }
        match &v.location {
            None => {
                v.location = Some(l.clone());
                v.storage = Storage::Located;
            }
            Some(other) if other.text == l.text => {}
            Some(other) => {
                cx.err(
                    BAD_GLOBAL,
                    span,
                    format!(
                        "`{}` is at {} here but at {} in another configuration; {} uses it through VAR_EXTERNAL and can have one address only",
                        g.name, l.text, other.text, sig.name
                    ),
                );
            }
        }
    }
}

/// A POU holding an instance of a FUNCTION_BLOCK that uses globals passes
/// them down: it must declare the same VAR_EXTERNALs.
pub(crate) fn check_fb_externals(cxs: &mut [Cx], pous: &[(usize, &ast::Pou)], env: &Env) {
    for (f, p) in pous {
        let Some(sig) = env.pou(&p.name.name) else {
            continue;
        };
        if sig.file != *f || sig.span != p.name.span {
            continue;
        }
        for v in &sig.vars {
            let mut t = &v.ty;
            while let Ty::Array(a) = t {
                t = &a.elem;
            }
            let Ty::Fb(fb) = t else { continue };
            let Some(fsig) = env.pou(fb) else { continue };
            for e in fsig
                .vars
                .iter()
                .filter(|e| e.kind == VarKind::External && e.location.is_none())
            {
                let ok = sig.var(&e.name).is_some_and(|(_, mine)| {
                    // A CONSTANT reference cannot be handed to a block that writes.
                    mine.kind == VarKind::External
                        && mine.ty == e.ty
                        && mine.location.is_none()
                        && (!mine.constant || e.constant)
                });
                if !ok {
                    let span = decl_span(&p.var_blocks, &v.name).unwrap_or(p.name.span);
                    cxs[*f]
                        .err(
                            BAD_GLOBAL,
                            span,
                            format!(
                                "`{}` is a {} instance, which uses the global `{}` : {}; {} must declare it too",
                                v.name, fsig.name, e.name, e.ty, sig.name
                            ),
                        )
                        .help = Some(format!(
                        "add `VAR_EXTERNAL {} : {}; END_VAR` to {}",
                        e.name, e.ty, sig.name
                    ));
                }
            }
        }
    }
}
