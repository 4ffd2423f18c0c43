//! A CONFIGURATION run by the interpreter as the generated struct runs it:
//! its globals, its program instances, and `run`, which decides every task's
//! release at the same instant (`il_std::TaskState`, the same code as the
//! emitted scheduler) and then runs the released tasks by priority, each
//! task's programs in declaration order, then the programs without a task.
//!
//! A program instance keeps its VAR_EXTERNALs and VAR_IN_OUTs as its own
//! memory (see [`Storage::External`]); around each run they are copied in
//! from the globals and back out. Programs run one after the other, so this
//! is the same as the references the generated code passes.

use crate::places::{Step, io_read, io_write};
use crate::values::{Instance, Value};
use crate::{Machine, find_var};
use il_codegen::ir::Area;
use il_codegen::ir::{
    AccessTarget, ConfigDef, GlobalRef, InstancePath, PathElem, ProgArg, Program, TaskSource,
};
use il_std::{Cycle, TIME, TaskState};

/// An instance of a CONFIGURATION ready to run.
#[derive(Clone, Debug)]
pub struct ConfigMachine {
    pub(crate) m: Machine,
    pub(crate) def: std::sync::Arc<ConfigDef>,
    globals: Vec<Value>,
    res_globals: Vec<Vec<Value>>,
    /// Per resource, its program instances in declaration order.
    pub(crate) programs: Vec<Vec<Instance>>,
    /// (resource, task) in the order they run: priority, then declaration.
    order: Vec<(usize, usize)>,
    states: Vec<TaskState>,
}

impl ConfigMachine {
    /// [`Machine::host_function`] for every program of the configuration.
    pub fn host_function(
        &mut self,
        name: &str,
        f: impl Fn(&mut il_std::Cycle, &mut [Value]) -> Value + Send + Sync + 'static,
    ) -> Result<(), String> {
        self.m.host_function(name, f)
    }

    /// The CONFIGURATION `name` (case-insensitive) with its initial values.
    pub fn new(prog: &Program, name: &str) -> Result<ConfigMachine, String> {
        let def = prog
            .configs
            .iter()
            .find(|c| c.name.eq_ignore_ascii_case(name))
            .cloned()
            .ok_or_else(|| {
                let avail: Vec<&str> = prog.configs.iter().map(|c| c.name.as_str()).collect();
                format!(
                    "no CONFIGURATION named `{name}` (there is {})",
                    if avail.is_empty() {
                        "none".to_string()
                    } else {
                        avail.join(", ")
                    }
                )
            })?;
        let m = Machine::bare(prog);
        let init = |vs: &[il_codegen::ir::Var]| -> Result<Vec<Value>, String> {
            vs.iter()
                .map(|v| m.init_of(&v.ty, v.init.as_ref()))
                .collect()
        };
        let globals = init(&def.globals)?;
        let res_globals = def
            .resources
            .iter()
            .map(|r| init(&r.globals))
            .collect::<Result<_, _>>()?;
        let mut programs = Vec::new();
        for r in &def.resources {
            let mut insts = Vec::new();
            for p in &r.programs {
                let pou = m
                    .prog
                    .pous
                    .iter()
                    .position(|x| x.name.eq_ignore_ascii_case(&p.program))
                    .ok_or_else(|| format!("internal: no program `{}`", p.program))?;
                insts.push(m.new_instance(pou)?);
            }
            programs.push(insts);
        }
        let order = def.task_order();
        let states = vec![TaskState::new(); order.len()];
        let mut c = ConfigMachine {
            m,
            def: std::sync::Arc::new(def),
            globals,
            res_globals,
            programs,
            order,
            states,
        };
        // VAR_CONFIG initial values, over the declared ones.
        let def = std::sync::Arc::clone(&c.def);
        for v in &def.var_config {
            if let Some(i) = &v.init {
                let val = c.m.init_of(&v.target.ty, Some(i))?;
                c.set_field(&v.target, val)?;
            }
        }
        Ok(c)
    }

