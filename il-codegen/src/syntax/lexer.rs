//! The IL lexer. IL is position-sensitive: the first word of a body line is
//! the operator field (`LD`, `ST`, a function name), words after it are
//! operands (`LD IN` loads the variable `IN`). The lexer therefore runs in
//! modes:
//!
//! * declaration modes (top level, header, `VAR..END_VAR`, `TYPE..END_TYPE`,
//!   `CONFIGURATION`): no line breaks, declaration keywords;
//! * body mode (between a POU header and its `END_` keyword, outside `VAR`
//!   blocks): line breaks are [`Tok::Nl`], the operator field gives operator
//!   tokens, `(` after an expression operator is a deferred parenthesis and
//!   any other `(` opens an argument list (in which line breaks are ignored).
//!
//! The lexer never fails: malformed text becomes a diagnostic and, where the
//! parser must not accept it, a [`Tok::Error`] token. It runs in linear time.

use crate::ast::*;
use crate::diag::Diagnostic;

use super::errors::code;
use super::literal;

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
    /// A literal: `5`, `16#FF`, `T#1s`, `'abc'`, `TRUE`.
    Lit(Literal),
    /// A direct address: `%IX0.1`, `%MW10`.
    Addr(DirectAddress),
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
    // Declaration keywords.
    /// `VAR`, `VAR_INPUT`, `VAR_OUTPUT`, `VAR_IN_OUT`, `VAR_EXTERNAL`, `VAR_GLOBAL`, `VAR_TEMP`.
    Var(VarKind),
    /// `END_VAR`
    EndVar,
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

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    Top,
    Header,
    Body,
    Var,
    Type,
    Config,
    /// Skipping a body written in ST or SFC, up to its END_ keyword.
    Skip,
}

/// Deferred parentheses deeper than this are refused (deep trees overflow
/// the stack when dropped).
pub const MAX_DEFER_DEPTH: usize = 256;

/// The mode-driven lexer; [`lex`] runs it over a whole file.
pub struct Lexer<'a> {
    src: &'a str,
    b: &'a [u8],
    pos: usize,
    mode: Mode,
    var_ret: Mode,
    orphan: bool,
    op_field: bool,
    dirty: bool,
    line_start: bool,
    header_toks: usize,
    arg_depth: usize,
    defer_stack: Vec<usize>,
    excess: usize,
    in_resource: bool,
    /// Declarations: open `(`, `[` and STRUCT; ARRAY keywords in this declaration.
    nest: usize,
    arrays: usize,
    nest_reported: bool,
    out: Vec<Spanned>,
    diags: Vec<Diagnostic>,
}

fn is_ident_start(c: u8) -> bool {
    c.is_ascii_alphabetic() || c == b'_'
}
fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

fn span(lo: usize, hi: usize) -> Span {
    Span::new(lo, hi)
}

