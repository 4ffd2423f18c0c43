//! The checked program: the one contract between the checker and every
//! consumer (the emitter, the interpreter, the language server, the
//! waveform writer). Every name is resolved, every value typed and every
//! decision made: the emitter only prints it and the interpreter only
//! evaluates it. The emitter turns it into Rust without further checks, so
//! anything it accepts here must compile.
//!
//! [`crate::Checked::ir`] gives it; [`types`] holds the types it names,
//! [`path`] the host paths (`tank.level`, `valves[2].open`) that tools
//! take from users.

pub mod path;
pub mod types;

/// The IR's binary operators are the IL expression operators themselves.
pub use crate::ast::ExprOp as BinOp;
/// The syntax the IR names: kinds of POUs and variables, edges, memory
/// areas, spans into the source, integer values.
pub use crate::ast::{Area, Edge, PouKind, Span, VarKind};
/// The initial value of a type (its default, or a subrange's lower limit).
pub use crate::sema::default_const;
/// Where `%IW1` lives in the process image, as the checker decides it for
/// an address in a program.
pub use crate::sema::parse_address;
use types::{Elem, Name, Ty};

/// A checked compilation unit: what the emitter and the interpreter consume.
#[derive(Clone, Debug, Default)]
pub struct Program {
    /// The name of the source file it was checked from (as in diagnostics),
    /// so that a consumer can say where a run-time error comes from.
    pub file: String,
    /// User types declared in this file (TYPE ... END_TYPE).
    pub types: Vec<TypeDef>,
    /// The POUs, in source order.
    pub pous: Vec<CheckedPou>,
    /// CONFIGURATIONs declared in this file.
    pub configs: Vec<ConfigDef>,
}

mod calls;
mod config;
mod resolutions;
pub use calls::*;
pub use config::*;
pub use resolutions::*;

/// A user type that becomes a Rust item.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeDef {
    /// `STRUCT ... END_STRUCT`: a Rust struct with a `Default` that applies the initial values.
    Struct {
        /// As declared.
        name: String,
        /// The fields, in declaration order.
        fields: Vec<Field>,
    },
    /// Values with their explicit discriminants, and the default value's index.
    Enum {
        /// As declared.
        name: String,
        /// Each value's name and its `:= n`, if given.
        values: Vec<(String, Option<i128>)>,
        /// Index into `values` of the default value.
        default: usize,
    },
}

/// A field of a user STRUCT.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// As declared.
    pub name: String,
    /// The field's type.
    pub ty: Ty,
    /// Its initial value (`None`: the type's default).
    pub init: Option<Init>,
    /// Subrange bounds of an integer field.
    pub range: Option<(i128, i128)>,
}

/// A checked FUNCTION, FUNCTION_BLOCK or PROGRAM, ready for emission.
#[derive(Clone, Debug)]
pub struct CheckedPou {
    /// FUNCTION, FUNCTION_BLOCK or PROGRAM.
    pub kind: PouKind,
    /// As declared (the Rust item keeps this spelling).
    pub name: String,
    /// The comment lines just above its declaration: generated Rust
    /// carries them as the item's documentation.
    pub doc: Option<String>,
    /// Every variable of every VAR block, in declaration order ([`Root::Var`] indexes into this).
    pub vars: Vec<Var>,
    /// FUNCTION result type.
    pub ret: Option<Ty>,
    /// The instructions, lowered to operations on typed CR locals.
    pub body: Vec<Stmt>,
    /// The places the body reads and writes ([`Value::Read`],
    /// [`Op::Store`], [`Op::SetIf`] name them by index): one entry per
    /// distinct place without subscripts (`LD a` and `ST a` share it),
    /// one per use of a place with subscripts. A place is 64 bytes and a
    /// box of one per read or store was a quarter of the checked IR.
    pub places: Vec<Place>,
    /// Number of labels: [`Op::Label`] and [`Op::Jump`] use indices below it.
    pub label_count: usize,
    /// Direct addresses used in the body (for `ADDRESSES`).
    pub addresses: Vec<Loc>,
    /// The CR locals the body uses (one per type): [`Value::Cr`] and
    /// [`Op::SetCr`] name them by index.
    pub cr_types: Vec<Ty>,
    /// Types of the slots that hold the outer CR of deferred parentheses
    /// ([`Value::Saved`] and [`Op::Save`] name them by index).
    pub save_types: Vec<Ty>,
    /// What the RETAIN snapshot of an FB/PROGRAM holds (empty: no snapshot).
    pub retained: Vec<(usize, Retained)>,
    /// The CR the checker proved before and after every instruction and at
    /// every label, in the order walked (an instruction inside parentheses
    /// comes before the group that holds it). Not used for code: it is what
    /// tools show (the language server's hover and inlay hints), decided here
    /// once instead of being recomputed there. Empty unless asked for
    /// ([`crate::Program::cr_steps`]).
    pub cr_steps: Vec<CrStep>,
    /// A host FUNCTION (`{extern}`): no body here; the crate around the
    /// generated code provides it, and the emitter only checks its signature.
    pub host: bool,
}

