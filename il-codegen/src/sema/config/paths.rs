//! The paths of VAR_CONFIG and VAR_ACCESS (Ed.2 2.7.1), resolved against
//! the configuration and the declarations they name.
//!
//! An access path is `[resource.] global` or `[resource.] program.{fb.}
//! variable`, followed by members of structures and elements of arrays
//! (Ed.2's `symbolic_variable`: `g.field`, `g[3]`, `RES1.P1.a[2]`,
//! `RES1.P1.fbs[1].Q`). A VAR_CONFIG path is `[resource.] program.{fb.}
//! variable` only (Ed.2 B.1.7 `instance_specific_init`: no subscripts, no
//! members of structures). Subscripts of an access path are constants,
//! checked against the bounds here, so a path names one place for the whole
//! run and the emitted code indexes it with literals that cannot fail.

use super::lookup::{all_global_names, lookup};
use crate::ast::{self, Accessor, ExprOp, Ident, LitKind, Operand, Span, Subscript, VarRef};
use crate::ir::{AccessTarget, ConfigDef, Const, InstancePath, PathElem, Storage, Value};
use crate::sema::codes::*;
use crate::sema::env::Env;
use crate::sema::types::{Elem, Ty};
use crate::sema::{Cx, suggest};

/// What VAR_CONFIG and VAR_ACCESS need of the place a path names.
pub(super) struct Named {
    /// `AT %I*` (the area and the address as written) of a whole variable.
    pub partly: Option<(ast::Area, String)>,
    /// Subrange bounds of the place.
    pub range: Option<(i128, i128)>,
    /// Some step of the path is a CONSTANT.
    pub constant: bool,
}

/// Which declaration section a path is in: what it may contain.
#[derive(Clone, Copy, PartialEq)]
enum Section {
    /// VAR_CONFIG: variables of program and FB instances only.
    Config,
    /// VAR_ACCESS: also globals, members of structures, array elements.
    Access,
}

/// One step of a path as written.
enum Seg<'a> {
    Name(&'a Ident),
    Index(&'a [Subscript], Span),
    Part(Span),
}

fn segments(path: &VarRef) -> Vec<Seg<'_>> {
    let mut out = vec![Seg::Name(&path.base)];
    for a in &path.path {
        out.push(match a {
            Accessor::Field(i) => Seg::Name(i),
            Accessor::Index(subs, span) => Seg::Index(subs, *span),
            Accessor::Part { span, .. } => Seg::Part(*span),
        });
    }
    out
}

fn hint(name: &str, candidates: Vec<&str>) -> Option<String> {
    suggest(name, candidates).map(|s| format!("did you mean `{s}`?"))
}

/// A VAR_CONFIG path: the variable it names.
pub(super) fn config_path(
    cx: &mut Cx,
    env: &Env,
    def: &ConfigDef,
    path: &VarRef,
) -> Option<(InstancePath, Named)> {
    let text = cx.file.snippet(path.span()).to_string();
    let segs = segments(path);
    let (resource, rest) = pick_resource(cx, def, &segs, path)?;
    let Some(Seg::Name(first)) = rest.first() else {
        return bare_resource(cx, path.span(), &text);
    };
    let progs = &def.resources[resource].programs;
    let Some(program) = progs.iter().position(|p| first.is(&p.name)) else {
        let names = progs.iter().map(|p| p.name.as_str()).collect();
        cx.err(
            BAD_CONFIG,
            first.span,
            format!("there is no program instance `{first}` here"),
        )
        .help = hint(&first.name, names);
        return None;
    };
    instance(
        cx,
        env,
        def,
        (resource, program),
        &rest[1..],
        text,
        path.span(),
        Section::Config,
    )
}

