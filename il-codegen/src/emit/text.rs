//! The emitter's output: Rust text in one `String`, laid out as it is
//! written (no token trees, no reparse, no pretty-printer).
//!
//! Injection safety is this module's job. The emitter writes its own code
//! as text, and every piece of IL-derived text reaches the output through
//! one of the helpers here: an identifier ([`super::names`], which only ever
//! yields `[A-Za-z0-9_]` or `r#` + a keyword), a string literal ([`str_lit`],
//! escaped character by character), a doc or line comment ([`doc`],
//! [`comment_text`]: nothing in it can end the comment early). Numbers are
//! formatted from integers and floats. Nothing else of the IL is written.
//!
//! [`Out`] lays the text out while it is appended: it reads it as Rust
//! (string literals, char literals and lifetimes, comments, brackets) and
//! breaks lines after `{`, `;`, `,` and `}` of blocks and items, indenting
//! by 4 spaces; inside `(...)` and `[...]` (and blocks opened there) the
//! text stays on one line. A `[` directly followed by a newline in the
//! written text is a list laid out one element per line.

/// An indenting writer of Rust text.
#[derive(Default)]
pub(crate) struct Out {
    buf: String,
    /// Open brackets: the character and whether it lays out inline.
    stack: Vec<(u8, bool)>,
    /// Open brackets that break lines (the indentation level).
    depth: usize,
    /// A line break is due before the next token: 1 after `;`, `{`, ...
    /// (`}` then `else`, `;`, `,`, `)` or `.` stays on the line), 2 after a
    /// comment (always).
    brk: u8,
    /// A space is due before the next token.
    space: bool,
    /// The stack depth of an attribute `#[...]` that began a line.
    attr: Option<usize>,
    /// Nothing written on the current line yet.
    fresh: bool,
    /// Where each `__il_line!(` written by [`Out::marker`] starts (the file
    /// writer then need not search 10 MB of text for them).
    markers: Vec<usize>,
}

impl Out {
    pub(crate) fn new() -> Self {
        Out {
            fresh: true,
            ..Default::default()
        }
    }

    /// Room for `n` line markers.
    pub(crate) fn reserve_markers(&mut self, n: usize) {
        self.markers.reserve_exact(n);
    }

    /// The text written so far, ending with a newline.
    #[cfg(test)]
    pub(crate) fn finish(self) -> String {
        self.finish_marked().0
    }

    /// The text written so far, ending with a newline, and the offsets of
    /// its line markers.
    pub(crate) fn finish_marked(mut self) -> (String, Vec<usize>) {
        if !self.buf.is_empty() && !self.buf.ends_with('\n') {
            self.buf.push('\n');
        }
        (self.buf, self.markers)
    }

    /// Whether the innermost bracket keeps its contents on one line.
    fn inline(&self) -> bool {
        self.stack
            .last()
            .is_some_and(|&(c, inline)| inline || c == b'(')
    }

    /// Before a token: the due line break (unless `glue` and it is soft)
    /// or space (unless `glue`, or right after an opening bracket).
    fn lead(&mut self, glue: bool) {
        if self.brk == 2 || (self.brk == 1 && !glue) {
            if !self.buf.is_empty() {
                self.buf.push('\n');
            }
            // The indentation in one piece (a line per statement).
            let mut n = self.depth * 4;
            while n > 0 {
                let k = n.min(SPACES.len());
                self.buf.push_str(&SPACES[..k]);
                n -= k;
            }
            self.fresh = true;
            self.space = false;
        }
        self.brk = 0;
        if self.space && !self.fresh && !glue && !matches!(self.last(), b'(' | b'[') {
            self.buf.push(' ');
        }
        self.space = false;
        self.fresh = false;
    }

    /// The last byte written (0 if none): the brackets asked about are ASCII,
    /// which no byte of a multi-byte character equals.
    fn last(&self) -> u8 {
        self.buf.as_bytes().last().copied().unwrap_or(0)
    }

    /// `__il_line!(N);`, as [`Out::code`] lays it out, without formatting
    /// the text first (one per IL line).
    pub(crate) fn marker(&mut self, line: u32) {
        self.lead(false);
        self.markers.push(self.buf.len());
        self.buf.push_str("__il_line!(");
        push_decimal(&mut self.buf, line.into());
        self.buf.push_str(");");
        self.after_separator();
    }