impl CheckedPou {
    /// The type of CR local `i` ([`Value::Cr`], [`Op::SetCr`]).
    pub fn cr_ty(&self, i: u32) -> &Ty {
        &self.cr_types[i as usize]
    }

    /// The type of save slot `i` ([`Value::Saved`], [`Op::Save`]).
    pub fn saved_ty(&self, i: u32) -> &Ty {
        &self.save_types[i as usize]
    }

    /// Place `i` of the body ([`Value::Read`], [`Op::Store`], [`Op::SetIf`]).
    pub fn place(&self, i: u32) -> &Place {
        &self.places[i as usize]
    }

    /// The elementary type of `v` (`None` for strings, enumerations and
    /// the other types): what an index or an operator needs, without
    /// cloning a type.
    pub fn value_elem(&self, v: &Value) -> Option<Elem> {
        match v {
            Value::Cr(i) => self.cr_ty(*i).elem(),
            Value::Saved(i) => self.saved_ty(*i).elem(),
            Value::Const(c) => c.elem(),
            Value::Read(i) => self.place(*i).ty.elem(),
            Value::Widen(b) => Some(b.1.to),
            Value::Resized(r) => r.1.elem(),
            Value::Arith(a) => Some(a.elem),
        }
    }
}

/// The CR at one instruction or label, as the checker proved it.
#[derive(Clone, Debug, PartialEq)]
pub struct CrStep {
    /// The instruction (operator to last operand), or the label's name.
    pub span: crate::ast::Span,
    /// A label rather than an instruction.
    pub label: bool,
    /// Before the instruction; at a label, the CR falling through into it.
    pub before: CrState,
    /// After the instruction; at a label, the CR joined from every path.
    pub after: CrState,
    /// At a label whose paths disagree: each path's type and line
    /// (`INT from line 3, BOOL from line 7`).
    pub paths: Option<String>,
}

/// What the CR holds at a point of the body.
#[derive(Clone, Debug, PartialEq)]
pub enum CrState {
    /// No path reaches here (after JMP or RET, no label).
    Dead,
    /// No usable value, and why (`no value loaded`, `the paths into
    /// `done` disagree`).
    Undefined(String),
    /// No usable value after the `CAL` on this line (1-based): a block's
    /// call leaves the CR undefined. Shown as `undefined (after CAL on
    /// line 4)`.
    AfterCal(u32),
    /// An untyped literal (described: `the integer literal 5`): it takes its
    /// type from its first typed use.
    Literal(String),
    /// A value of this type.
    Typed(Ty),
}

impl std::fmt::Display for CrState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CrState::Dead => f.write_str("unreachable"),
            CrState::Undefined(why) => write!(f, "undefined ({why})"),
            CrState::AfterCal(line) => write!(f, "undefined (after CAL on line {line})"),
            CrState::Literal(what) => f.write_str(what),
            CrState::Typed(t) => write!(f, "{t}"),
        }
    }
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

/// A declared variable of a POU or configuration, after type resolution.
#[derive(Clone, Debug)]
pub struct Var {
    /// As declared.
    pub name: String,
    /// `AT %...`: the variable is that place of the process image.
    pub location: Option<Loc>,
    /// `AT %I*` / `%Q*` / `%M*` (Ed.2 2.4.1.1): an ordinary field the host
    /// binds, listed in `ADDRESSES` as unbound; the text as written.
    pub partly: Option<(crate::ast::Area, String)>,
    /// R_EDGE / F_EDGE input: the body sees the edge, not the level.
    pub edge: Option<crate::ast::Edge>,
    /// Subrange bounds of an integer variable.
    pub range: Option<(i128, i128)>,
    /// The section it was declared in.
    pub kind: VarKind,
    /// Where it lives, decided by the checker from the POU, the section and
    /// the address: the emitter and the interpreter both read this.
    pub storage: Storage,
    /// The resolved type.
    pub ty: Ty,
    /// Its initial value (`None`: the type's default).
    pub init: Option<Init>,
    /// Declared CONSTANT: the checker refuses every write.
    pub constant: bool,
    /// Declared in a RETAIN section: part of the snapshot the host saves.
    pub retain: bool,
    /// An array of more than 64 KiB in an FB/PROGRAM: the field is a
    /// `Box<[Row]>` built on the heap (a stack value would overflow).
    pub heap: bool,
    /// Line of the declaration, for comments.
    pub line: u32,
    /// The comment after its declaration on that line, as the engineer
    /// wrote it (`start : BOOL; (* push button *)`): generated Rust
    /// carries it as the field's documentation.
    pub doc: Option<String>,
}

