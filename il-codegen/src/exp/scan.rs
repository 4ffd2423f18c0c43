//! The tokens of EXP text that the import needs to see: words, comments
//! (nested where the object's `@NESTEDCOMMENTS := 'Yes'` says so), strings,
//! pragmas and single characters. The IL itself is read later by the real
//! lexer; this only finds where objects, declaration blocks and names are,
//! so it must never mistake a comment or a string for code.

use std::ops::Range;

/// What a token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Tok {
    /// A name or keyword (`LD`, `END_VAR`, `Pump1`).
    Word,
    /// A number or typed literal (`10`, `T#1s`, `16#FF`), or a direct
    /// address (`%IX0.0`).
    Literal,
    /// `(* ... *)`, `closed` false when the text ends inside it.
    Comment { closed: bool },
    /// `'...'` or `"..."`.
    Str,
    /// `{ ... }`
    Pragma,
    /// Any other character.
    Punct,
}

/// Tokens of `text[range]`.
pub(super) struct Scanner<'a> {
    text: &'a str,
    pub(super) pos: usize,
    end: usize,
    /// Whether `(*` inside a comment opens a nested one.
    pub(super) nested: bool,
}

impl<'a> Scanner<'a> {
    pub(super) fn new(text: &'a str, range: Range<usize>, nested: bool) -> Self {
        Scanner {
            text,
            pos: range.start,
            end: range.end.min(text.len()),
            nested,
        }
    }

    fn byte(&self, at: usize) -> u8 {
        if at < self.end {
            self.text.as_bytes()[at]
        } else {
            0
        }
    }

    fn run(&mut self, f: impl Fn(u8) -> bool) {
        while self.pos < self.end && f(self.text.as_bytes()[self.pos]) {
            self.pos += 1;
        }
    }
}

fn word_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

impl Iterator for Scanner<'_> {
    type Item = (Tok, Range<usize>);

    fn next(&mut self) -> Option<Self::Item> {
        self.run(|b| b.is_ascii_whitespace());
        if self.pos >= self.end {
            return None;
        }
        let start = self.pos;
        let b = self.byte(start);
        let tok = match b {
            b'(' if self.byte(start + 1) == b'*' => {
                self.pos += 2;
                let mut depth = 1usize;
                while self.pos < self.end && depth > 0 {
                    if self.byte(self.pos) == b'*' && self.byte(self.pos + 1) == b')' {
                        depth -= 1;
                        self.pos += 2;
                    } else if self.nested
                        && self.byte(self.pos) == b'('
                        && self.byte(self.pos + 1) == b'*'
                    {
                        depth += 1;
                        self.pos += 2;
                    } else {
                        self.pos += 1;
                    }
                }
                Tok::Comment { closed: depth == 0 }
            }
            b'\'' | b'"' => {
                self.pos += 1;
                while self.pos < self.end && self.byte(self.pos) != b {
                    // `$'` is a quote inside the string; `$$` a dollar.
                    if self.byte(self.pos) == b'$' {
                        self.pos += 1;
                    }
                    if self.byte(self.pos) == b'\n' {
                        break;
                    }
                    self.pos += 1;
                }
                self.pos = (self.pos + 1).min(self.end);
                Tok::Str
            }
            b'{' => {
                self.run(|b| b != b'}');
                self.pos = (self.pos + 1).min(self.end);
                Tok::Pragma
            }
            b'%' => {
                self.pos += 1;
                self.run(|b| word_byte(b) || b == b'.' || b == b'*');
                Tok::Literal
            }
            b'0'..=b'9' => {
                self.run(|b| b.is_ascii_digit() || b == b'_');
                if self.byte(self.pos) == b'#' {
                    self.pos += 1;
                    self.run(|b| word_byte(b) || b == b'.');
                } else {
                    if self.byte(self.pos) == b'.' && self.byte(self.pos + 1).is_ascii_digit() {
                        self.pos += 1;
                        self.run(|b| b.is_ascii_digit() || b == b'_');
                    }
                    if matches!(self.byte(self.pos), b'e' | b'E') {
                        let sign = matches!(self.byte(self.pos + 1), b'+' | b'-') as usize;
                        if self.byte(self.pos + 1 + sign).is_ascii_digit() {
                            self.pos += 1 + sign;
                            self.run(|b| b.is_ascii_digit());
                        }
                    }
                }
                Tok::Literal
            }
            b if b.is_ascii_alphabetic() || b == b'_' => {
                self.run(word_byte);
                if self.byte(self.pos) == b'#' {
                    // A typed literal: `T#1s0ms`, `INT#-5`, `DT#2020-01-01-10:00`.
                    self.pos += 1;
                    if self.byte(self.pos) == b'-' {
                        self.pos += 1;
                    }
                    self.run(|b| word_byte(b) || b == b'.' || b == b':' || b == b'-' || b == b'#');
                    Tok::Literal
                } else {
                    Tok::Word
                }
            }
            _ => {
                // One character (a multi-byte one whole).
                let len = self.text[start..].chars().next().map_or(1, char::len_utf8);
                self.pos += len;
                Tok::Punct
            }
        };
        Some((tok, start..self.pos))
    }
}