    /// After a `;` or `,`: a space inside an inline bracket, else a break.
    fn after_separator(&mut self) {
        if self.inline() {
            self.space = true;
        } else {
            self.brk = 1;
        }
    }

    /// Whether the `#` just written began its line (an attribute follows).
    fn hash_begins_line(&self) -> bool {
        let before = self.buf.strip_suffix('#').unwrap_or("x");
        let before = before.trim_end_matches(' ');
        before.is_empty() || before.ends_with('\n')
    }

    /// Append Rust text (see the module comment for the layout).
    pub(crate) fn code(&mut self, s: &str) {
        let b = s.as_bytes();
        let mut i = 0;
        while i < b.len() {
            let c = b[i];
            match c {
                b' ' | b'\t' | b'\n' | b'\r' => {
                    self.space = true;
                    i += 1;
                }
                b'"' => {
                    let end = string_end(b, i + 1);
                    self.lead(false);
                    self.buf.push_str(&s[i..end]);
                    i = end;
                }
                b'\'' => {
                    // A char literal `'x'` / `'\n'`, or a lifetime `'a`.
                    self.lead(false);
                    let end = if b.get(i + 1) == Some(&b'\\') {
                        char_end(b, i + 2)
                    } else if b.get(i + 2) == Some(&b'\'') {
                        i + 3
                    } else {
                        i + 1
                    };
                    self.buf.push_str(&s[i..end]);
                    i = end;
                }
                b'/' if b.get(i + 1) == Some(&b'/') => {
                    // A line comment runs to the end of the line; a line
                    // break always follows it.
                    let end = s[i..].find('\n').map_or(b.len(), |k| i + k);
                    if !self.fresh && self.brk == 0 {
                        self.brk = 2;
                    }
                    self.lead(false);
                    self.buf.push_str(s[i..end].trim_end());
                    self.brk = 2;
                    i = end;
                }
                b'{' => {
                    self.lead(false);
                    self.buf.push('{');
                    let inline = self.inline();
                    self.stack.push((b'{', inline));
                    if inline {
                        self.space = true;
                    } else {
                        self.depth += 1;
                        self.brk = 1;
                    }
                    i += 1;
                }
                b'(' | b'[' => {
                    if c == b'[' && self.attr.is_none() && self.hash_begins_line() {
                        self.attr = Some(self.stack.len());
                    }
                    // `[` then a newline: a list, one element per line.
                    let list = c == b'[' && !self.inline() && b.get(i + 1) == Some(&b'\n');
                    self.lead(false);
                    self.buf.push(c as char);
                    self.stack.push((c, !list));
                    if list {
                        self.depth += 1;
                        self.brk = 1;
                    }
                    i += 1;
                }
                b'}' | b')' | b']' => {
                    let (open, inline) = self.stack.pop().unwrap_or((c, true));
                    if !inline {
                        self.depth = self.depth.saturating_sub(1);
                        if self.brk == 1 && matches!(self.last(), b'{' | b'[') {
                            // Empty: `{}`.
                            self.brk = 0;
                        } else {
                            self.brk = self.brk.max(1);
                        }
                        self.space = false;
                        self.lead(false);
                        self.buf.push(c as char);
                        self.brk = 1;
                    } else if open == b'{' {
                        if self.last() == b'{' {
                            self.space = false;
                        }
                        self.lead(false);
                        self.buf.push('}');
                        self.space = true;
                    } else {
                        self.space = false;
                        self.lead(true);
                        self.buf.push(c as char);
                    }
                    if c == b']' && self.attr == Some(self.stack.len()) {
                        self.attr = None;
                        self.brk = 1;
                    }
                    i += 1;
                }
                b';' | b',' => {
                    self.space = false;
                    self.lead(true);
                    self.buf.push(c as char);
                    self.after_separator();
                    i += 1;
                }
                b'.' if b.get(i + 1) != Some(&b'.') => {
                    // `x.y`, `{ .. }.y`: no space, no break.
                    self.space = false;
                    self.lead(true);
                    self.buf.push('.');
                    i += 1;
                }
                _ => {
                    // A run of identifier characters, or of punctuation.
                    let mut end = i + 1;
                    if CLASS[c as usize] == WORD {
                        while end < b.len() && CLASS[b[end] as usize] == WORD {
                            end += 1;
                        }
                    } else {
                        // Punctuation stops at a word, a delimiter, a `.`
                        // that is not `..` and a `//`.
                        while end < b.len() {
                            let d = b[end];
                            if CLASS[d as usize] != PUNCT
                                || (d == b'.' && b.get(end + 1) != Some(&b'.'))
                                || (d == b'/' && b.get(end + 1) == Some(&b'/'))
                            {
                                break;
                            }
                            end += 1;
                        }
                    }
                    let t = &s[i..end];
                    if t == "else" && self.brk == 1 && self.last() == b'}' {
                        self.brk = 0;
                        self.space = true;
                    }
                    self.lead(false);
                    self.buf.push_str(t);
                    i = end;
                }
            }
        }
    }
}