/// Where a variable lives: decided once, by the checker ([`Storage::of`]),
/// for the emitter and the interpreter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    /// Memory of the instance, kept between calls: VAR, VAR_INPUT and
    /// VAR_OUTPUT of a FUNCTION_BLOCK or PROGRAM (a `pub` field of its struct).
    Instance,
    /// VAR_EXTERNAL of a FUNCTION_BLOCK or PROGRAM: the configuration's
    /// global. Generated code reaches it through the reference its caller
    /// passes (`__ext`), so it is not a field. The interpreter runs a PROGRAM
    /// alone, without a configuration: it keeps the global as memory of the
    /// instance and copies the caller's value in and out around each `CAL` of
    /// a block, so it treats this variant as [`Storage::Instance`].
    External,
    /// VAR_IN_OUT: the caller's variable, by reference.
    InOut,
    /// Lives for one call, initialised on entry: VAR_TEMP, and the VAR of a
    /// FUNCTION.
    Temp,
    /// VAR_INPUT of a FUNCTION: a parameter passed by value.
    Param,
    /// VAR_OUTPUT of a FUNCTION (and its ENO): an out-parameter, set to its
    /// initial value on entry.
    OutParam,
    /// `AT %...`, or a VAR_EXTERNAL of a located global: a place of the
    /// process image (reads and writes go through `Root::Addr`).
    Located,
    /// VAR_GLOBAL of a CONFIGURATION or RESOURCE: a field of the configuration.
    Global,
}

impl Storage {
    /// Where a variable of section `kind` in a POU of kind `pou` lives;
    /// `located`: it has an address (its own, or its global's).
    pub fn of(pou: PouKind, kind: VarKind, located: bool) -> Storage {
        if located {
            return Storage::Located;
        }
        match (pou, kind) {
            (_, VarKind::Global) => Storage::Global,
            (_, VarKind::External) => Storage::External,
            (_, VarKind::InOut) => Storage::InOut,
            (_, VarKind::Temp) => Storage::Temp,
            (PouKind::Function, VarKind::Input) => Storage::Param,
            (PouKind::Function, VarKind::Output) => Storage::OutParam,
            (PouKind::Function, _) => Storage::Temp,
            _ => Storage::Instance,
        }
    }
}

/// The value an element of the array type `t` starts with when nothing
/// else is given, where it is not the element type's default: the lower
/// limit of a subrange element type (IEC Ed.2 2.3.3.2; `ARRAY[1..3] OF
/// INT (5..9)` starts as `[5, 5, 5]`). The emitter and the interpreter
/// both build array defaults with it.
pub fn element_start(t: &Ty) -> Option<Const> {
    match t {
        Ty::Array(a) => match (&a.elem, a.range) {
            (Ty::Elem(e), Some((lo, _))) if lo != 0 => Some(Const::Int(lo.into(), *e)),
            _ => None,
        },
        _ => None,
    }
}

/// Initial values.
#[derive(Clone, Debug, PartialEq)]
pub enum Init {
    /// A single value.
    Const(Const),
    /// Row-major elements of an array as runs `(count, value)`, in order;
    /// the elements after the last run keep their default value
    /// ([`element_start`], else the element type's). Runs, not the
    /// expanded list: `[16000000(0)]` is one run (expanded, a 60-byte
    /// declaration took 1.5 GB and 13 s to check; found by fuzzing). An
    /// element is a constant or, for an array of structures, a structure
    /// initialiser (`[(x := 1), (x := 2, y := 3)]`).
    Array(Vec<(usize, Init)>),
    /// Inputs of an FB instance: `t : TON := (PT := T#1s)`.
    Fields(Vec<(Member, Const)>),
    /// A structure: `(x := 1, inner := (y := 2))`, with each field's type:
    /// the type's default value, then each given field in turn.
    Struct(Vec<(String, Ty, Init)>),
}

