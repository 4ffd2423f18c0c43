//! Parsing a changed text again only where it changed: the top-level items
//! (POUs, TYPE blocks, CONFIGURATIONs) the edit touches are parsed alone,
//! the others are kept with their spans moved.
//!
//! The result must be the tree a parse of the whole new text gives, so the
//! short way is taken only where that is sure, and a full parse is done
//! otherwise (`None`):
//! - the old text parsed without any diagnostic (after an error the
//!   parser's recovery may have placed the item boundaries anywhere);
//! - the part parsed again runs from the start of an item's line to the
//!   start of another's (or the end), with only blanks before those items
//!   on their lines: the lexer starts such a line in the state a fresh
//!   lexer starts a file in;
//! - that part parses alone without any diagnostic (an unclosed comment, a
//!   lost `END_`, an `{extern}` before a kept POU all give one).

use super::lexer::comments::InnerOpen;
use super::spans::shift;
use crate::ast::{CompilationUnit, Item};
use crate::diag::SourceFile;

/// A tree parsed again: the tree of the whole new text, the comments that
/// hold a `(*`, and the byte range of the new text that was parsed.
pub(crate) struct Reparsed {
    pub unit: CompilationUnit,
    pub inner_opens: Vec<InnerOpen>,
    pub parsed: std::ops::Range<usize>,
    /// The items parsed again (their numbers in `unit.items`) and the old
    /// items they replace (in the old text's positions).
    pub items: std::ops::Range<usize>,
    pub replaced: Vec<Item>,
    /// The old bytes the edit replaced, and how many bytes longer the new
    /// text is.
    pub change: (usize, usize),
    pub delta: i64,
    /// How many lines longer the new text is (every line from the first
    /// kept item after the edit on moved by this many).
    pub lines: i64,
}

/// Where an item starts: its keyword (a TYPE block's tree starts at its
/// first declaration: the `TYPE` before it is found in the text, right
/// before it but for blanks; `None` when something else stands between).
fn item_start(b: &[u8], item: &Item) -> Option<usize> {
    match item {
        Item::Pou(p) => Some(p.span.lo as usize),
        Item::Configuration(c) => Some(c.span.lo as usize),
        Item::Types(t) => {
            let mut i = t.first()?.span.lo as usize;
            while i > 0 && b[i - 1].is_ascii_whitespace() {
                i -= 1;
            }
            let kw = i.checked_sub(4)?;
            let bounded = kw == 0 || !(b[kw - 1].is_ascii_alphanumeric() || b[kw - 1] == b'_');
            (b[kw..i].eq_ignore_ascii_case(b"TYPE") && bounded).then_some(kw)
        }
    }
}

fn blank(b: u8) -> bool {
    b == b' ' || b == b'\t'
}

/// The start of the line of the item that starts at `lo`, if only spaces
/// and tabs stand before it on that line.
fn line_of(b: &[u8], lo: usize) -> Option<usize> {
    let mut i = lo;
    while i > 0 && blank(b[i - 1]) {
        i -= 1;
    }
    (i == 0 || b[i - 1] == b'\n').then_some(i)
}

/// The length of the common prefix (or suffix) of `a` and `b`: compared
/// in blocks first (`memcmp`), as the texts are megabytes.
fn common(a: &[u8], b: &[u8], front: bool) -> usize {
    const BLOCK: usize = 256;
    let len = a.len().min(b.len());
    let at = |s: &[u8], i: usize, k: usize| {
        if front {
            i..i + k
        } else {
            s.len() - i - k..s.len() - i
        }
    };
    let mut i = 0;
    while i + BLOCK <= len && a[at(a, i, BLOCK)] == b[at(b, i, BLOCK)] {
        i += BLOCK;
    }
    while i < len && a[at(a, i, 1)] == b[at(b, i, 1)] {
        i += 1;
    }
    i
}

