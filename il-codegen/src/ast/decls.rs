//! Declarations: VAR blocks, variables, types as written, initial values
//! and TYPE ... END_TYPE.

use super::*;

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
