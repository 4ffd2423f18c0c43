//! CONFIGURATION / RESOURCE / TASK: the globals, their binding to the
//! VAR_EXTERNALs of programs and function blocks, and the task table.
//!
//! Binding is by name, as in IEC 61131-3. A global with an address (`AT %QX0.0`)
//! lives in the process image; every VAR_EXTERNAL of that name becomes a
//! located variable, so no reference to it needs passing around.

use super::codes::*;
use super::env::{Env, Names, PouSig};
use super::interface::pou_sig;
use super::ir::{ConfigDef, GlobalRef, ProgramInst, ResourceDef, Retained, Var};
use super::types::Ty;
use super::{Cx, suggest};
use crate::ast::{self, PouKind, Span, VarKind};
use std::collections::HashMap;

/// Check every configuration; returns them with the index of their file.
pub(crate) fn collect(
    cxs: &mut [Cx],
    units: &[&ast::CompilationUnit],
    names: &Names,
    env: &mut Env,
) -> Vec<(usize, ConfigDef)> {
    let configs: Vec<(usize, &ast::Configuration)> = units
        .iter()
        .enumerate()
        .flat_map(|(f, u)| {
            u.items.iter().filter_map(move |i| match i {
                ast::Item::Configuration(c) => Some((f, c)),
                _ => None,
            })
        })
        .collect();
    // Globals first, for every configuration: the located ones bind the
    // VAR_EXTERNALs of every POU before any POU body is checked.
    let mut out = Vec::new();
    for (f, c) in &configs {
        let cx = &mut cxs[*f];
        let globals = globals(cx, names, env, &c.name, &c.globals);
        let mut resources = Vec::new();
        for r in &c.resources {
            let g = globals_of_resource(cx, names, env, c, r, &globals);
            resources.push(g);
        }
        out.push((*f, c, globals, resources));
    }
    for (f, c, globals, resources) in &out {
        let all = globals.iter().chain(resources.iter().flatten());
        for (v, span) in all {
            if let Some(l) = &v.location {
                bind_located(&mut cxs[*f], env, v, l, *span);
            }
        }
        let _ = c;
    }
    let mut result = Vec::new();
    for (f, c, globals, res_globals) in out {
        let cx = &mut cxs[f];
        let mut def = ConfigDef {
            name: c.name.name.to_string(),
            globals: globals.into_iter().map(|(v, _)| v).collect(),
            resources: Vec::new(),
            var_config: Vec::new(),
            access: Vec::new(),
        };
        for (ri, (r, rg)) in c.resources.iter().zip(res_globals).enumerate() {
            let rdef = ResourceDef {
                name: r.name.as_ref().map(|n| n.name.to_string()),
                globals: rg.into_iter().map(|(v, _)| v).collect(),
                tasks: Vec::new(),
                programs: Vec::new(),
            };
            def.resources.push(rdef);
            let tasks = super::config_tasks::tasks(cx, &def, ri, r);
            def.resources[ri].tasks = tasks;
            let programs = programs(cx, env, &def, ri, r);
            def.resources[ri].programs = programs;
        }
        def.var_config = super::config_vars::var_config(cx, names, env, &def, &c.var_config);
        def.access = super::config_vars::access(cx, names, env, &def, &c.var_access);
        result.push((f, def));
    }
    result
}

/// The checked VAR_GLOBAL blocks of a configuration or resource, with the
/// span of each name. Declarations are checked like a PROGRAM's VARs.
fn globals(
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
        super::partly::refuse_in_globals(cx, &mut b);
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
            v.storage =
                super::ir::Storage::of(PouKind::Program, VarKind::Global, v.location.is_some());
            let span = decl_span(&fake.var_blocks, &v.name).unwrap_or(owner.span);
            (v, span)
        })
        .collect()
}

