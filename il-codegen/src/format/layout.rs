//! The layout of each line: where it starts (what it is inside), the
//! columns of a body line (label, operator, operand) and of a declaration
//! (names, `:`), one space between tokens where the text had blanks, and
//! trailing comments aligned across a run of lines.

use super::lines::{Item, Line};
use super::{FormatOptions, KeywordCase};
use crate::syntax::lexer::Tok;

/// What a line is, for its indentation and columns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// At a fixed indentation, tokens spaced.
    Plain(usize),
    /// A declaration inside `VAR`/`TYPE`/`STRUCT` at this indentation,
    /// aligned by its `:` within its block.
    Decl(usize),
    /// A body instruction (label, operator, operands).
    Instr,
    /// A later line of a body instruction (an argument list over lines).
    InstrCont,
}

/// Tracks what the lines are inside, from their tokens.
#[derive(Default)]
struct State {
    pou: bool,
    var: bool,
    types: bool,
    structs: usize,
    config: usize,
    instr_open: bool,
    decl_open: bool,
}

impl State {
    /// Indentation of a VAR block's keywords: 0 in a POU or at top level,
    /// nested in a configuration.
    fn block_indent(&self) -> usize {
        self.config * 4
    }

    /// The kind of a line whose tokens are `toks`, then the state after it.
    fn classify(&mut self, toks: &[&Tok], ends_instruction: bool) -> Kind {
        let Some(first) = toks.first() else {
            // Comment-only: at the indentation of where it stands.
            return if self.var || self.types {
                Kind::Plain(self.block_indent() + 4 + self.structs * 4)
            } else if self.pou {
                Kind::Plain(4)
            } else {
                Kind::Plain(self.block_indent())
            };
        };
        let kind = match first {
            Tok::Pou(_) => Kind::Plain(0),
            Tok::EndPou(_)
            | Tok::Type
            | Tok::EndType
            | Tok::Configuration
            | Tok::EndConfiguration => Kind::Plain(0),
            Tok::Resource | Tok::EndResource => Kind::Plain(4),
            Tok::Var(_) | Tok::VarConfig | Tok::VarAccess | Tok::EndVar => {
                Kind::Plain(self.block_indent())
            }
            Tok::EndStruct if self.types || self.var => {
                Kind::Decl(self.block_indent() + self.structs.max(1) * 4)
            }
            _ if self.var || self.types => {
                let indent = self.block_indent() + 4 + self.structs * 4;
                if self.decl_open {
                    Kind::Plain(indent + 4)
                } else {
                    Kind::Decl(indent)
                }
            }
            _ if self.pou => {
                if self.instr_open {
                    Kind::InstrCont
                } else {
                    Kind::Instr
                }
            }
            _ => Kind::Plain(self.block_indent()),
        };
        for t in toks {
            match t {
                Tok::Pou(_) => self.pou = true,
                Tok::EndPou(_) => {
                    self.pou = false;
                    self.var = false;
                }
                Tok::Var(_) | Tok::VarConfig | Tok::VarAccess => self.var = true,
                Tok::EndVar => self.var = false,
                Tok::Type => self.types = true,
                Tok::EndType => {
                    self.types = false;
                    self.structs = 0;
                }
                Tok::Struct => self.structs += 1,
                Tok::EndStruct => self.structs = self.structs.saturating_sub(1),
                Tok::Configuration => self.config = 1,
                Tok::Resource => self.config = 2,
                Tok::EndResource => self.config = 1,
                Tok::EndConfiguration => self.config = 0,
                _ => {}
            }
        }
        if self.pou && !self.var && matches!(kind, Kind::Instr | Kind::InstrCont) {
            self.instr_open = !ends_instruction;
        } else {
            self.instr_open = false;
        }
        self.decl_open = (self.var || self.types)
            && matches!(kind, Kind::Decl(_) | Kind::Plain(_))
            && !matches!(
                toks.last(),
                Some(Tok::Semi | Tok::Struct | Tok::EndStruct | Tok::Var(_) | Tok::VarConfig)
                    | Some(
                        Tok::VarAccess | Tok::Type | Tok::Constant | Tok::Retain | Tok::NonRetain
                    )
            );
        kind
    }
}

/// One laid-out line before comments are aligned.
struct Out {
    /// The code, indented; empty for a comment-only line.
    code: String,
    /// Comments after the code (aligned across a run), or a comment-only
    /// line's text.
    comment: Option<String>,
    /// Runs of comments to align: lines of one block or body share an id;
    /// `None` for lines that never align (verbatim, blank).
    run: Option<usize>,
}

