//! CONFIGURATION, RESOURCE, TASK and program instances.

use super::*;

/// `CONFIGURATION c ... END_CONFIGURATION`
#[derive(Clone, Debug, PartialEq)]
pub struct Configuration {
    /// The configuration's name.
    pub name: Ident,
    /// Its `VAR_GLOBAL` blocks.
    pub globals: Vec<VarBlock>,
    /// Resources; a configuration without RESOURCE gets one unnamed resource
    /// holding its tasks and programs (`name` = None).
    pub resources: Vec<Resource>,
    /// The declarations of its `VAR_CONFIG` blocks.
    pub var_config: Vec<ConfigVar>,
    /// The declarations of its `VAR_ACCESS` blocks.
    pub var_access: Vec<AccessVar>,
    /// `CONFIGURATION` to `END_CONFIGURATION`.
    pub span: Span,
}

/// `RESOURCE r ON cpu ... END_RESOURCE`: tasks and program instances on one processor.
#[derive(Clone, Debug, PartialEq)]
pub struct Resource {
    /// The resource's name; `None` for the implicit resource that holds the tasks and
    /// programs declared directly in the configuration.
    pub name: Option<Ident>,
    /// `ON processor`
    pub on: Option<Ident>,
    /// Its `VAR_GLOBAL` blocks.
    pub globals: Vec<VarBlock>,
    /// Its `TASK` declarations.
    pub tasks: Vec<Task>,
    /// Its `PROGRAM` instances.
    pub programs: Vec<ProgramInstance>,
    /// The whole resource (for the implicit one, the whole configuration).
    pub span: Span,
}

/// `TASK t (INTERVAL := T#10ms, PRIORITY := 1);`
#[derive(Clone, Debug, PartialEq)]
pub struct Task {
    /// The task's name.
    pub name: Ident,
    /// `SINGLE := flag`: run once on each rising edge of a BOOL global.
    pub single: Option<Operand>,
    /// `INTERVAL := T#10ms`: the period.
    pub interval: Option<Operand>,
    /// `PRIORITY := 1`: 0 is the highest.
    pub priority: Option<Literal>,
    /// `TASK` to `;`.
    pub span: Span,
}

/// `PROGRAM p WITH t : MyProgram (a := x, b => y);`
#[derive(Clone, Debug, PartialEq)]
pub struct ProgramInstance {
    /// The instance's name.
    pub name: Ident,
    /// `PROGRAM RETAIN p ...` / `PROGRAM NON_RETAIN p ...`.
    pub retain: Retain,
    /// `WITH t`: the task that runs it; `None` runs it on every cycle.
    pub task: Option<Ident>,
    /// The PROGRAM type instantiated.
    pub program: Ident,
    /// `a := x` binds an input to a global or a constant, `b => y` an output to a global.
    pub args: Vec<ParamAssign>,
    /// `PROGRAM` to `;`.
    pub span: Span,
}

/// `Res.Prog.fb.x AT %QX1.0 : BOOL := TRUE;` in VAR_CONFIG (Ed.2 2.7.1): an
/// address for a variable declared `AT %Q*`, and/or an initial value, for
/// one variable inside one program instance.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigVar {
    /// The instance path: resource (if named), program instance, FB
    /// instances, variable (the checker refuses subscripts and members of
    /// structures here, which Ed.2 2.7.1 does not allow).
    pub path: VarRef,
    /// `AT %QX1.0`
    pub location: Option<DirectAddress>,
    /// The type, which must be the variable's.
    pub ty: TypeSpec,
    /// `:= init`
    pub init: Option<Initializer>,
    /// From the path to the `;`.
    pub span: Span,
}

/// `name : Res.Prog.x : INT READ_WRITE;` in VAR_ACCESS: an access path the
/// configuration offers to the host.
#[derive(Clone, Debug, PartialEq)]
pub struct AccessVar {
    /// The access path's name.
    pub name: Ident,
    /// What it names: a global (`g`, `g.field`, `g[3]`), or a variable of a
    /// program instance (`Res.Prog.x`, `Prog.fbs[1].Q`), with members of
    /// structures and elements of arrays (constant subscripts).
    pub path: VarRef,
    /// The type, which must be the variable's.
    pub ty: TypeSpec,
    /// `READ_WRITE` (true) or `READ_ONLY` (false, also when omitted).
    pub writable: bool,
    /// From the name to the `;`.
    pub span: Span,
}
