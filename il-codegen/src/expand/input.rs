//! The `il!` call's input as `il-macros` hands it over: a few kinds of
//! token, each with the number of its span (`il-macros` keeps the spans
//! themselves), so that reading it needs neither syn nor proc_macro2 and an
//! `il!` user compiles neither.

use super::literal::{string_source, string_value};
use crate::Standard;

/// Which span a token or an error has: an index into the caller's list of
/// spans, or [`CALL_SITE`].
pub type SpanId = u32;

/// The span of the macro call itself.
pub const CALL_SITE: SpanId = u32::MAX;

/// One token of the input.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    /// A literal: its source text (`"..."`, `r#"..."#`, `1`) and where it
    /// starts in the caller's file (line and column 0 and an empty file
    /// when unknown).
    Literal {
        /// As written.
        text: String,
        /// The line it starts on (1-based), or 0.
        line: usize,
        /// The column it starts at (1-based, in characters), or 0.
        column: usize,
        /// The Rust file, as rustc names it in its messages, or empty.
        file: String,
        /// Its span.
        span: SpanId,
    },
    /// An identifier or keyword.
    Ident(String, SpanId),
    /// One punctuation character.
    Punct(char, SpanId),
    /// `[...]`, `(...)` or `{...}` (`open` is the opening character; a
    /// group without delimiters has `' '`).
    Group {
        /// `[`, `(`, `{` or `' '`.
        open: char,
        /// The tokens inside.
        inner: Vec<Tok>,
        /// The whole group.
        span: SpanId,
    },
}

impl Tok {
    /// A string literal with this value (for callers without a tokenizer:
    /// benches, fuzzers, tests).
    pub fn string(value: &str, span: SpanId) -> Tok {
        Tok::Literal {
            text: string_source(value),
            line: 0,
            column: 0,
            file: String::new(),
            span,
        }
    }

    /// Its span.
    pub fn span(&self) -> SpanId {
        match self {
            Tok::Literal { span, .. } | Tok::Group { span, .. } => *span,
            Tok::Ident(_, s) | Tok::Punct(_, s) => *s,
        }
    }
}

/// A string literal of the input.
pub use crate::diag::render::RustPlace;

pub(super) struct Lit {
    pub value: String,
    /// Where the value's first character is in the Rust file, when known.
    pub place: Option<RustPlace>,
    pub span: SpanId,
}

pub(super) enum Input {
    Inline(Lit),
    /// `file = "a.il"` or `files = ["a.il", "b.xml"]`: one program.
    Files(Vec<Lit>),
}

/// What may follow the IL: `, serde`, `, std = "iec2003"`,
/// `, dialect = "m221"` and `, encoding = "windows-1251"`.
#[derive(Clone, Copy, Default)]
pub(super) struct Flags {
    pub serde: bool,
    pub standard: Standard,
    /// The encoding of files that are not UTF-8.
    pub encoding: crate::read::Encoding,
    /// The Instruction List of the text: `dialect = "m221"`.
    pub dialect: crate::Dialect,
}

/// Why the input is refused, and where.
pub(super) struct Refusal {
    pub msg: String,
    pub span: SpanId,
}

pub(super) const USAGE: &str = "il! takes Instruction List as a string, `il!(r#\"...IL...\"#)`, or files relative to the crate, `il!(file = \"plc/motor.il\")` or `il!(files = [\"plc/types.il\", \"plc/tank.il\"])` (one program: a POU may use the TYPEs and FBs of every file), optionally followed by `, serde`, `, std = \"iec2003\"`, `, dialect = \"m221\"` and (for files that are not UTF-8) `, encoding = \"windows-1251\"`";

fn usage(span: SpanId) -> Refusal {
    Refusal {
        msg: USAGE.to_string(),
        span,
    }
}

struct Cursor<'a> {
    toks: &'a [Tok],
    at: usize,
    /// Where a missing token is reported.
    end: SpanId,
}