/// A VAR_ACCESS path: a global or a place inside a program instance, with
/// its type.
pub(super) fn access_path(
    cx: &mut Cx,
    env: &Env,
    def: &ConfigDef,
    path: &VarRef,
) -> Option<(AccessTarget, Ty, Named)> {
    let text = cx.file.snippet(path.span()).to_string();
    let segs = segments(path);
    let named_res = match &segs[0] {
        Seg::Name(n) => def
            .resources
            .iter()
            .position(|r| r.name.as_ref().is_some_and(|x| n.is(x))),
        _ => None,
    };
    // `Res.x`: x is a program instance or a global of that resource; a
    // name alone: a program instance of the unnamed resource, else a global
    // of the configuration or of any of its resources.
    let (resources, rest): (Vec<usize>, &[Seg]) = match named_res {
        Some(r) => (vec![r], &segs[1..]),
        None => ((0..def.resources.len().max(1)).collect(), &segs[..]),
    };
    let Some(Seg::Name(first)) = rest.first() else {
        return bare_resource(cx, path.span(), &text);
    };
    let unnamed_or_given = resources
        .iter()
        .copied()
        .filter(|&r| named_res.is_some() || def.resources.get(r).is_some_and(|x| x.name.is_none()));
    for r in unnamed_or_given {
        if let Some(p) = def.resources[r]
            .programs
            .iter()
            .position(|p| first.is(&p.name))
        {
            let (ip, named) = instance(
                cx,
                env,
                def,
                (r, p),
                &rest[1..],
                text,
                path.span(),
                Section::Access,
            )?;
            let ty = ip.ty.clone();
            return Some((AccessTarget::Instance(ip), ty, named));
        }
    }
    let Some((global, gv)) = resources.iter().find_map(|&r| lookup(def, r, &first.name)) else {
        let res = named_res.unwrap_or(0);
        let mut names = all_global_names(def, res);
        if let Some(r) = def
            .resources
            .get(res)
            .filter(|r| named_res.is_some() || r.name.is_none())
        {
            names.extend(r.programs.iter().map(|p| p.name.as_str()));
        }
        if named_res.is_none() {
            names.extend(def.resources.iter().filter_map(|r| r.name.as_deref()));
        }
        let what = if segs.len() == 1 {
            "global"
        } else if named_res.is_some() {
            // `R.x.y`: x is a program instance or a global of R.
            "program instance or global"
        } else if def.resources.iter().any(|r| r.name.is_none()) {
            "program instance or global"
        } else {
            "resource or global"
        };
        let msg = match named_res {
            Some(r) => format!(
                "resource `{}` has no {what} `{first}`",
                def.resources[r].name.as_deref().unwrap_or_default()
            ),
            None => format!("configuration `{}` has no {what} `{first}`", def.name),
        };
        cx.err(BAD_CONFIG, first.span, msg).help = hint(&first.name, names);
        return None;
    };
    if let Some(l) = &gv.location {
        cx.err(
            BAD_CONFIG,
            first.span,
            format!(
                "the global `{}` is at {} in the process image: the host reads it there (`io_{}`)",
                gv.name, l.text, gv.name
            ),
        );
        return None;
    }
    let start = Named {
        partly: None,
        range: gv.range,
        constant: gv.constant,
    };
    let from = (gv.ty.clone(), first.name.as_ref());
    let (steps, ty, named) = walk(cx, env, from, start, &rest[1..], Section::Access)?;
    Some((AccessTarget::Global { global, steps }, ty, named))
}

/// The resource a VAR_CONFIG path starts in and the segments after it.
fn pick_resource<'s, 'a>(
    cx: &mut Cx,
    def: &ConfigDef,
    segs: &'s [Seg<'a>],
    path: &VarRef,
) -> Option<(usize, &'s [Seg<'a>])> {
    let first = &path.base;
    if let Some(r) =
        (def.resources.iter()).position(|r| r.name.as_ref().is_some_and(|n| first.is(n)))
    {
        return Some((r, &segs[1..]));
    }
    match def.resources.iter().position(|r| r.name.is_none()) {
        Some(r) => Some((r, segs)),
        None => {
            let all = def
                .resources
                .iter()
                .filter_map(|r| r.name.as_deref())
                .collect();
            cx.err(
                BAD_CONFIG,
                first.span,
                format!("configuration `{}` has no resource `{first}`", def.name),
            )
            .help = hint(&first.name, all);
            None
        }
    }
}

fn bare_resource<T>(cx: &mut Cx, span: Span, text: &str) -> Option<T> {
    cx.err(
        BAD_CONFIG,
        span,
        format!("`{text}` names a resource: add the program instance and the variable"),
    );
    None
}