/// A typed constant.
#[derive(Clone, Debug, PartialEq)]
pub enum Const {
    /// `TRUE` / `FALSE`.
    Bool(bool),
    /// Integer or bit string of the given type, value in range.
    Int(IntValue, Elem),
    /// REAL or LREAL (held as f64; the emitter narrows it to f32 for REAL).
    Real(f64, Elem),
    /// TIME/LTIME (ns), DATE (days), TOD (ns), DT (ns).
    Time(i64, Elem),
    /// A STRING or WSTRING literal. Boxed: rare, and its text inline made
    /// every constant (and every value) twice as large.
    Str(Box<StrConst>),
    /// A value of a user enumeration. Boxed: rare, and its two names
    /// inline made every constant (and every value) half as large again.
    Enum(Box<EnumConst>),
}

pub use crate::ast::IntValue;

/// A STRING or WSTRING literal ([`Const::Str`]).
#[derive(Clone, Debug, PartialEq)]
pub struct StrConst {
    /// The characters.
    pub value: String,
    /// WSTRING rather than STRING.
    pub wide: bool,
    /// The declared maximum length in characters.
    pub len: u32,
}

/// A value of a user enumeration ([`Const::Enum`]).
#[derive(Clone, Debug, PartialEq)]
pub struct EnumConst {
    /// The enumeration type, as declared (shared with its [`Ty::Enum`]).
    pub ty: Name,
    /// The value's name, as declared.
    pub value: String,
}

impl Const {
    /// The constant `value` of the enumeration `ty`.
    pub fn enum_value(ty: Name, value: String) -> Const {
        Const::Enum(Box::new(EnumConst { ty, value }))
    }
}

impl Const {
    /// The constant's elementary type (`None` for strings and enumerations).
    pub fn elem(&self) -> Option<Elem> {
        match self {
            Const::Bool(_) => Some(Elem::BOOL),
            Const::Int(_, e) | Const::Real(_, e) | Const::Time(_, e) => Some(*e),
            Const::Str(_) | Const::Enum(_) => None,
        }
    }

    /// The constant's type.
    pub fn ty(&self) -> Ty {
        match self {
            Const::Bool(_) => Ty::BOOL,
            Const::Int(_, e) | Const::Real(_, e) | Const::Time(_, e) => Ty::Elem(*e),
            Const::Str(s) => Ty::Str {
                wide: s.wide,
                len: s.len,
            },
            Const::Enum(e) => Ty::Enum(e.ty.clone()),
        }
    }
}

/// A variable, or a part of one.
#[derive(Clone, Debug, PartialEq)]
pub struct Place {
    /// The variable the place starts from.
    pub root: Root,
    /// Field and subscript steps from the root, in order.
    pub path: Vec<PathElem>,
    /// The type of the place itself (after the path).
    pub ty: Ty,
    /// Subrange bounds to check on stores: a store of a value outside them
    /// does not happen and records [`il_std::FaultKind::SubrangeViolation`].
    /// Boxed: rare, and inline the pair of `i128` would more than double
    /// every place (and every value).
    pub range: Option<Box<(i128, i128)>>,
}

/// Where a [`Place`] starts.
#[derive(Clone, Debug, PartialEq)]
pub enum Root {
    /// Index into `CheckedPou::vars`.
    Var(usize),
    /// The FUNCTION's result variable (named like the function).
    Ret,
    /// A place of the process image (a direct address or a located variable).
    /// Boxed: rarer than variables, and a `Loc` is five times a `usize`.
    Addr(Box<Loc>),
}

/// A resolved direct address.
#[derive(Clone, Debug, PartialEq)]
pub struct Loc {
    /// `%I`, `%Q` or `%M`.
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

/// One step from a variable to a part of it.
#[derive(Clone, Debug, PartialEq)]
pub enum PathElem {
    /// A member of an FB instance or a structure.
    Field(Member),
    /// Subscripts of an array with these bounds.
    Index {
        /// `(lo, hi)` per dimension, inclusive.
        dims: Vec<(i64, i64)>,
        /// One subscript per dimension, checked against `dims`. Every
        /// subscript of a place is evaluated first, in path order; when one
        /// is out of bounds, `IndexOutOfRange` is recorded and a read gives
        /// the place type's default, a write does nothing.
        subs: Vec<Value>,
    },
    /// A part of an integer or bit string (3rd edition: `v.3`, `v.%B1`):
    /// always the last step. The checker proved `(index + 1) * bits(part)`
    /// is at most the width of `whole`, so reading shifts and masks, and
    /// writing reads the whole, replaces the part and writes the whole back.
    Part {
        /// The type of the place the part is taken from.
        whole: Elem,
        /// BOOL (a bit), BYTE, WORD or DWORD.
        part: Elem,
        /// Which part, counted in parts from the least significant.
        index: u32,
    },
}

impl PathElem {
    /// Bits of the types a [`PathElem::Part`] joins: 1 for BOOL, 8 to 64
    /// for the integers and bit strings.
    pub fn part_bits(e: Elem) -> u32 {
        use Elem::*;
        match e {
            BOOL => 1,
            SINT | USINT | BYTE => 8,
            INT | UINT | WORD => 16,
            DINT | UDINT | DWORD => 32,
            _ => 64,
        }
    }