    /// [`Machine::set_hook`]: a debugger for every program of the configuration.
    pub fn set_hook(&mut self, hook: Option<Box<dyn crate::Hook>>) {
        self.m.set_hook(hook);
    }

    /// [`Machine::set_locate`], for every program of the configuration.
    pub fn set_locate(&mut self, f: crate::Locate) {
        self.m.set_locate(f);
    }

    /// [`Machine::take_hook`].
    pub fn take_hook<T: crate::Hook>(&mut self) -> Option<Box<T>> {
        self.m.take_hook()
    }

    /// [`Machine::hook_mut`].
    pub fn hook_mut<T: crate::Hook>(&mut self) -> Option<&mut T> {
        self.m.hook_mut()
    }

    /// The configuration this machine runs.
    pub fn def(&self) -> &ConfigDef {
        &self.def
    }

    /// A global's value: `name` of the configuration (or of the unnamed
    /// resource), or `Resource.name`. Located globals: `None` (they are in
    /// the process image).
    pub fn global(&self, name: &str) -> Option<Value> {
        let g = self.find_global(name)?;
        if self.var_of(g).location.is_some() {
            return None;
        }
        Some(self.slot(g).clone())
    }

    /// Set an unlocated global (the value must have its type).
    pub fn set_global(&mut self, name: &str, v: Value) -> Result<(), String> {
        let g = self
            .find_global(name)
            .ok_or_else(|| format!("configuration `{}` has no global `{name}`", self.def.name))?;
        if self.var_of(g).location.is_some() {
            return Err(format!("`{name}` is in the process image"));
        }
        *self.slot_mut(g) = v;
        Ok(())
    }

    /// A variable of program instance `inst` (`Resource.inst` for a named resource).
    pub fn program_var(&self, inst: &str, var: &str) -> Option<Value> {
        let (r, p) = self.find_program(inst)?;
        let i = &self.programs[r][p];
        let idx = find_var(&self.m.prog.pous[i.pou], var)?;
        Some(i.vars[idx].clone())
    }

    /// Read the VAR_ACCESS path `name`.
    pub fn access(&self, name: &str) -> Option<Value> {
        let a = self
            .def
            .access
            .iter()
            .find(|a| a.name.eq_ignore_ascii_case(name))?;
        match &a.target {
            AccessTarget::Global { global, steps } => self.global_at(*global, steps).ok(),
            AccessTarget::Instance(p) => self.field(p).ok(),
        }
    }

    /// Write the VAR_ACCESS path `name`; refused for READ_ONLY ones.
    pub fn set_access(&mut self, name: &str, v: Value) -> Result<(), String> {
        let a = self
            .def
            .access
            .iter()
            .find(|a| a.name.eq_ignore_ascii_case(name))
            .cloned()
            .ok_or_else(|| format!("no access path `{name}`"))?;
        if !a.writable {
            return Err(format!("the access path `{}` is READ_ONLY", a.name));
        }
        // As the generated setter: a value outside the subrange is refused.
        if let (Some((lo, hi)), Value::Int(x, _)) = (a.range, &v)
            && (*x < lo || *x > hi)
        {
            return Err(format!(
                "{x} is outside the subrange {lo}..{hi} of the access path `{}` ({})",
                a.name,
                il_std::FaultKind::SubrangeViolation
            ));
        }
        match &a.target {
            AccessTarget::Global { global, steps } => self.set_global_at(*global, steps, v)?,
            AccessTarget::Instance(p) => self.set_field(p, v)?,
        }
        Ok(())
    }

    /// Missed periodic releases per task, in run order (as the generated `overruns`).
    pub fn overruns(&self) -> Vec<u64> {
        self.states.iter().map(|s| s.overruns()).collect()
    }

