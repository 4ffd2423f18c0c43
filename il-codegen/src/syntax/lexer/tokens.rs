//! The tokens the lexer gives the parser.

use crate::ast::*;

/// A token with its byte span, in lalrpop's external-lexer shape.
pub type Spanned = (usize, Tok, usize);

/// The lexer never reports errors through lalrpop (that would stop the
/// parse); this type only fills lalrpop's `Error` slot.
#[derive(Clone, Debug, PartialEq)]
pub enum LexError {}

/// `AND`, `ANDN`, `&`, `&N`, `ADD` ...
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExprTok {
    /// The operator.
    pub op: ExprOp,
    /// The `N` modifier (`ANDN`, `&N`).
    pub negate: bool,
}

/// A token of IL text; which ones appear depends on the lexer's mode.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    /// End of an instruction line (body mode only).
    Nl,
    /// `name:` at the start of a body line (the span covers the name).
    Label(String),
    /// A name (spelling as written); also an operator word in operand position.
    Ident(String),
    /// A literal: `5`, `16#FF`, `T#1s`, `'abc'`, `TRUE`. Boxed, like the
    /// address: they are large (an `i128` value) and rare next to names and
    /// operators, and every token is as large as the largest one.
    Lit(Box<Literal>),
    /// A direct address: `%IX0.1`, `%MW10`.
    Addr(Box<DirectAddress>),
    /// `%X3`, `%B1`, `%W0`, `%D1` right after a `.`: a partial access (3rd edition).
    Part(AddrSize, u32),
    // Operators (operator field of a body line).
    /// `LD` (false) / `LDN` (true).
    Ld(bool),
    /// `ST` (false) / `STN` (true).
    St(bool),
    /// `S`.
    Set,
    /// `R`.
    Reset,
    /// `NOT`: the operator, or the complement of an output in `NOT Q => x`.
    Not,
    /// `AND`, `ANDN`, `&`, `ADD`, `GT` ...
    Expr(ExprTok),
    /// `JMP`, `JMPC`, `JMPCN` / `JMPNC`.
    Jmp(Cond),
    /// `CAL`, `CALC`, `CALCN` / `CALNC`.
    Cal(Cond),
    /// `RET`, `RETC`, `RETCN` / `RETNC`.
    Ret(Cond),
    /// `S1`, `R1`, `CLK`, `CU`, `CD`, `PV`, `IN`, `PT`.
    FbIn(FbInputOp),
    /// KAS-IDE `BEGIN_IL`.
    BeginIl,
    /// KAS-IDE `END_IL`.
    EndIl,
    // Punctuation.
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `[`
    LBracket,
    /// `]`
    RBracket,
    /// `,`
    Comma,
    /// `;`
    Semi,
    /// `:`
    Colon,
    /// `:=`
    Assign,
    /// `=>`
    Arrow,
    /// `.`
    Dot,
    /// `..`
    DotDot,
    /// `+` in a subscript (`a[i + 1]`).
    Plus,
    /// `-` in a subscript (`a[i - 1]`).
    Minus,
    /// `*` in a subscript (`m[2 * i]`).
    Star,
    /// `/` in a subscript (`a[i / 2]`).
    Slash,
    /// `MOD` in a subscript (`a[i MOD 4]`).
    ModKw,
    // Declaration keywords.
    /// `VAR`, `VAR_INPUT`, `VAR_OUTPUT`, `VAR_IN_OUT`, `VAR_EXTERNAL`, `VAR_GLOBAL`, `VAR_TEMP`.
    Var(VarKind),
    /// `END_VAR`
    EndVar,
    /// `VAR_CONFIG` (in a CONFIGURATION)
    VarConfig,
    /// `VAR_ACCESS` (in a CONFIGURATION or RESOURCE)
    VarAccess,
    /// `READ_WRITE`
    ReadWrite,
    /// `READ_ONLY`
    ReadOnly,
    /// `CONSTANT`
    Constant,
    /// `RETAIN`
    Retain,
    /// `NON_RETAIN`
    NonRetain,
    /// `AT`
    At,
    /// `ARRAY`
    Array,
    /// `OF`
    Of,
    /// `STRUCT`
    Struct,
    /// `END_STRUCT`
    EndStruct,
    /// `TYPE`
    Type,
    /// `END_TYPE`
    EndType,
    /// `STRING`
    StringKw,
    /// `WSTRING`
    WStringKw,
    /// `R_EDGE`
    REdge,
    /// `F_EDGE`
    FEdge,
    /// `FUNCTION`, `FUNCTION_BLOCK`, `PROGRAM`.
    Pou(PouKind),
    /// `END_FUNCTION`, `END_FUNCTION_BLOCK`, `END_PROGRAM`.
    EndPou(PouKind),
    /// `CONFIGURATION`
    Configuration,
    /// `END_CONFIGURATION`
    EndConfiguration,
    /// `RESOURCE`
    Resource,
    /// `END_RESOURCE`
    EndResource,
    /// `ON`
    On,
    /// `TASK`
    Task,
    /// `WITH`
    With,
    // Synthetic tokens.
    /// Instructions at top level, outside any POU (zero width).
    Orphan,
    /// End of such instructions (zero width).
    EndOrphan,
    /// A VAR block that was never closed (zero width; already reported).
    MissingEndVar,
    /// Malformed text, already reported by the lexer.
    Error,
}
