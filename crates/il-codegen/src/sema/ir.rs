//! The checked program: every name resolved, every value typed. The emitter
//! turns this into Rust without further checks, so anything it accepts here
//! must compile.

use super::types::{Elem, Ty};
/// The IR's binary operators are the IL expression operators themselves.
pub use crate::ast::ExprOp as BinOp;
use crate::ast::{PouKind, VarKind};

#[derive(Clone, Debug, Default)]
pub struct Program {
    /// User types declared in this file (TYPE ... END_TYPE).
    pub types: Vec<TypeDef>,
    pub pous: Vec<CheckedPou>,
    /// CONFIGURATIONs declared in this file.
    pub configs: Vec<ConfigDef>,
}

/// A CONFIGURATION: its globals, and its resources with their tasks and
/// program instances. It becomes a struct the host drives with the time.
#[derive(Clone, Debug)]
pub struct ConfigDef {
    pub name: String,
    /// VAR_GLOBAL of the configuration (kind `Var`; located ones live in the
    /// process image and are not fields).
    pub globals: Vec<Var>,
    pub resources: Vec<ResourceDef>,
}

/// A RESOURCE (or the unnamed one of a configuration without RESOURCE).
#[derive(Clone, Debug)]
pub struct ResourceDef {
    /// `None`: the configuration declares its tasks and programs directly.
    pub name: Option<String>,
    pub globals: Vec<Var>,
    pub tasks: Vec<TaskDef>,
    pub programs: Vec<ProgramInst>,
}

/// `TASK t (INTERVAL := T#10ms, PRIORITY := 1)`.
#[derive(Clone, Debug)]
pub struct TaskDef {
    pub name: String,
    /// Nanoseconds; 0 = no periodic release.
    pub interval: i64,
    pub priority: u32,
    /// SINGLE: released on a rising edge of this BOOL global.
    pub single: Option<GlobalRef>,
}

/// A global of a configuration: `resource` None = the configuration's own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlobalRef {
    pub resource: Option<usize>,
    pub index: usize,
}

/// `PROGRAM p WITH t : P (a := g, b => h)`.
#[derive(Clone, Debug)]
pub struct ProgramInst {
    pub name: String,
    /// The PROGRAM type.
    pub program: String,
    /// Index into the resource's tasks; `None`: runs on every call, after the tasks.
    pub task: Option<usize>,
    /// The globals bound to the program's (non-located) VAR_EXTERNALs, in
    /// their declaration order; `true` for a VAR_EXTERNAL CONSTANT.
    pub externals: Vec<(String, GlobalRef, bool)>,
    /// Inputs set before every run.
    pub inputs: Vec<(String, ProgArg)>,
    /// Outputs copied to globals after every run (target, source output).
    pub outputs: Vec<(String, GlobalRef)>,
    /// The program has RETAIN variables (a `retain()` snapshot).
    pub retain: bool,
}

/// The value given to a program input in a configuration.
#[derive(Clone, Debug)]
pub enum ProgArg {
    Global(GlobalRef),
    Const(Const),
}

/// A user type that becomes a Rust item.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeDef {
    Struct {
        name: String,
        fields: Vec<Field>,
    },
    /// Values with their explicit discriminants, and the default value's index.
    Enum {
        name: String,
        values: Vec<(String, Option<i128>)>,
        default: usize,
    },
}

/// A field of a user STRUCT.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    pub name: String,
    pub ty: Ty,
    pub init: Option<Init>,
    /// Subrange bounds of an integer field.
    pub range: Option<(i128, i128)>,
}

