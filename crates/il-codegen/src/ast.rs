//! The syntax tree of an IL compilation unit. Every node carries the byte span
//! of its source text so that every later stage can point at it.

use std::fmt;

/// Half-open byte range `lo..hi` into the source file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    pub lo: u32,
    pub hi: u32,
}

impl Span {
    pub fn new(lo: usize, hi: usize) -> Self {
        // Sources over 4 GiB are refused before parsing, so these never truncate.
        Span {
            lo: lo as u32,
            hi: hi as u32,
        }
    }
    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }
    pub fn range(self) -> std::ops::Range<usize> {
        self.lo as usize..self.hi as usize
    }
}

/// A name as written. IEC names are case-insensitive: compare with [`Ident::key`]
/// or [`Ident::is`], never with `==` on `name`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Ident {
    pub name: String,
    pub span: Span,
}

impl Ident {
    pub fn new(name: impl Into<String>, span: Span) -> Self {
        Ident {
            name: name.into(),
            span,
        }
    }
    /// The case-folded lookup key.
    pub fn key(&self) -> String {
        self.name.to_ascii_uppercase()
    }
    /// Case-insensitive comparison with a name.
    pub fn is(&self, other: &str) -> bool {
        self.name.eq_ignore_ascii_case(other)
    }
}

impl fmt::Display for Ident {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

/// One source file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CompilationUnit {
    pub items: Vec<Item>,
}

// A file holds a handful of items; boxing the large POU would buy nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    Pou(Pou),
    /// `TYPE ... END_TYPE`
    Types(Vec<TypeDecl>),
    Configuration(Configuration),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PouKind {
    Function,
    FunctionBlock,
    Program,
}

impl PouKind {
    pub fn keyword(self) -> &'static str {
        match self {
            PouKind::Function => "FUNCTION",
            PouKind::FunctionBlock => "FUNCTION_BLOCK",
            PouKind::Program => "PROGRAM",
        }
    }
}