fn globals_of_resource(
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
pub(crate) fn decl_span(blocks: &[ast::VarBlock], name: &str) -> Option<Span> {
    blocks
        .iter()
        .flat_map(|b| &b.decls)
        .flat_map(|d| &d.names)
        .find(|n| n.is(name))
        .map(|n| n.span)
}

/// Every VAR_EXTERNAL named like the located global `g` becomes located there.
fn bind_located(cx: &mut Cx, env: &mut Env, g: &Var, l: &super::ir::Loc, span: Span) {
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
                v.storage = super::ir::Storage::Located;
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

/// A global by name: the resource's first, then the configuration's.
pub(crate) fn lookup(def: &ConfigDef, res: usize, name: &str) -> Option<(GlobalRef, Var)> {
    let find = |vars: &[Var]| vars.iter().position(|v| v.name.eq_ignore_ascii_case(name));
    if let Some(r) = def.resources.get(res)
        && let Some(i) = find(&r.globals)
    {
        return Some((
            GlobalRef {
                resource: Some(res),
                index: i,
            },
            r.globals[i].clone(),
        ));
    }
    let i = find(&def.globals)?;
    Some((
        GlobalRef {
            resource: None,
            index: i,
        },
        def.globals[i].clone(),
    ))
}

pub(crate) fn all_global_names(def: &ConfigDef, res: usize) -> Vec<&str> {
    def.globals
        .iter()
        .chain(
            def.resources
                .get(res)
                .map(|r| r.globals.as_slice())
                .unwrap_or(&[]),
        )
        .map(|v| v.name.as_str())
        .collect()
}

pub(crate) fn unknown_global(
    cx: &mut Cx,
    def: &ConfigDef,
    res: usize,
    name: &ast::Ident,
    what: &str,
) {
    let names = all_global_names(def, res);
    let hint = suggest(&name.name, names).map(|s| format!("did you mean `{s}`?"));
    let d = cx.err(
        BAD_GLOBAL,
        name.span,
        format!(
            "{what}: configuration `{}` has no global `{name}`",
            def.name
        ),
    );
    d.help = hint;
}

fn programs(
    cx: &mut Cx,
    env: &Env,
    def: &ConfigDef,
    res: usize,
    r: &ast::Resource,
) -> Vec<ProgramInst> {
    let tasks = &def.resources[res].tasks;
    let mut out: Vec<ProgramInst> = Vec::new();
    let mut seen: HashMap<String, Span> = HashMap::new();
    for pi in &r.programs {
        if let Some(prev) = seen.get(&pi.name.key()) {
            cx.err(
                DUPLICATE_DECL,
                pi.name.span,
                format!("program instance `{}` is declared twice", pi.name),
            )
            .add_secondary(*prev, "first declared here");
            continue;
        }
        seen.insert(pi.name.key(), pi.name.span);
        let Some(sig) = env
            .pou(&pi.program.name)
            .filter(|s| s.kind == PouKind::Program)
        else {
            let programs = env
                .pous
                .values()
                .filter(|s| s.kind == PouKind::Program)
                .map(|s| s.name.as_str());
            let hint = suggest(&pi.program.name, programs).map(|s| format!("did you mean `{s}`?"));
            let what = match env.pou(&pi.program.name) {
                Some(s) => format!("`{}` is a {}, not a PROGRAM", s.name, s.kind.keyword()),
                None => format!("unknown program `{}`", pi.program),
            };
            let d = cx.err(BAD_CONFIG, pi.program.span, what);
            d.help = hint;
            continue;
        };
        let task = match &pi.task {
            None => None,
            Some(t) => match tasks.iter().position(|x| t.is(&x.name)) {
                Some(i) => Some(i),
                None => {
                    let hint = suggest(&t.name, tasks.iter().map(|x| x.name.as_str()))
                        .map(|s| format!("did you mean `{s}`?"));
                    let d = cx.err(BAD_CONFIG, t.span, format!("unknown task `{t}`"));
                    d.help = hint;
                    continue;
                }
            },
        };
        let mut externals = Vec::new();
        for v in sig
            .vars
            .iter()
            .filter(|v| v.kind == VarKind::External && v.location.is_none())
        {
            match lookup(def, res, &v.name) {
                None => {
                    let near = suggest(&v.name, all_global_names(def, res))
                        .map(|s| format!("the configuration has `{s}`; "))
                        .unwrap_or_default();
                    cx.err(
                        BAD_GLOBAL,
                        pi.span,
                        format!(
                            "program `{}` uses the global `{}` (VAR_EXTERNAL), which configuration `{}` does not declare",
                            sig.name, v.name, def.name
                        ),
                    )
                    .help = Some(format!(
                        "{near}add `{} : {};` to a VAR_GLOBAL block",
                        v.name, v.ty
                    ));
                }
                Some((_, g)) if g.ty != v.ty => {
                    cx.err(
                        BAD_GLOBAL,
                        pi.span,
                        format!(
                            "program `{}` declares VAR_EXTERNAL `{}` : {}, but the global is {}",
                            sig.name, v.name, v.ty, g.ty
                        ),
                    );
                }
                Some((_, g)) if g.constant && !v.constant => {
                    cx.err(
                        BAD_GLOBAL,
                        pi.span,
                        format!(
                            "the global `{}` is CONSTANT: program `{}` must declare it VAR_EXTERNAL CONSTANT",
                            g.name, sig.name
                        ),
                    );
                }
                Some((gr, _)) => externals.push((v.name.clone(), gr, v.constant)),
            }
        }
        let args = super::config_args::program_args(cx, env, def, res, sig, pi, &externals);
        out.push(ProgramInst {
            name: pi.name.name.to_string(),
            program: sig.name.clone(),
            task,
            externals,
            inputs: args.inputs,
            outputs: args.outputs,
            inouts: args.inouts,
            retain: !retained(env, sig).is_empty(),
        });
    }
    out
}

/// The variables of an FB/PROGRAM that its RETAIN snapshot holds.
pub(crate) fn retained(env: &Env, sig: &PouSig) -> Vec<(usize, Retained)> {
    if sig.kind == PouKind::Function {
        return Vec::new();
    }
    sig.vars
        .iter()
        .enumerate()
        .filter(|(_, v)| {
            matches!(v.kind, VarKind::Var | VarKind::Input | VarKind::Output)
                && v.location.is_none()
        })
        .filter_map(|(i, v)| {
            if v.retain {
                return Some((i, Retained::Whole));
            }
            let fb = instance_of(&v.ty)?;
            holds_retain(env, fb, 0).then_some((i, Retained::Nested))
        })
        .collect()
}

/// The FB type of an instance variable (or of an array of instances).
fn instance_of(mut t: &Ty) -> Option<&str> {
    while let Ty::Array(a) = t {
        t = &a.elem;
    }
    match t {
        Ty::Fb(fb) => Some(fb),
        _ => None,
    }
}

/// Whether an instance of `fb` holds a RETAIN variable at any depth.
/// Memoised per FB in `env`, so each FB is looked at once however often its
/// instances repeat; a cycle (an FB holding itself, refused elsewhere) and
/// nesting past the depth bound count as holding nothing.
fn holds_retain(env: &Env, fb: &str, depth: u32) -> bool {
    let key = fb.to_ascii_uppercase();
    if let Some(&known) = env.holds_retain.borrow().get(&key) {
        return known;
    }
    let Some(sig) = env.pou(fb) else { return false };
    if sig.kind == PouKind::Function || depth > 256 {
        return false;
    }
    // In progress: a cycle back here adds nothing.
    env.holds_retain.borrow_mut().insert(key.clone(), false);
    let found = sig
        .vars
        .iter()
        .filter(|v| {
            matches!(v.kind, VarKind::Var | VarKind::Input | VarKind::Output)
                && v.location.is_none()
        })
        .any(|v| {
            v.retain || instance_of(&v.ty).is_some_and(|inner| holds_retain(env, inner, depth + 1))
        });
    env.holds_retain.borrow_mut().insert(key, found);
    found
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