/// The place `rest` names inside program instance `(resource, program)`.
#[allow(clippy::too_many_arguments)]
fn instance(
    cx: &mut Cx,
    env: &Env,
    def: &ConfigDef,
    (resource, program): (usize, usize),
    rest: &[Seg],
    text: String,
    span: Span,
    section: Section,
) -> Option<(InstancePath, Named)> {
    if rest.is_empty() {
        cx.err(
            BAD_CONFIG,
            span,
            format!("`{text}` names a program instance: add the variable"),
        );
        return None;
    }
    let inst = &def.resources[resource].programs[program];
    let prog = (Ty::Fb(inst.program.clone().into()), inst.name.as_str());
    let start = Named {
        partly: None,
        range: None,
        constant: false,
    };
    let (steps, ty, named) = walk(cx, env, prog, start, rest, section)?;
    Some((
        InstancePath {
            resource,
            program,
            steps,
            ty,
            text,
        },
        named,
    ))
}

/// The steps `segs` take from a place of type `ty` named `from`.
fn walk(
    cx: &mut Cx,
    env: &Env,
    (mut ty, from): (Ty, &str),
    mut named: Named,
    segs: &[Seg],
    section: Section,
) -> Option<(Vec<PathElem>, Ty, Named)> {
    let mut steps = Vec::new();
    // What the place so far is called in messages (`n`, `a[2]`).
    let mut prev = from.to_string();
    for seg in segs {
        match seg {
            Seg::Name(part) => {
                let (name, t, range, constant, partly) =
                    member(cx, env, &ty, &prev, part, section)?;
                prev = part.name.to_string();
                steps.push(PathElem::Field(name));
                ty = t;
                named.range = range;
                named.constant |= constant;
                named.partly = partly;
            }
            Seg::Index(subs, span) => {
                if section == Section::Config {
                    cx.err(
                        BAD_CONFIG,
                        *span,
                        "VAR_CONFIG names a whole variable of a program or FB instance (Ed.2 2.7.1: `Res.Prog.fb.x`), not an array element: give the array's initial value (`[1, 2, 3]`), or name the element in VAR_ACCESS",
                    );
                    return None;
                }
                let Ty::Array(arr) = &ty else {
                    cx.err(BAD_INDEX, *span, format!("`{prev}` is {ty}, not an array"));
                    return None;
                };
                let (dims, elem, range) = (&arr.dims, &arr.elem, &arr.range);
                prev = format!("{prev}{}", cx.file.snippet(*span));
                if subs.len() != dims.len() {
                    cx.err(
                        BAD_INDEX,
                        *span,
                        format!(
                            "{} subscripts for an array of {} dimensions",
                            subs.len(),
                            dims.len()
                        ),
                    );
                    return None;
                }
                let mut vals = Vec::new();
                for (s, &(lo, hi)) in subs.iter().zip(dims) {
                    let (n, sp) = constant_subscript(cx, s)?;
                    if n < lo as i128 || n > hi as i128 {
                        cx.err(
                            BAD_INDEX,
                            sp,
                            format!("subscript {n} is outside the bounds {lo}..{hi}"),
                        );
                        return None;
                    }
                    vals.push(Value::Const(Const::Int(n.into(), Elem::LINT)));
                }
                steps.push(PathElem::Index {
                    dims: dims.clone(),
                    subs: vals,
                });
                named.range = *range;
                named.partly = None;
                ty = elem.clone();
            }
            Seg::Part(span) => {
                cx.err(
                    BAD_CONFIG,
                    *span,
                    "a partial access (`.3`, `.%X3`) is not part of a configuration path: name the whole variable",
                );
                return None;
            }
        }
    }
    Some((steps, ty, named))
}

/// A member `part` of a place of type `ty`: (the member, type, range,
/// CONSTANT, `AT %I*`).
type Member = (
    crate::ir::Member,
    Ty,
    Option<(i128, i128)>,
    bool,
    Option<(ast::Area, String)>,
);

fn member_at(name: &str, index: usize) -> crate::ir::Member {
    crate::ir::Member {
        name: name.into(),
        index: index as u32,
    }
}