/// The text of `text[range]` with the same length, ready for the IL lexer:
/// inside a nested comment the inner `(*` and `*)` lose their star, so the
/// lexer (whose comments do not nest) sees one comment; in a declaration,
/// `STRING(20)` becomes `STRING[20]`, the standard spelling CODESYS 2.3
/// writes with parentheses. Byte for byte the same length, so every
/// position maps back one to one.
pub(super) fn for_lexer(text: &str, range: Range<usize>, nested: bool, decl: bool) -> String {
    let mut out = text[range.clone()].as_bytes().to_vec();
    let base = range.start;
    let toks: Vec<(Tok, Range<usize>)> = Scanner::new(text, range, nested).collect();
    for (i, (tok, r)) in toks.iter().enumerate() {
        match tok {
            Tok::Comment { closed } if nested => {
                // Every `(*`/`*)` strictly inside becomes `( `/` )`.
                let end = if *closed { r.end - 2 } else { r.end };
                let mut k = r.start + 2;
                while k + 1 < end {
                    match &text.as_bytes()[k..k + 2] {
                        b"(*" => {
                            out[k + 1 - base] = b' ';
                            k += 2;
                        }
                        b"*)" => {
                            out[k - base] = b' ';
                            k += 2;
                        }
                        _ => k += 1,
                    }
                }
            }
            Tok::Word if decl && is_string_kw(&text[r.clone()]) => {
                if let (
                    Some((Tok::Punct, open)),
                    Some((Tok::Literal, _)),
                    Some((Tok::Punct, close)),
                ) = (toks.get(i + 1), toks.get(i + 2), toks.get(i + 3))
                    && &text[open.clone()] == "("
                    && &text[close.clone()] == ")"
                {
                    out[open.start - base] = b'[';
                    out[close.start - base] = b']';
                }
            }
            _ => {}
        }
    }
    // Only ASCII bytes were replaced by ASCII bytes, at character starts.
    String::from_utf8(out).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}

fn is_string_kw(w: &str) -> bool {
    w.eq_ignore_ascii_case("STRING") || w.eq_ignore_ascii_case("WSTRING")
}

/// For each token of `toks` (in order), whether it is the first on its
/// line: a line break lies between it and the token before (whose end is
/// `from` for the first). Linear in the text, where searching back to each
/// token's line start grew with the square of a long line.
pub(super) fn line_firsts(text: &str, from: usize, toks: &[(Tok, Range<usize>)]) -> Vec<bool> {
    // Before the first token: its line from the start up to `from`.
    let mut prev = line_start(text, from.min(text.len()));
    toks.iter()
        .enumerate()
        .map(|(k, (_, r))| {
            let gap = &text[prev.min(r.start)..r.start];
            let first = gap.contains('\n') || k == 0 && gap.trim().is_empty();
            prev = r.end;
            first
        })
        .collect()
}

/// The end of the line holding `at`, after its line break.
pub(super) fn next_line(text: &str, at: usize) -> usize {
    text[at..].find('\n').map_or(text.len(), |k| at + k + 1)
}

/// The start of the line holding `at`.
pub(super) fn line_start(text: &str, at: usize) -> usize {
    text[..at].rfind('\n').map_or(0, |k| k + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(text: &str) -> Vec<(Tok, &str)> {
        Scanner::new(text, 0..text.len(), true)
            .map(|(t, r)| (t, &text[r]))
            .collect()
    }

    #[test]
    fn comments_nest_strings_and_literals_are_whole() {
        let t = "LD x (* a (* b *) c *) 'it$'s (*' T#1s0ms 16#FF %IX0.1 1..N";
        assert_eq!(
            words(t),
            [
                (Tok::Word, "LD"),
                (Tok::Word, "x"),
                (Tok::Comment { closed: true }, "(* a (* b *) c *)"),
                (Tok::Str, "'it$'s (*'"),
                (Tok::Literal, "T#1s0ms"),
                (Tok::Literal, "16#FF"),
                (Tok::Literal, "%IX0.1"),
                (Tok::Literal, "1"),
                (Tok::Punct, "."),
                (Tok::Punct, "."),
                (Tok::Word, "N"),
            ]
        );
        assert_eq!(
            words("(* open (* *)"),
            [(Tok::Comment { closed: false }, "(* open (* *)")]
        );
    }

    #[test]
    fn the_lexer_text_keeps_every_position() {
        let t = "s : STRING(20); (* a (* b *) c *)";
        let out = for_lexer(t, 0..t.len(), true, true);
        assert_eq!(out, "s : STRING[20]; (* a (  b  ) c *)");
        assert_eq!(out.len(), t.len());
        // Not nested: left as it is (the lexer reports what it finds).
        assert_eq!(for_lexer(t, 0..t.len(), false, false), t);
    }
}
