//! The checked CONFIGURATION: resources, tasks and their data sources,
//! program instances with their arguments, VAR_CONFIG and VAR_ACCESS.

use super::types::Ty;
use super::{Const, Init, Loc, PathElem, Value, Var};

/// A CONFIGURATION: its globals, and its resources with their tasks and
/// program instances. It becomes a struct the host drives with the time.
#[derive(Clone, Debug)]
pub struct ConfigDef {
    /// As declared (the generated struct keeps this spelling).
    pub name: String,
    /// VAR_GLOBAL of the configuration (kind `Global`; located ones live in the
    /// process image and are not fields).
    pub globals: Vec<Var>,
    /// Its resources (at least one: the implicit one if it declares none).
    pub resources: Vec<ResourceDef>,
    /// VAR_CONFIG: initial values and addresses of variables inside
    /// program instances, in declaration order.
    pub var_config: Vec<ConfigVarDef>,
    /// VAR_ACCESS: the access paths offered to the host.
    pub access: Vec<AccessDef>,
}

impl ConfigDef {
    /// Every task as `(resource, task)`, in the order a cycle releases them:
    /// by priority, ties in declaration order. The emitted scheduler and the
    /// interpreter both take this order.
    pub fn task_order(&self) -> Vec<(usize, usize)> {
        let mut order: Vec<(usize, usize)> = self
            .resources
            .iter()
            .enumerate()
            .flat_map(|(r, res)| (0..res.tasks.len()).map(move |t| (r, t)))
            .collect();
        // The sort is stable: declaration order breaks ties.
        order.sort_by_key(|&(r, t)| self.resources[r].tasks[t].priority);
        order
    }
}

/// A variable inside a program instance, named from the configuration
/// (`Res.Prog.fb.x`, `Res.Prog.a[2]`): the resource, the instance, then the
/// steps down to the place.
#[derive(Clone, Debug, PartialEq)]
pub struct InstancePath {
    /// Index into [`ConfigDef::resources`].
    pub resource: usize,
    /// Index into that resource's programs.
    pub program: usize,
    /// From the program instance down, at least one step, the first a
    /// [`PathElem::Field`] naming a variable of the program. A `Field` is a
    /// variable of an FB instance (storage `Instance`), a member of a
    /// STRUCT, or an input or output of a standard block (the il-std field,
    /// `PT`, `Q`: always the last step); an [`PathElem::Index`] has constant
    /// subscripts the checker proved inside the bounds. VAR_CONFIG paths
    /// have fields only (Ed.2 2.7.1).
    pub steps: Vec<PathElem>,
    /// The type of the place.
    pub ty: Ty,
    /// The path as written (`Cpu.Main.sensor`).
    pub text: String,
}

/// One VAR_CONFIG declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigVarDef {
    /// The variable.
    pub target: InstancePath,
    /// `:= init`: set when the configuration is created.
    pub init: Option<Init>,
    /// `AT %QX1.0` completing the variable's `AT %Q*`: the configuration
    /// copies `%I`/`%M` into the field before each run of the program and
    /// the field to `%Q`/`%M` after it (the process image of Ed.2 2.4.1.1).
    pub location: Option<Loc>,
}

/// One VAR_ACCESS declaration: `name : path : type READ_WRITE`.
#[derive(Clone, Debug, PartialEq)]
pub struct AccessDef {
    /// The access path's name, as declared.
    pub name: String,
    /// What it reads and writes.
    pub target: AccessTarget,
    /// The variable's type.
    pub ty: Ty,
    /// READ_WRITE; READ_ONLY (the default) offers no setter.
    pub writable: bool,
    /// The subrange of the named place: a write outside it is refused
    /// (the place keeps its value), as a store in a body skips it.
    pub range: Option<(i128, i128)>,
}

/// What an access path names.
#[derive(Clone, Debug, PartialEq)]
pub enum AccessTarget {
    /// An unlocated global of the configuration, or a member or element of
    /// one (`g.field`, `g[3]`: `steps` as in [`InstancePath::steps`], empty
    /// for the whole global).
    Global {
        /// The global.
        global: GlobalRef,
        /// Members and elements inside it.
        steps: Vec<PathElem>,
    },
    /// A variable inside a program instance.
    Instance(InstancePath),
}

