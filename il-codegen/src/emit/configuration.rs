//! A CONFIGURATION as a struct the host drives: its globals, its program
//! instances, and `run`, which runs the tasks released at the current time.

use super::text::{Out, doc, each, join, str_lit};
use super::{item_ident, names, rust_ident, rust_ty, values};
use crate::ir::{ConfigDef, GlobalRef, ProgArg, Var};

pub(crate) fn emit_config(o: &mut Out, c: &ConfigDef, opts: super::Options) {
    let name = item_ident(&c.name);
    // Named resources are sub-structs; the unnamed one is flattened.
    let res_path = |r: usize| -> String {
        match c.resources.get(r).and_then(|r| r.name.as_ref()) {
            Some(n) => format!("self.{}", rust_ident(n)),
            None => "self".to_string(),
        }
    };
    let global = |g: &GlobalRef| -> (&Var, String) {
        let (v, base) = match g.resource {
            None => (&c.globals[g.index], "self".to_string()),
            Some(r) => (&c.resources[r].globals[g.index], res_path(r)),
        };
        let id = rust_ident(&v.name);
        (v, format!("{base}.{id}"))
    };
    let read_global = |g: &GlobalRef| -> String {
        let (v, path) = global(g);
        match &v.location {
            Some(l) => values::io_read(l),
            None => path,
        }
    };

    let (fields, inits) = members(&c.globals, &[]);
    let mut sub_items = String::new();
    let mut res_fields = String::new();
    let mut res_inits = String::new();
    let mut prog_fields = String::new();
    let mut prog_inits = String::new();
    for r in &c.resources {
        let programs: Vec<(String, String)> = r
            .programs
            .iter()
            .map(|p| (p.name.clone(), p.program.clone()))
            .collect();
        let (f, i) = members(&r.globals, &programs);
        match &r.name {
            None => {
                prog_fields.push_str(&f);
                prog_inits.push_str(&i);
            }
            Some(rn) => {
                let st = rust_ident(&format!("{}__{}", c.name, rn));
                let id = rust_ident(rn);
                let d = doc(&format!(" RESOURCE `{rn}` of CONFIGURATION `{}`.", c.name));
                sub_items.push_str(&format!(
                    "{d}#[derive(Clone, Debug, PartialEq)] #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all, clippy::pedantic)] pub struct {st} {{ {f} }} \
                     #[allow(dead_code, clippy::all, clippy::pedantic)] impl ::core::default::Default for {st} {{ fn default() -> Self {{ Self {{ {i} }} }} }}"
                ));
                let fdoc = doc(&format!(" RESOURCE `{rn}`"));
                res_fields.push_str(&format!("{fdoc}pub {id}: {st},"));
                res_inits.push_str(&format!("{id}: ::core::default::Default::default(),"));
            }
        }
    }

    // Tasks in priority order (ties: declaration order), each with its programs.
    let tasks = c.task_order();
    let state_ids: Vec<_> = (0..tasks.len()).map(|n| format!("__task_{n}")).collect();
    let mut dues = String::new();
    let mut runs = String::new();
    let mut infos = Vec::new();
    let run_program = |r: usize, p: usize, task: &str| -> String {
        let pi = &c.resources[r].programs[p];
        let inst = rust_ident(&pi.name);
        let base = res_path(r);
        let sets: String = pi
            .inputs
            .iter()
            .map(|(n, a)| {
                let f = rust_ident(&n.name);
                let v = match a {
                    ProgArg::Const(k) => values::constant(k),
                    ProgArg::Global(g) => read_global(g),
                };
                format!("{base}.{inst}.{f} = {v};")
            })
            .collect();
        let ext = if pi.externals.is_empty() {
            String::new()
        } else {
            let st = names::ext_ident(&pi.program);
            let fs = pi.externals.iter().map(|(n, g, constant)| {
                let id = rust_ident(&n.name);
                let (_, path) = global(g);
                if *constant {
                    format!("{id}: &{path}")
                } else {
                    format!("{id}: &mut {path}")
                }
            });
            format!(", {st} {{ {} }}", join(fs, ", "))
        };
        // VAR_IN_OUTs: the global itself (disjoint fields of `self`).
        let inouts: String = pi
            .inouts
            .iter()
            .map(|(_, g)| format!(", &mut {}", global(g).1))
            .collect();
        let outs: String = pi
            .outputs
            .iter()
            .map(|(n, g)| {
                let f = rust_ident(&n.name);
                let (v, path) = global(g);
                let src = format!("{base}.{inst}.{f}");
                match &v.location {
                    Some(l) => values::io_write(l, src),
                    None => format!("{path} = {src};"),
                }
            })
            .collect();
        let copy_in = super::config_vars::copies(c, r, p, true);
        let copy_out = super::config_vars::copies(c, r, p, false);
        let (tname, pname) = (str_lit(task), str_lit(&pi.name));
        format!(
            "__trace({tname}, {pname}); {sets} {copy_in} {base}.{inst}.call(__ctx{inouts}{ext}); {copy_out} {outs} __ran += 1;"
        )
    };
    for (k, &(r, t)) in tasks.iter().enumerate() {
        let task = &c.resources[r].tasks[t];
        let due = format!("__due_{k}");
        let st = &state_ids[k];
        let single = super::tasks::single(task.single.as_ref(), &read_global);
        let interval = super::tasks::interval(&task.interval, &read_global);
        dues.push_str(&format!(
            "let {due} = self.{st}.due(__now, {interval}, {single});"
        ));
        let progs: Vec<_> = c.resources[r]
            .programs
            .iter()
            .enumerate()
            .filter(|(_, p)| p.task == Some(t))
            .map(|(p, _)| run_program(r, p, &task.name))
            .collect();
        runs.push_str(&format!("if {due} {{ {} }}", progs.concat()));
        let res_name = str_lit(&c.resources[r].name.clone().unwrap_or_default());
        let global_name = |g: &GlobalRef| global(g).0.name.clone();
        let (_, single_name) = super::tasks::info(task.single.as_ref(), &global_name);
        let (ns, interval_from) = super::tasks::info(Some(&task.interval), &global_name);
        let pnames = c.resources[r]
            .programs
            .iter()
            .filter(|p| p.task == Some(t))
            .map(|p| str_lit(&p.name));
        let (tn, prio) = (str_lit(&task.name), task.priority);
        infos.push(format!(
            "::il_std::TaskInfo {{ name: {tn}, resource: {res_name}, interval: ::il_std::TIME({ns}i64), priority: {prio}, interval_from: {interval_from}, single: {single_name}, programs: &[{}], }}",
            join(pnames, ", ")
        ));
    }
    // Programs without a task run on every call, after the tasks.
    for (r, res) in c.resources.iter().enumerate() {
        for (p, pi) in res.programs.iter().enumerate() {
            if pi.task.is_none() {
                runs.push_str(&run_program(r, p, ""));
            }
        }
    }
    let ntasks = tasks.len();
    let located = c
        .globals
        .iter()
        .chain(c.resources.iter().flat_map(|r| &r.globals))
        .filter_map(|v| {
            v.location
                .as_ref()
                .map(|l| super::io::located(&v.name, l, v.retain))
        })
        .chain(super::config_vars::located(c));
    let located = each(located, ", ");
    let mut io_accessors = String::new();
    for r in &c.resources {
        let prefix = r.name.as_ref().map(|n| format!("{n}_")).unwrap_or_default();
        io_accessors.push_str(&super::io::accessors_in(&prefix, &r.globals));
    }
    io_accessors.push_str(&super::io::accessors(&c.globals));
    // Globals not located (those are in `Cycle::io`), the unnamed resource's
    // programs, then each named resource as a scope.
    let mut top_programs = Vec::new();
    let mut named = Vec::new();
    for r in &c.resources {
        let progs: Vec<&str> = r.programs.iter().map(|p| p.name.as_str()).collect();
        match &r.name {
            None => top_programs.extend(progs.iter().map(|p| (None, *p))),
            Some(rn) => named.push((rn.as_str(), unlocated(&r.globals), progs)),
        }
    }
    let mut globals = unlocated(&c.globals);
    // The unnamed resource's globals are flattened into the struct too.
    for r in c.resources.iter().filter(|r| r.name.is_none()) {
        globals.extend(unlocated(&r.globals));
    }
    let d = doc(&format!(
        " IEC 61131-3 CONFIGURATION `{}`, generated from Instruction List: its globals and program instances. Call [`{}::run`] once per host cycle with the current time in the context.",
        c.name, name
    ));
    let state_fields = each(
        state_ids
            .iter()
            .map(|s| format!("{s}: ::il_std::TaskState")),
        ", ",
    );
    let state_inits = each(
        state_ids
            .iter()
            .map(|s| format!("{s}: ::il_std::TaskState::new()")),
        ", ",
    );
    let fresh = format!("Self {{ {inits} {prog_inits} {res_inits} {state_inits} }}");
    // VAR_CONFIG initial values go onto the fresh configuration.
    let cfg_inits = super::config_vars::inits(c);
    let new_self = if cfg_inits.is_empty() {
        fresh
    } else {
        format!("let mut __s = {fresh}; {cfg_inits} __s")
    };
    let access = super::access::methods(c);
    o.code(&format!(
        "{d}#[derive(Clone, Debug, PartialEq)] #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all, clippy::pedantic)] pub struct {name} {{ {fields} {prog_fields} {res_fields} {state_fields} }} \
         #[allow(dead_code, clippy::all, clippy::pedantic)] impl ::core::default::Default for {name} {{ fn default() -> Self {{ {new_self} }} }} \
         {sub_items}"
    ));
    retain_items(o, c, &name, opts);
    super::visit::config(o, &name, &globals, &top_programs, &named);
    let infos = each(infos, ", ");
    let overruns = join(
        state_ids.iter().map(|s| format!("self.{s}.overruns()")),
        ", ",
    );
    o.code(&format!(
        "#[allow(dead_code, non_snake_case, unused_mut, unused_variables, clippy::all, clippy::pedantic)] impl {name} {{ \
         /// The tasks, highest priority first.\n\
         pub const TASKS: &'static [::il_std::TaskInfo] = &[\n{infos}]; \
         /// The located globals (`AT %...`), which live in `Cycle::io`.\n\
         pub const ADDRESSES: &'static [::il_std::Located] = &[\n{located}]; \
         {io_accessors} {access} \
         /// Runs every task released at `__ctx.now()`, highest priority\n\
         /// first (each task's programs in declaration order), then the\n\
         /// programs without a task. Returns how many programs ran.\n\
         pub fn run(&mut self, __ctx: &mut ::il_std::Cycle) -> usize {{ self.run_traced(__ctx, |_, _| {{}}) }} \
         /// [`Self::run`], calling `__trace(task, program)` before each\n\
         /// program runs (`task` is `\"\"` for programs without a task).\n\
         pub fn run_traced(&mut self, __ctx: &mut ::il_std::Cycle, mut __trace: impl FnMut(&'static str, &'static str)) -> usize {{ \
         let __now = __ctx.now(); let mut __ran: usize = 0; \
         {dues} {runs} __ran }} \
         /// Periodic releases missed because `run` was called too late, per task (in [`Self::TASKS`] order).\n\
         pub fn overruns(&self) -> [u64; {ntasks}] {{ [{overruns}] }} }}"
    ));
}

