//! A file as lines of code items: each token with its text, and the
//! comments and pragmas between them, found exactly as the lexer skips them
//! (`skip_trivia`), so that the layout only ever changes blanks.

use crate::syntax::lexer::{self, Tok};

/// One thing on a line.
#[derive(Debug)]
pub(super) enum Item {
    /// A token: its kind, its text as written, and whether blanks (or a
    /// comment) came before it on its line.
    Tok(Tok, String, bool),
    /// A comment or pragma that ends on this line, as written.
    Comment(String),
}

/// One line of the file.
#[derive(Debug)]
pub(super) struct Line {
    /// Its items, in order (empty: a blank line).
    pub items: Vec<Item>,
    /// The line is (partly) inside a comment that started on an earlier
    /// line, or a comment starting on it goes on to a later one: it is kept
    /// as written.
    pub verbatim: bool,
    /// Its text as written (without the line break).
    pub text: String,
    /// The lexer ended a body instruction on this line (a `Tok::Nl` at its
    /// end): the next line starts a new instruction.
    pub ends_instruction: bool,
}

/// Why a file cannot be laid out.
pub(super) struct Unformattable(pub usize, pub &'static str);

/// Split `src` into lines of items. Tokens come from `toks` (the lexer's,
/// for this text); what lies between them must be blanks, comments,
/// pragmas and a label's `:`, or the file is refused.
pub(super) fn split(src: &str, toks: &[lexer::Spanned]) -> Result<Vec<Line>, Unformattable> {
    let line_of = line_starts(src);
    let mut lines: Vec<Line> = line_of
        .iter()
        .enumerate()
        .map(|(i, &lo)| {
            let hi = line_of.get(i + 1).map_or(src.len(), |&n| n - 1);
            Line {
                items: Vec::new(),
                verbatim: false,
                text: src[lo..hi].trim_end_matches('\r').to_string(),
                ends_instruction: false,
            }
        })
        .collect();
    let line_at = |pos: usize| line_of.partition_point(|&s| s <= pos) - 1;
    let mut pos = if src.starts_with('\u{feff}') { 3 } else { 0 };
    let mut after_label = false;
    let mut prev_end = 0;
    for (lo, tok, hi) in toks {
        let (lo, hi) = (*lo, *hi);
        match tok {
            // The line break (or a zero-width one) ending an instruction: it
            // may lie inside a comment that crosses lines, so it moves
            // nothing.
            Tok::Nl => {
                lines[line_at(lo.min(src.len()))].ends_instruction = true;
                continue;
            }
            Tok::Error => return Err(Unformattable(lo, "malformed text")),
            _ if lo == hi => continue,
            _ => {}
        }
        if lo < pos {
            return Err(Unformattable(lo, "tokens overlap"));
        }
        trivia(src, pos, lo, after_label, &mut lines, &line_at)?;
        after_label = matches!(tok, Tok::Label(_));
        let text = &src[lo..hi];
        if text.contains('\n') {
            return Err(Unformattable(lo, "a token spans lines"));
        }
        let l = line_at(lo);
        let blank = lo > prev_end || lines[l].items.is_empty();
        lines[l]
            .items
            .push(Item::Tok(tok.clone(), text.to_string(), blank));
        pos = hi;
        prev_end = hi;
    }
    trivia(src, pos, src.len(), after_label, &mut lines, &line_at)?;
    Ok(lines)
}

fn line_starts(src: &str) -> Vec<usize> {
    std::iter::once(0)
        .chain(src.match_indices('\n').map(|(i, _)| i + 1))
        .collect()
}

/// The text between two tokens: blanks, comments and pragmas (a label's
/// `:` first, after a label), put on their lines; a comment that crosses a
/// line break makes every line it touches verbatim.
fn trivia(
    src: &str,
    mut pos: usize,
    end: usize,
    after_label: bool,
    lines: &mut [Line],
    line_at: &dyn Fn(usize) -> usize,
) -> Result<(), Unformattable> {
    let b = src.as_bytes();
    if after_label {
        while matches!(b.get(pos), Some(b' ' | b'\t')) {
            pos += 1;
        }
        if b.get(pos) != Some(&b':') {
            return Err(Unformattable(pos, "a label without its `:`"));
        }
        pos += 1;
        let l = line_at(pos - 1);
        if let Some(Item::Tok(_, t, _)) = lines[l].items.last_mut() {
            t.push(':');
        }
    }
    while pos < end {
        let start = pos;
        let stop = match b[pos] {
            b' ' | b'\t' | b'\r' | b'\n' | 0x0B | 0x0C => {
                pos += 1;
                continue;
            }
            b'(' if b.get(pos + 1) == Some(&b'*') => {
                match lexer::comments::scan(src, pos, false).end {
                    Some(e) => e,
                    None => return Err(Unformattable(pos, "an unterminated comment")),
                }
            }
            b'/' if b.get(pos + 1) == Some(&b'/') => {
                src[pos..end].find('\n').map_or(end, |i| pos + i)
            }
            b'{' => match src[pos..].find('}') {
                Some(e) => pos + e + 1,
                None => return Err(Unformattable(pos, "an unterminated pragma")),
            },
            _ => return Err(Unformattable(pos, "text the lexer skipped")),
        };
        if stop > end {
            return Err(Unformattable(pos, "a comment overlaps a token"));
        }
        let text = &src[start..stop];
        let (first, last) = (line_at(start), line_at(stop.saturating_sub(1).max(start)));
        if first == last {
            lines[first].items.push(Item::Comment(text.to_string()));
        } else {
            for l in &mut lines[first..=last] {
                l.verbatim = true;
            }
        }
        pos = stop;
    }
    Ok(())
}