#[derive(Clone, Debug)]
pub struct CheckedPou {
    pub kind: PouKind,
    /// As declared (the Rust item keeps this spelling).
    pub name: String,
    pub vars: Vec<Var>,
    /// FUNCTION result type.
    pub ret: Option<Ty>,
    pub body: Vec<Stmt>,
    pub label_count: usize,
    /// Direct addresses used in the body (for `ADDRESSES`).
    pub addresses: Vec<Loc>,
    /// The CR locals the body uses (one per type).
    pub cr_types: Vec<Ty>,
    /// Types of the slots that hold the outer CR of deferred parentheses.
    pub save_types: Vec<Ty>,
    /// What the RETAIN snapshot of an FB/PROGRAM holds (empty: no snapshot).
    pub retained: Vec<(usize, Retained)>,
}

/// How a variable is part of a RETAIN snapshot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Retained {
    /// Declared RETAIN: its whole value (an FB instance with all its state).
    Whole,
    /// An instance (or array of instances) of a block that has RETAIN
    /// variables: their snapshot.
    Nested,
}

#[derive(Clone, Debug)]
pub struct Var {
    /// As declared.
    pub name: String,
    /// `AT %...`: the variable is that place of the process image.
    pub location: Option<Loc>,
    /// R_EDGE / F_EDGE input: the body sees the edge, not the level.
    pub edge: Option<crate::ast::Edge>,
    /// Subrange bounds of an integer variable.
    pub range: Option<(i128, i128)>,
    pub kind: VarKind,
    pub ty: Ty,
    pub init: Option<Init>,
    pub constant: bool,
    /// Declared in a RETAIN section: part of the snapshot the host saves.
    pub retain: bool,
    /// Line of the declaration, for comments.
    pub line: u32,
}

/// Initial values.
#[derive(Clone, Debug, PartialEq)]
pub enum Init {
    Const(Const),
    /// Row-major elements of an array (already expanded to its full length).
    Array(Vec<Const>),
    /// Inputs of an FB instance: `t : TON := (PT := T#1s)`.
    Fields(Vec<(String, Const)>),
    /// A structure: `(x := 1, inner := (y := 2))`, with each field's type.
    Struct(Vec<(String, Ty, Init)>),
}

/// A typed constant.
#[derive(Clone, Debug, PartialEq)]
pub enum Const {
    Bool(bool),
    /// Integer or bit string of the given type, value in range.
    Int(i128, Elem),
    Real(f64, Elem),
    /// TIME/LTIME (ns), DATE (days), TOD (ns), DT (ns).
    Time(i64, Elem),
    Str {
        value: String,
        wide: bool,
        len: u32,
    },
    /// A value of a user enumeration.
    Enum {
        ty: String,
        value: String,
    },
}

impl Const {
    pub fn ty(&self) -> Ty {
        match self {
            Const::Bool(_) => Ty::BOOL,
            Const::Int(_, e) | Const::Real(_, e) | Const::Time(_, e) => Ty::Elem(*e),
            Const::Str { wide, len, .. } => Ty::Str {
                wide: *wide,
                len: *len,
            },
            Const::Enum { ty, .. } => Ty::Enum(ty.clone()),
        }
    }
}