/// Each line's kind, and what it is inside after it (POU, VAR block, TYPE
/// block): classified once, in order, for every pass over the lines.
fn classify_all(lines: &[Line]) -> Vec<(Kind, (bool, bool, bool))> {
    let mut state = State::default();
    lines
        .iter()
        .map(|l| {
            let toks: Vec<&Tok> = toks(l).collect();
            let kind = state.classify(&toks, l.ends_instruction);
            (kind, (state.pou, state.var, state.types))
        })
        .collect()
}

pub(super) fn layout(lines: &[Line], opts: &FormatOptions, crlf: bool) -> String {
    let case = match opts.keywords {
        KeywordCase::Preserve => None,
        KeywordCase::Upper => Some(true),
        KeywordCase::Lower => Some(false),
        KeywordCase::AsTheFile => Some(mostly_upper(lines)),
    };
    let kinds = classify_all(lines);
    let op_width = operator_width(lines, &kinds);
    let mut outs = Vec::with_capacity(lines.len());
    let mut run = 0;
    let mut names_width = names_widths(lines, &kinds);
    for (i, line) in lines.iter().enumerate() {
        if line.verbatim {
            outs.push(Out {
                code: line.text.clone(),
                comment: None,
                run: None,
            });
            run += 1;
            continue;
        }
        if line.items.is_empty() {
            outs.push(Out {
                code: String::new(),
                comment: None,
                run: None,
            });
            run += 1;
            continue;
        }
        let (kind, section) = kinds[i];
        let was = i
            .checked_sub(1)
            .map_or((false, false, false), |p| kinds[p].1);
        if section != was {
            run += 1;
        }
        let toks: Vec<&Tok> = toks(line).collect();
        let (code, trailing) = match kind {
            Kind::Plain(indent) => (indent_by(indent, &join(&line.items, case)), trailing(line)),
            Kind::InstrCont => (indent_by(8, &join(&line.items, case)), trailing(line)),
            Kind::Decl(indent) => (
                decl(line, indent, names_width.remove(&i), case),
                trailing(line),
            ),
            Kind::Instr => (instr(line, op_width, case), trailing(line)),
        };
        if toks.is_empty() {
            // A comment-only line, at the indentation of where it stands.
            let indent = match kind {
                Kind::Plain(n) | Kind::Decl(n) => n,
                Kind::Instr | Kind::InstrCont => 4,
            };
            outs.push(Out {
                code: " ".repeat(indent),
                comment: trailing,
                run: None,
            });
            continue;
        }
        let code = code.trim_end().to_string();
        outs.push(Out {
            code,
            comment: trailing,
            run: Some(run),
        });
        if matches!(
            toks.last(),
            Some(Tok::EndVar | Tok::EndPou(_) | Tok::EndType)
        ) {
            run += 1;
        }
    }
    align(&mut outs);
    let nl = if crlf { "\r\n" } else { "\n" };
    let mut text = String::new();
    for (i, o) in outs.iter().enumerate() {
        if i > 0 {
            text.push_str(nl);
        }
        text.push_str(&o.code);
        if let Some(c) = &o.comment {
            text.push_str(c);
        }
    }
    text
}

fn toks(line: &Line) -> impl Iterator<Item = &Tok> {
    line.items.iter().filter_map(|i| match i {
        Item::Tok(t, ..) => Some(t),
        Item::Comment(_) => None,
    })
}

fn indent_by(n: usize, s: &str) -> String {
    format!("{}{s}", " ".repeat(n))
}

/// Comments after the last token of a line, joined by one space.
fn trailing(line: &Line) -> Option<String> {
    let last_tok = line.items.iter().rposition(|i| matches!(i, Item::Tok(..)));
    let from = last_tok.map_or(0, |i| i + 1);
    let cs: Vec<&str> = line.items[from..]
        .iter()
        .filter_map(|i| match i {
            Item::Comment(c) => Some(c.as_str()),
            Item::Tok(..) => None,
        })
        .collect();
    (!cs.is_empty()).then(|| cs.join(" "))
}