/// Spaces to indent by (deeper levels take several pieces).
const SPACES: &str = "                                                                ";

/// The classes of the bytes in [`Out::code`]'s runs of identifier
/// characters (`[A-Za-z0-9_]` and any byte of a non-ASCII character) and of
/// punctuation; the delimiters (whitespace, quotes, brackets, `;` and `,`)
/// end both.
const PUNCT: u8 = 0;
const WORD: u8 = 1;
const DELIM: u8 = 2;
const CLASS: [u8; 256] = {
    let mut t = [PUNCT; 256];
    let mut b = 0;
    while b < 256 {
        let c = b as u8;
        if c.is_ascii_alphanumeric() || c == b'_' || c >= 0x80 {
            t[b] = WORD;
        }
        b += 1;
    }
    let delims = b" \t\n\r\"'{}()[];,";
    let mut k = 0;
    while k < delims.len() {
        t[delims[k] as usize] = DELIM;
        k += 1;
    }
    t
};

/// The end of a string literal whose body starts at `i` (after the `"`).
fn string_end(b: &[u8], mut i: usize) -> usize {
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'"' => return i + 1,
            _ => i += 1,
        }
    }
    b.len()
}

/// The end of a char literal whose escape starts at `i` (after `'\`).
fn char_end(b: &[u8], mut i: usize) -> usize {
    i += 1;
    while i < b.len() && b[i] != b'\'' {
        i += 1;
    }
    (i + 1).min(b.len())
}

