//! Positions: byte offsets of our spans ↔ LSP positions (line and UTF-16
//! column, the protocol's default encoding), and file URIs ↔ names.
//!
//! Every conversion clamps: a position past the end of a line or of the
//! text (an editor racing an edit, or a hostile client) lands on the
//! nearest real place instead of panicking.

use il_codegen::ast::Span;
use lsp_types::{Position, Range, Uri};

/// The line table of one text, built once per text (and kept through the
/// editor's edits, [`LineIndex::edit`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LineIndex {
    /// Byte offset of each line's start.
    starts: Vec<usize>,
    /// Whether each line is pure ASCII: then a column is a byte difference
    /// (the common case), without walking its characters.
    ascii: Vec<bool>,
    len: usize,
}

impl LineIndex {
    pub fn new(text: &str) -> LineIndex {
        let mut starts = vec![0];
        let mut ascii = Vec::new();
        let mut all_ascii = true;
        for (i, b) in text.bytes().enumerate() {
            if b == b'\n' {
                starts.push(i + 1);
                ascii.push(all_ascii);
                all_ascii = true;
            } else if !b.is_ascii() {
                all_ascii = false;
            }
        }
        ascii.push(all_ascii);
        LineIndex {
            starts,
            ascii,
            len: text.len(),
        }
    }

    /// The table of `text`, which is this table's text with bytes
    /// `lo..hi` replaced by `new_len` bytes: the lines of the edit read
    /// again, the later ones moved (a table of 100 000 lines costs a
    /// millisecond to build, its move a memmove).
    pub fn edit(&mut self, text: &str, lo: usize, hi: usize, new_len: usize) {
        let delta = new_len as isize - (hi - lo) as isize;
        let (first, last) = (self.line_of(lo), self.line_of(hi));
        let from = self.starts[first];
        // The start of the line after the edit's last one, in the new text.
        let next = self
            .starts
            .get(last + 1)
            .map(|&t| (t as isize + delta) as usize);
        let to = next.unwrap_or(text.len()).min(text.len());
        let mut starts = Vec::new();
        let mut ascii = Vec::new();
        let mut all = true;
        for (i, b) in text.as_bytes()[from.min(to)..to].iter().enumerate() {
            if *b == b'\n' {
                starts.push(from + i + 1);
                ascii.push(all);
                all = true;
            } else if !b.is_ascii() {
                all = false;
            }
        }
        let kept = match next {
            // The last line read ends the text.
            None => {
                ascii.push(all);
                self.starts.len()
            }
            Some(_) => last + 2,
        };
        let added = starts.len();
        self.starts.splice(first + 1..kept, starts);
        for s in &mut self.starts[first + 1 + added..] {
            *s = (*s as isize + delta) as usize;
        }
        let kept = if next.is_none() {
            self.ascii.len()
        } else {
            last + 1
        };
        self.ascii.splice(first..kept, ascii);
        self.len = text.len();
    }

    /// The 0-based line holding byte `off` (clamped to the text).
    pub fn line_of(&self, off: usize) -> usize {
        let off = off.min(self.len);
        self.starts.partition_point(|&s| s <= off) - 1
    }

    /// Byte range of a 0-based line without its `\n` (and `\r`).
    pub fn line_range(&self, text: &str, line: usize) -> (usize, usize) {
        let line = line.min(self.starts.len() - 1);
        // Clamped to `text` too: a table is only ever used with its own
        // text, but a slip must not become a panic.
        let hi = self.starts.get(line + 1).map_or(self.len, |&n| n - 1);
        let mut hi = floor_char(text, hi);
        let lo = floor_char(text, self.starts[line].min(hi));
        if hi > lo && text.as_bytes().get(hi - 1) == Some(&b'\r') {
            hi -= 1;
        }
        (lo, hi.max(lo))
    }

    /// The LSP position of a byte offset.
    pub fn position(&self, text: &str, off: usize) -> Position {
        let off = floor_char(text, off.min(self.len));
        let line = self.line_of(off);
        let lo = floor_char(text, self.starts[line].min(off));
        let character = if self.ascii[line] {
            off - lo
        } else {
            text[lo..off].chars().map(char::len_utf16).sum()
        };
        Position::new(line as u32, character as u32)
    }

    /// The byte offset of an LSP position, clamped to its line and the text.
    pub fn offset(&self, text: &str, pos: Position) -> usize {
        let line = (pos.line as usize).min(self.starts.len() - 1);
        let (lo, hi) = self.line_range(text, line);
        let want = pos.character as usize;
        if self.ascii[line] {
            return (lo + want).min(hi);
        }
        let mut units = 0;
        for (i, c) in text[lo..hi].char_indices() {
            // A column inside a surrogate pair lands on its character.
            if units + c.len_utf16() > want {
                return lo + i;
            }
            units += c.len_utf16();
        }
        hi
    }