fn member(
    cx: &mut Cx,
    env: &Env,
    ty: &Ty,
    prev: &str,
    part: &Ident,
    section: Section,
) -> Option<Member> {
    match ty {
        Ty::Fb(fb) if env.pou(fb).is_some() => {
            let sig = env.pou(fb)?;
            let Some((i, v)) = sig.var(&part.name) else {
                let names = sig.vars.iter().map(|v| v.name.as_str()).collect();
                cx.err(
                    BAD_CONFIG,
                    part.span,
                    format!(
                        "{} `{}` has no variable `{part}`",
                        sig.kind.keyword(),
                        sig.name
                    ),
                )
                .help = hint(&part.name, names);
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
            Some((
                member_at(&v.name, i),
                v.ty.clone(),
                v.range,
                v.constant,
                v.partly.clone(),
            ))
        }
        Ty::Fb(fb) if crate::sema::stdfb::lookup(fb).is_some() => {
            let std = crate::sema::stdfb::lookup(fb)?;
            let params = || std.inputs.iter().chain(&std.outputs);
            let Some((i, (name, elem))) = params().enumerate().find(|(_, (n, _))| part.is(n))
            else {
                let names = params().map(|(n, _)| *n).collect();
                cx.err(
                    BAD_CONFIG,
                    part.span,
                    format!(
                        "the standard block {} has no input or output `{part}`",
                        std.name
                    ),
                )
                .help = hint(&part.name, names);
                return None;
            };
            Some((member_at(name, i), Ty::Elem(*elem), None, false, None))
        }
        Ty::Struct(s) if section == Section::Access => {
            let fields = env.types.structs.get(&s.to_ascii_uppercase())?;
            let Some((i, f)) = fields.iter().enumerate().find(|(_, f)| part.is(&f.name)) else {
                let names = fields.iter().map(|f| f.name.as_str()).collect();
                cx.err(
                    BAD_CONFIG,
                    part.span,
                    format!("the structure {s} has no member `{part}`"),
                )
                .help = hint(&part.name, names);
                return None;
            };
            Some((member_at(&f.name, i), f.ty.clone(), f.range, false, None))
        }
        Ty::Struct(_) => {
            cx.err(
                BAD_CONFIG,
                part.span,
                format!(
                    "VAR_CONFIG names a whole variable of a program or FB instance (Ed.2 2.7.1: `Res.Prog.fb.x`), not the member `{part}` of a structure: give the structure's initial value (`(a := 1)`), or name the member in VAR_ACCESS"
                ),
            );
            None
        }
        t => {
            cx.err(
                BAD_CONFIG,
                part.span,
                format!("`{prev}` is {t}, which has no members"),
            );
            None
        }
    }
}

/// The value of a subscript of a configuration path: integer literals
/// joined by `+ - * / MOD`, parentheses and unary minus (a path names one
/// place for the whole run), folded exactly.
fn constant_subscript(cx: &mut Cx, s: &Subscript) -> Option<(i128, Span)> {
    match s {
        Subscript::Operand(Operand::Lit(l)) => match &l.kind {
            LitKind::Int(n) => Some((n.get(), l.span)),
            _ => {
                cx.err(BAD_INDEX, l.span, "a subscript must be an integer");
                None
            }
        },
        Subscript::Operand(o) => {
            cx.err(
                BAD_CONFIG,
                o.span(),
                "a subscript of a configuration path must be a constant (integer literals with `+ - * / MOD`): the path names one place for the whole run",
            );
            None
        }
        Subscript::Neg { operand, span } => {
            let (n, _) = constant_subscript(cx, operand)?;
            Some((-n, *span))
        }
        Subscript::Bin { op, lhs, rhs, span } => {
            let (l, _) = constant_subscript(cx, lhs)?;
            let (r, _) = constant_subscript(cx, rhs)?;
            if r == 0 && matches!(op, ExprOp::Div | ExprOp::Mod) {
                cx.err(BAD_INDEX, *span, "the subscript divides by zero");
                return None;
            }
            let v = crate::ir::path::fold(*op, l, r);
            let Some(v) = v.filter(|v| i64::try_from(*v).is_ok()) else {
                cx.err(BAD_INDEX, *span, "the subscript overflows LINT");
                return None;
            };
            Some((v, *span))
        }
    }
}
