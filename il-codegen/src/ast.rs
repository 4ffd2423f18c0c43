//! The syntax tree of an IL compilation unit. Every node carries the byte span
//! of its source text so that every later stage can point at it.

use std::fmt;

/// Half-open byte range `lo..hi` into the source file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    /// First byte (inclusive).
    pub lo: u32,
    /// End byte (exclusive).
    pub hi: u32,
}

impl Span {
    /// A span from byte offsets (a source is at most 4 GiB, so they fit in `u32`).
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
    /// The span as a `usize` range, for slicing the source text.
    pub fn range(self) -> std::ops::Range<usize> {
        self.lo as usize..self.hi as usize
    }
}

/// A name as written. IEC names are case-insensitive: compare with [`Ident::key`]
/// or [`Ident::is`], never with `==` on `name`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Ident {
    /// The name with its original spelling (case preserved).
    pub name: String,
    /// Where the name is written.
    pub span: Span,
}

impl Ident {
    /// A name with its spelling and position.
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
    /// POUs, TYPE blocks and CONFIGURATIONs, in source order.
    pub items: Vec<Item>,
}

// A file holds a handful of items; boxing the large POU would buy nothing.
/// A top-level declaration of a compilation unit.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A FUNCTION, FUNCTION_BLOCK or PROGRAM.
    Pou(Pou),
    /// `TYPE ... END_TYPE`
    Types(Vec<TypeDecl>),
    /// `CONFIGURATION ... END_CONFIGURATION`
    Configuration(Configuration),
}

/// The kind of a program organisation unit (POU).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PouKind {
    /// `FUNCTION f : INT ... END_FUNCTION`: no memory between calls, returns a value.
    Function,
    /// `FUNCTION_BLOCK fb ... END_FUNCTION_BLOCK`: instantiated; keeps its variables between calls.
    FunctionBlock,
    /// `PROGRAM p ... END_PROGRAM`: the top-level unit a task or the host runs every cycle.
    Program,
}

impl PouKind {
    /// The opening keyword (`FUNCTION`, `FUNCTION_BLOCK`, `PROGRAM`).
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
    /// FUNCTION, FUNCTION_BLOCK or PROGRAM.
    pub kind: PouKind,
    /// The POU's name (the FUNCTION's name is also its result variable).
    pub name: Ident,
    /// The result type of a FUNCTION.
    pub return_type: Option<TypeSpec>,
    /// The VAR blocks, in source order.
    pub var_blocks: Vec<VarBlock>,
    /// The instruction list, labels included.
    pub body: Vec<Stmt>,
    /// Whether the body was wrapped in KAS-IDE `BEGIN_IL ... END_IL`.
    pub begin_il: bool,
    /// The whole POU, keyword to END_ keyword.
    pub span: Span,
    /// The END_FUNCTION / END_FUNCTION_BLOCK / END_PROGRAM keyword.
    pub end_span: Span,
}

/// The section keyword of a [`VarBlock`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VarKind {
    /// `VAR`: internal variables (kept between calls, except in a FUNCTION).
    Var,
    /// `VAR_INPUT`: inputs, set by the caller.
    Input,
    /// `VAR_OUTPUT`: outputs, read by the caller.
    Output,
    /// `VAR_IN_OUT`: passed by reference; the caller must give a variable.
    InOut,
    /// `VAR_EXTERNAL`: a VAR_GLOBAL of the configuration, bound by name.
    External,
    /// `VAR_GLOBAL`: in a CONFIGURATION or RESOURCE (the checker refuses it in a POU).
    Global,
    /// `VAR_TEMP`: re-initialised on every call.
    Temp,
}

impl VarKind {
    /// The section keyword (`VAR_INPUT`, ...).
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

/// The retention qualifier of a VAR block or program instance.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Retain {
    /// Neither keyword: the implementation's default (not retained here).
    #[default]
    Unspecified,
    /// `RETAIN`: kept across a warm restart (in the generated RETAIN snapshot).
    Retain,
    /// `NON_RETAIN`: explicitly re-initialised on a warm restart.
    NonRetain,
}

/// `VAR_INPUT CONSTANT RETAIN ... END_VAR`
#[derive(Clone, Debug, PartialEq)]
pub struct VarBlock {
    /// The section keyword.
    pub kind: VarKind,
    /// `CONSTANT`: the variables may not be written.
    pub constant: bool,
    /// `RETAIN` / `NON_RETAIN`, if given.
    pub retain: Retain,
    /// The declarations of the block.
    pub decls: Vec<VarDecl>,
    /// From the VAR keyword to END_VAR.
    pub span: Span,
}

/// Edge detection of a BOOL input (`R_EDGE` / `F_EDGE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Edge {
    /// `R_EDGE`: the body sees TRUE only in the call where the input goes FALSE → TRUE.
    Rising,
    /// `F_EDGE`: the body sees TRUE only in the call where the input goes TRUE → FALSE.
    Falling,
}