/// The configuration's RETAIN snapshot: its RETAIN globals and the
/// snapshots of its programs (fields of named resources are prefixed
/// `Resource__`).
fn retain_items(o: &mut Out, c: &ConfigDef, name: &str, opts: super::Options) {
    let mut fields = String::new();
    let mut takes = String::new();
    let mut puts = String::new();
    let scopes = std::iter::once((None, &c.globals, &[][..])).chain(
        c.resources
            .iter()
            .map(|r| (r.name.as_ref(), &r.globals, &r.programs[..])),
    );
    for (res, globals, programs) in scopes {
        let (base, prefix) = match res {
            Some(r) => (format!("self.{}", rust_ident(r)), format!("{r}__")),
            None => ("self".to_string(), String::new()),
        };
        for v in globals.iter().filter(|v| v.retain && v.location.is_none()) {
            let id = rust_ident(&v.name);
            let f = rust_ident(&format!("{prefix}{}", v.name));
            let ty = rust_ty(&v.ty);
            let d = doc(&format!(" `VAR_GLOBAL RETAIN` (IL line {})", v.line));
            let sf = super::serde_field(&v.ty, opts);
            fields.push_str(&format!("{d}{sf} pub {f}: {ty},"));
            takes.push_str(&format!("{f}: ::core::clone::Clone::clone(&{base}.{id}),"));
            puts.push_str(&format!(
                "{base}.{id} = ::core::clone::Clone::clone(&s.{f});"
            ));
        }
        for p in programs.iter().filter(|p| p.retain) {
            let id = rust_ident(&p.name);
            let f = rust_ident(&format!("{prefix}{}", p.name));
            let ty = names::retain_ident(&p.program);
            let d = doc(&format!(
                " The RETAIN variables of program instance `{}`",
                p.name
            ));
            fields.push_str(&format!("{d}pub {f}: {ty},"));
            takes.push_str(&format!("{f}: {base}.{id}.retain(),"));
            puts.push_str(&format!("{base}.{id}.restore(&s.{f});"));
        }
    }
    if fields.is_empty() {
        return;
    }
    let st = names::retain_ident(&c.name);
    let doc = format!(
        " The RETAIN state of CONFIGURATION `{}`: what a host saves before power-off and restores at a warm start.",
        c.name
    );
    super::snapshot_item(o, name, &st, &doc, (fields, takes, puts), opts)
}