/// The items up to the last token, spaced: one space where the text had
/// blanks, none inside brackets and before `,` `;` `)`, spaces around `:=`
/// `=>` and `:`, one after `,`. Comments between tokens keep one space on
/// each side. Keywords in `case` (`Some(true)`: upper).
fn join(items: &[Item], case: Option<bool>) -> String {
    // Comments after the last token are trailing ones, laid out apart.
    let Some(last) = items.iter().rposition(|i| matches!(i, Item::Tok(..))) else {
        return String::new();
    };
    let items = &items[..=last];
    let mut s = String::new();
    let mut prev: Option<&Tok> = None;
    for item in items {
        match item {
            Item::Comment(c) => {
                if !s.is_empty() {
                    s.push(' ');
                }
                s.push_str(c);
                s.push(' ');
                prev = None;
            }
            Item::Tok(t, text, blank) => {
                if let Some(p) = prev
                    && space_between(p, t, *blank)
                {
                    s.push(' ');
                }
                s.push_str(&cased(t, text, case));
                prev = Some(t);
            }
        }
    }
    s.trim_end().to_string()
}

/// Whether one space goes between tokens `a` and `b`; `blank`: the text had
/// blanks between them.
fn space_between(a: &Tok, b: &Tok, blank: bool) -> bool {
    use Tok::*;
    match (a, b) {
        (_, Assign | Arrow | Colon) | (Assign | Arrow | Colon | Comma, _) => true,
        (LParen | LBracket | Dot, _) | (_, RParen | RBracket | Comma | Semi | Dot | Part(..)) => {
            false
        }
        (_, DotDot) | (DotDot, _) => false,
        // `CAL t(`, `x[`, `ARRAY[`, `STRING[`: the bracket after a name.
        (Ident(_) | Array | StringKw | WStringKw, LParen | LBracket) => false,
        _ => blank,
    }
}

/// A keyword's text in the case asked; every other token as written.
fn cased(t: &Tok, text: &str, case: Option<bool>) -> String {
    match case {
        Some(upper) if is_keyword(t) => {
            if upper {
                text.to_ascii_uppercase()
            } else {
                text.to_ascii_lowercase()
            }
        }
        _ => text.to_string(),
    }
}

/// Tokens whose text is a keyword or operator word (not names, literals,
/// addresses or punctuation).
fn is_keyword(t: &Tok) -> bool {
    use Tok::*;
    !matches!(
        t,
        Nl | Label(_)
            | Ident(_)
            | Lit(_)
            | Addr(_)
            | Part(..)
            | LParen
            | RParen
            | LBracket
            | RBracket
            | Comma
            | Semi
            | Colon
            | Assign
            | Arrow
            | Dot
            | DotDot
            | Plus
            | Minus
            | Star
            | Slash
            | Orphan
            | EndOrphan
            | MissingEndVar
            | Error
    )
}

/// Whether the file's keywords are mostly upper case (ties: upper).
fn mostly_upper(lines: &[Line]) -> bool {
    let (mut up, mut low) = (0usize, 0usize);
    for l in lines {
        for i in &l.items {
            if let Item::Tok(t, text, _) = i
                && is_keyword(t)
                && text.bytes().any(|b| b.is_ascii_alphabetic())
            {
                if !text.bytes().any(|b| b.is_ascii_lowercase()) {
                    up += 1;
                } else if !text.bytes().any(|b| b.is_ascii_uppercase()) {
                    low += 1;
                }
            }
        }
    }
    up >= low
}

/// The operator column's width: the longest operator word of the file's
/// instructions, between 3 and 6 (a longer one, a user function's name,
/// takes one space after it).
fn operator_width(lines: &[Line], kinds: &[(Kind, (bool, bool, bool))]) -> usize {
    let mut w = 3;
    for (l, &(kind, _)) in lines.iter().zip(kinds) {
        if kind == Kind::Instr
            && let Some((_, text)) = operator_of(l)
        {
            w = w.max(text.chars().count().min(6));
        }
    }
    w
}

/// The operator of an instruction line: its first token after a label.
fn operator_of(line: &Line) -> Option<(usize, &str)> {
    line.items.iter().enumerate().find_map(|(i, it)| match it {
        Item::Tok(Tok::Label(_), ..) | Item::Comment(_) => None,
        Item::Tok(_, text, _) => Some((i, text.as_str())),
    })
}