    /// Run every task released at `ctx.now()`; how many programs ran.
    pub fn run(&mut self, ctx: &mut Cycle) -> Result<usize, String> {
        self.run_traced(ctx, |_, _| {})
    }

    /// [`Self::run`], calling `trace(task, program)` before each program
    /// (`task` is `""` for programs without a task).
    pub fn run_traced(
        &mut self,
        ctx: &mut Cycle,
        mut trace: impl FnMut(&str, &str),
    ) -> Result<usize, String> {
        let now = ctx.now();
        // Every task's release is decided at the same instant.
        let mut due = Vec::with_capacity(self.order.len());
        for k in 0..self.order.len() {
            let (r, t) = self.order[k];
            let task = &self.def.resources[r].tasks[t];
            let interval = match &task.interval {
                TaskSource::Fixed(ns) => *ns,
                TaskSource::Global(g) => self.read(ctx, *g).as_i64(),
                TaskSource::Addr(_) => 0,
            };
            let single = task.single.as_ref().map(|s| match s {
                TaskSource::Fixed(b) => *b,
                TaskSource::Global(g) => self.read(ctx, *g).as_bool(),
                TaskSource::Addr(l) => io_read(ctx, l).as_bool(),
            });
            due.push(self.states[k].due(now, TIME(interval), single));
        }
        let mut ran = 0;
        for (k, &(r, t)) in self.order.clone().iter().enumerate() {
            if !due[k] {
                continue;
            }
            for p in 0..self.def.resources[r].programs.len() {
                if self.def.resources[r].programs[p].task == Some(t) {
                    let task = self.def.resources[r].tasks[t].name.clone();
                    trace(&task, &self.def.resources[r].programs[p].name);
                    self.run_program(ctx, r, p)?;
                    ran += 1;
                }
            }
        }
        for r in 0..self.def.resources.len() {
            for p in 0..self.def.resources[r].programs.len() {
                if self.def.resources[r].programs[p].task.is_none() {
                    trace("", &self.def.resources[r].programs[p].name);
                    self.run_program(ctx, r, p)?;
                    ran += 1;
                }
            }
        }
        Ok(ran)
    }

    fn run_program(&mut self, ctx: &mut Cycle, r: usize, p: usize) -> Result<(), String> {
        // The definition is shared (an Arc), so a scan clones none of it.
        let def = std::sync::Arc::clone(&self.def);
        let pi = &def.resources[r].programs[p];
        let mut inst = std::mem::take(&mut self.programs[r][p]);
        // The program's variable of each argument, as the checker decided.
        let idx = |inst: &Instance, n: &il_codegen::ir::Member| {
            let i = n.index as usize;
            (i < inst.vars.len())
                .then_some(i)
                .ok_or_else(|| format!("internal: no variable `{n}`"))
        };
        for (n, a) in &pi.inputs {
            let v = match a {
                ProgArg::Const(c) => Value::from_const(c),
                ProgArg::Global(g) => self.read(ctx, *g),
            };
            let i = idx(&inst, n)?;
            inst.vars[i] = v;
        }
        let refs = pi
            .externals
            .iter()
            .map(|(n, g, _)| (n, g))
            .chain(pi.inouts.iter().map(|(n, g)| (n, g)));
        for (n, g) in refs.clone() {
            let i = idx(&inst, n)?;
            inst.vars[i] = self.slot(*g).clone();
        }
        self.programs[r][p] = inst;
        self.copy_config(ctx, r, p, true)?;
        let mut inst = std::mem::take(&mut self.programs[r][p]);
        self.m.steps = 0;
        self.m.error_located = false;
        if self.m.dbg.on() {
            self.m.dbg_enter(pi.name.clone());
            let globals = self.debug_globals(ctx);
            self.m.dbg_globals(globals);
        }
        let result = self.m.call_instance(&mut inst, ctx);
        for (n, g) in refs {
            let v = inst.vars[idx(&inst, n)?].clone();
            *self.slot_mut(*g) = v;
        }
        for (n, g) in &pi.outputs {
            let v = inst.vars[idx(&inst, n)?].clone();
            match &self.var_of(*g).location {
                Some(l) => io_write(ctx, l, &v),
                None => *self.slot_mut(*g) = v,
            }
        }
        self.programs[r][p] = inst;
        self.copy_config(ctx, r, p, false)?;
        result
    }

