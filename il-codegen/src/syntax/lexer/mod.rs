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
use crate::diag::{Diagnostic, MAX_PER_FILE};
use std::collections::VecDeque;

/// The longest name, in characters (IL0034).
pub(crate) const MAX_NAME: usize = 255;

use super::code;
use super::literal_message;
use il_std::literal;

mod body;
pub mod comments;
mod decls;
mod keywords;
mod literals;
mod tokens;

#[cfg(feature = "plcopen")]
pub(crate) use keywords::is_decl_keyword;
pub use keywords::operator;
use keywords::*;
pub use tokens::*;

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
    /// Tokens lexed and not yet taken; the last one pushed stays until the
    /// end (the lexer looks back at it), so this holds one or two tokens
    /// while the parser pulls them ([`Lexer::next`]).
    out: VecDeque<Spanned>,
    /// The end of the file was reached and the last tokens pushed.
    done: bool,
    /// The last `VAR...` keyword (the block a missing END_VAR leaves open).
    last_var: Option<Span>,
    /// At most [`MAX_PER_FILE`] diagnostics: the first ones by position
    /// (the lexer reports in order), the only ones a file shows.
    diags: Vec<Diagnostic>,
    /// The diagnostics past those: counted (all, errors) with the span of
    /// the first, for the "not shown" note. A line of 16,000 stray
    /// characters held 16,000 diagnostics, twice (see `syntax::parse_std`).
    dropped: (usize, usize, Option<Span>),
    /// Where a diagnostic that is not kept is built (its callers may add a
    /// help or a label to what [`Lexer::diag`] returns).
    scratch: Diagnostic,
    /// Pragmas are errors under the 2nd edition.
    standard: crate::dialect::Standard,
    /// `{extern}` pragmas, which mark the next FUNCTION as a host function.
    host_marks: Vec<Span>,
    /// Comments that hold a `(*` (see `comments.rs`).
    inner_opens: Vec<comments::InnerOpen>,
    /// Whether comments nest: never in IEC (and so here), but some tools'
    /// exports declare that theirs do.
    nested_comments: bool,
}

/// What the lexer leaves besides the tokens ([`Lexer::finish_marked`]).
pub struct Finished {
    /// Its diagnostics.
    pub diags: Vec<Diagnostic>,
    /// The spans of the `{extern}` pragmas.
    pub host_marks: Vec<Span>,
    /// The comments that hold a `(*`, in file order.
    pub inner_opens: Vec<comments::InnerOpen>,
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

/// Lex a whole file. Returns the tokens and the lexer's diagnostics.
pub fn lex(src: &str) -> (Vec<Spanned>, Vec<Diagnostic>) {
    lex_std(src, crate::dialect::Standard::default())
}

/// [`lex`] against a standard (pragmas are errors under the 2nd edition).
pub fn lex_std(src: &str, standard: crate::dialect::Standard) -> (Vec<Spanned>, Vec<Diagnostic>) {
    let mut lx = Lexer::new(src, standard);
    let toks = lx.by_ref().collect();
    (toks, lx.take_diags())
}

/// Tokens as the parser takes them, one at a time: the whole token list of
/// a file (48 bytes a token, about as large as the syntax tree) is never
/// held. Drain it (`by_ref`) before [`Lexer::finish_marked`].
impl Iterator for Lexer<'_> {
    type Item = Spanned;

    fn next(&mut self) -> Option<Spanned> {
        while self.out.len() < 2 && self.step() {}
        self.out.pop_front()
    }
}

impl<'a> Lexer<'a> {
    /// A lexer at the start of `src`.
    pub fn new(src: &'a str, standard: crate::dialect::Standard) -> Lexer<'a> {
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
            out: VecDeque::new(),
            done: false,
            last_var: None,
            diags: Vec::new(),
            dropped: (0, 0, None),
            scratch: Diagnostic::error("", Span::default(), ""),
            standard,
            host_marks: Vec::new(),
            inner_opens: Vec::new(),
            nested_comments: false,
        };
        if src.starts_with('\u{feff}') {
            lx.pos = 3;
        }
        lx
    }

    /// The lexer's diagnostics, the spans of the `{extern}` pragmas (the
    /// only pragma with a meaning: the FUNCTION after it is the host's, see
    /// `syntax::host`) and the comments that hold a `(*`, once every token
    /// was taken.
    pub fn finish_marked(mut self) -> Finished {
        Finished {
            diags: self.take_diags(),
            host_marks: std::mem::take(&mut self.host_marks),
            inner_opens: std::mem::take(&mut self.inner_opens),
        }
    }

    /// The diagnostics kept, and a "not shown" note for those that were not.
    fn take_diags(&mut self) -> Vec<Diagnostic> {
        let mut diags = std::mem::take(&mut self.diags);
        if let (cut, cut_errors, Some(at)) = self.dropped {
            diags.push(Diagnostic::not_shown(at, cut, cut_errors));
        }
        diags
    }