    /// The mask of part `index` of type `part` and its shift in the whole:
    /// how the emitter and the interpreter both read and write a part.
    pub fn part_mask(part: Elem, index: u32) -> (u64, u32) {
        let bits = Self::part_bits(part);
        let mask = if bits >= 64 {
            u64::MAX
        } else {
            (1u64 << bits) - 1
        };
        (mask, index * bits)
    }
}

impl Place {
    /// A place ending in a partial access: the place of the whole and the
    /// part (`None` for any other place). A partial access is written by
    /// reading the whole, replacing the part and writing the whole back.
    pub fn split_part(&self) -> Option<(Place, Elem, Elem, u32)> {
        let Some(PathElem::Part { whole, part, index }) = self.path.last() else {
            return None;
        };
        let mut p = self.clone();
        p.path.pop();
        p.ty = Ty::Elem(*whole);
        Some((p, *whole, *part, *index))
    }
}

/// Something to read. Two words: the rare values that need more (a
/// widening, a resized string, a subscript expression) are boxed, and the
/// CR, the saved slots and the places read are named by index into tables
/// of the POU ([`CheckedPou::cr_types`], [`CheckedPou::save_types`],
/// [`CheckedPou::places`]): an instruction holds up to three values, and
/// with a type inline every value (so every statement) was half as large
/// again.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// The CR local: index into [`CheckedPou::cr_types`] (its type).
    Cr(u32),
    /// A typed constant.
    Const(Const),
    /// The current value of a variable or part of one: index into
    /// [`CheckedPou::places`] (a place is four times the other values, and
    /// a body reads few distinct ones, many times).
    Read(u32),
    /// A saved outer CR of a deferred parenthesis: index into
    /// [`CheckedPou::save_types`] (its type).
    Saved(u32),
    /// A value converted implicitly to a wider type (3rd edition). Boxed
    /// with its conversion: rare, and the conversion beside the box made
    /// every value a third larger.
    Widen(Box<(Value, Widen)>),
    /// A STRING (WSTRING) value given the capacity of the string type
    /// (the second; [`Ty::resizes_to`]): cut at that length, and a
    /// `StringOverflow` fault recorded when that cut something off. Boxed
    /// with its type: rare.
    Resized(Box<(Value, Ty)>),
    /// A subscript expression (`i + 1`, `2 * i`, `-i`, `i MOD 4`). Only in
    /// [`PathElem::Index`] subscripts. Boxed: rare.
    Arith(Box<Arith>),
}

/// A subscript expression ([`Value::Arith`]): `lhs op rhs` computed in
/// the integer type `elem` that both sides already have (the checker
/// widened them), as the operator of that name computes it: wrapping, and
/// `Div`/`Mod` by zero give 0 and record a `DivisionByZero` fault.
#[derive(Clone, Debug, PartialEq)]
pub struct Arith {
    /// `Add`, `Sub`, `Mul`, `Div` or `Mod`.
    pub op: BinOp,
    /// The type of both sides and of the result.
    pub elem: Elem,
    /// The left operand.
    pub lhs: Value,
    /// The right operand.
    pub rhs: Value,
}

impl Value {
    /// `v` as a value of type `to`: wrapped in [`Value::Resized`] when `from`
    /// is a string of another capacity, else unchanged.
    pub fn fit_string(v: Value, from: &Ty, to: &Ty) -> Value {
        if from.resizes_to(to) {
            Value::Resized(Box::new((v, to.clone())))
        } else {
            v
        }
    }
}

/// An implicit widening conversion the checker applied (from its one table of
/// implicit widenings): lossless, so the emitter and the interpreter
/// convert as the `FROM_TO_TO` function does and never fail.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Widen {
    /// The value's type.
    pub from: Elem,
    /// The type it becomes.
    pub to: Elem,
}