/// `a, b AT %IX0.0 : BOOL R_EDGE := TRUE;`
#[derive(Clone, Debug, PartialEq)]
pub struct VarDecl {
    /// The names declared together (`a, b`); at least one.
    pub names: Vec<Ident>,
    /// `AT %IX0.0`: the variable is that place of the process image.
    pub location: Option<DirectAddress>,
    /// The declared type.
    pub ty: TypeSpec,
    /// `R_EDGE` / `F_EDGE` (the checker allows it on VAR_INPUTs of FBs and PROGRAMs).
    pub edge: Option<Edge>,
    /// `:= init`, if given.
    pub init: Option<Initializer>,
    /// From the first name to the `;`.
    pub span: Span,
}

/// A type as written in a declaration.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeSpec {
    /// An elementary type, a user type or a function block type, by name.
    Named(Ident),
    /// `STRING`, `STRING[20]`, `WSTRING(10)`.
    String {
        /// `WSTRING` (UTF-16) rather than `STRING` (bytes).
        wide: bool,
        /// The maximum length in characters, if given.
        len: Option<ConstExpr>,
        /// The whole type.
        span: Span,
    },
    /// `ARRAY [0..9, 1..3] OF INT`
    Array {
        /// One `lo..hi` per dimension.
        dims: Vec<Subrange>,
        /// The element type.
        elem: Box<TypeSpec>,
        /// The whole type.
        span: Span,
    },
    /// `INT (0..100)`
    Subrange {
        /// The integer base type (`INT`).
        base: Ident,
        /// The allowed range.
        range: Subrange,
        /// The whole type.
        span: Span,
    },
    /// `(Red, Green := 5, Blue)` (only in TYPE declarations)
    Enum {
        /// The values in declaration order.
        values: Vec<EnumValue>,
        /// The whole type.
        span: Span,
    },
    /// `STRUCT a : INT; b : BOOL := TRUE; END_STRUCT` (only in TYPE declarations)
    Struct {
        /// The field declarations.
        fields: Vec<VarDecl>,
        /// `STRUCT` to `END_STRUCT`.
        span: Span,
    },
}

impl TypeSpec {
    /// Where the type is written.
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
    /// Lower bound (inclusive).
    pub lo: ConstExpr,
    /// Upper bound (inclusive).
    pub hi: ConstExpr,
    /// `lo..hi` as written.
    pub span: Span,
}

/// A compile-time constant in a type: a literal or the name of a constant.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstExpr {
    /// A literal (`10`, `INT#-5`).
    Lit(Literal),
    /// The name of a constant (`VAR CONSTANT` or `VAR_GLOBAL CONSTANT`).
    Name(Ident),
}

impl ConstExpr {
    /// Where the constant is written.
    pub fn span(&self) -> Span {
        match self {
            ConstExpr::Lit(l) => l.span,
            ConstExpr::Name(n) => n.span,
        }
    }
}

/// One value of an enumeration type: `Green` or `Green := 5`.
#[derive(Clone, Debug, PartialEq)]
pub struct EnumValue {
    /// The value's name.
    pub name: Ident,
    /// The explicit value after `:=`, if given.
    pub value: Option<Literal>,
}

/// The value after `:=` in a declaration.
#[derive(Clone, Debug, PartialEq)]
pub enum Initializer {
    /// A literal, an enumeration value or a constant's name.
    Simple(Operand),
    /// `[1, 2, 3(0)]` — each element with its repeat count.
    Array {
        /// Each element with its repeat count, if any (`3(0)`: three zeros).
        elems: Vec<(Option<Literal>, Initializer)>,
        /// `[` to `]`.
        span: Span,
    },
    /// `(a := 1, b := TRUE)` for structures, and for FB instances' inputs.
    Struct {
        /// `name := value` for each field or FB input.
        fields: Vec<(Ident, Initializer)>,
        /// `(` to `)`.
        span: Span,
    },
}

impl Initializer {
    /// Where the initial value is written.
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
    /// The type's name.
    pub name: Ident,
    /// What it is: a renamed type, subrange, enumeration, array, STRUCT or STRING.
    pub spec: TypeSpec,
    /// The type's default initial value, if given (`INT := 5`).
    pub init: Option<Initializer>,
    /// From the name to the `;`.
    pub span: Span,
}

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

/// One element of an instruction list.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// `name:` — alone on its line or before an instruction.
    Label(Ident),
    /// An instruction, e.g. `LD x` or `JMPC next`.
    Instr(Instr),
}