/// Fields and initialisers for globals (not located: those are in the
/// process image) and program instances.
fn unlocated(gs: &[Var]) -> Vec<&Var> {
    gs.iter().filter(|v| v.location.is_none()).collect()
}

fn members(globals: &[Var], programs: &[(String, String)]) -> (String, String) {
    let mut fields = String::new();
    let mut inits = String::new();
    for v in globals.iter().filter(|v| v.location.is_none()) {
        let id = rust_ident(&v.name);
        let ty = rust_ty(&v.ty);
        let d = doc(&format!(
            " `VAR_GLOBAL{}{}` (IL line {})",
            if v.constant { " CONSTANT" } else { "" },
            if v.retain { " RETAIN" } else { "" },
            v.line
        ));
        let init = values::init_value(&v.ty, v.init.as_ref());
        fields.push_str(&format!("{d}pub {id}: {ty},"));
        inits.push_str(&format!("{id}: {init},"));
    }
    for (inst, prog) in programs {
        let id = rust_ident(inst);
        let ty = item_ident(prog);
        let d = doc(&format!(" PROGRAM instance `{inst}` : {prog}"));
        fields.push_str(&format!("{d}pub {id}: {ty},"));
        inits.push_str(&format!("{id}: ::core::default::Default::default(),"));
    }
    (fields, inits)
}