/// A computation whose result becomes the CR.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// Just the value (`LD x`).
    Value(Value),
    /// Logical/bitwise complement.
    Not(Value),
    /// `lhs op rhs` (rhs is already complemented for ANDN etc. via
    /// `negate_rhs`). Comparisons yield BOOL.
    Bin {
        /// The operator.
        op: BinOp,
        /// The operands' elementary type (the checker made both sides have
        /// it); `None` for strings and enumerations, which only compare.
        /// Not the whole type: the operator needs no more, and a type
        /// inline made every statement a quarter larger.
        elem: Option<Elem>,
        /// The left operand (usually the CR).
        lhs: Value,
        /// The right operand.
        rhs: Value,
        /// The right operand is complemented first (`ANDN`, `ORN`, `XORN`).
        negate_rhs: bool,
    },
    /// TIME/LTIME scaled by a number: `MUL`/`DIV` with a numeric operand.
    /// TIME: il-std's `MUL_TIME` / `DIV_TIME` (a divisor of integer 0 gives
    /// `T#0s` and records `DivisionByZero`). LTIME, in nanoseconds: an
    /// integer factor wraps, a real one goes through `f64` (saturating to
    /// the range), an integer divisor truncates and 0 gives `LTIME#0s` and
    /// records `DivisionByZero`.
    TimeScale {
        /// `DIV` rather than `MUL`.
        div: bool,
        /// TIME or LTIME: the type of `lhs` and of the result.
        time: Elem,
        /// The duration.
        lhs: Value,
        /// The numeric type of `rhs`.
        num: Elem,
        /// The factor or divisor.
        rhs: Value,
    },
    /// A call of a user FUNCTION (boxed, as the other calls: rare and large,
    /// inline they would set the size of every expression).
    CallUser(Box<UserCall>),
    /// A call of an il-std function.
    CallStd(Box<StdFnCall>),
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

/// One operation, with the IL line it comes from.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    /// The operation.
    pub op: Op,
    /// IL source line (1-based), carried into a comment.
    pub line: u32,
    /// Column (1-based) of the instruction on that line, for messages.
    pub col: u32,
}

/// `Some((value, when))`: act when the BOOL value equals `when`.
pub type Condition = Option<(Value, bool)>;

/// What one IL instruction (or part of one) becomes.
#[derive(Clone, Debug, PartialEq)]
pub enum Op {
    /// `__cr_<ty> = expr`
    SetCr {
        /// The CR after the instruction: index into
        /// [`CheckedPou::cr_types`] (its type; BOOL for comparisons).
        cr: u32,
        /// The computation.
        expr: Expr,
    },
    /// `__save_n = value`
    Save {
        /// The save slot: index into [`CheckedPou::save_types`] (the `__save_n` local).
        slot: u32,
        /// The outer CR to keep.
        value: Value,
    },
    /// `place = value` (complemented for STN).
    Store {
        /// The target: index into [`CheckedPou::places`], as in a
        /// [`Value::Read`].
        place: u32,
        /// The value stored (usually the CR).
        value: Value,
        /// `STN`: store the complement, taken in the CR's type: when
        /// `value` is a [`Value::Widen`], before the widening.
        negate: bool,
    },
    /// S / R on a BOOL: `if cond { place = value }`.
    SetIf {
        /// The BOOL target: index into [`CheckedPou::places`].
        place: u32,
        /// TRUE for `S`, FALSE for `R`.
        value: bool,
        /// The BOOL condition (the CR).
        cond: Value,
    },
    /// Call an FB instance after setting inputs; then copy outputs (boxed:
    /// rare and large, inline it would set the size of every statement).
    CallFb(Box<FbCall>),
    /// `JMP`, `JMPC`, `JMPCN`: go to a label of the same POU.
    Jump {
        /// Index of the label (below [`CheckedPou::label_count`]).
        label: usize,
        /// `None` for `JMP`; the CR and the value that jumps otherwise.
        cond: Condition,
    },
    /// `name:`: a jump target (the label's index).
    Label(usize),
    /// `RET`, `RETC`, `RETCN`: leave the POU.
    Return {
        /// `None` for `RET`; the CR and the value that returns otherwise.
        cond: Condition,
    },
    /// Nothing to do: keeps the line (and its comment) of an instruction
    /// that pushed no statement on its own line (one whose effect is only on
    /// the checker's state, like loading a literal). Any other instruction's
    /// line is that of its first statement.
    Nop,
}