/// One IL instruction: an operator with its modifiers and operands.
#[derive(Clone, Debug, PartialEq)]
pub struct Instr {
    /// The operator and its operands.
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
    /// No modifier: unconditional.
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
    /// `AND` / `&` (`ANDN` / `&N` with negate): Boolean or bitwise AND.
    And,
    /// `OR` (`ORN`): Boolean or bitwise OR.
    Or,
    /// `XOR` (`XORN`): Boolean or bitwise exclusive OR.
    Xor,
    /// `ADD`: addition.
    Add,
    /// `SUB`: subtraction.
    Sub,
    /// `MUL`: multiplication.
    Mul,
    /// `DIV`: division.
    Div,
    /// `MOD`: integer remainder.
    Mod,
    /// `GT`: CR > operand.
    Gt,
    /// `GE`: CR >= operand.
    Ge,
    /// `EQ`: CR = operand.
    Eq,
    /// `NE`: CR <> operand.
    Ne,
    /// `LE`: CR <= operand.
    Le,
    /// `LT`: CR < operand.
    Lt,
}

impl ExprOp {
    /// The IL operator name without the `N` modifier (`AND`, `ADD`, `GT`).
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
    /// `AND`, `OR`, `XOR`: BOOL or bit-string operands.
    pub fn is_logic(self) -> bool {
        matches!(self, ExprOp::And | ExprOp::Or | ExprOp::Xor)
    }
    /// `ADD`, `SUB`, `MUL`, `DIV`, `MOD`: numeric operands.
    pub fn is_arith(self) -> bool {
        matches!(
            self,
            ExprOp::Add | ExprOp::Sub | ExprOp::Mul | ExprOp::Div | ExprOp::Mod
        )
    }
    /// `GT`, `GE`, `EQ`, `NE`, `LE`, `LT`: the result is BOOL.
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
    /// `S1 ff`: the set input of an SR.
    S1,
    /// `R1 ff`: the reset input of an RS.
    R1,
    /// `CLK trig`: the clock input of R_TRIG / F_TRIG.
    Clk,
    /// `CU c`: the count-up input of CTU / CTUD.
    Cu,
    /// `CD c`: the count-down input of CTD / CTUD.
    Cd,
    /// `PV c`: the preset value of a counter.
    Pv,
    /// `IN t`: the input of a timer (TON, TOF, TP).
    In,
    /// `PT t`: the preset time of a timer.
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

/// What an instruction does, with its operands.
#[derive(Clone, Debug, PartialEq)]
pub enum InstrKind {
    /// `LD x` / `LDN x`
    Load {
        /// `LDN`: load the complement.
        negate: bool,
        /// The value loaded into the CR.
        operand: Operand,
    },
    /// `ST x` / `STN x`
    Store {
        /// `STN`: store the complement.
        negate: bool,
        /// Where the CR is stored.
        target: Operand,
    },
    /// `S x`: set a BOOL, or the S input operator of an RS.
    Set {
        /// The BOOL set to TRUE when the CR is TRUE (or the RS instance).
        target: Operand,
    },
    /// `R x`: reset a BOOL, or the R input operator of SR/CTU/CTUD.
    Reset {
        /// The BOOL set to FALSE when the CR is TRUE (or the SR/CTU/CTUD instance).
        target: Operand,
    },
    /// `NOT` — complements the CR.
    Not,
    /// `AND x`, `ANDN x`, `& x`, `&N x`, `ADD x`, `GT x` ...
    Expr {
        /// The operator.
        op: ExprOp,
        /// The `N` modifier: the operand is complemented (`ANDN`, `&N`).
        negate: bool,
        /// The right-hand operand (the CR is the left-hand one).
        operand: Operand,
    },
    /// `AND( x` / `AND(` newline ... `)`: `first` is the operand of the short
    /// form (the inner CR's first load); `body` holds the inner instructions.
    Deferred {
        /// The deferred operator.
        op: ExprOp,
        /// The `N` modifier (`ANDN(`).
        negate: bool,
        /// The operand after `(` on the same line, if any.
        first: Option<Operand>,
        /// The instructions inside the parentheses.
        body: Vec<Stmt>,
        /// The closing `)`.
        close_span: Span,
    },
    /// `JMP l`, `JMPC l`, `JMPCN l`
    Jump {
        /// `C` / `CN` modifier.
        cond: Cond,
        /// The target label.
        label: Ident,
    },
    /// `CAL fb`, `CAL fb(...)`, `CALC`, `CALCN`; also `CAL LIMIT(...)` of a
    /// function with a formal list (3rd edition).
    Call {
        /// `C` / `CN` modifier.
        cond: Cond,
        /// The FB instance (or function) called.
        target: Operand,
        /// The argument list, if any.
        args: Option<CallArgs>,
    },
    /// `RET`, `RETC`, `RETCN`
    Return {
        /// `C` / `CN` modifier.
        cond: Cond,
    },
    /// A function as operator: `LIMIT 0, 100` (CR is the first argument),
    /// or a formal call `LIMIT(MN := 0, MX := 100)`.
    FnCall {
        /// The function's name.
        name: Ident,
        /// The arguments after the CR (non-formal) or all of them (formal).
        args: CallArgs,
    },
    /// `PV C10`, `IN T1`, `S1 ff` ...
    FbInput {
        /// The input operator.
        op: FbInputOp,
        /// The FB instance whose input is set from the CR.
        instance: Operand,
    },
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
    /// The formal parameter's name.
    pub name: Ident,
    /// Input or output assignment.
    pub kind: ParamKind,
    /// The whole assignment.
    pub span: Span,
}

/// The direction of a [`ParamAssign`].
#[derive(Clone, Debug, PartialEq)]
pub enum ParamKind {
    /// `name := value`: sets an input before the call.
    Input(Operand),
    /// `name => var` (`NOT name => var` with negate): copies an output after the call.
    Output {
        /// `NOT name => var`: store the output's complement.
        negate: bool,
        /// The variable that receives the output.
        target: Operand,
    },
}

/// Something an instruction works on.
#[derive(Clone, Debug, PartialEq)]
pub enum Operand {
    /// A literal: `5`, `T#1s`, `'text'`.
    Lit(Literal),
    /// A variable, possibly with fields, subscripts and bit access: `fb.Q`, `a[i]`.
    Var(VarRef),
    /// A direct address: `%IX0.1`.
    Addr(DirectAddress),
}

impl Operand {
    /// Where the operand is written.
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
    /// The variable's name.
    pub base: Ident,
    /// Field, subscript and bit accesses after it, in order.
    pub path: Vec<Accessor>,
    /// The whole reference.
    pub span: Span,
}

/// One step after a variable name in a [`VarRef`].
#[derive(Clone, Debug, PartialEq)]
pub enum Accessor {
    /// `.name`: a field of a STRUCT or FB instance.
    Field(Ident),
    /// Subscripts: literals, variables or direct addresses.
    Index(Vec<Operand>, Span),
    /// `.%X3` / `.3` bit access on a bit string (3rd edition).
    Bit(u32, Span),
}

/// The memory area of a direct address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Area {
    /// `%I`: inputs of the process image.
    Input,
    /// `%Q`: outputs of the process image.
    Output,
    /// `%M`: memory (markers).
    Memory,
}