/// `new` parsed from `old` (whose whole parse gave `unit` and
/// `inner_opens`, and no diagnostic), or `None` where a full parse is
/// needed.
pub(crate) fn reparse(
    old: &str,
    mut unit: CompilationUnit,
    inner_opens: Vec<InnerOpen>,
    new: &SourceFile,
    standard: crate::dialect::Standard,
) -> Option<Reparsed> {
    let (o, n) = (old.as_bytes(), new.text.as_bytes());
    if new.text.len() > u32::MAX as usize {
        return None;
    }
    let prefix = common(o, n, true);
    let room = o.len().min(n.len()) - prefix;
    let suffix = common(o, n, false).min(room);
    let delta = n.len() as i64 - o.len() as i64;
    if prefix == o.len() && o.len() == n.len() {
        return Some(Reparsed {
            unit,
            inner_opens,
            parsed: 0..0,
            items: 0..0,
            replaced: Vec::new(),
            change: (0, 0),
            delta: 0,
            lines: 0,
        });
    }
    // The edit replaced old[prefix..old_end] by new[prefix..new_end].
    let old_end = o.len() - suffix;
    // Each item's boundary: the start of its line, when only blanks stand
    // before it there. The text from one boundary to the next is an item
    // and what follows it (comments, blank lines, a TYPE block's END_TYPE).
    let starts: Vec<Option<usize>> = (unit.items.iter())
        .map(|it| line_of(o, item_start(o, it)?))
        .collect();
    // Kept before: the items before the last boundary before the edit.
    let (mut before, mut lo) = (0, 0);
    for (i, s) in starts.iter().enumerate().skip(1) {
        if let Some(s) = *s
            && s <= prefix
        {
            (before, lo) = (i, s);
        }
    }
    // Kept after: the items from the first boundary after the edit on.
    let (mut after, mut old_hi) = (starts.len(), o.len());
    for (i, s) in starts.iter().enumerate().skip(before + 1) {
        if let Some(s) = *s
            && s >= old_end
            && s > lo
        {
            (after, old_hi) = (i, s);
            break;
        }
    }
    if before == 0 && after == starts.len() {
        // Nothing kept: a full parse is the same work.
        return None;
    }
    let hi = (old_hi as i64 + delta) as usize;
    if hi < lo || (hi < n.len() && hi > 0 && n[hi - 1] != b'\n') {
        return None;
    }
    let slice = SourceFile::new(new.name.clone(), new.text[lo..hi].to_string());
    let (mut part, diags, mut opens) = super::parse_noted(&slice, standard);
    if !diags.is_empty() {
        return None;
    }
    shift(&mut part.items, lo as i64);
    let mut tail = unit.items.split_off(after);
    let replaced = unit.items.split_off(before);
    shift(&mut tail, delta);
    let items = before..before + part.items.len();
    unit.items.append(&mut part.items);
    unit.items.append(&mut tail);
    for c in &mut opens {
        c.open += lo;
        c.inner += lo;
        c.close += lo;
    }
    let mut out: Vec<InnerOpen> = Vec::with_capacity(inner_opens.len() + opens.len());
    let mut kept_after = Vec::new();
    for c in inner_opens {
        if c.close < lo {
            out.push(c);
        } else if c.open >= old_hi {
            let mv = |x: usize| (x as i64 + delta) as usize;
            kept_after.push(InnerOpen {
                open: mv(c.open),
                inner: mv(c.inner),
                close: mv(c.close),
            });
        }
    }
    out.extend(opens);
    out.extend(kept_after);
    let new_end = (old_end as i64 + delta) as usize;
    let lines = |b: &[u8]| b.iter().filter(|&&c| c == b'\n').count() as i64;
    Some(Reparsed {
        unit,
        inner_opens: out,
        parsed: lo..hi,
        items,
        replaced,
        change: (prefix, old_end),
        delta,
        lines: lines(&n[prefix..new_end]) - lines(&o[prefix..old_end]),
    })
}