/// A FUNCTION, FUNCTION_BLOCK or PROGRAM.
#[derive(Clone, Debug, PartialEq)]
pub struct Pou {
    pub kind: PouKind,
    pub name: Ident,
    /// The result type of a FUNCTION.
    pub return_type: Option<TypeSpec>,
    pub var_blocks: Vec<VarBlock>,
    pub body: Vec<Stmt>,
    /// Whether the body was wrapped in KAS-IDE `BEGIN_IL ... END_IL`.
    pub begin_il: bool,
    /// The whole POU, keyword to END_ keyword.
    pub span: Span,
    /// The END_FUNCTION / END_FUNCTION_BLOCK / END_PROGRAM keyword.
    pub end_span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VarKind {
    Var,
    Input,
    Output,
    InOut,
    External,
    Global,
    Temp,
}

impl VarKind {
    pub fn keyword(self) -> &'static str {
        match self {
            VarKind::Var => "VAR",
            VarKind::Input => "VAR_INPUT",
            VarKind::Output => "VAR_OUTPUT",
            VarKind::InOut => "VAR_IN_OUT",
            VarKind::External => "VAR_EXTERNAL",
            VarKind::Global => "VAR_GLOBAL",
            VarKind::Temp => "VAR_TEMP",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Retain {
    #[default]
    Unspecified,
    Retain,
    NonRetain,
}

/// `VAR_INPUT CONSTANT RETAIN ... END_VAR`
#[derive(Clone, Debug, PartialEq)]
pub struct VarBlock {
    pub kind: VarKind,
    pub constant: bool,
    pub retain: Retain,
    pub decls: Vec<VarDecl>,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Edge {
    Rising,
    Falling,
}

/// `a, b AT %IX0.0 : BOOL R_EDGE := TRUE;`
#[derive(Clone, Debug, PartialEq)]
pub struct VarDecl {
    pub names: Vec<Ident>,
    pub location: Option<DirectAddress>,
    pub ty: TypeSpec,
    pub edge: Option<Edge>,
    pub init: Option<Initializer>,
    pub span: Span,
}

/// A type as written in a declaration.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeSpec {
    /// An elementary type, a user type or a function block type, by name.
    Named(Ident),
    /// `STRING`, `STRING[20]`, `WSTRING(10)`.
    String {
        wide: bool,
        len: Option<ConstExpr>,
        span: Span,
    },
    /// `ARRAY [0..9, 1..3] OF INT`
    Array {
        dims: Vec<Subrange>,
        elem: Box<TypeSpec>,
        span: Span,
    },
    /// `INT (0..100)`
    Subrange {
        base: Ident,
        range: Subrange,
        span: Span,
    },
    /// `(Red, Green := 5, Blue)` (only in TYPE declarations)
    Enum { values: Vec<EnumValue>, span: Span },
    /// `STRUCT a : INT; b : BOOL := TRUE; END_STRUCT` (only in TYPE declarations)
    Struct { fields: Vec<VarDecl>, span: Span },
}

impl TypeSpec {
    pub fn span(&self) -> Span {
        match self {
            TypeSpec::Named(id) => id.span,
            TypeSpec::String { span, .. }
            | TypeSpec::Array { span, .. }
            | TypeSpec::Subrange { span, .. }
            | TypeSpec::Enum { span, .. }
            | TypeSpec::Struct { span, .. } => *span,
        }
    }
}

/// `lo..hi`
#[derive(Clone, Debug, PartialEq)]
pub struct Subrange {
    pub lo: ConstExpr,
    pub hi: ConstExpr,
    pub span: Span,
}

/// A compile-time constant in a type: a literal or the name of a constant.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstExpr {
    Lit(Literal),
    Name(Ident),
}

impl ConstExpr {
    pub fn span(&self) -> Span {
        match self {
            ConstExpr::Lit(l) => l.span,
            ConstExpr::Name(n) => n.span,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct EnumValue {
    pub name: Ident,
    pub value: Option<Literal>,
}

/// The value after `:=` in a declaration.
#[derive(Clone, Debug, PartialEq)]
pub enum Initializer {
    /// A literal, an enumeration value or a constant's name.
    Simple(Operand),
    /// `[1, 2, 3(0)]` — each element with its repeat count.
    Array {
        elems: Vec<(Option<Literal>, Initializer)>,
        span: Span,
    },
    /// `(a := 1, b := TRUE)` for structures, and for FB instances' inputs.
    Struct {
        fields: Vec<(Ident, Initializer)>,
        span: Span,
    },
}

impl Initializer {
    pub fn span(&self) -> Span {
        match self {
            Initializer::Simple(o) => o.span(),
            Initializer::Array { span, .. } | Initializer::Struct { span, .. } => *span,
        }
    }
}

/// `name : spec := init;` inside TYPE ... END_TYPE.
#[derive(Clone, Debug, PartialEq)]
pub struct TypeDecl {
    pub name: Ident,
    pub spec: TypeSpec,
    pub init: Option<Initializer>,
    pub span: Span,
}

/// `CONFIGURATION c ... END_CONFIGURATION`
#[derive(Clone, Debug, PartialEq)]
pub struct Configuration {
    pub name: Ident,
    pub globals: Vec<VarBlock>,
    /// Resources; a configuration without RESOURCE gets one unnamed resource
    /// holding its tasks and programs (`name` = None).
    pub resources: Vec<Resource>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Resource {
    pub name: Option<Ident>,
    /// `ON processor`
    pub on: Option<Ident>,
    pub globals: Vec<VarBlock>,
    pub tasks: Vec<Task>,
    pub programs: Vec<ProgramInstance>,
    pub span: Span,
}

/// `TASK t (INTERVAL := T#10ms, PRIORITY := 1);`
#[derive(Clone, Debug, PartialEq)]
pub struct Task {
    pub name: Ident,
    pub single: Option<Operand>,
    pub interval: Option<Operand>,
    pub priority: Option<Literal>,
    pub span: Span,
}

/// `PROGRAM p WITH t : MyProgram (a := x, b => y);`
#[derive(Clone, Debug, PartialEq)]
pub struct ProgramInstance {
    pub name: Ident,
    pub retain: Retain,
    pub task: Option<Ident>,
    pub program: Ident,
    pub args: Vec<ParamAssign>,
    pub span: Span,
}

/// One element of an instruction list.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// `name:` — alone on its line or before an instruction.
    Label(Ident),
    Instr(Instr),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Instr {
    pub kind: InstrKind,
    /// The operator as written (`JMPNC`, `&N`, `ld`): for messages.
    pub op_span: Span,
    /// The whole instruction, operator to last operand (for a deferred group,
    /// to its closing `)`).
    pub span: Span,
}

/// The condition of JMP, CAL and RET.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Cond {
    Always,
    /// `C`: when the CR is TRUE.
    IfTrue,
    /// `CN` (also KAS-IDE `NC`): when the CR is FALSE.
    IfFalse,
}

/// Operators that take the CR on the left and an operand on the right, and so
/// may be deferred with `(`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ExprOp {
    And,
    Or,
    Xor,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Gt,
    Ge,
    Eq,
    Ne,
    Le,
    Lt,
}

impl ExprOp {
    pub fn name(self) -> &'static str {
        match self {
            ExprOp::And => "AND",
            ExprOp::Or => "OR",
            ExprOp::Xor => "XOR",
            ExprOp::Add => "ADD",
            ExprOp::Sub => "SUB",
            ExprOp::Mul => "MUL",
            ExprOp::Div => "DIV",
            ExprOp::Mod => "MOD",
            ExprOp::Gt => "GT",
            ExprOp::Ge => "GE",
            ExprOp::Eq => "EQ",
            ExprOp::Ne => "NE",
            ExprOp::Le => "LE",
            ExprOp::Lt => "LT",
        }
    }
    pub fn is_logic(self) -> bool {
        matches!(self, ExprOp::And | ExprOp::Or | ExprOp::Xor)
    }
    pub fn is_arith(self) -> bool {
        matches!(
            self,
            ExprOp::Add | ExprOp::Sub | ExprOp::Mul | ExprOp::Div | ExprOp::Mod
        )
    }
    pub fn is_compare(self) -> bool {
        matches!(
            self,
            ExprOp::Gt | ExprOp::Ge | ExprOp::Eq | ExprOp::Ne | ExprOp::Le | ExprOp::Lt
        )
    }
}

/// The FB input operators of Table 54 that are not also other operators
/// (`S`, `R` and `LD` are parsed as [`InstrKind::Set`], [`InstrKind::Reset`]
/// and [`InstrKind::Load`]; the checker decides from the operand's type).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FbInputOp {
    S1,
    R1,
    Clk,
    Cu,
    Cd,
    Pv,
    In,
    Pt,
}

impl FbInputOp {
    /// The FB input this operator sets.
    pub fn input_name(self) -> &'static str {
        match self {
            FbInputOp::S1 => "S1",
            FbInputOp::R1 => "R1",
            FbInputOp::Clk => "CLK",
            FbInputOp::Cu => "CU",
            FbInputOp::Cd => "CD",
            FbInputOp::Pv => "PV",
            FbInputOp::In => "IN",
            FbInputOp::Pt => "PT",
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum InstrKind {
    /// `LD x` / `LDN x`
    Load { negate: bool, operand: Operand },
    /// `ST x` / `STN x`
    Store { negate: bool, target: Operand },
    /// `S x`: set a BOOL, or the S input operator of an RS.
    Set { target: Operand },
    /// `R x`: reset a BOOL, or the R input operator of SR/CTU/CTUD.
    Reset { target: Operand },
    /// `NOT` — complements the CR.
    Not,
    /// `AND x`, `ANDN x`, `& x`, `&N x`, `ADD x`, `GT x` ...
    Expr {
        op: ExprOp,
        negate: bool,
        operand: Operand,
    },
    /// `AND( x` / `AND(` newline ... `)`: `first` is the operand of the short
    /// form (the inner CR's first load); `body` holds the inner instructions.
    Deferred {
        op: ExprOp,
        negate: bool,
        first: Option<Operand>,
        body: Vec<Stmt>,
        /// The closing `)`.
        close_span: Span,
    },
    /// `JMP l`, `JMPC l`, `JMPCN l`
    Jump { cond: Cond, label: Ident },
    /// `CAL fb`, `CAL fb(...)`, `CALC`, `CALCN`; also `CAL LIMIT(...)` of a
    /// function with a formal list (3rd edition).
    Call {
        cond: Cond,
        target: Operand,
        args: Option<CallArgs>,
    },
    /// `RET`, `RETC`, `RETCN`
    Return { cond: Cond },
    /// A function as operator: `LIMIT 0, 100` (CR is the first argument),
    /// or a formal call `LIMIT(MN := 0, MX := 100)`.
    FnCall { name: Ident, args: CallArgs },
    /// `PV C10`, `IN T1`, `S1 ff` ...
    FbInput { op: FbInputOp, instance: Operand },
}

/// An argument list.
#[derive(Clone, Debug, PartialEq)]
pub enum CallArgs {
    /// `(IN := x, Q => y)` or the lines of a multi-line list.
    Formal(Vec<ParamAssign>),
    /// `a, b, c` after a function name, or `(a, b, c)` after CAL.
    NonFormal(Vec<Operand>),
}

/// `name := value`, `name => var`, `NOT name => var`
#[derive(Clone, Debug, PartialEq)]
pub struct ParamAssign {
    pub name: Ident,
    pub kind: ParamKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ParamKind {
    Input(Operand),
    Output { negate: bool, target: Operand },
}

/// Something an instruction works on.
#[derive(Clone, Debug, PartialEq)]
pub enum Operand {
    Lit(Literal),
    Var(VarRef),
    Addr(DirectAddress),
}

impl Operand {
    pub fn span(&self) -> Span {
        match self {
            Operand::Lit(l) => l.span,
            Operand::Var(v) => v.span,
            Operand::Addr(a) => a.span,
        }
    }
}

/// `a`, `fb.Q`, `arr[i, 2].field`
#[derive(Clone, Debug, PartialEq)]
pub struct VarRef {
    pub base: Ident,
    pub path: Vec<Accessor>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Accessor {
    Field(Ident),
    /// Subscripts: literals, variables or direct addresses.
    Index(Vec<Operand>, Span),
    /// `.%X3` / `.3` bit access on a bit string (3rd edition).
    Bit(u32, Span),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Area {
    Input,
    Output,
    Memory,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AddrSize {
    /// No size letter: a bit.
    Default,
    X,
    B,
    W,
    D,
    L,
}

/// `%IX1.0`, `%QW3`, `%MD10`, `%I*` (partly specified, only in declarations).
#[derive(Clone, Debug, PartialEq)]
pub struct DirectAddress {
    pub area: Area,
    pub size: AddrSize,
    /// The dotted numbers; empty for `%I*`.
    pub path: Vec<u32>,
    pub partial: bool,
    pub span: Span,
}

/// A literal and, when written with a type prefix (`INT#5`, `T#1s`), that type.
#[derive(Clone, Debug, PartialEq)]
pub struct Literal {
    pub kind: LitKind,
    /// `INT#`, `UINT#`, `BOOL#` ... (not for T#/D#/TOD#/DT#, whose kind says it).
    pub type_prefix: Option<Ident>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum LitKind {
    /// Integer value, sign included (`-1`, `16#FF`).
    Int(i128),
    /// The value and its source text (REAL is parsed from the text as f32 to
    /// avoid double rounding).
    Real {
        value: f64,
        text: String,
    },
    Bool(bool),
    /// `T#` / `TIME#` in nanoseconds; `long` for `LT#` / `LTIME#`.
    Time {
        nanos: i64,
        long: bool,
    },
    /// `D#`: days since 1970-01-01.
    Date(i64),
    /// `TOD#`: nanoseconds since midnight.
    Tod(i64),
    /// `DT#`: nanoseconds since 1970-01-01T00:00:00.
    Dt(i64),
    /// `'...'` (wide = false) or `"..."` (wide = true), escapes resolved.
    String {
        value: String,
        wide: bool,
    },
    /// `Color#Red`
    Enum {
        ty: Ident,
        value: Ident,
    },
}