    /// The VAR_CONFIG addresses of program `p` of resource `r`: `%I`/`%M`
    /// into the field before the run, the field to `%Q`/`%M` after it.
    fn copy_config(
        &mut self,
        ctx: &mut Cycle,
        r: usize,
        p: usize,
        before: bool,
    ) -> Result<(), String> {
        let def = std::sync::Arc::clone(&self.def);
        for v in &def.var_config {
            let Some(l) = &v.location else { continue };
            if (v.target.resource, v.target.program) != (r, p) {
                continue;
            }
            match (before, l.area) {
                (true, Area::Input | Area::Memory) => self.set_field(&v.target, io_read(ctx, l))?,
                (false, Area::Output | Area::Memory) => io_write(ctx, l, &self.field(&v.target)?),
                _ => {}
            }
        }
        Ok(())
    }

    /// The value a path names (a standard block's member read from it).
    pub(crate) fn field(&self, p: &InstancePath) -> Result<Value, String> {
        let (i, rest) = path_steps(&p.steps)?;
        let inst = &self.programs[p.resource][p.program];
        let var = inst
            .vars
            .get(i)
            .ok_or_else(|| format!("internal: no variable {i} for `{}`", p.text))?;
        self.m
            .read_at(var, &rest)
            .ok_or_else(|| format!("internal: cannot read `{}`", p.text))
    }

    /// Write the value a path names.
    pub(crate) fn set_field(&mut self, p: &InstancePath, v: Value) -> Result<(), String> {
        let (i, rest) = path_steps(&p.steps)?;
        let slot = self.programs[p.resource][p.program]
            .vars
            .get_mut(i)
            .ok_or_else(|| format!("internal: no variable {i} for `{}`", p.text))?;
        if self.m.write_at(slot, &rest, v) {
            Ok(())
        } else {
            Err(format!("internal: cannot write `{}`", p.text))
        }
    }

    /// The value of a global access path (`g`, `g.field`, `g[3]`).
    pub(crate) fn global_at(&self, g: GlobalRef, steps: &[PathElem]) -> Result<Value, String> {
        let steps = interp_steps(steps)?;
        self.m
            .read_at(self.slot(g), &steps)
            .ok_or_else(|| "internal: cannot read a global's path".to_string())
    }

    /// Write a global access path.
    pub(crate) fn set_global_at(
        &mut self,
        g: GlobalRef,
        steps: &[PathElem],
        v: Value,
    ) -> Result<(), String> {
        let steps = interp_steps(steps)?;
        let mut slot = std::mem::replace(self.slot_mut(g), Value::Bool(false));
        let ok = self.m.write_at(&mut slot, &steps, v);
        *self.slot_mut(g) = slot;
        if ok {
            Ok(())
        } else {
            Err("internal: cannot write a global's path".into())
        }
    }

    /// Every global with its value, named as a host names it (`g`,
    /// `Resource.g` for a named resource's), for a debugger.
    #[cold]
    fn debug_globals(&self, ctx: &Cycle) -> Vec<(String, Value, il_codegen::ir::types::Ty)> {
        let mut out = Vec::new();
        for (i, v) in self.def.globals.iter().enumerate() {
            let g = GlobalRef {
                resource: None,
                index: i,
            };
            out.push((v.name.clone(), self.read(ctx, g), v.ty.clone()));
        }
        for (r, res) in self.def.resources.iter().enumerate() {
            for (i, v) in res.globals.iter().enumerate() {
                let g = GlobalRef {
                    resource: Some(r),
                    index: i,
                };
                let name = match &res.name {
                    Some(rn) => format!("{rn}.{}", v.name),
                    None => v.name.clone(),
                };
                out.push((name, self.read(ctx, g), v.ty.clone()));
            }
        }
        out
    }

