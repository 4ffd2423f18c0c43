//! VAR_CONFIG and VAR_ACCESS of a configuration (Ed.2 2.7.1): the
//! declarations, once `paths` has resolved the path each names.

use super::paths::{access_path, config_path};
use crate::ast;
use crate::ir::{AccessDef, ConfigDef, ConfigVarDef, InstancePath};
use crate::sema::Cx;
use crate::sema::codes::*;
use crate::sema::env::{Env, Names};
use crate::sema::init::init_value;
use crate::sema::resolve::{resolve_addr, resolve_type};

/// The checked VAR_CONFIG declarations.
pub(crate) fn var_config(
    cx: &mut Cx,
    names: &Names,
    env: &Env,
    def: &ConfigDef,
    decls: &[ast::ConfigVar],
) -> Vec<ConfigVarDef> {
    let mut out: Vec<ConfigVarDef> = Vec::new();
    for d in decls {
        let Some((target, var)) = config_path(cx, env, def, &d.path) else {
            continue;
        };
        if !same_type(cx, names, &d.ty, &target) {
            continue;
        }
        if out.iter().any(|o| {
            o.target.steps == target.steps
                && (o.target.resource, o.target.program) == (target.resource, target.program)
        }) {
            cx.err(
                DUPLICATE_DECL,
                d.span,
                format!("VAR_CONFIG already configures `{}`", target.text),
            );
            continue;
        }
        let location = match &d.location {
            None => None,
            Some(a) => {
                let Some((area, star)) = &var.partly else {
                    cx.err(
                        BAD_CONFIG,
                        a.span,
                        format!(
                            "`{}` is not declared `AT %I*`, `%Q*` or `%M*`: VAR_CONFIG gives an address only to a partly specified variable",
                            target.text
                        ),
                    );
                    continue;
                };
                if a.partial {
                    cx.err(
                        BAD_CONFIG,
                        a.span,
                        "VAR_CONFIG must give the full address (`%IX0.1`, `%QW2`)",
                    );
                    continue;
                }
                let Some(l) = resolve_addr(cx, a, Some(&target.ty)) else {
                    continue;
                };
                if l.area != *area {
                    cx.err(
                        BAD_CONFIG,
                        a.span,
                        format!("`{}` is declared `AT {star}`, so its address must be in the same area, not {}", target.text, l.text),
                    );
                    continue;
                }
                Some(l)
            }
        };
        let init = match &d.init {
            None => None,
            Some(i) => match init_value(cx, &env.types, i, &target.ty, var.range) {
                Some(v) => Some(v),
                None => continue,
            },
        };
        out.push(ConfigVarDef {
            target,
            init,
            location,
        });
    }
    out
}

/// The checked VAR_ACCESS declarations.
pub(crate) fn access(
    cx: &mut Cx,
    names: &Names,
    env: &Env,
    def: &ConfigDef,
    decls: &[ast::AccessVar],
) -> Vec<AccessDef> {
    let mut out: Vec<AccessDef> = Vec::new();
    for d in decls {
        if out.iter().any(|o| d.name.is(&o.name)) {
            cx.err(
                DUPLICATE_DECL,
                d.name.span,
                format!("access path `{}` is declared twice", d.name),
            );
            continue;
        }
        let Some((target, ty, named)) = access_path(cx, env, def, &d.path) else {
            continue;
        };
        let constant = named.constant;
        let want = resolve_type(cx, names, &d.ty);
        if let Some(want) = want.filter(|w| *w != ty) {
            cx.err(
                BAD_CONFIG,
                d.ty.span(),
                format!(
                    "the access path `{}` is declared {want}, but what it names is {ty}",
                    d.name
                ),
            );
            continue;
        }
        if d.writable && constant {
            cx.err(
                NOT_WRITABLE,
                d.span,
                format!("`{}` names a CONSTANT: it can only be READ_ONLY", d.name),
            );
            continue;
        }
        out.push(AccessDef {
            name: d.name.name.to_string(),
            target,
            ty,
            writable: d.writable,
            range: named.range,
        });
    }
    out
}

fn same_type(cx: &mut Cx, names: &Names, spec: &ast::TypeSpec, p: &InstancePath) -> bool {
    match resolve_type(cx, names, spec) {
        None => false,
        Some(t) if t == p.ty => true,
        Some(t) => {
            cx.err(
                BAD_CONFIG,
                spec.span(),
                format!("`{}` is {}, not {t}", p.text, p.ty),
            );
            false
        }
    }
}