impl<'a> Cursor<'a> {
    fn peek(&self) -> Option<&'a Tok> {
        self.toks.get(self.at)
    }

    fn next(&mut self) -> Option<&'a Tok> {
        let t = self.toks.get(self.at);
        self.at += 1;
        t
    }

    fn here(&self) -> SpanId {
        self.peek().map_or(self.end, Tok::span)
    }

    fn done(&self) -> bool {
        self.at >= self.toks.len()
    }

    fn punct(&mut self, c: char) -> Result<(), Refusal> {
        match self.next() {
            Some(Tok::Punct(p, _)) if *p == c => Ok(()),
            t => Err(usage(t.map_or(self.end, Tok::span))),
        }
    }

    fn string(&mut self) -> Result<Lit, Refusal> {
        match self.next() {
            Some(Tok::Literal {
                text,
                line,
                column,
                file,
                span,
            }) => match string_value(text) {
                Ok(value) => Ok(Lit {
                    value,
                    // The value starts after `"`, `r"`, `r#"` ...
                    place: (*line > 0 && *column > 0 && !file.is_empty()).then(|| RustPlace {
                        file: file.clone(),
                        line: *line,
                        column: column + text.find('"').map_or(0, |q| q + 1),
                    }),
                    span: *span,
                }),
                Err(_) => Err(usage(*span)),
            },
            t => Err(usage(t.map_or(self.end, Tok::span))),
        }
    }
}

/// Read `il!`'s input.
pub(super) fn parse(toks: &[Tok]) -> Result<(Input, Flags), Refusal> {
    let mut c = Cursor {
        toks,
        at: 0,
        end: CALL_SITE,
    };
    let input = match c.peek() {
        Some(Tok::Literal { .. }) => Input::Inline(c.string()?),
        Some(Tok::Ident(kw, span)) if kw == "file" || kw == "files" => {
            c.next();
            c.punct('=')?;
            if kw == "file" {
                Input::Files(vec![c.string()?])
            } else {
                Input::Files(file_list(&mut c, *span)?)
            }
        }
        _ => return Err(usage(c.here())),
    };
    Ok((input, flags(&mut c)?))
}

/// `["a.il", "b.il"]`, a trailing comma allowed.
fn file_list(c: &mut Cursor, kw: SpanId) -> Result<Vec<Lit>, Refusal> {
    let Some(Tok::Group {
        open: '[',
        inner,
        span,
    }) = c.next()
    else {
        return Err(usage(c.toks.get(c.at - 1).map_or(c.end, Tok::span)));
    };
    let mut list = Cursor {
        toks: inner,
        at: 0,
        end: *span,
    };
    let mut lits: Vec<Lit> = Vec::new();
    while !list.done() {
        let lit = list.string()?;
        if lits.iter().any(|o| o.value == lit.value) {
            return Err(Refusal {
                msg: format!("`{}` is listed twice", lit.value),
                span: lit.span,
            });
        }
        lits.push(lit);
        if !list.done() {
            list.punct(',')?;
        }
    }
    if lits.is_empty() {
        return Err(Refusal {
            msg: "`files = [...]` lists no file".to_string(),
            span: kw,
        });
    }
    Ok(lits)
}

/// `, serde`, `, std = "iec2003"`, `, dialect = "m221"`,
/// `, encoding = "windows-1251"`, in any
/// order, a trailing comma allowed.
fn flags(c: &mut Cursor) -> Result<Flags, Refusal> {
    let mut flags = Flags::default();
    while !c.done() {
        c.punct(',')?;
        match c.next() {
            None => break,
            Some(Tok::Ident(f, _)) if f == "serde" => flags.serde = true,
            Some(Tok::Ident(f, _)) if f == "std" => {
                c.punct('=')?;
                let name = c.string()?;
                flags.standard = Standard::from_name(&name.value).ok_or_else(|| Refusal {
                    msg: format!(
                        "unknown standard `{}`: use `std = \"iec2003\"` (2nd edition, strict) or `std = \"iec2013\"` (the default)",
                        name.value
                    ),
                    span: name.span,
                })?;
            }
            Some(Tok::Ident(f, _)) if f == "dialect" => {
                c.punct('=')?;
                let name = c.string()?;
                flags.dialect = crate::Dialect::from_name(&name.value).ok_or_else(|| Refusal {
                    msg: format!(
                        "unknown dialect `{}`: use `dialect = \"m221\"` (a Modicon M221 / TwidoSuite listing) or `dialect = \"iec\"` (the default)",
                        name.value
                    ),
                    span: name.span,
                })?;
            }
            Some(Tok::Ident(f, _)) if f == "encoding" => {
                c.punct('=')?;
                let name = c.string()?;
                flags.encoding =
                    crate::read::Encoding::from_label(&name.value).map_err(|msg| Refusal {
                        msg,
                        span: name.span,
                    })?;
            }
            Some(t) => return Err(usage(t.span())),
        }
    }
    Ok(flags)
}
