//! Keywords of each mode: operators of the operator field, declaration
//! keywords, and the Structured Text and SFC words we recognise to explain.

use super::*;

pub(super) const ST_KEYWORDS: &[&str] = &[
    "IF",
    "THEN",
    "ELSIF",
    "ELSE",
    "END_IF",
    "CASE",
    "END_CASE",
    "FOR",
    "END_FOR",
    "WHILE",
    "END_WHILE",
    "REPEAT",
    "UNTIL",
    "END_REPEAT",
    "EXIT",
    "RETURN",
];
pub(super) const SFC_KEYWORDS: &[&str] = &[
    "INITIAL_STEP",
    "STEP",
    "END_STEP",
    "TRANSITION",
    "END_TRANSITION",
    "ACTION",
    "END_ACTION",
];
/// Operators that cannot be confused with a variable name at the start of a
/// declaration line (used to detect a missing END_VAR).
pub(super) const CLEAR_OPERATORS: &[&str] = &[
    "LD", "LDN", "ST", "STN", "ANDN", "ORN", "XORN", "JMP", "JMPC", "JMPCN", "JMPNC", "CAL",
    "CALC", "CALCN", "CALNC", "RET", "RETC", "RETCN", "RETNC", "ADD", "SUB", "MUL", "DIV", "MOD",
    "GT", "GE", "EQ", "NE", "LE", "LT", "AND", "OR", "XOR", "NOT",
];

/// The operator token for an upper-cased word in the operator field, if it is one.
pub fn operator(up: &str) -> Option<Tok> {
    use ExprOp::*;
    let e = |op, negate| Some(Tok::Expr(ExprTok { op, negate }));
    match up {
        "LD" => Some(Tok::Ld(false)),
        "LDN" => Some(Tok::Ld(true)),
        "ST" => Some(Tok::St(false)),
        "STN" => Some(Tok::St(true)),
        "S" => Some(Tok::Set),
        "R" => Some(Tok::Reset),
        "NOT" => Some(Tok::Not),
        "AND" => e(And, false),
        "ANDN" => e(And, true),
        "OR" => e(Or, false),
        "ORN" => e(Or, true),
        "XOR" => e(Xor, false),
        "XORN" => e(Xor, true),
        "ADD" => e(Add, false),
        "SUB" => e(Sub, false),
        "MUL" => e(Mul, false),
        "DIV" => e(Div, false),
        "MOD" => e(Mod, false),
        "GT" => e(Gt, false),
        "GE" => e(Ge, false),
        "EQ" => e(Eq, false),
        "NE" => e(Ne, false),
        "LE" => e(Le, false),
        "LT" => e(Lt, false),
        "JMP" => Some(Tok::Jmp(Cond::Always)),
        "JMPC" => Some(Tok::Jmp(Cond::IfTrue)),
        "JMPCN" | "JMPNC" => Some(Tok::Jmp(Cond::IfFalse)),
        "CAL" => Some(Tok::Cal(Cond::Always)),
        "CALC" => Some(Tok::Cal(Cond::IfTrue)),
        "CALCN" | "CALNC" => Some(Tok::Cal(Cond::IfFalse)),
        "RET" => Some(Tok::Ret(Cond::Always)),
        "RETC" => Some(Tok::Ret(Cond::IfTrue)),
        "RETCN" | "RETNC" => Some(Tok::Ret(Cond::IfFalse)),
        "S1" => Some(Tok::FbIn(FbInputOp::S1)),
        "R1" => Some(Tok::FbIn(FbInputOp::R1)),
        "CLK" => Some(Tok::FbIn(FbInputOp::Clk)),
        "CU" => Some(Tok::FbIn(FbInputOp::Cu)),
        "CD" => Some(Tok::FbIn(FbInputOp::Cd)),
        "PV" => Some(Tok::FbIn(FbInputOp::Pv)),
        "IN" => Some(Tok::FbIn(FbInputOp::In)),
        "PT" => Some(Tok::FbIn(FbInputOp::Pt)),
        "BEGIN_IL" => Some(Tok::BeginIl),
        "END_IL" => Some(Tok::EndIl),
        _ => None,
    }
}

pub(super) fn var_kind(up: &str) -> Option<VarKind> {
    Some(match up {
        "VAR" => VarKind::Var,
        "VAR_INPUT" => VarKind::Input,
        "VAR_OUTPUT" => VarKind::Output,
        "VAR_IN_OUT" => VarKind::InOut,
        "VAR_EXTERNAL" => VarKind::External,
        "VAR_GLOBAL" => VarKind::Global,
        "VAR_TEMP" => VarKind::Temp,
        _ => return None,
    })
}

pub(super) fn pou_kind(up: &str) -> Option<PouKind> {
    Some(match up {
        "FUNCTION" => PouKind::Function,
        "FUNCTION_BLOCK" => PouKind::FunctionBlock,
        "PROGRAM" => PouKind::Program,
        _ => return None,
    })
}

pub(super) fn end_pou_kind(up: &str) -> Option<PouKind> {
    Some(match up {
        "END_FUNCTION" => PouKind::Function,
        "END_FUNCTION_BLOCK" => PouKind::FunctionBlock,
        "END_PROGRAM" => PouKind::Program,
        _ => return None,
    })
}

/// Whether an upper-cased word is a declaration keyword (`END_VAR`,
/// `PROGRAM`, `ON` ...): such a word can never be a name (the PLCopen
/// import checks names with it).
#[cfg(feature = "plcopen")]
pub(crate) fn is_decl_keyword(up: &str) -> bool {
    decl_keyword(up).is_some()
}

pub(super) fn decl_keyword(up: &str) -> Option<Tok> {
    if let Some(k) = var_kind(up) {
        return Some(Tok::Var(k));
    }
    if let Some(k) = pou_kind(up) {
        return Some(Tok::Pou(k));
    }
    if let Some(k) = end_pou_kind(up) {
        return Some(Tok::EndPou(k));
    }
    Some(match up {
        "END_VAR" => Tok::EndVar,
        "VAR_CONFIG" => Tok::VarConfig,
        "VAR_ACCESS" => Tok::VarAccess,
        "READ_WRITE" => Tok::ReadWrite,
        "READ_ONLY" => Tok::ReadOnly,
        "CONSTANT" => Tok::Constant,
        "RETAIN" => Tok::Retain,
        "NON_RETAIN" => Tok::NonRetain,
        "AT" => Tok::At,
        "ARRAY" => Tok::Array,
        "OF" => Tok::Of,
        "STRUCT" => Tok::Struct,
        "END_STRUCT" => Tok::EndStruct,
        "TYPE" => Tok::Type,
        "END_TYPE" => Tok::EndType,
        "STRING" => Tok::StringKw,
        "WSTRING" => Tok::WStringKw,
        "R_EDGE" => Tok::REdge,
        "F_EDGE" => Tok::FEdge,
        "CONFIGURATION" => Tok::Configuration,
        "END_CONFIGURATION" => Tok::EndConfiguration,
        "RESOURCE" => Tok::Resource,
        "END_RESOURCE" => Tok::EndResource,
        "ON" => Tok::On,
        "TASK" => Tok::Task,
        "WITH" => Tok::With,
        "NOT" => Tok::Not,
        _ => return None,
    })
}

pub(super) const ELEMENTARY: &[&str] = &[
    "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL", "BOOL",
    "BYTE", "WORD", "DWORD", "LWORD",
];
