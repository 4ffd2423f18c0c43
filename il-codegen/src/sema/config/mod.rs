//! CONFIGURATION / RESOURCE / TASK: the globals, their binding to the
//! VAR_EXTERNALs of programs and function blocks, and the task table.
//!
//! Binding is by name, as in IEC 61131-3. A global with an address (`AT %QX0.0`)
//! lives in the process image; every VAR_EXTERNAL of that name becomes a
//! located variable, so no reference to it needs passing around.
//!
//! The steps, each in its own file: [`globals`] (VAR_GLOBAL of a
//! configuration and its resources), [`externals`] (VAR_EXTERNALs bound to
//! them), [`tasks`], [`programs`] (program instances, with their [`args`]),
//! [`vars`] (VAR_CONFIG and VAR_ACCESS, whose [`paths`] it resolves) and
//! [`retain`]. Those that name a global find it through [`lookup`]; none of
//! them imports this file, which only runs them in order.

mod args;
mod externals;
mod globals;
mod lookup;
mod paths;
mod programs;
pub(crate) mod retain;
mod tasks;
mod vars;

use crate::ast;
use crate::ir::{ConfigDef, ResourceDef};
use crate::sema::Cx;
use crate::sema::env::{Env, Names};

pub(crate) use externals::check_fb_externals;

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
        let globals = globals::globals(cx, names, env, &c.name, &c.globals);
        let mut resources = Vec::new();
        for r in &c.resources {
            let g = globals::globals_of_resource(cx, names, env, c, r, &globals);
            resources.push(g);
        }
        out.push((*f, c, globals, resources));
    }
    for (f, c, globals, resources) in &out {
        let all = globals.iter().chain(resources.iter().flatten());
        for (v, span) in all {
            if let Some(l) = &v.location {
                externals::bind_located(&mut cxs[*f], env, v, l, *span);
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
            let tasks = tasks::tasks(cx, &def, ri, r);
            def.resources[ri].tasks = tasks;
            let programs = programs::programs(cx, env, &def, ri, r);
            def.resources[ri].programs = programs;
        }
        def.var_config = vars::var_config(cx, names, env, &def, &c.var_config);
        def.access = vars::access(cx, names, env, &def, &c.var_access);
        result.push((f, def));
    }
    result
}