/// A Rust string literal holding `s`: quotes, backslashes and every control
/// or invisible format character escaped (rustc denies bidirectional
/// controls even inside literals), so that nothing in `s` can end it.
/// `n` in decimal, appended without the formatting machinery (the emitter
/// writes one per IL line and per parenthesis).
pub(crate) fn push_decimal(buf: &mut String, n: u64) {
    let mut digits = [0u8; 20];
    let mut at = digits.len();
    let mut n = n;
    loop {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    for &d in &digits[at..] {
        buf.push(d as char);
    }
}

pub(crate) fn str_lit(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() || is_invisible_format(c) => {
                out.push_str(&format!("\\u{{{:x}}}", c as u32));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The engineer's comment of a declaration ([`crate::ir::Var::doc`]) as
/// doc lines, then an empty doc line before what the generator adds: each
/// line of text, its Markdown punctuation escaped (an IL comment is plain
/// text: `[x]` must not become a broken link, nor `<b>` an HTML tag, in the
/// user's `cargo doc`).
pub(crate) fn user_doc(text: Option<&str>) -> String {
    let Some(text) = text else {
        return String::new();
    };
    let mut out = String::new();
    for line in text.lines() {
        let mut escaped = String::with_capacity(line.len() + 8);
        escaped.push(' ');
        for c in line.chars() {
            if "\\`*_[]<>#|~!&".contains(c) {
                escaped.push('\\');
            }
            escaped.push(c);
        }
        out.push_str(&doc(&escaped));
    }
    out.push_str("///\n");
    out
}

/// A doc comment line `/// text` (with its newline) for [`Out::code`].
pub(crate) fn doc(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 5);
    out.push_str("///");
    out.push_str(&comment_text(text));
    out.push('\n');
    out
}

/// The text of a `//` comment. A line comment cannot be escaped from (only
/// `\n` ends it, and control characters, `\r` included, become spaces), but
/// rustc refuses some characters even inside comments: the bidirectional
/// text controls (lint `text_direction_codepoint_in_comment`, deny by
/// default), so an IL comment holding U+202E made the generated file fail to
/// build. Those, and the other invisible format characters and line/paragraph
/// separators (U+2028/U+2029, which editors may show as line breaks), are
/// written as `\u{...}` escapes. `*/` is broken up too, so that the text
/// stays inert even inside a block comment.
pub(crate) fn comment_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut star = false;
    for c in s.chars() {
        if c == '/' && star {
            out.push(' ');
        }
        star = c == '*';
        if c.is_control() {
            out.push(' ');
        } else if is_invisible_format(c) {
            out.push_str(&format!("\\u{{{:x}}}", c as u32));
        } else {
            out.push(c);
        }
    }
    out
}

/// Bidirectional controls (U+061C, U+200E/F, U+202A-E, U+2066-9), zero-width
/// and other invisible format characters, line and paragraph separators.
fn is_invisible_format(c: char) -> bool {
    matches!(
        c,
        '\u{061C}'
            | '\u{180E}'
            | '\u{200B}'..='\u{200F}'
            | '\u{2028}'..='\u{202E}'
            | '\u{2060}'..='\u{206F}'
            | '\u{FEFF}'
            | '\u{FFF9}'..='\u{FFFB}'
    )
}

/// Items separated by `sep` (`a, b, c`).
pub(crate) fn join<I: IntoIterator<Item = S>, S: AsRef<str>>(items: I, sep: &str) -> String {
    let mut out = String::new();
    for (k, s) in items.into_iter().enumerate() {
        if k > 0 {
            out.push_str(sep);
        }
        out.push_str(s.as_ref());
    }
    out
}

/// Items each after `, ` (`, a, b`): the rest of an argument list.
pub(crate) fn tail<I: IntoIterator<Item = S>, S: AsRef<str>>(items: I) -> String {
    let mut out = String::new();
    for s in items {
        out.push_str(", ");
        out.push_str(s.as_ref());
    }
    out
}

/// Items each followed by `sep` (`a, b, c, `), as `quote!`'s `#(#x,)*`.
pub(crate) fn each<I: IntoIterator<Item = S>, S: AsRef<str>>(items: I, sep: &str) -> String {
    let mut out = String::new();
    for s in items {
        out.push_str(s.as_ref());
        out.push_str(sep);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{Out, comment_text, doc, str_lit, user_doc};

    #[test]
    fn an_il_comment_becomes_plain_doc_text() {
        assert_eq!(user_doc(None), "");
        assert_eq!(
            user_doc(Some("see [Motor] <b>x</b>\n*/ a_b")),
            "/// see \\[Motor\\] \\<b\\>x\\</b\\>\n/// \\* / a\\_b\n///\n"
        );
    }

    fn lay(s: &str) -> String {
        let mut o = Out::new();
        o.code(s);
        o.finish()
    }

    #[test]
    fn blocks_break_and_indent_parens_stay_inline() {
        assert_eq!(
            lay("fn f(a: u8) -> u8 { let x = g(a, { 1 }); if x { y(); } else { z(); } x }"),
            "fn f(a: u8) -> u8 {\n    let x = g(a, { 1 });\n    if x {\n        y();\n    } else {\n        z();\n    }\n    x\n}\n"
        );
        assert_eq!(lay("impl X {}"), "impl X {}\n");
        assert_eq!(
            lay("#[allow(x)] pub struct S { pub a: [u8; 3], }"),
            "#[allow(x)]\npub struct S {\n    pub a: [u8; 3],\n}\n"
        );
    }

    #[test]
    fn literals_comments_and_lifetimes_are_not_layout() {
        assert_eq!(
            lay("'__l0: { f(\"{ ; }\", 'x'); } &'a T"),
            "'__l0: {\n    f(\"{ ; }\", 'x');\n}\n&'a T\n"
        );
        assert_eq!(
            lay(&format!("{}struct S;", doc(" a\nb */ c"))),
            "/// a b * / c\nstruct S;\n"
        );
    }

    #[test]
    fn strings_and_comments_cannot_be_left() {
        assert_eq!(str_lit("a\"b\\\n\u{202e}"), "\"a\\\"b\\\\\\n\\u{202e}\"");
        assert!(!comment_text("x\n*/y\r").contains(['\n', '\r']));
        assert!(!comment_text("x*/").contains("*/"));
    }
}