/// A RESOURCE (or the unnamed one of a configuration without RESOURCE).
#[derive(Clone, Debug)]
pub struct ResourceDef {
    /// `None`: the configuration declares its tasks and programs directly.
    pub name: Option<String>,
    /// VAR_GLOBAL of the resource (kind `Global`; located ones live in the process image).
    pub globals: Vec<Var>,
    /// Its tasks; [`ProgramInst::task`] indexes into this list.
    pub tasks: Vec<TaskDef>,
    /// Its program instances, in declaration order.
    pub programs: Vec<ProgramInst>,
}

/// `TASK t (INTERVAL := T#10ms, PRIORITY := 1)`.
#[derive(Clone, Debug)]
pub struct TaskDef {
    /// As declared.
    pub name: String,
    /// `INTERVAL`: a TIME literal in nanoseconds (0 = no periodic release),
    /// or a TIME global or direct address read at each release decision.
    pub interval: TaskSource<i64>,
    /// PRIORITY: 0 is the highest; orders tasks released in the same cycle.
    pub priority: u32,
    /// SINGLE: released on a rising edge of this BOOL global or direct
    /// address (a literal is decided by the checker: TRUE is `Some(Fixed)`).
    pub single: Option<TaskSource<bool>>,
}

/// Where a TASK input comes from (Ed.2 2.7.2: any data source): a literal,
/// a global of the configuration, or a direct address of the process image.
#[derive(Clone, Debug, PartialEq)]
pub enum TaskSource<T> {
    /// A literal, decided by the checker.
    Fixed(T),
    /// A global (read before the task's release is decided).
    Global(GlobalRef),
    /// A direct address (`SINGLE := %IX0.0`).
    Addr(Loc),
}

/// A global of a configuration: `resource` None = the configuration's own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlobalRef {
    /// Index into [`ConfigDef::resources`]; `None`: [`ConfigDef::globals`].
    pub resource: Option<usize>,
    /// Index into that list of globals.
    pub index: usize,
}

/// `PROGRAM p WITH t : P (a := g, b => h)`.
#[derive(Clone, Debug)]
pub struct ProgramInst {
    /// The instance's name (a field of the configuration struct).
    pub name: String,
    /// The PROGRAM type.
    pub program: String,
    /// Index into the resource's tasks; `None`: runs on every call, after the tasks.
    pub task: Option<usize>,
    /// The globals bound to the program's (non-located) VAR_EXTERNALs, in
    /// their declaration order; `true` for a VAR_EXTERNAL CONSTANT. Each
    /// variable of the program is a [`super::Member`]: its name and its
    /// index in the program's [`super::CheckedPou::vars`].
    pub externals: Vec<(super::Member, GlobalRef, bool)>,
    /// Inputs set before every run.
    pub inputs: Vec<(super::Member, ProgArg)>,
    /// Outputs copied to globals after every run (source output, target).
    pub outputs: Vec<(super::Member, GlobalRef)>,
    /// The globals bound to the program's VAR_IN_OUTs (`PROGRAM p : P(io :=
    /// g)`), one for each, in their declaration order: passed by reference.
    pub inouts: Vec<(super::Member, GlobalRef)>,
    /// The program has RETAIN variables (a `retain()` snapshot).
    pub retain: bool,
}

/// The value given to a program input in a configuration.
#[derive(Clone, Debug)]
pub enum ProgArg {
    /// `a := g`: the value of a global, read before every run.
    Global(GlobalRef),
    /// `a := 5`: a constant.
    Const(Const),
}

impl PathElem {
    /// For an [`PathElem::Index`] of constant subscripts inside the bounds
    /// (the checker makes only these in configuration paths): the offset of
    /// each from its lower bound, which the emitter indexes nested arrays
    /// with, and the row-major index over all dimensions, which the
    /// interpreter's flat arrays use. `None` for anything else.
    pub fn constant_index(&self) -> Option<(Vec<usize>, usize)> {
        let PathElem::Index { dims, subs } = self else {
            return None;
        };
        let mut offsets = Vec::new();
        let mut flat = 0usize;
        for (s, &(lo, hi)) in subs.iter().zip(dims) {
            let Value::Const(Const::Int(n, _)) = s else {
                return None;
            };
            let n = n.get();
            if n < lo as i128 || n > hi as i128 {
                return None;
            }
            let k = usize::try_from(n - lo as i128).ok()?;
            let size = usize::try_from(hi - lo + 1).ok()?;
            flat = flat.checked_mul(size)?.checked_add(k)?;
            offsets.push(k);
        }
        Some((offsets, flat))
    }
}