const ST_KEYWORDS: &[&str] = &[
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
const SFC_KEYWORDS: &[&str] = &[
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
const CLEAR_OPERATORS: &[&str] = &[
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

fn var_kind(up: &str) -> Option<VarKind> {
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

fn pou_kind(up: &str) -> Option<PouKind> {
    Some(match up {
        "FUNCTION" => PouKind::Function,
        "FUNCTION_BLOCK" => PouKind::FunctionBlock,
        "PROGRAM" => PouKind::Program,
        _ => return None,
    })
}

fn end_pou_kind(up: &str) -> Option<PouKind> {
    Some(match up {
        "END_FUNCTION" => PouKind::Function,
        "END_FUNCTION_BLOCK" => PouKind::FunctionBlock,
        "END_PROGRAM" => PouKind::Program,
        _ => return None,
    })
}

fn decl_keyword(up: &str) -> Option<Tok> {
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

const ELEMENTARY: &[&str] = &[
    "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL", "BOOL",
    "BYTE", "WORD", "DWORD", "LWORD",
];

/// Lex a whole file. Returns the tokens and the lexer's diagnostics.
pub fn lex(src: &str) -> (Vec<Spanned>, Vec<Diagnostic>) {
    let mut lx = Lexer {
        src,
        b: src.as_bytes(),
        pos: 0,
        mode: Mode::Top,
        var_ret: Mode::Top,
        orphan: false,
        op_field: true,
        dirty: false,
        line_start: true,
        header_toks: 0,
        arg_depth: 0,
        defer_stack: Vec::new(),
        excess: 0,
        in_resource: false,
        nest: 0,
        arrays: 0,
        nest_reported: false,
        out: Vec::new(),
        diags: Vec::new(),
    };
    if src.starts_with('\u{feff}') {
        lx.pos = 3;
    }
    lx.run();
    (lx.out, lx.diags)
}

impl<'a> Lexer<'a> {
    fn peek(&self, off: usize) -> u8 {
        self.b.get(self.pos + off).copied().unwrap_or(0)
    }

    fn push(&mut self, lo: usize, t: Tok, hi: usize) {
        self.out.push((lo, t, hi));
        self.line_start = false;
        if self.mode == Mode::Body && !matches!(self.out.last(), Some((_, Tok::Nl, _))) {
            self.dirty = true;
        }
    }

    fn diag(
        &mut self,
        code: &'static str,
        lo: usize,
        hi: usize,
        msg: impl Into<String>,
        label: &str,
    ) -> &mut Diagnostic {
        self.diags
            .push(Diagnostic::error(code, span(lo, hi), msg).with_label(label));
        self.diags.last_mut().expect("just pushed")
    }

    fn last_tok(&self) -> Option<&Tok> {
        self.out.last().map(|(_, t, _)| t)
    }

    fn run(&mut self) {
        loop {
            if let Some(nl) = self.skip_trivia() {
                self.on_newline(nl);
            }
            if self.pos >= self.b.len() {
                self.finish();
                return;
            }
            let before = (self.pos, self.out.len(), self.mode);
            match self.mode {
                Mode::Skip => self.skip_step(),
                Mode::Body if self.arg_depth == 0 => self.body_token(),
                Mode::Body => self.operand_token(),
                _ => self.decl_token(),
            }
            // Progress guard: every step consumes input, emits a token or
            // changes mode; anything else would loop forever.
            if (self.pos, self.out.len(), self.mode) == before {
                let c = self.char_len();
                self.pos += c;
            }
        }
    }

    fn char_len(&self) -> usize {
        self.src[self.pos..]
            .chars()
            .next()
            .map_or(1, char::len_utf8)
    }

    /// Skip blanks and comments; return the position of the first line break
    /// crossed, if any.
    fn skip_trivia(&mut self) -> Option<usize> {
        let mut nl = None;
        loop {
            match self.peek(0) {
                b'\n' => {
                    nl.get_or_insert(self.pos);
                    self.pos += 1;
                }
                b' ' | b'\t' | b'\r' | 0x0B | 0x0C => self.pos += 1,
                b'(' if self.peek(1) == b'*' => {
                    let start = self.pos;
                    match self.src[start + 2..].find("*)") {
                        Some(end) => {
                            let end = start + 2 + end + 2;
                            if let Some(i) = self.src[start..end].find('\n') {
                                nl.get_or_insert(start + i);
                            }
                            self.pos = end;
                        }
                        None => {
                            self.diag(
                                code::UNTERMINATED_COMMENT,
                                start,
                                start + 2,
                                "this comment is never closed",
                                "comment starts here",
                            )
                            .help = Some("close it with `*)`; IEC comments do not nest".into());
                            if let Some(i) = self.src[start..].find('\n') {
                                nl.get_or_insert(start + i);
                            }
                            self.pos = self.b.len();
                        }
                    }
                }
                b'/' if self.peek(1) == b'/' => {
                    // 3rd-edition line comment.
                    while self.pos < self.b.len() && self.b[self.pos] != b'\n' {
                        self.pos += 1;
                    }
                }
                b'{' => {
                    let start = self.pos;
                    let end = self.src[start..]
                        .find('}')
                        .map_or(self.b.len(), |e| start + e + 1);
                    self.diag(
                        code::PRAGMA,
                        start,
                        end,
                        "pragmas `{ ... }` are not part of IEC 61131-3 Instruction List",
                        "pragma ignored",
                    );
                    if let Some(i) = self.src[start..end].find('\n') {
                        nl.get_or_insert(start + i);
                    }
                    self.pos = end;
                }
                b';' if self.mode == Mode::Body || self.mode == Mode::Skip => {
                    let start = self.pos;
                    let end = self.src[start..]
                        .find('\n')
                        .map_or(self.b.len(), |e| start + e);
                    if self.mode == Mode::Body {
                        self.diag(
                            code::SEMI_COMMENT,
                            start,
                            end,
                            "`;` comments are not IEC 61131-3; write (* ... *)",
                            "non-IEC comment",
                        )
                        .help = Some("IEC 61131-3 comments are written (* like this *)".into());
                    }
                    self.pos = end;
                }
                _ => return nl,
            }
        }
    }

    fn on_newline(&mut self, at: usize) {
        self.line_start = true;
        match self.mode {
            Mode::Body => {
                if self.arg_depth > 0 && self.arglist_ended() {
                    self.arg_depth = 0;
                }
                if self.arg_depth == 0 {
                    self.nest = 0;
                    self.nest_reported = false;
                    if self.dirty {
                        self.out.push((at, Tok::Nl, at + 1));
                        self.dirty = false;
                    }
                    self.op_field = true;
                }
            }
            Mode::Header => {
                self.header_incomplete(at);
                self.mode = Mode::Body;
                self.op_field = true;
                self.dirty = false;
            }
            _ => {}
        }
    }

    /// Inside an argument list at the start of a line: does this line look
    /// like the next instruction (so the list was never closed)?
    fn arglist_ended(&self) -> bool {
        let rest = &self.src[self.pos..];
        let word_len = rest.bytes().take_while(|&c| is_ident(c)).count();
        if word_len == 0 {
            return false;
        }
        let up = rest[..word_len].to_ascii_uppercase();
        let after = rest[word_len..].trim_start_matches([' ', '\t']);
        if after.starts_with(":=")
            || after.starts_with("=>")
            || after.starts_with(',')
            || after.starts_with(')')
        {
            return false;
        }
        if up == "NOT" {
            return false;
        }
        end_pou_kind(&up).is_some()
            || operator(&up).is_some()
            || (after.starts_with(':') && !after.starts_with(":="))
    }

    fn finish(&mut self) {
        let eof = self.b.len();
        if self.mode == Mode::Var {
            self.missing_end_var(eof);
            self.mode = self.var_ret;
        }
        match self.mode {
            Mode::Body | Mode::Skip => {
                self.mode = Mode::Body;
                self.close_deferred(eof);
                if self.dirty {
                    self.out.push((eof, Tok::Nl, eof));
                    self.dirty = false;
                }
                if self.orphan {
                    self.out.push((eof, Tok::EndOrphan, eof));
                    self.orphan = false;
                }
            }
            Mode::Type => {
                self.diag(
                    code::MISSING_END,
                    eof,
                    eof,
                    "missing END_TYPE",
                    "the file ends here",
                );
                self.out.push((eof, Tok::EndType, eof));
            }
            Mode::Config => {
                if self.in_resource {
                    self.out.push((eof, Tok::EndResource, eof));
                }
                self.diag(
                    code::MISSING_END,
                    eof,
                    eof,
                    "missing END_CONFIGURATION",
                    "the file ends here",
                );
                self.out.push((eof, Tok::EndConfiguration, eof));
            }
            _ => {}
        }
    }

    fn missing_end_var(&mut self, at: usize) {
        let open = self
            .out
            .iter()
            .rev()
            .find(|(_, t, _)| matches!(t, Tok::Var(_)))
            .map_or(span(at, at), |(l, _, h)| span(*l, *h));
        self.diags.push(
            Diagnostic::error(code::MISSING_END_VAR, span(at, at), "missing END_VAR")
                .with_label("the declarations should end before this")
                .with_secondary(open, "this block is not closed"),
        );
        self.out.push((at, Tok::MissingEndVar, at));
    }

    /// Close deferred parentheses left open at the end of a body.
    fn close_deferred(&mut self, at: usize) {
        if let Some(&first) = self.defer_stack.first() {
            let n = self.defer_stack.len();
            self.diag(
                code::PAREN,
                first,
                first + 1,
                if n == 1 {
                    "this `(` is never closed".to_string()
                } else {
                    format!("{n} parentheses are never closed")
                },
                "opened here",
            )
            .help = Some("close a deferred operation with `)` on a line of its own".into());
            if self.dirty {
                self.out.push((at, Tok::Nl, at));
            }
            for _ in 0..n {
                self.out.push((at, Tok::RParen, at));
                self.out.push((at, Tok::Nl, at));
            }
            self.dirty = false;
            self.defer_stack.clear();
        }
        self.excess = 0;
        self.arg_depth = 0;
    }

    fn read_word(&mut self) -> (usize, usize) {
        let start = self.pos;
        while self.pos < self.b.len() && is_ident(self.b[self.pos]) {
            self.pos += 1;
        }
        // `_`, `__`...: no letter or digit, so no IEC identifier (as a name
        // it would reach Rust as `_`, which is not an identifier there).
        if self.b[start..self.pos].iter().all(|&c| c == b'_') && self.pos > start {
            self.diag(
                crate::sema::codes::BAD_IDENT,
                start,
                self.pos,
                format!(
                    "`{}` is not an identifier: an IEC identifier needs a letter or a digit",
                    &self.src[start..self.pos]
                ),
                "not an identifier",
            );
        }
        (start, self.pos)
    }

    /// A token in the operator field of a body line.
    fn body_token(&mut self) {
        if !self.op_field {
            return self.operand_token();
        }
        let start = self.pos;
        if self.excess > 0 {
            return self.skip_excess_line();
        }
        match self.peek(0) {
            b')' => {
                self.pos += 1;
                self.op_field = false;
                if self.excess > 0 {
                    self.excess -= 1;
                    self.push(start, Tok::Error, start + 1);
                } else if self.defer_stack.pop().is_some() {
                    self.push(start, Tok::RParen, start + 1);
                } else {
                    self.diag(
                        code::PAREN,
                        start,
                        start + 1,
                        "this `)` has no matching `(`",
                        "unmatched",
                    );
                    self.push(start, Tok::Error, start + 1);
                }
            }
            b'&' => {
                self.pos += 1;
                let negate = matches!(self.peek(0), b'N' | b'n') && !is_ident(self.peek(1));
                if negate {
                    self.pos += 1;
                }
                self.op_field = false;
                self.push(
                    start,
                    Tok::Expr(ExprTok {
                        op: ExprOp::And,
                        negate,
                    }),
                    self.pos,
                );
            }
            c if is_ident_start(c) => self.op_word(),
            _ => {
                self.op_field = false;
                self.operand_token();
            }
        }
    }

    /// Inside parentheses nested too deep (already reported): skip whole
    /// lines, only counting the parentheses they open and close, so that the
    /// parser sees neither them nor a cascade of errors.
    fn skip_excess_line(&mut self) {
        let start = self.pos;
        let end = self.src[start..]
            .find('\n')
            .map_or(self.b.len(), |i| start + i);
        let line = &self.src[start..end];
        let word_len = line
            .bytes()
            .take_while(|&c| is_ident(c) || c == b'&')
            .count();
        let word = line[..word_len].to_ascii_uppercase();
        let opens = (word.starts_with('&') || matches!(operator(&word), Some(Tok::Expr(_))))
            && line[word_len..].trim_start().starts_with('(')
            && !line[word_len..].trim_start().starts_with("(*");
        if line.starts_with(')') {
            self.excess -= 1;
        } else if opens {
            self.excess += 1;
        } else if end_pou_kind(&word).is_some() {
            // The body ends: close_deferred will report and repair.
            self.excess = 0;
            return self.op_word();
        }
        self.pos = end;
    }

    fn op_word(&mut self) {
        let (start, end) = self.read_word();
        if self.peek(0) == b'#' {
            self.pos = start;
            self.op_field = false;
            return self.operand_token();
        }
        let word = &self.src[start..end];
        let up = word.to_ascii_uppercase();
        // A label?
        let mut j = end;
        while matches!(self.b.get(j), Some(b' ' | b'\t')) {
            j += 1;
        }
        if self.b.get(j) == Some(&b':') && self.b.get(j + 1) != Some(&b'=') {
            self.pos = j + 1;
            self.push(start, Tok::Label(word.to_string()), end);
            return;
        }
        if let Some(t) = operator(&up) {
            self.op_field = false;
            self.push(start, t, end);
            return;
        }
        if let Some(k) = end_pou_kind(&up) {
            self.close_deferred(start);
            if self.orphan {
                self.out.push((start, Tok::EndOrphan, start));
                self.orphan = false;
            }
            self.push(start, Tok::EndPou(k), end);
            self.mode = Mode::Top;
            return;
        }
        if let Some(k) = var_kind(&up) {
            self.push(start, Tok::Var(k), end);
            self.mode = Mode::Var;
            self.var_ret = Mode::Body;
            return;
        }
        if pou_kind(&up).is_some() || up == "TYPE" || up == "CONFIGURATION" {
            // A new item while a body is open: its END_ keyword is missing.
            self.close_deferred(start);
            if self.orphan {
                self.out.push((start, Tok::EndOrphan, start));
                self.orphan = false;
            }
            self.pos = start;
            self.mode = Mode::Top;
            self.line_start = true;
            return;
        }
        if ST_KEYWORDS.contains(&up.as_str()) || self.assignment_follows(end) {
            let line_end = self.src[start..]
                .find('\n')
                .map_or(self.b.len(), |e| start + e);
            let shown = self.src[start..line_end].trim_end();
            let shown = if shown.len() > 40 {
                format!("{}...", &shown[..floor_char(shown, 37)])
            } else {
                shown.to_string()
            };
            self.diag(
                code::ST_CODE,
                start,
                line_end,
                format!("this is a Structured Text statement (`{shown}`); only Instruction List is supported"),
                "Structured Text",
            )
            .notes
            .push("the rest of this POU is skipped".into());
            self.mode = Mode::Skip;
            return;
        }
        if SFC_KEYWORDS.contains(&up.as_str()) {
            self.diag(
                code::SFC_CODE,
                start,
                end,
                "SFC (STEP/TRANSITION/ACTION) is not supported",
                "SFC element",
            )
            .notes
            .push("the rest of this POU is skipped".into());
            self.mode = Mode::Skip;
            return;
        }
        // Any other word is a function used as an operator.
        self.op_field = false;
        self.push(start, Tok::Ident(word.to_string()), end);
    }

    /// After a word at the start of a line: `:=` (possibly after `.a` / `[i]`)?
    fn assignment_follows(&self, mut j: usize) -> bool {
        let b = self.b;
        loop {
            while matches!(b.get(j), Some(b' ' | b'\t')) {
                j += 1;
            }
            match b.get(j) {
                Some(b'.') => {
                    j += 1;
                    while b.get(j).is_some_and(|&c| is_ident(c)) {
                        j += 1;
                    }
                }
                Some(b'[') => {
                    while b.get(j).is_some_and(|&c| c != b']' && c != b'\n') {
                        j += 1;
                    }
                    j += 1;
                }
                Some(b':') => return b.get(j + 1) == Some(&b'='),
                _ => return false,
            }
        }
    }

    /// Skip a body in ST or SFC up to the END_ keyword of its POU.
    fn skip_step(&mut self) {
        let c = self.peek(0);
        if is_ident_start(c) {
            let line_start = self.line_start;
            let (start, end) = self.read_word();
            let up = self.src[start..end].to_ascii_uppercase();
            let new_item = line_start
                && self.orphan
                && (pou_kind(&up).is_some() || up == "TYPE" || up == "CONFIGURATION");
            if end_pou_kind(&up).is_some() || new_item {
                self.pos = start;
                self.mode = Mode::Body;
                self.op_field = true;
                self.dirty = false;
            }
            self.line_start = false;
        } else if c == b'\'' || c == b'"' {
            let (end, _) = self.string_end(self.pos);
            self.pos = end.max(self.pos + 1);
        } else {
            self.pos += self.char_len();
            self.line_start = false;
        }
    }

    /// A token in declaration modes.
    fn decl_token(&mut self) {
        let start = self.pos;
        let c = self.peek(0);
        if self.mode == Mode::Top {
            if is_ident_start(c) {
                let (s, e) = self.read_word();
                let up = self.src[s..e].to_ascii_uppercase();
                self.pos = start;
                if up.starts_with("END_") && (decl_keyword(&up).is_some() || up == "END_IL") {
                    self.pos = e;
                    let opener = up.trim_start_matches("END_").to_string();
                    self.diag(
                        code::MISSING_END,
                        s,
                        e,
                        format!("`{}` without a matching `{opener}`", &self.src[s..e]),
                        "nothing to close",
                    );
                    return;
                }
                if pou_kind(&up).is_none() && up != "TYPE" && up != "CONFIGURATION" {
                    return self.start_orphan();
                }
            } else {
                return self.start_orphan();
            }
        }
        if !is_ident_start(c) {
            return self.operand_token();
        }
        let (s, e) = self.read_word();
        if self.peek(0) == b'#' {
            self.pos = s;
            return self.operand_token();
        }
        let word = &self.src[s..e];
        let up = word.to_ascii_uppercase();
        if self.mode == Mode::Var && self.line_start && self.var_ret == Mode::Body {
            let line_end = self.src[s..].find('\n').map_or(self.b.len(), |x| s + x);
            let looks_like_code = (CLEAR_OPERATORS.contains(&up.as_str())
                && !self.src[e..line_end].contains(':'))
                || end_pou_kind(&up).is_some();
            if looks_like_code {
                self.missing_end_var(s);
                self.pos = s;
                self.mode = Mode::Body;
                self.op_field = true;
                self.dirty = false;
                return;
            }
        }
        let Some(kw) = decl_keyword(&up) else {
            if self.mode == Mode::Header {
                self.header_toks += 1;
            }
            if up == "TRUE" || up == "FALSE" {
                let lit = Literal {
                    kind: LitKind::Bool(up == "TRUE"),
                    type_prefix: None,
                    span: span(s, e),
                };
                self.push(s, Tok::Lit(lit), e);
            } else {
                self.push(s, Tok::Ident(word.to_string()), e);
            }
            return;
        };
        match (self.mode, &kw) {
            (Mode::Top, Tok::Pou(_)) => {
                self.mode = Mode::Header;
                self.header_toks = 0;
            }
            (Mode::Top, Tok::Type) => self.mode = Mode::Type,
            (Mode::Top, Tok::Configuration) => {
                self.mode = Mode::Config;
                self.in_resource = false;
            }
            (Mode::Header, Tok::Var(_)) => {
                self.header_incomplete(s);
                self.mode = Mode::Var;
                self.var_ret = Mode::Body;
            }
            (Mode::Header, Tok::EndPou(_)) => self.mode = Mode::Top,
            (Mode::Header, _) => self.header_toks += 1,
            (Mode::Var, Tok::EndVar) => {
                self.mode = self.var_ret;
                if self.mode == Mode::Body {
                    self.push(s, kw, e);
                    self.op_field = true;
                    self.dirty = false;
                    return;
                }
            }
            (Mode::Var, Tok::EndPou(_) | Tok::Pou(_) | Tok::Type | Tok::Configuration)
                if self.var_ret != Mode::Config =>
            {
                self.missing_end_var(s);
                self.pos = s;
                self.mode = self.var_ret;
                if self.mode == Mode::Body {
                    self.op_field = true;
                    self.dirty = false;
                }
                return;
            }
            (Mode::Type, Tok::EndType) => self.mode = Mode::Top,
            (Mode::Type, Tok::Pou(_) | Tok::Configuration) => {
                self.diag(
                    code::MISSING_END,
                    s,
                    e,
                    "missing END_TYPE before this",
                    "a new declaration starts here",
                );
                self.out.push((s, Tok::EndType, s));
                self.pos = s;
                self.mode = Mode::Top;
                return;
            }
            (Mode::Config, Tok::EndConfiguration | Tok::Resource) if self.in_resource => {
                self.diag(
                    code::MISSING_END,
                    s,
                    e,
                    "missing END_RESOURCE before this",
                    "the resource should end before this",
                );
                self.out.push((s, Tok::EndResource, s));
                self.in_resource = kw == Tok::Resource;
                if kw == Tok::EndConfiguration {
                    self.mode = Mode::Top;
                }
            }
            (Mode::Config, Tok::EndConfiguration) => self.mode = Mode::Top,
            (Mode::Config, Tok::Resource) => self.in_resource = true,
            (Mode::Config, Tok::EndResource) => self.in_resource = false,
            (Mode::Config, Tok::Var(_)) => {
                self.mode = Mode::Var;
                self.var_ret = Mode::Config;
            }
            (Mode::Config, Tok::Pou(PouKind::Function | PouKind::FunctionBlock) | Tok::Type) => {
                self.diag(
                    code::MISSING_END,
                    s,
                    e,
                    "missing END_CONFIGURATION before this",
                    "a new declaration starts here",
                );
                if self.in_resource {
                    self.out.push((s, Tok::EndResource, s));
                }
                self.out.push((s, Tok::EndConfiguration, s));
                self.pos = s;
                self.mode = Mode::Top;
                return;
            }
            _ => {}
        }
        match kw {
            Tok::Struct | Tok::Array => {
                if !self.nest_ok(s, e) {
                    return;
                }
                if kw == Tok::Struct {
                    self.nest += 1;
                } else {
                    self.arrays += 1;
                }
            }
            Tok::EndStruct => self.nest = self.nest.saturating_sub(1),
            Tok::EndVar | Tok::EndType | Tok::EndConfiguration => {
                self.nest = 0;
                self.arrays = 0;
                self.nest_reported = false;
            }
            _ => {}
        }
        self.push(s, kw, e);
    }

    /// Declarations nest at most MAX_DEFER_DEPTH deep; beyond, the token is
    /// replaced by an error token (deep trees overflow the stack when dropped).
    fn nest_ok(&mut self, lo: usize, hi: usize) -> bool {
        if self.nest + self.arrays < MAX_DEFER_DEPTH {
            return true;
        }
        if !self.nest_reported {
            self.nest_reported = true;
            self.diag(
                code::TOO_DEEP,
                lo,
                hi,
                format!("this declaration is nested more than {MAX_DEFER_DEPTH} deep"),
                "too deep",
            );
        }
        // Skip the rest of the declaration: one error token, so that the
        // parser's recovery does not walk a deep stack once per token.
        let stop = if self.mode == Mode::Body { '\n' } else { ';' };
        let end = self.src[hi..].find(stop).map_or(self.b.len(), |i| hi + i);
        self.pos = end;
        self.nest = 0;
        self.arrays = 0;
        self.push(lo, Tok::Error, end.max(hi));
        false
    }

    /// A POU header ends (line break or VAR): synthesize a missing name or
    /// result type so that the rest of the POU still parses.
    fn header_incomplete(&mut self, at: usize) {
        match self.out.last() {
            Some((lo, Tok::Pou(k), hi)) => {
                let (lo, hi, k) = (*lo, *hi, *k);
                self.diag(
                    code::SYNTAX,
                    lo,
                    hi,
                    format!(
                        "expected the name of the {} after `{}`",
                        k.keyword(),
                        &self.src[lo..hi]
                    ),
                    "name missing",
                );
                self.out.push((at, Tok::Ident(String::new()), at));
            }
            Some((_, Tok::Colon, _)) => self.out.push((at, Tok::Ident(String::new()), at)),
            _ => {}
        }
        self.header_toks += 1;
    }

    fn start_orphan(&mut self) {
        let p = self.pos;
        self.out.push((p, Tok::Orphan, p));
        self.mode = Mode::Body;
        self.orphan = true;
        self.op_field = true;
        self.dirty = false;
    }

    /// Operands, literals, punctuation (body operand field, argument lists and
    /// declarations).
    fn operand_token(&mut self) {
        let start = self.pos;
        let c = self.peek(0);
        let body = self.mode == Mode::Body;
        match c {
            c if is_ident_start(c) => {
                let (s, e) = self.read_word();
                if self.peek(0) == b'#' {
                    return self.typed_literal(s, e);
                }
                let word = &self.src[s..e];
                let up = word.to_ascii_uppercase();
                if up == "TRUE" || up == "FALSE" {
                    let lit = Literal {
                        kind: LitKind::Bool(up == "TRUE"),
                        type_prefix: None,
                        span: span(s, e),
                    };
                    self.push(s, Tok::Lit(lit), e);
                } else if up == "NOT" && (self.arg_depth > 0 || !body) {
                    self.push(s, Tok::Not, e);
                } else if !body && let Some(kw) = decl_keyword(&up) {
                    self.push(s, kw, e);
                } else {
                    self.push(s, Tok::Ident(word.to_string()), e);
                }
            }
            b'0'..=b'9' => self.number(start, None),
            b'-' | b'+' if self.peek(1).is_ascii_digit() => self.number(start, None),
            b'\'' | b'"' => {
                if let Some((kind, end)) = self.string(start) {
                    let lit = Literal {
                        kind,
                        type_prefix: None,
                        span: span(start, end),
                    };
                    self.push(start, Tok::Lit(lit), end);
                }
            }
            b'%' => self.address(start),
            b'(' => {
                self.pos += 1;
                let deferred =
                    body && self.arg_depth == 0 && matches!(self.last_tok(), Some(Tok::Expr(_)));
                if deferred {
                    if self.defer_stack.len() >= MAX_DEFER_DEPTH || self.excess > 0 {
                        if self.excess == 0 {
                            self.diag(
                                code::TOO_DEEP,
                                start,
                                start + 1,
                                format!("parentheses are nested more than {MAX_DEFER_DEPTH} deep"),
                                "too deep",
                            )
                            .help =
                                Some("store intermediate results in temporary variables".into());
                        }
                        self.excess += 1;
                        self.push(start, Tok::Error, start + 1);
                    } else {
                        self.defer_stack.push(start);
                        self.push(start, Tok::LParen, start + 1);
                    }
                } else if body {
                    self.arg_depth += 1;
                    self.push(start, Tok::LParen, start + 1);
                } else if self.nest_ok(start, start + 1) {
                    self.nest += 1;
                    self.push(start, Tok::LParen, start + 1);
                }
            }
            b')' => {
                self.pos += 1;
                if body && self.arg_depth > 0 {
                    self.arg_depth -= 1;
                } else if !body {
                    self.nest = self.nest.saturating_sub(1);
                }
                self.push(start, Tok::RParen, start + 1);
            }
            b'[' if !body => {
                if self.nest_ok(start, start + 1) {
                    self.nest += 1;
                    self.punct(start, 1, Tok::LBracket);
                }
            }
            b']' if !body => {
                self.nest = self.nest.saturating_sub(1);
                self.punct(start, 1, Tok::RBracket);
            }
            b';' if !body => {
                self.arrays = 0;
                self.punct(start, 1, Tok::Semi);
            }
            b'[' => {
                if self.nest_ok(start, start + 1) {
                    self.nest += 1;
                    self.punct(start, 1, Tok::LBracket);
                }
            }
            b']' => {
                self.nest = self.nest.saturating_sub(1);
                self.punct(start, 1, Tok::RBracket);
            }
            b',' => self.punct(start, 1, Tok::Comma),
            b';' => self.punct(start, 1, Tok::Semi),
            b':' if self.peek(1) == b'=' => self.punct(start, 2, Tok::Assign),
            b':' => self.punct(start, 1, Tok::Colon),
            b'=' if self.peek(1) == b'>' => self.punct(start, 2, Tok::Arrow),
            b'.' if self.peek(1) == b'.' => self.punct(start, 2, Tok::DotDot),
            b'.' => self.punct(start, 1, Tok::Dot),
            _ => {
                // One diagnostic for a run of stray characters.
                let n = self.char_len();
                let ch = self.src[start..start + n].to_string();
                self.pos += n;
                while self.src[self.pos..].starts_with(ch.as_str()) {
                    self.pos += n;
                }
                let shown = &self.src[start..self.pos];
                self.diag(
                    code::BAD_CHAR,
                    start,
                    self.pos,
                    format!("`{shown}` has no meaning in Instruction List"),
                    "unexpected character",
                );
                self.push(start, Tok::Error, self.pos);
            }
        }
    }

    fn punct(&mut self, start: usize, n: usize, t: Tok) {
        self.pos = start + n;
        self.push(start, t, start + n);
    }

    /// A number at `start` (optionally signed): integer, based integer or real.
    /// `prefix`: the type prefix of a typed literal (its span starts earlier).
    fn number(&mut self, start: usize, prefix: Option<(Ident, usize)>) {
        let b = self.b;
        let mut i = start;
        if matches!(b.get(i), Some(b'-' | b'+')) {
            i += 1;
        }
        while b.get(i).is_some_and(|c| c.is_ascii_digit() || *c == b'_') {
            i += 1;
        }
        let mut real = false;
        let mut no_dot_exp = false;
        if b.get(i) == Some(&b'#') {
            i += 1;
            while b.get(i).is_some_and(|&c| is_ident(c)) {
                i += 1;
            }
        } else {
            if b.get(i) == Some(&b'.') && b.get(i + 1).is_some_and(u8::is_ascii_digit) {
                real = true;
                i += 1;
                while b.get(i).is_some_and(|c| c.is_ascii_digit() || *c == b'_') {
                    i += 1;
                }
            }
            if matches!(b.get(i), Some(b'e' | b'E')) {
                let mut j = i + 1;
                if matches!(b.get(j), Some(b'+' | b'-')) {
                    j += 1;
                }
                if b.get(j).is_some_and(u8::is_ascii_digit) {
                    while b.get(j).is_some_and(u8::is_ascii_digit) {
                        j += 1;
                    }
                    no_dot_exp = !real;
                    real = true;
                    i = j;
                }
            }
        }
        // Letters glued to a number (`25x`) make it malformed.
        let mut bad = false;
        while b.get(i).is_some_and(|&c| is_ident(c)) {
            i += 1;
            bad = true;
        }
        self.pos = i;
        let text = &self.src[start..i];
        let lo = prefix.as_ref().map_or(start, |p| p.1);
        let kind = if bad {
            self.diag(
                code::BAD_NUMBER,
                start,
                i,
                format!("`{text}` is not a number"),
                "malformed number",
            );
            LitKind::Int(0)
        } else if real {
            if no_dot_exp {
                let (mant, exp) = text.split_at(text.find(['e', 'E']).unwrap_or(text.len()));
                self.diag(
                    code::BAD_NUMBER,
                    start,
                    i,
                    format!("`{text}` is not an IEC real literal: a REAL needs a decimal point"),
                    "exponent without `.`",
                )
                .help = Some(format!("write {mant}.0{exp}"));
            }
            match literal::parse_real(text) {
                Ok(value) => LitKind::Real {
                    value,
                    text: text.to_string(),
                },
                Err(m) => {
                    self.diag(code::BAD_NUMBER, start, i, m, "malformed number");
                    LitKind::Int(0)
                }
            }
        } else {
            match literal::parse_int(text) {
                Ok(v) => LitKind::Int(v),
                Err(m) => {
                    self.diag(
                        code::BAD_NUMBER,
                        start,
                        i,
                        format!("`{text}`: {m}"),
                        "malformed number",
                    );
                    LitKind::Int(0)
                }
            }
        };
        let (kind, type_prefix) = match prefix {
            Some((p, _)) if p.is("BOOL") => match kind {
                LitKind::Int(0) => (LitKind::Bool(false), Some(p)),
                LitKind::Int(1) => (LitKind::Bool(true), Some(p)),
                k => {
                    self.diag(
                        code::BAD_NUMBER,
                        lo,
                        i,
                        "a BOOL literal is 0, 1, TRUE or FALSE",
                        "not a BOOL",
                    );
                    (k, Some(p))
                }
            },
            Some((p, _)) => (kind, Some(p)),
            None => (kind, None),
        };
        let lit = Literal {
            kind,
            type_prefix,
            span: span(lo, i),
        };
        self.push(lo, Tok::Lit(lit), i);
    }

    /// End (exclusive) of the string literal starting with a quote at
    /// `start`, and whether it is closed on its line.
    fn string_end(&self, start: usize) -> (usize, bool) {
        let q = self.b[start];
        let mut i = start + 1;
        while i < self.b.len() {
            match self.b[i] {
                b'$' if self.b.get(i + 1).is_some_and(|&c| c != b'\n') => i += 2,
                b'\n' => return (i, false),
                c if c == q => return (i + 1, true),
                _ => i += 1,
            }
        }
        (self.b.len(), false)
    }

    fn string(&mut self, start: usize) -> Option<(LitKind, usize)> {
        let q = self.b[start];
        let wide = q == b'"';
        let (end, closed) = self.string_end(start);
        self.pos = end;
        if !closed {
            self.diag(
                code::BAD_STRING,
                start,
                end,
                "this string is not closed on its line",
                "unterminated string",
            )
            .help = Some(format!("end it with {}", q as char));
            self.push(start, Tok::Error, end);
            return None;
        }
        let body = &self.src[start + 1..end - 1];
        match literal::unescape(body, wide) {
            Ok(value) => Some((LitKind::String { value, wide }, end)),
            Err(m) => {
                self.diag(code::BAD_STRING, start, end, m, "in this string");
                Some((
                    LitKind::String {
                        value: body.to_string(),
                        wide,
                    },
                    end,
                ))
            }
        }
    }

    /// `PREFIX#value` with the prefix word at `s..e` and `#` at `e`.
    fn typed_literal(&mut self, s: usize, e: usize) {
        let word = &self.src[s..e];
        let up = word.to_ascii_uppercase();
        let vstart = e + 1;
        self.pos = vstart;
        let take = |this: &mut Self, ok: &dyn Fn(u8) -> bool| {
            let mut i = this.pos;
            while this.b.get(i).is_some_and(|&c| ok(c)) {
                i += 1;
            }
            this.pos = i;
            &this.src[vstart..i]
        };
        let done =
            |this: &mut Self, r: Result<LitKind, String>, code_: &'static str, what: &str| {
                let hi = this.pos;
                let kind = match r {
                    Ok(k) => k,
                    Err(m) => {
                        this.diag(code_, s, hi, m, what);
                        LitKind::Int(0)
                    }
                };
                let lit = Literal {
                    kind,
                    type_prefix: None,
                    span: span(s, hi),
                };
                this.push(s, Tok::Lit(lit), hi);
            };
        match up.as_str() {
            "T" | "TIME" | "LT" | "LTIME" => {
                let long = up.starts_with('L');
                let text = take(self, &|c| {
                    is_ident(c) || c == b'.' || c == b'-' || c == b'+'
                });
                let r = literal::parse_duration(text).map(|nanos| LitKind::Time { nanos, long });
                done(self, r, code::BAD_DURATION, "invalid duration");
            }
            "D" | "DATE" | "LDATE" => {
                let text = take(self, &|c| {
                    c.is_ascii_alphanumeric() || c == b'-' || c == b'_'
                });
                let r = literal::parse_date(text).map(LitKind::Date);
                done(self, r, code::BAD_DATE, "invalid date");
            }
            "TOD" | "TIME_OF_DAY" | "LTOD" | "LTIME_OF_DAY" => {
                let text = take(self, &|c| {
                    c.is_ascii_alphanumeric() || c == b':' || c == b'.'
                });
                let r = literal::parse_tod(text).map(LitKind::Tod);
                done(self, r, code::BAD_DATE, "invalid time of day");
            }
            "DT" | "DATE_AND_TIME" | "LDT" | "LDATE_AND_TIME" => {
                let text = take(self, &|c| {
                    c.is_ascii_alphanumeric() || c == b':' || c == b'.' || c == b'-'
                });
                let r = literal::parse_dt(text).map(LitKind::Dt);
                done(self, r, code::BAD_DATE, "invalid date and time");
            }
            _ => {
                let prefix = Ident::new(word, span(s, e));
                let c = self.peek(0);
                let elementary = ELEMENTARY.contains(&up.as_str());
                if matches!(up.as_str(), "STRING" | "WSTRING" | "CHAR" | "WCHAR")
                    && (c == b'\'' || c == b'"')
                {
                    if let Some((kind, end)) = self.string(vstart) {
                        let lit = Literal {
                            kind,
                            type_prefix: Some(prefix),
                            span: span(s, end),
                        };
                        self.push(s, Tok::Lit(lit), end);
                    }
                } else if c.is_ascii_digit()
                    || (matches!(c, b'-' | b'+') && self.peek(1).is_ascii_digit())
                {
                    if !elementary {
                        // `Color#1`? Not IEC, but give it to the checker as a typed number.
                        self.diag(code::BAD_NUMBER, s, e, format!("`{word}` is not an elementary type: only numeric, bit-string and BOOL types prefix a number"), "not a type for numbers");
                    }
                    self.number(vstart, Some((prefix, s)));
                } else if is_ident_start(c) {
                    let (vs, ve) = self.read_word();
                    let v = &self.src[vs..ve];
                    let vup = v.to_ascii_uppercase();
                    let kind = if elementary && (vup == "TRUE" || vup == "FALSE") {
                        if up != "BOOL" {
                            self.diag(
                                code::BAD_NUMBER,
                                s,
                                ve,
                                format!("`{word}#{v}`: TRUE and FALSE are BOOL values"),
                                "not a BOOL type",
                            );
                        }
                        LitKind::Bool(vup == "TRUE")
                    } else {
                        LitKind::Enum {
                            ty: prefix.clone(),
                            value: Ident::new(v, span(vs, ve)),
                        }
                    };
                    let type_prefix = if matches!(kind, LitKind::Enum { .. }) {
                        None
                    } else {
                        Some(prefix)
                    };
                    let lit = Literal {
                        kind,
                        type_prefix,
                        span: span(s, ve),
                    };
                    self.push(s, Tok::Lit(lit), ve);
                } else {
                    self.diag(
                        code::BAD_NUMBER,
                        s,
                        vstart,
                        format!("expected a value after `{word}#`"),
                        "value missing",
                    );
                    self.push(s, Tok::Error, vstart);
                }
            }
        }
    }

    /// `%IX1.0`, `%QW3`, `%MD10`, `%I*`.
    fn address(&mut self, start: usize) {
        let b = self.b;
        let mut i = start + 1;
        let area = match b.get(i).map(u8::to_ascii_uppercase) {
            Some(b'I') => Some(Area::Input),
            Some(b'Q') => Some(Area::Output),
            Some(b'M') => Some(Area::Memory),
            _ => None,
        };
        let end_of = |mut j: usize| {
            while b
                .get(j)
                .is_some_and(|&c| is_ident(c) || c == b'.' || c == b'*')
            {
                j += 1;
            }
            j
        };
        let Some(area) = area else {
            let end = end_of(i);
            self.pos = end.max(start + 1);
            self.diag(
                code::BAD_ADDRESS,
                start,
                self.pos,
                format!(
                    "`{}` is not a direct address: the area must be I, Q or M",
                    &self.src[start..self.pos]
                ),
                "invalid address",
            );
            self.push(start, Tok::Error, self.pos);
            return;
        };
        i += 1;
        let mut size = AddrSize::Default;
        let mut error: Option<(String, Option<String>)> = None;
        match b.get(i).map(u8::to_ascii_uppercase) {
            Some(b'X') => size = AddrSize::X,
            Some(b'B') => size = AddrSize::B,
            Some(b'W') => size = AddrSize::W,
            Some(b'D') => size = AddrSize::D,
            Some(b'L') => size = AddrSize::L,
            Some(b'F') => {
                size = AddrSize::D;
                error = Some((
                    "`F` is not an IEC address size: %IF/%QF/%MF float addresses are a vendor extension".into(),
                    Some("use a double word (`%MD0`) and declare the variable as REAL".into()),
                ));
            }
            _ => i -= 1,
        }
        i += 1;
        let mut path = Vec::new();
        let mut partial = false;
        if b.get(i) == Some(&b'*') {
            partial = true;
            i += 1;
        } else {
            loop {
                let ds = i;
                while b.get(i).is_some_and(u8::is_ascii_digit) {
                    i += 1;
                }
                if ds == i {
                    error.get_or_insert((
                        "expected a number in this direct address, e.g. `%IX0.1`".into(),
                        None,
                    ));
                    break;
                }
                match self.src[ds..i].parse::<u32>() {
                    Ok(n) => path.push(n),
                    Err(_) => {
                        error.get_or_insert(("this address number is too large".into(), None));
                    }
                }
                if b.get(i) == Some(&b'.') && b.get(i + 1).is_some_and(u8::is_ascii_digit) {
                    i += 1;
                } else {
                    break;
                }
            }
        }
        if b.get(i).is_some_and(|&c| is_ident(c)) {
            i = end_of(i);
            error.get_or_insert((
                format!("`{}` is not a valid direct address", &self.src[start..i]),
                None,
            ));
        }
        self.pos = i;
        if partial && self.mode == Mode::Body {
            error.get_or_insert((
                "a partly specified address (`%I*`) may only appear in a declaration".into(),
                Some("give the full address, e.g. `%IX0.0`, or use the declared variable".into()),
            ));
        }
        if let Some((m, help)) = error {
            let d = self.diag(code::BAD_ADDRESS, start, i, m, "invalid address");
            d.help = help;
        }
        let addr = DirectAddress {
            area,
            size,
            path,
            partial,
            span: span(start, i),
        };
        self.push(start, Tok::Addr(addr), i);
    }
}

fn floor_char(s: &str, mut i: usize) -> usize {
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(src: &str) -> Vec<Tok> {
        lex(src).0.into_iter().map(|(_, t, _)| t).collect()
    }

    #[test]
    fn position_decides() {
        let t = toks("PROGRAM p\nVAR R1 : BOOL; END_VAR\nLD R1\nR1 R1\nEND_PROGRAM");
        assert!(t.contains(&Tok::Ld(false)));
        assert!(t.contains(&Tok::FbIn(FbInputOp::R1)));
        assert_eq!(
            t.iter().filter(|t| **t == Tok::Ident("R1".into())).count(),
            3
        );
    }

    #[test]
    fn deferred_vs_arglist() {
        let t = toks("PROGRAM p\nAND( x\nCAL f(\n a := 1,\n b => c\n)\n)\nEND_PROGRAM");
        let nls = t.iter().filter(|t| **t == Tok::Nl).count();
        // header line break is not a token; AND( x / CAL...) / ) lines
        assert_eq!(nls, 3, "{t:?}");
    }

    #[test]
    fn never_loops() {
        for src in [
            "%",
            "(*",
            "'abc",
            "PROGRAM",
            "\u{0}\u{1}",
            "T#",
            "16#",
            "&",
            ")",
            "x:",
            "PROGRAM p\n(((",
            "é",
        ] {
            let _ = lex(src);
        }
    }
}
