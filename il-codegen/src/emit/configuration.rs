//! A CONFIGURATION as a struct the host drives: its globals, its program
//! instances, and `run`, which runs the tasks released at the current time.

use super::{item_ident, names, rust_ident, rust_ty, values};
use crate::sema::ir::{ConfigDef, GlobalRef, ProgArg, Var};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

pub(crate) fn emit_config(c: &ConfigDef, opts: super::Options) -> TokenStream {
    let name = item_ident(&c.name);
    // Named resources are sub-structs; the unnamed one is flattened.
    let res_path = |r: usize| -> TokenStream {
        match c.resources.get(r).and_then(|r| r.name.as_ref()) {
            Some(n) => {
                let id = rust_ident(n);
                quote!(self.#id)
            }
            None => quote!(self),
        }
    };
    let global = |g: &GlobalRef| -> (&Var, TokenStream) {
        let (v, base) = match g.resource {
            None => (&c.globals[g.index], quote!(self)),
            Some(r) => (&c.resources[r].globals[g.index], res_path(r)),
        };
        let id = rust_ident(&v.name);
        (v, quote!(#base.#id))
    };
    let read_global = |g: &GlobalRef| -> TokenStream {
        let (v, path) = global(g);
        match &v.location {
            Some(l) => values::io_read(l),
            None => path,
        }
    };

    let (fields, inits) = members(&c.globals, &[]);
    let mut sub_items = TokenStream::new();
    let mut res_fields = TokenStream::new();
    let mut res_inits = TokenStream::new();
    let mut prog_fields = TokenStream::new();
    let mut prog_inits = TokenStream::new();
    for r in &c.resources {
        let programs: Vec<(String, String)> = r
            .programs
            .iter()
            .map(|p| (p.name.clone(), p.program.clone()))
            .collect();
        let (f, i) = members(&r.globals, &programs);
        match &r.name {
            None => {
                prog_fields.extend(f);
                prog_inits.extend(i);
            }
            Some(rn) => {
                let st = rust_ident(&format!("{}__{}", c.name, rn));
                let id = rust_ident(rn);
                let doc = format!(" RESOURCE `{rn}` of CONFIGURATION `{}`.", c.name);
                sub_items.extend(quote! {
                    #[doc = #doc]
                    #[derive(Clone, Debug, PartialEq)]
                    #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all)]
                    pub struct #st { #f }
                    #[allow(dead_code, clippy::all)]
                    impl ::core::default::Default for #st {
                        fn default() -> Self { Self { #i } }
                    }
                });
                let fdoc = format!(" RESOURCE `{rn}`");
                res_fields.extend(quote!(#[doc = #fdoc] pub #id: #st,));
                res_inits.extend(quote!(#id: ::core::default::Default::default(),));
            }
        }
    }

    // Tasks in priority order (ties: declaration order), each with its programs.
    let mut tasks: Vec<(usize, usize)> = c
        .resources
        .iter()
        .enumerate()
        .flat_map(|(r, res)| (0..res.tasks.len()).map(move |t| (r, t)))
        .collect();
    let number = |r: usize, t: usize| -> usize {
        c.resources[..r]
            .iter()
            .map(|x| x.tasks.len())
            .sum::<usize>()
            + t
    };
    tasks.sort_by_key(|&(r, t)| (c.resources[r].tasks[t].priority, number(r, t)));
    let state_ids: Vec<_> = (0..tasks.len())
        .map(|n| format_ident!("__task_{}", n))
        .collect();
    let mut dues = TokenStream::new();
    let mut runs = TokenStream::new();
    let mut infos = Vec::new();
    let run_program = |r: usize, p: usize, task: &str| -> TokenStream {
        let pi = &c.resources[r].programs[p];
        let inst = rust_ident(&pi.name);
        let base = res_path(r);
        let sets = pi.inputs.iter().map(|(n, a)| {
            let f = rust_ident(n);
            let v = match a {
                ProgArg::Const(k) => values::constant(k),
                ProgArg::Global(g) => read_global(g),
            };
            quote!(#base.#inst.#f = #v;)
        });
        let ext = (!pi.externals.is_empty()).then(|| {
            let st = names::ext_ident(&pi.program);
            let fs = pi.externals.iter().map(|(n, g, constant)| {
                let id = rust_ident(n);
                let (_, path) = global(g);
                if *constant {
                    quote!(#id: &#path)
                } else {
                    quote!(#id: &mut #path)
                }
            });
            quote!(#st { #(#fs,)* })
        });
        // VAR_IN_OUTs: the global itself (disjoint fields of `self`).
        let inouts = pi.inouts.iter().map(|(_, g)| {
            let (_, path) = global(g);
            quote!(&mut #path,)
        });
        let outs = pi.outputs.iter().map(|(n, g)| {
            let f = rust_ident(n);
            let (v, path) = global(g);
            let src = quote!(#base.#inst.#f);
            match &v.location {
                Some(l) => values::io_write(l, src),
                None => quote!(#path = #src;),
            }
        });
        let copy_in = super::config_vars::copies(c, r, p, true);
        let copy_out = super::config_vars::copies(c, r, p, false);
        let (tname, pname) = (task, &pi.name);
        quote! {
            __trace(#tname, #pname);
            #(#sets)*
            #copy_in
            #base.#inst.call(__ctx, #(#inouts)* #ext);
            #copy_out
            #(#outs)*
            __ran += 1;
        }
    };
    for (k, &(r, t)) in tasks.iter().enumerate() {
        let task = &c.resources[r].tasks[t];
        let due = format_ident!("__due_{}", k);
        let st = &state_ids[k];
        let single = super::tasks::single(task.single.as_ref(), &read_global);
        let interval = super::tasks::interval(&task.interval, &read_global);
        dues.extend(quote!(let #due = self.#st.due(__now, #interval, #single);));
        let progs: Vec<_> = c.resources[r]
            .programs
            .iter()
            .enumerate()
            .filter(|(_, p)| p.task == Some(t))
            .map(|(p, _)| run_program(r, p, &task.name))
            .collect();
        runs.extend(quote!(if #due { #(#progs)* }));
        let res_name = c.resources[r].name.clone().unwrap_or_default();
        let global_name = |g: &GlobalRef| global(g).0.name.clone();
        let (_, single_name) = super::tasks::info(task.single.as_ref(), &global_name);
        let (ns, interval_from) = super::tasks::info(Some(&task.interval), &global_name);
        let pnames = c.resources[r]
            .programs
            .iter()
            .filter(|p| p.task == Some(t))
            .map(|p| p.name.as_str());
        let (tn, prio) = (&task.name, task.priority);
        infos.push(quote!(::il_std::TaskInfo {
            name: #tn, resource: #res_name, interval: ::il_std::TIME(#ns), priority: #prio,
            interval_from: #interval_from, single: #single_name, programs: &[#(#pnames),*],
        }));
    }
    // Programs without a task run on every call, after the tasks.
    for (r, res) in c.resources.iter().enumerate() {
        for (p, pi) in res.programs.iter().enumerate() {
            if pi.task.is_none() {
                runs.extend(run_program(r, p, ""));
            }
        }
    }
    let ntasks = tasks.len();
    let cfg_inits = super::config_vars::inits(c);
    let fresh = quote! {
        Self {
            #inits
            #prog_inits
            #res_inits
            #(#state_ids: ::il_std::TaskState::new(),)*
        }
    };
    // VAR_CONFIG initial values go onto the fresh configuration.
    let new_self = if cfg_inits.is_empty() {
        fresh
    } else {
        quote!(let mut __s = #fresh; #cfg_inits __s)
    };
    let access = super::access::methods(c);
    let retain = retain_items(c, &name, opts);
    let located = c
        .globals
        .iter()
        .chain(c.resources.iter().flat_map(|r| &r.globals))
        .filter_map(|v| v.location.as_ref().map(|l| super::io::located(&v.name, l)))
        .chain(super::config_vars::located(c));
    let mut io_accessors = TokenStream::new();
    for r in &c.resources {
        let prefix = r.name.as_ref().map(|n| format!("{n}_")).unwrap_or_default();
        io_accessors.extend(super::io::accessors_in(&prefix, &r.globals));
    }
    io_accessors.extend(super::io::accessors(&c.globals));
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
    let visit = super::visit::config(&name, &globals, &top_programs, &named);
    let doc = format!(
        " IEC 61131-3 CONFIGURATION `{}`, generated from Instruction List: its globals and program instances. Call [`{}::run`] once per host cycle with the current time in the context.",
        c.name, name
    );
    quote! {
        #[doc = #doc]
        #[derive(Clone, Debug, PartialEq)]
        #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all)]
        pub struct #name {
            #fields
            #prog_fields
            #res_fields
            #(#state_ids: ::il_std::TaskState,)*
        }

        #[allow(dead_code, clippy::all)]
        impl ::core::default::Default for #name {
            fn default() -> Self {
                #new_self
            }
        }

        #sub_items
        #retain
        #visit

        #[allow(dead_code, non_snake_case, unused_mut, unused_variables, clippy::all)]
        impl #name {
            /// The tasks, highest priority first.
            pub const TASKS: &'static [::il_std::TaskInfo] = &[#(#infos),*];
            /// The located globals (`AT %...`), which live in `Cycle::io`.
            pub const ADDRESSES: &'static [::il_std::Located] = &[#(#located),*];
            #io_accessors
            #access

            /// Runs every task released at `__ctx.now()`, highest priority
            /// first (each task's programs in declaration order), then the
            /// programs without a task. Returns how many programs ran.
            pub fn run(&mut self, __ctx: &mut ::il_std::Cycle) -> usize {
                self.run_traced(__ctx, |_, _| {})
            }

            /// [`Self::run`], calling `__trace(task, program)` before each
            /// program runs (`task` is `""` for programs without a task).
            pub fn run_traced(
                &mut self,
                __ctx: &mut ::il_std::Cycle,
                mut __trace: impl FnMut(&'static str, &'static str),
            ) -> usize {
                let __now = __ctx.now();
                let mut __ran: usize = 0;
                // Every task's release is decided at the same instant.
                #dues
                #runs
                __ran
            }

            /// Periodic releases missed because `run` was called too late, per task (in [`Self::TASKS`] order).
            pub fn overruns(&self) -> [u64; #ntasks] {
                [#(self.#state_ids.overruns()),*]
            }
        }
    }
}

/// The configuration's RETAIN snapshot: its RETAIN globals and the
/// snapshots of its programs (fields of named resources are prefixed
/// `Resource__`).
fn retain_items(c: &ConfigDef, name: &proc_macro2::Ident, opts: super::Options) -> TokenStream {
    let mut fields = Vec::new();
    let mut takes = Vec::new();
    let mut puts = Vec::new();
    let scopes = std::iter::once((None, &c.globals, &[][..])).chain(
        c.resources
            .iter()
            .map(|r| (r.name.as_ref(), &r.globals, &r.programs[..])),
    );
    for (res, globals, programs) in scopes {
        let (base, prefix) = match res {
            Some(r) => {
                let id = rust_ident(r);
                (quote!(self.#id), format!("{r}__"))
            }
            None => (quote!(self), String::new()),
        };
        for v in globals.iter().filter(|v| v.retain && v.location.is_none()) {
            let id = rust_ident(&v.name);
            let f = rust_ident(&format!("{prefix}{}", v.name));
            let ty = rust_ty(&v.ty);
            let doc = format!(" VAR_GLOBAL RETAIN (IL line {})", v.line);
            let sf = super::serde_field(&v.ty, opts);
            fields.push(quote!(#[doc = #doc] #sf pub #f: #ty,));
            takes.push(quote!(#f: ::core::clone::Clone::clone(&#base.#id),));
            puts.push(quote!(#base.#id = ::core::clone::Clone::clone(&s.#f);));
        }
        for p in programs.iter().filter(|p| p.retain) {
            let id = rust_ident(&p.name);
            let f = rust_ident(&format!("{prefix}{}", p.name));
            let ty = names::retain_ident(&p.program);
            let doc = format!(" The RETAIN variables of program instance `{}`", p.name);
            fields.push(quote!(#[doc = #doc] pub #f: #ty,));
            takes.push(quote!(#f: #base.#id.retain(),));
            puts.push(quote!(#base.#id.restore(&s.#f);));
        }
    }
    if fields.is_empty() {
        return quote!();
    }
    let st = names::retain_ident(&c.name);
    let doc = format!(
        " The RETAIN state of CONFIGURATION `{}`: what a host saves before power-off and restores at a warm start.",
        c.name
    );
    super::snapshot_item(name, &st, &doc, (fields, takes, puts), opts)
}

/// Fields and initialisers for globals (not located: those are in the
/// process image) and program instances.
fn unlocated(gs: &[Var]) -> Vec<&Var> {
    gs.iter().filter(|v| v.location.is_none()).collect()
}

fn members(globals: &[Var], programs: &[(String, String)]) -> (TokenStream, TokenStream) {
    let mut fields = TokenStream::new();
    let mut inits = TokenStream::new();
    for v in globals.iter().filter(|v| v.location.is_none()) {
        let id = rust_ident(&v.name);
        let ty = rust_ty(&v.ty);
        let doc = format!(
            " VAR_GLOBAL{}{} (IL line {})",
            if v.constant { " CONSTANT" } else { "" },
            if v.retain { " RETAIN" } else { "" },
            v.line
        );
        let init = values::init_value(&v.ty, v.init.as_ref());
        fields.extend(quote!(#[doc = #doc] pub #id: #ty,));
        inits.extend(quote!(#id: #init,));
    }
    for (inst, prog) in programs {
        let id = rust_ident(inst);
        let ty = item_ident(prog);
        let doc = format!(" PROGRAM instance `{inst}` : {prog}");
        fields.extend(quote!(#[doc = #doc] pub #id: #ty,));
        inits.extend(quote!(#id: ::core::default::Default::default(),));
    }
    (fields, inits)
}
