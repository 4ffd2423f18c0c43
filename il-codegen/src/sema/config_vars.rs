//! VAR_CONFIG and VAR_ACCESS of a configuration (Ed.2 2.7.1): paths into
//! program instances (`Res.Prog.fb.x`), checked against the declarations
//! they name.

use super::Cx;
use super::codes::*;
use super::configuration::lookup;
use super::env::{Env, Names, PouSig};
use super::init::init_value;
use super::ir::{AccessDef, AccessTarget, ConfigDef, ConfigVarDef, InstancePath, Storage};
use super::resolve::{resolve_addr, resolve_type};
use super::suggest;
use super::types::Ty;
use crate::ast::{self, Ident, Span};

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
        let Some((target, var)) = instance_path(cx, env, def, &d.path) else {
            continue;
        };
        if !same_type(cx, names, &d.ty, &target) {
            continue;
        }
        if out.iter().any(|o| {
            (&o.target.fields, &o.target.member) == (&target.fields, &target.member)
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
        // A single name is a global; a dotted one a variable of an instance.
        let (target, ty, constant) = if let [g] = d.path.as_slice() {
            let Some((gr, gv)) =
                (0..def.resources.len().max(1)).find_map(|r| lookup(def, r, &g.name))
            else {
                cx.err(
                    BAD_CONFIG,
                    g.span,
                    format!("configuration `{}` has no global `{g}`", def.name),
                );
                continue;
            };
            if let Some(l) = &gv.location {
                cx.err(
                    BAD_CONFIG,
                    g.span,
                    format!("the global `{}` is at {} in the process image: the host reads it there (`io_{}`)", gv.name, l.text, gv.name),
                );
                continue;
            }
            (AccessTarget::Global(gr), gv.ty.clone(), gv.constant)
        } else {
            let Some((p, var)) = instance_path(cx, env, def, &d.path) else {
                continue;
            };
            let ty = p.ty.clone();
            (AccessTarget::Instance(p), ty, var.constant)
        };
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
            name: d.name.name.clone(),
            target,
            ty,
            writable: d.writable,
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

/// What VAR_CONFIG and VAR_ACCESS need of the declaration a path names.
struct Named {
    /// `AT %I*` (the area and the address as written).
    partly: Option<(ast::Area, String)>,
    range: Option<(i128, i128)>,
    constant: bool,
}

impl Named {
    fn of(v: &super::ir::Var) -> Named {
        Named {
            partly: v.partly.clone(),
            range: v.range,
            constant: v.constant,
        }
    }
}

/// `Res.Prog.fb.x` (or `Prog.x` in a configuration without RESOURCE; the
/// last step may be an input or output of a standard FB instance,
/// `Prog.tmr.PT`): the variable it names and its declaration.
fn instance_path(
    cx: &mut Cx,
    env: &Env,
    def: &ConfigDef,
    path: &[Ident],
) -> Option<(InstancePath, Named)> {
    let text = path
        .iter()
        .map(|i| i.name.as_str())
        .collect::<Vec<_>>()
        .join(".");
    let span = Span {
        lo: path[0].span.lo,
        hi: path[path.len() - 1].span.hi,
    };
    let named = def
        .resources
        .iter()
        .position(|r| r.name.as_ref().is_some_and(|n| path[0].is(n)));
    let (resource, rest) = match named {
        Some(r) => (r, &path[1..]),
        None => match def.resources.iter().position(|r| r.name.is_none()) {
            Some(r) => (r, path),
            None => {
                let all = def.resources.iter().filter_map(|r| r.name.as_deref());
                let hint = suggest(&path[0].name, all).map(|s| format!("did you mean `{s}`?"));
                cx.err(
                    BAD_CONFIG,
                    path[0].span,
                    format!("configuration `{}` has no resource `{}`", def.name, path[0]),
                )
                .help = hint;
                return None;
            }
        },
    };
    let progs = &def.resources[resource].programs;
    let Some(first) = rest.first() else {
        cx.err(
            BAD_CONFIG,
            span,
            format!("`{text}` names a resource: add the program instance and the variable"),
        );
        return None;
    };
    let Some(program) = progs.iter().position(|p| first.is(&p.name)) else {
        let hint = suggest(&first.name, progs.iter().map(|p| p.name.as_str()))
            .map(|s| format!("did you mean `{s}`?"));
        cx.err(
            BAD_CONFIG,
            first.span,
            format!("there is no program instance `{first}` here"),
        )
        .help = hint;
        return None;
    };
    let mut sig: &PouSig = env.pou(&progs[program].program)?;
    let mut fields = Vec::new();
    let mut member = None;
    let mut found = None;
    for (k, part) in rest[1..].iter().enumerate() {
        let Some((_, v)) = sig.var(&part.name) else {
            let hint = suggest(&part.name, sig.vars.iter().map(|v| v.name.as_str()))
                .map(|s| format!("did you mean `{s}`?"));
            cx.err(
                BAD_CONFIG,
                part.span,
                format!(
                    "{} `{}` has no variable `{part}`",
                    sig.kind.keyword(),
                    sig.name
                ),
            )
            .help = hint;
            return None;
        };
        if v.storage != Storage::Instance {
            cx.err(
                BAD_CONFIG,
                part.span,
                format!(
                    "`{}` of {} is a {}, which is not part of the instance",
                    v.name,
                    sig.name,
                    v.kind.keyword()
                ),
            );
            return None;
        }
        fields.push(v.name.clone());
        if k + 2 == rest.len() {
            found = Some((v.ty.clone(), Named::of(v)));
            break;
        }
        match &v.ty {
            Ty::Fb(fb) if env.pou(fb).is_some() => sig = env.pou(fb)?,
            Ty::Fb(fb) if k + 3 == rest.len() && super::stdfb::lookup(fb).is_some() => {
                let std = super::stdfb::lookup(fb)?;
                let m = &rest[k + 2];
                let params = || std.inputs.iter().chain(&std.outputs);
                let Some((name, elem)) = params().find(|(n, _)| m.is(n)) else {
                    let hint = suggest(&m.name, params().map(|(n, _)| *n))
                        .map(|s| format!("did you mean `{s}`?"));
                    cx.err(
                        BAD_CONFIG,
                        m.span,
                        format!(
                            "the standard block {} has no input or output `{m}`",
                            std.name
                        ),
                    )
                    .help = hint;
                    return None;
                };
                member = Some(name.to_string());
                let named = Named {
                    partly: None,
                    range: None,
                    constant: v.constant,
                };
                found = Some((Ty::Elem(*elem), named));
                break;
            }
            t => {
                cx.err(
                    BAD_CONFIG,
                    part.span,
                    format!(
                        "`{}` is {t}: only instances of FUNCTION_BLOCKs can be stepped into (a standard one's input or output ends the path)",
                        v.name
                    ),
                );
                return None;
            }
        }
    }
    let Some((ty, var)) = found else {
        cx.err(
            BAD_CONFIG,
            span,
            format!("`{text}` names a program instance: add the variable"),
        );
        return None;
    };
    Some((
        InstancePath {
            resource,
            program,
            fields,
            member,
            ty,
            text,
        },
        var,
    ))
}