/// `label: OP   operand` with the operator at column 4 (after a label
/// shorter than that) and the operands after the operator column.
fn instr(line: &Line, op_width: usize, case: Option<bool>) -> String {
    let mut s = String::new();
    let mut rest = &line.items[..];
    if let Some(Item::Tok(Tok::Label(_), text, _)) = rest.first() {
        s.push_str(text);
        rest = &rest[1..];
    }
    // A label alone (its comments are trailing ones).
    let Some(i) = rest.iter().position(|it| matches!(it, Item::Tok(..))) else {
        return s;
    };
    // Comments between a label and the operator stay there.
    for c in &rest[..i] {
        if let Item::Comment(c) = c {
            s.push(' ');
            s.push_str(c);
        }
    }
    let Item::Tok(op_tok, op_text, _) = &rest[i] else {
        return s;
    };
    let pad = 4usize.saturating_sub(s.chars().count()).max(1);
    s.push_str(&" ".repeat(if s.is_empty() { 4 } else { pad }));
    s.push_str(&cased(op_tok, op_text, case));
    let operands = &rest[i + 1..];
    let joined = join(operands, case);
    if !joined.is_empty() {
        // `AND(` stays on its operator as written; `AND (` too.
        let attached = matches!(operands.first(), Some(Item::Tok(Tok::LParen, _, false)));
        if !attached {
            let n = op_text.chars().count();
            s.push_str(&" ".repeat(op_width.saturating_sub(n) + 1));
        }
        s.push_str(&joined);
    }
    s
}

/// A declaration: the names before the first `:` padded to the block's
/// widest (`width`), then ` : ` and the rest.
fn decl(line: &Line, indent: usize, width: Option<usize>, case: Option<bool>) -> String {
    let colon = line
        .items
        .iter()
        .position(|i| matches!(i, Item::Tok(Tok::Colon, ..)));
    match (colon, width) {
        (Some(c), Some(w)) if c > 0 => {
            let names = join(&line.items[..c], case);
            let rest = join(&line.items[c + 1..], case);
            let pad = w.saturating_sub(names.chars().count());
            format!("{}{names}{} : {rest}", " ".repeat(indent), " ".repeat(pad))
        }
        _ => indent_by(indent, &join(&line.items, case)),
    }
}

/// The width of the names before `:` for each declaration line that is
/// aligned: the widest of its block (consecutive declaration lines) at its
/// indentation, so a STRUCT's members align among themselves.
fn names_widths(
    lines: &[Line],
    kinds: &[(Kind, (bool, bool, bool))],
) -> std::collections::HashMap<usize, usize> {
    type Blocks = std::collections::BTreeMap<usize, Vec<(usize, usize)>>;
    let mut out = std::collections::HashMap::new();
    let mut blocks: Blocks = Blocks::new();
    let flush = |blocks: &mut Blocks, out: &mut std::collections::HashMap<usize, usize>| {
        for block in blocks.values_mut() {
            let w = block.iter().map(|b| b.1).max().unwrap_or(0);
            for (i, _) in block.drain(..) {
                out.insert(i, w);
            }
        }
    };
    for (i, l) in lines.iter().enumerate() {
        if l.verbatim || toks(l).next().is_none() {
            if l.items.is_empty() && !l.verbatim {
                flush(&mut blocks, &mut out);
            }
            continue;
        }
        match kinds[i].0 {
            Kind::Decl(indent) => {
                let colon = l
                    .items
                    .iter()
                    .position(|it| matches!(it, Item::Tok(Tok::Colon, ..)));
                if let Some(c) = colon.filter(|&c| c > 0) {
                    let w = join(&l.items[..c], None).chars().count();
                    blocks.entry(indent).or_default().push((i, w));
                }
            }
            _ => flush(&mut blocks, &mut out),
        }
    }
    flush(&mut blocks, &mut out);
    out
}

/// Trailing comments of a run start one column: three spaces after the
/// run's longest code that has one.
fn align(outs: &mut [Out]) {
    let mut i = 0;
    while i < outs.len() {
        let Some(run) = outs[i].run else {
            i += 1;
            continue;
        };
        let end = (i..outs.len())
            .find(|&j| outs[j].run != Some(run))
            .unwrap_or(outs.len());
        let col = outs[i..end]
            .iter()
            .filter(|o| o.comment.is_some())
            .map(|o| o.code.chars().count())
            .max();
        if let Some(col) = col {
            for o in &mut outs[i..end] {
                if o.comment.is_some() {
                    let pad = col + 3 - o.code.chars().count();
                    o.code.push_str(&" ".repeat(pad));
                }
            }
        }
        i = end;
    }
}
