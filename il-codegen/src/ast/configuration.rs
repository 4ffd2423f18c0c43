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
