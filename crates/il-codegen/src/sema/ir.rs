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
    /// Line of the declaration, for comments.
    pub line: u32,
}

/// Initial values.
#[derive(Clone, Debug, PartialEq)]
pub enum Init {
    Const(Const),
    /// Row-major elements of an array as runs `(count, value)`, in order;
    /// the elements after the last run keep the default value. Runs, not the
    /// expanded list: `[16000000(0)]` is one run (expanded, a 60-byte
    /// declaration took 1.5 GB and 13 s to check; found by fuzzing).
    Array(Vec<(usize, Const)>),
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
