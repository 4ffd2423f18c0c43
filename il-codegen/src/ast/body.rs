//! Instruction lists: statements, instructions, operators and operands.

use super::*;

/// One element of an instruction list.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// `name:` — alone on its line or before an instruction.
    Label(Ident),
    /// An instruction, e.g. `LD x` or `JMPC next`.
    Instr(Instr),
}

impl Stmt {
    /// Where the label or the instruction is written.
    pub fn span(&self) -> Span {
        match self {
            Stmt::Label(l) => l.span,
            Stmt::Instr(i) => i.span,
        }
    }
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
    /// The standard function the operator computes (IL's `ADD x` is
    /// `ADD(CR, x)`): what an evaluator dispatches on.
    pub fn func(self) -> il_std::signature::Func {
        use il_std::signature::Func;
        match self {
            ExprOp::And => Func::AND,
            ExprOp::Or => Func::OR,
            ExprOp::Xor => Func::XOR,
            ExprOp::Add => Func::ADD,
            ExprOp::Sub => Func::SUB,
            ExprOp::Mul => Func::MUL,
            ExprOp::Div => Func::DIV,
            ExprOp::Mod => Func::MOD,
            ExprOp::Gt => Func::GT,
            ExprOp::Ge => Func::GE,
            ExprOp::Eq => Func::EQ,
            ExprOp::Ne => Func::NE,
            ExprOp::Le => Func::LE,
            ExprOp::Lt => Func::LT,
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
        /// The operand after `(` on the same line, if any. Boxed, as the
        /// arguments of a `CAL`: inline they set the size of every
        /// instruction.
        first: Option<Box<Operand>>,
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
        /// The argument list, if any (boxed, see `Deferred::first`).
        args: Option<Box<CallArgs>>,
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
            Operand::Var(v) => v.span(),
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
    /// A boxed slice: most references have no steps (no allocation), and
    /// none grows once parsed.
    pub path: Box<[Accessor]>,
}

impl VarRef {
    /// The whole reference: from the name to the end of its last step (each
    /// step's span ends at its last token). Computed, not stored: a span
    /// more made every operand of the syntax tree a word larger.
    pub fn span(&self) -> Span {
        let hi = self.path.last().map_or(self.base.span.hi, |a| a.span().hi);
        Span {
            lo: self.base.span.lo,
            hi,
        }
    }
}

impl Accessor {
    /// Where the step is written (`.name`: the name; `[i]`: the brackets
    /// and what is between them).
    pub fn span(&self) -> Span {
        match self {
            Accessor::Field(id) => id.span,
            Accessor::Index(_, span) | Accessor::Part { span, .. } => *span,
        }
    }
}

/// One step after a variable name in a [`VarRef`].
#[derive(Clone, Debug, PartialEq)]
pub enum Accessor {
    /// `.name`: a field of a STRUCT or FB instance.
    Field(Ident),
    /// Subscripts, one per dimension: integer expressions over literals,
    /// variables and direct addresses (Ed.2 B.1.4.2).
    Index(Vec<Subscript>, Span),
    /// Partial access (3rd edition): `.3` (size `Default`), `.%X3`, `.%B1`,
    /// `.%W0`, `.%D1`: the `index`-th bit, byte, word or double word.
    Part {
        /// `Default` for `.3`, else the letter after `%`.
        size: AddrSize,
        /// Which part, counted from the least significant one.
        index: u32,
        /// The number (and `%X` etc.).
        span: Span,
    },
}

/// One subscript of an array access: `i`, `2 * i - 1`, `(i + 1) * 2`,
/// `-i`, `n MOD 4`, `k / 2`.
#[derive(Clone, Debug, PartialEq)]
pub enum Subscript {
    /// A literal, variable or direct address.
    Operand(Operand),
    /// `-operand`.
    Neg {
        /// What is negated.
        operand: Box<Subscript>,
        /// The whole expression.
        span: Span,
    },
    /// `lhs op rhs` with `op` one of `Add`, `Sub`, `Mul`, `Div`, `Mod`.
    Bin {
        /// The operator.
        op: ExprOp,
        /// The left operand.
        lhs: Box<Subscript>,
        /// The right operand.
        rhs: Box<Subscript>,
        /// The whole expression.
        span: Span,
    },
}

impl Subscript {
    /// Where the subscript is written.
    pub fn span(&self) -> Span {
        match self {
            Subscript::Operand(o) => o.span(),
            Subscript::Neg { span, .. } | Subscript::Bin { span, .. } => *span,
        }
    }

    /// Its operands, left to right (for tools that look for names).
    pub fn operands(&self) -> Vec<&Operand> {
        match self {
            Subscript::Operand(o) => vec![o],
            Subscript::Neg { operand, .. } => operand.operands(),
            Subscript::Bin { lhs, rhs, .. } => {
                let mut v = lhs.operands();
                v.extend(rhs.operands());
                v
            }
        }
    }
}

/// The memory area of a direct address: il-std's, so the compiler and the
/// runtime name the areas with one type.
pub use il_std::Area;

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
    /// Boxed: most literals have none, and inline it was a third of every literal.
    pub type_prefix: Option<Box<Ident>>,
    /// The literal as written, prefix included.
    pub span: Span,
}

/// The value of a [`Literal`].
#[derive(Clone, Debug, PartialEq)]
pub enum LitKind {
    /// Integer value, sign included (`-1`, `16#FF`).
    Int(IntValue),
    /// The value and its source text (REAL is parsed from the text as f32 to
    /// avoid double rounding).
    Real {
        /// The value.
        value: f64,
        /// The number as written after any type prefix (sign, digits, `_`, exponent).
        text: Box<str>,
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
        value: Box<str>,
        /// `"..."` (WSTRING) rather than `'...'` (STRING).
        wide: bool,
    },
    /// `Color#Red`. Boxed: rare, and its two names inline made every
    /// literal (and every operand) larger by half.
    Enum(Box<EnumLit>),
}

/// An enumeration literal `Color#Red` ([`LitKind::Enum`]).
#[derive(Clone, Debug, PartialEq)]
pub struct EnumLit {
    /// The enumeration type.
    pub ty: Ident,
    /// The value's name.
    pub value: Ident,
}

impl Instr {
    /// Every operand of the instruction, nested ones (inside parentheses,
    /// call lists and subscripts) included, in source order.
    pub fn each_operand(&self, f: &mut dyn FnMut(&Operand)) {
        fn args(a: &CallArgs, f: &mut dyn FnMut(&Operand)) {
            match a {
                CallArgs::NonFormal(list) => list.iter().for_each(|o| operand(o, f)),
                CallArgs::Formal(list) => {
                    for p in list {
                        match &p.kind {
                            ParamKind::Input(o) | ParamKind::Output { target: o, .. } => {
                                operand(o, f)
                            }
                        }
                    }
                }
            }
        }
        fn operand(o: &Operand, f: &mut dyn FnMut(&Operand)) {
            f(o);
            if let Operand::Var(v) = o {
                for a in &v.path {
                    if let Accessor::Index(subs, _) = a {
                        for s in subs {
                            s.operands().into_iter().for_each(|o| operand(o, f));
                        }
                    }
                }
            }
        }
        match &self.kind {
            InstrKind::Load { operand: o, .. }
            | InstrKind::Expr { operand: o, .. }
            | InstrKind::Store { target: o, .. }
            | InstrKind::Set { target: o }
            | InstrKind::Reset { target: o }
            | InstrKind::FbInput { instance: o, .. } => operand(o, f),
            InstrKind::Deferred { first, body, .. } => {
                if let Some(o) = first {
                    operand(o, f);
                }
                for s in body {
                    if let Stmt::Instr(i) = s {
                        i.each_operand(f);
                    }
                }
            }
            InstrKind::Call {
                target, args: a, ..
            } => {
                operand(target, f);
                if let Some(a) = a {
                    args(a, f);
                }
            }
            InstrKind::FnCall { args: a, .. } => args(a, f),
            InstrKind::Not | InstrKind::Jump { .. } | InstrKind::Return { .. } => {}
        }
    }
}