/// The size letter of a direct address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AddrSize {
    /// No size letter: a bit.
    Default,
    /// `X`: a bit.
    X,
    /// `B`: a byte (8 bits).
    B,
    /// `W`: a word (16 bits).
    W,
    /// `D`: a double word (32 bits).
    D,
    /// `L`: a long word (64 bits).
    L,
}

/// `%IX1.0`, `%QW3`, `%MD10`, `%I*` (partly specified, only in declarations).
#[derive(Clone, Debug, PartialEq)]
pub struct DirectAddress {
    /// `I`, `Q` or `M`.
    pub area: Area,
    /// The size letter (none = bit).
    pub size: AddrSize,
    /// The dotted numbers; empty for `%I*`.
    pub path: Vec<u32>,
    /// `%I*` / `%Q*`: the address is left to the configuration.
    pub partial: bool,
    /// The address as written.
    pub span: Span,
}

/// A literal and, when written with a type prefix (`INT#5`, `T#1s`), that type.
#[derive(Clone, Debug, PartialEq)]
pub struct Literal {
    /// The value.
    pub kind: LitKind,
    /// `INT#`, `UINT#`, `BOOL#` ... (not for T#/D#/TOD#/DT#, whose kind says it).
    pub type_prefix: Option<Ident>,
    /// The literal as written, prefix included.
    pub span: Span,
}

/// The value of a [`Literal`].
#[derive(Clone, Debug, PartialEq)]
pub enum LitKind {
    /// Integer value, sign included (`-1`, `16#FF`).
    Int(i128),
    /// The value and its source text (REAL is parsed from the text as f32 to
    /// avoid double rounding).
    Real {
        /// The value.
        value: f64,
        /// The number as written after any type prefix (sign, digits, `_`, exponent).
        text: String,
    },
    /// `TRUE` / `FALSE` (also `BOOL#1`, `BOOL#0`).
    Bool(bool),
    /// `T#` / `TIME#` in nanoseconds; `long` for `LT#` / `LTIME#`.
    Time {
        /// The duration in nanoseconds (may be negative).
        nanos: i64,
        /// `LT#` / `LTIME#` (LTIME) rather than `T#` (TIME).
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
        /// The characters.
        value: String,
        /// `"..."` (WSTRING) rather than `'...'` (STRING).
        wide: bool,
    },
    /// `Color#Red`
    Enum {
        /// The enumeration type.
        ty: Ident,
        /// The value's name.
        value: Ident,
    },
}