    pub(crate) fn var_of(&self, g: GlobalRef) -> &il_codegen::ir::Var {
        match g.resource {
            None => &self.def.globals[g.index],
            Some(r) => &self.def.resources[r].globals[g.index],
        }
    }

    pub(crate) fn slot(&self, g: GlobalRef) -> &Value {
        match g.resource {
            None => &self.globals[g.index],
            Some(r) => &self.res_globals[r][g.index],
        }
    }

    pub(crate) fn slot_mut(&mut self, g: GlobalRef) -> &mut Value {
        match g.resource {
            None => &mut self.globals[g.index],
            Some(r) => &mut self.res_globals[r][g.index],
        }
    }

    /// A global's value, from the process image when it is located.
    pub(crate) fn read(&self, ctx: &Cycle, g: GlobalRef) -> Value {
        match &self.var_of(g).location {
            Some(l) => io_read(ctx, l),
            None => self.slot(g).clone(),
        }
    }

    pub(crate) fn find_global(&self, name: &str) -> Option<GlobalRef> {
        let find = |vs: &[il_codegen::ir::Var], n: &str| {
            vs.iter().position(|v| v.name.eq_ignore_ascii_case(n))
        };
        if let Some((res, n)) = name.split_once('.') {
            let r = self.def.resources.iter().position(|x| {
                x.name
                    .as_ref()
                    .is_some_and(|rn| rn.eq_ignore_ascii_case(res))
            })?;
            let index = find(&self.def.resources[r].globals, n)?;
            return Some(GlobalRef {
                resource: Some(r),
                index,
            });
        }
        if let Some(index) = find(&self.def.globals, name) {
            return Some(GlobalRef {
                resource: None,
                index,
            });
        }
        let r = self.def.resources.iter().position(|x| x.name.is_none())?;
        let index = find(&self.def.resources[r].globals, name)?;
        Some(GlobalRef {
            resource: Some(r),
            index,
        })
    }

    pub(crate) fn find_program(&self, name: &str) -> Option<(usize, usize)> {
        let (res, n) = match name.split_once('.') {
            Some((r, n)) => (Some(r), n),
            None => (None, name),
        };
        self.def.resources.iter().enumerate().find_map(|(r, x)| {
            let same_res = match (res, &x.name) {
                (None, None) => true,
                (Some(a), Some(b)) => a.eq_ignore_ascii_case(b),
                _ => false,
            };
            if !same_res {
                return None;
            }
            let p = x
                .programs
                .iter()
                .position(|p| p.name.eq_ignore_ascii_case(n))?;
            Some((r, p))
        })
    }
}

/// The interpreter's steps for the steps of a configuration path (members
/// by name, elements by their row-major index, as the checker fixed them).
pub(crate) fn interp_steps(steps: &[PathElem]) -> Result<Vec<Step>, String> {
    steps
        .iter()
        .map(|e| match e {
            PathElem::Field(m) => Ok(Step::Field(m.index as usize)),
            _ => e
                .constant_index()
                .map(|(_, flat)| Step::Index(Some(flat)))
                .ok_or_else(|| "internal: a configuration path with a run-time subscript".into()),
        })
        .collect()
}

/// The program variable a path starts at (its index), and the steps after it.
fn path_steps(steps: &[PathElem]) -> Result<(usize, Vec<Step>), String> {
    match steps.split_first() {
        Some((PathElem::Field(m), rest)) => Ok((m.index as usize, interp_steps(rest)?)),
        _ => Err("internal: an instance path that does not start at a variable".into()),
    }
}