    pub fn range(&self, text: &str, span: Span) -> Range {
        Range::new(
            self.position(text, span.lo as usize),
            self.position(text, span.hi as usize),
        )
    }
}

/// The largest char boundary at or before `off`.
pub fn floor_char(text: &str, mut off: usize) -> usize {
    off = off.min(text.len());
    while !text.is_char_boundary(off) {
        off -= 1;
    }
    off
}

/// The name a document gets in messages (as `ilc check` shows a path): the
/// decoded path of a `file:` URI, the URI itself otherwise.
pub fn uri_to_name(uri: &Uri) -> String {
    let s = uri.as_str();
    match s.strip_prefix("file://") {
        Some(rest) => {
            // `file:///C:/x` on Windows: drop the slash before the drive.
            let path = percent_decode(rest.trim_start_matches("localhost"));
            match path.as_bytes() {
                [b'/', d, b':', ..] if d.is_ascii_alphabetic() => path[1..].to_string(),
                _ => path,
            }
        }
        None => s.to_string(),
    }
}

/// A `file:` URI for a path found on disk.
pub fn path_to_uri(path: &std::path::Path) -> Option<Uri> {
    let p = path.to_str()?.replace('\\', "/");
    let mut s = String::from("file://");
    if !p.starts_with('/') {
        s.push('/');
    }
    for b in p.bytes() {
        if b.is_ascii_alphanumeric() || b"/-._~:".contains(&b) {
            s.push(b as char);
        } else {
            s.push_str(&format!("%{b:02X}"));
        }
    }
    s.parse().ok()
}

fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        if b[i] == b'%'
            && i + 2 < b.len()
            && let (Some(h), Some(l)) = (hex(b[i + 1]), hex(b[i + 2]))
        {
            out.push((h * 16 + l) as u8);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf16_columns_round_trip_and_clamp() {
        let text = "LD x\n(* ä😀 *) LD y\r\nend";
        let ix = LineIndex::new(text);
        let y = text.find('y').unwrap();
        let p = ix.position(text, y);
        // `(* ` 3, `ä` 1, `😀` 2 (a surrogate pair), ` *) LD ` 7.
        assert_eq!(p, Position::new(1, 13));
        assert_eq!(ix.offset(text, p), y);
        // Past the end of a line: its end, before `\r\n`.
        assert_eq!(
            ix.offset(text, Position::new(1, 999)),
            text.find('\r').unwrap()
        );
        // Past the last line: the last line.
        assert_eq!(ix.offset(text, Position::new(99, 1)), text.len() - 2);
        // Inside a surrogate pair: the character's start.
        let emoji = text.find('😀').unwrap();
        assert_eq!(ix.offset(text, Position::new(1, 5)), emoji);
        // An offset inside a character is floored.
        assert_eq!(ix.position(text, emoji + 1), Position::new(1, 4));
    }

    /// A table moved through random edits is the table of the new text.
    #[test]
    fn an_edited_table_is_the_table_of_the_new_text() {
        let pieces = ["", "x", "\n", "ä\n", "LD y\r\n", "\n\n😀", "(* ä *)"];
        let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut rand = |n: usize| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % n.max(1) as u64) as usize
        };
        let mut text = String::from("LD x\n(* ä *) LD y\r\nST z\n");
        let mut ix = LineIndex::new(&text);
        for step in 0..2000 {
            let floor = |t: &str, i: usize| floor_char(t, i);
            let lo = floor(&text, rand(text.len() + 1));
            let hi = floor(&text, (lo + rand(8)).min(text.len())).max(lo);
            let new = pieces[rand(pieces.len())];
            text.replace_range(lo..hi, new);
            ix.edit(&text, lo, hi, new.len());
            assert_eq!(ix, LineIndex::new(&text), "step {step}: {text:?}");
            if text.len() > 400 {
                text.truncate(floor(&text, 40));
                ix = LineIndex::new(&text);
            }
        }
    }

    #[test]
    fn file_uris() {
        let u: Uri = "file:///tmp/a%20b/m.il".parse().unwrap();
        assert_eq!(uri_to_name(&u), "/tmp/a b/m.il");
        let back = path_to_uri(std::path::Path::new("/tmp/a b/m.il")).unwrap();
        assert_eq!(back.as_str(), "file:///tmp/a%20b/m.il");
    }
}