/// A variable, or a part of one.
#[derive(Clone, Debug, PartialEq)]
pub struct Place {
    pub root: Root,
    pub path: Vec<PathElem>,
    pub ty: Ty,
    /// Subrange bounds to check on stores.
    pub range: Option<(i128, i128)>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Root {
    /// Index into `CheckedPou::vars`.
    Var(usize),
    /// The FUNCTION's result variable (named like the function).
    Ret,
    /// A place of the process image (a direct address or a located variable).
    Addr(Loc),
}

/// A resolved direct address.
#[derive(Clone, Debug, PartialEq)]
pub struct Loc {
    pub area: crate::ast::Area,
    /// Byte offset in the area.
    pub byte: usize,
    /// Bit number of a bit address.
    pub bit: Option<u8>,
    /// The type stored there (its size matches the address).
    pub elem: Elem,
    /// As written (`%IX1.0`).
    pub text: String,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PathElem {
    /// A member of an FB instance, as declared in the FB.
    Field(String),
    /// Subscripts of an array with these bounds.
    Index {
        dims: Vec<(i64, i64)>,
        subs: Vec<Value>,
    },
}

/// Something to read.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// The CR local of that type.
    Cr(Ty),
    Const(Const),
    Read(Place),
    /// A saved outer CR of a deferred parenthesis.
    Saved(usize, Ty),
}

/// A computation whose result becomes the CR.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    Value(Value),
    /// Logical/bitwise complement.
    Not(Value),
    /// `lhs op rhs`; `ty` is the operands' type (rhs is already complemented
    /// for ANDN etc. via `negate_rhs`). Comparisons yield BOOL.
    Bin {
        op: BinOp,
        ty: Ty,
        lhs: Value,
        rhs: Value,
        negate_rhs: bool,
    },
    /// TIME/LTIME scaled by a number: `MUL`/`DIV` with a numeric operand.
    TimeScale {
        div: bool,
        time: Elem,
        lhs: Value,
        num: Elem,
        rhs: Value,
    },
    /// A call of a user FUNCTION: arguments in declaration order of its
    /// inputs; `out_types` are all its outputs, `outputs` the ones read with
    /// `=>` (index into `out_types`, target, complemented).
    CallUser {
        /// EN := value: run only when TRUE.
        en: Option<Value>,
        /// Places bound to the VAR_IN_OUTs, in their declaration order.
        inouts: Vec<Place>,
        /// Index of the implicit ENO among the outputs, if the function sets ENO.
        eno: Option<usize>,
        ret: Ty,
        name: String,
        args: Vec<Value>,
        out_types: Vec<Ty>,
        outputs: Vec<(usize, Place, bool)>,
    },
    /// A call of an il-std function.
    CallStd {
        call: StdCall,
        args: Vec<Value>,
        arg_types: Vec<Ty>,
        ret: Ty,
    },
}

/// How to call a standard function.
#[derive(Clone, Debug, PartialEq)]
pub enum StdCall {
    /// `::il_std::func::NAME(args...)`.
    Plain(&'static str),
    /// Folded over more than two arguments (`ADD a, b, c`).
    Fold(&'static str),
    /// Comparison chain: `GT(a,b) AND GT(b,c)`.
    Chain(&'static str),
    /// `MUX(K, IN0, ...)`.
    Mux,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    pub op: Op,
    /// IL source line (1-based), carried into a comment.
    pub line: u32,
}

/// `Some((value, when))`: act when the BOOL value equals `when`.
pub type Condition = Option<(Value, bool)>;

#[derive(Clone, Debug, PartialEq)]
pub enum Op {
    /// `__cr_<ty> = expr`
    SetCr {
        ty: Ty,
        expr: Expr,
    },
    /// `__save_n = value`
    Save {
        slot: usize,
        value: Value,
    },
    /// `place = value` (complemented for STN).
    Store {
        place: Place,
        value: Value,
        negate: bool,
    },
    /// S / R on a BOOL: `if cond { place = value }`.
    SetIf {
        place: Place,
        value: bool,
        cond: Value,
    },
    /// Call an FB instance after setting inputs; then copy outputs.
    CallFb {
        inst: Place,
        inputs: Vec<(String, Value)>,
        outputs: Vec<(String, Place, bool)>,
        /// Places bound to the FB's VAR_IN_OUTs, in their declaration order.
        inouts: Vec<Place>,
        /// The FB's (non-located) VAR_EXTERNALs, in declaration order: the
        /// caller passes its own externals of the same names. `true`: the
        /// FB declares it CONSTANT (a shared reference suffices).
        externals: Vec<(String, bool)>,
        cond: Condition,
    },
    Jump {
        label: usize,
        cond: Condition,
    },
    Label(usize),
    Return {
        cond: Condition,
    },
    /// Nothing to do (an instruction whose effect is only on the checker's
    /// state, like loading a literal); keeps its line comment.
    Nop,
}