    /// Keep `d` if it is among the first [`MAX_PER_FILE`], else count it;
    /// either way the diagnostic to add to.
    fn record(&mut self, d: Diagnostic) -> &mut Diagnostic {
        if self.diags.len() < MAX_PER_FILE {
            self.diags.push(d);
            return self.diags.last_mut().expect("just pushed");
        }
        self.dropped.0 += 1;
        self.dropped.1 += usize::from(d.is_error());
        self.dropped.2.get_or_insert(d.span);
        self.scratch = d;
        &mut self.scratch
    }
}

impl<'a> Lexer<'a> {
    fn peek(&self, off: usize) -> u8 {
        self.b.get(self.pos + off).copied().unwrap_or(0)
    }

    /// Queue a token for the parser.
    fn put(&mut self, tok: Spanned) {
        if let (lo, Tok::Var(_), hi) = tok {
            self.last_var = Some(span(lo, hi));
        }
        self.out.push_back(tok);
    }

    fn push(&mut self, lo: usize, t: Tok, hi: usize) {
        self.put((lo, t, hi));
        self.line_start = false;
        if self.mode == Mode::Body && !matches!(self.out.back(), Some((_, Tok::Nl, _))) {
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
        self.record(Diagnostic::error(code, span(lo, hi), msg).with_label(label))
    }

    fn last_tok(&self) -> Option<&Tok> {
        self.out.back().map(|(_, t, _)| t)
    }

    /// One step of lexing (a token, a mode change or skipped input); false
    /// once the file is done.
    fn step(&mut self) -> bool {
        if self.done {
            return false;
        }
        {
            if let Some(nl) = self.skip_trivia() {
                self.on_newline(nl);
            }
            if self.pos >= self.b.len() {
                self.finish();
                self.done = true;
                return false;
            }
            let before = (self.pos, self.out.len(), self.mode);
            crate::step_counter::add(1);
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
        true
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
                    let comment = comments::scan(self.src, start, self.nested_comments);
                    match comment.end {
                        Some(end) => {
                            if let Some(inner) = comment.inner
                                && self.inner_opens.len() < comments::MAX_NOTED
                            {
                                self.inner_opens.push(comments::InnerOpen {
                                    open: start,
                                    inner,
                                    close: end - 2,
                                });
                            }
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
                    // A pragma (Ed.2 2.1.5): ignored wherever a comment may stand.
                    let start = self.pos;
                    let end = match self.src[start..].find('}') {
                        Some(e) => start + e + 1,
                        None => {
                            self.diag(
                                code::PRAGMA,
                                start,
                                start + 1,
                                "this pragma is never closed",
                                "pragma starts here",
                            )
                            .help = Some("close it with `}`".into());
                            self.b.len()
                        }
                    };
                    if let Some(d) = self
                        .standard
                        .refuse(crate::dialect::Feature::Pragma, span(start, end))
                    {
                        self.record(d);
                    }
                    if let Some(i) = self.src[start..end].find('\n') {
                        nl.get_or_insert(start + i);
                    }
                    let inner = self.src[start + 1..end].trim_end_matches('}').trim();
                    if inner.eq_ignore_ascii_case("extern") {
                        self.host_marks.push(span(start, end));
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
                        self.put((at, Tok::Nl, at + 1));
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
                    self.put((eof, Tok::Nl, eof));
                    self.dirty = false;
                }
                if self.orphan {
                    self.put((eof, Tok::EndOrphan, eof));
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
                self.put((eof, Tok::EndType, eof));
            }
            Mode::Config => {
                if self.in_resource {
                    self.put((eof, Tok::EndResource, eof));
                }
                self.diag(
                    code::MISSING_END,
                    eof,
                    eof,
                    "missing END_CONFIGURATION",
                    "the file ends here",
                );
                self.put((eof, Tok::EndConfiguration, eof));
            }
            _ => {}
        }
    }

    fn missing_end_var(&mut self, at: usize) {
        let open = self.last_var.unwrap_or(span(at, at));
        self.record(
            Diagnostic::error(code::MISSING_END_VAR, span(at, at), "missing END_VAR")
                .with_label("the declarations should end before this")
                .with_secondary(open, "this block is not closed"),
        );
        self.put((at, Tok::MissingEndVar, at));
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
                self.put((at, Tok::Nl, at));
            }
            for _ in 0..n {
                self.put((at, Tok::RParen, at));
                self.put((at, Tok::Nl, at));
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
                code::NOT_IDENT,
                start,
                self.pos,
                format!(
                    "`{}` is not an identifier: an IEC identifier needs a letter or a digit",
                    &self.src[start..self.pos]
                ),
                "not an identifier",
            );
        }
        if self.pos - start > MAX_NAME {
            self.diag(
                code::LONG_NAME,
                start,
                self.pos,
                format!(
                    "a name of {} characters: names are at most {MAX_NAME}",
                    self.pos - start
                ),
                "too long",
            );
        }
        (start, self.pos)
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
