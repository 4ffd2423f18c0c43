//! The program instances of a resource: `PROGRAM p WITH t : P(...)`, its
//! task, its VAR_EXTERNALs found among the globals and its arguments.

use super::args::program_args;
use super::lookup::{all_global_names, lookup};
use super::retain::retained;
use crate::ast::{self, PouKind, Span, VarKind};
use crate::ir::{ConfigDef, ProgramInst};
use crate::sema::codes::*;
use crate::sema::env::Env;
use crate::sema::{Cx, suggest};
use std::collections::HashMap;

pub(super) fn programs(
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
        for (index, v) in (sig.vars.iter().enumerate())
            .filter(|(_, v)| v.kind == VarKind::External && v.location.is_none())
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
                Some((gr, _)) => {
                    externals.push((super::args::member(index, &v.name), gr, v.constant));
                }
            }
        }
        let args = program_args(cx, env, def, res, sig, pi, &externals);
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
