//! The syntax tree of an IL compilation unit. Every node carries the byte span
//! of its source text so that every later stage can point at it.

use std::fmt;

mod body;
mod configuration;
mod decls;
mod int_value;

/// Parse one IL file into its syntax tree, with the syntax diagnostics
/// (tools that read the tree itself: outlines, formatters, fuzzers).
pub use crate::syntax::{parse, parse_std};
pub use body::*;
pub use configuration::*;
pub use decls::*;
pub use int_value::IntValue;

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
    /// The name with its original spelling (case preserved). A boxed
    /// `str`, not a `String`: a name never grows, and the spare word was a
    /// sixth of every operand of the syntax tree.
    pub name: Box<str>,
    /// Where the name is written.
    pub span: Span,
}

impl Ident {
    /// A name with its spelling and position.
    pub fn new(name: impl Into<String>, span: Span) -> Self {
        Ident {
            name: name.into().into_boxed_str(),
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
    /// The `{extern}` pragma before a FUNCTION: the host crate provides its
    /// body (see `syntax::host`).
    pub host: Option<Span>,
}
