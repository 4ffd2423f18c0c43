//! Parsing a changed text again only where it changed: the top-level items
//! (POUs, TYPE blocks, CONFIGURATIONs) the edit touches are parsed alone,
//! the others are kept with their spans moved.
//!
//! The result must be the tree a parse of the whole new text gives, so the
//! short way is taken only where that is sure, and a full parse is done
//! otherwise (`None`):
//! - the old text parsed without any diagnostic (after an error the
//!   parser's recovery may have placed the item boundaries anywhere);
//! - the part parsed again runs from a line start to a line start, with
//!   only spaces and tabs between a kept item and those line breaks: the
//!   lexer starts each line between items in the same state as a fresh
//!   lexer does at the start of a file;
//! - that part parses alone without any diagnostic (an unclosed comment, a
//!   lost `END_`, an `{extern}` before a kept POU all give one).

use super::lexer::comments::InnerOpen;
use super::spans::shift;
use crate::ast::{CompilationUnit, Item, Span};
use crate::diag::SourceFile;

/// A tree parsed again: the tree of the whole new text, the comments that
/// hold a `(*`, and the byte range of the new text that was parsed.
pub(crate) struct Reparsed {
    pub unit: CompilationUnit,
    pub inner_opens: Vec<InnerOpen>,
    pub parsed: std::ops::Range<usize>,
}

fn item_span(item: &Item) -> Option<Span> {
    match item {
        Item::Pou(p) => Some(p.span),
        Item::Configuration(c) => Some(c.span),
        Item::Types(t) => Some(t.first()?.span.to(t.last()?.span)),
    }
}

fn blank(b: u8) -> bool {
    b == b' ' || b == b'\t'
}

/// The start of the line after the item that ends at `hi`, if only spaces
/// and tabs (or a `\r`) stand between.
fn line_after(b: &[u8], hi: usize) -> Option<usize> {
    let mut i = hi;
    while i < b.len() && (blank(b[i]) || b[i] == b'\r') {
        i += 1;
    }
    (b.get(i) == Some(&b'\n')).then_some(i + 1)
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
        });
    }
    // The edit replaced old[prefix..old_end] by new[prefix..new_end].
    let old_end = o.len() - suffix;
    let spans: Vec<Span> = unit.items.iter().map(item_span).collect::<Option<_>>()?;
    // Kept before: the items whose line ends before the edit.
    let mut before = 0;
    let mut lo = 0;
    for s in &spans {
        match line_after(o, s.hi as usize) {
            Some(next) if next <= prefix => {
                before += 1;
                lo = next;
            }
            _ => break,
        }
    }
    // Kept after: the items whose line starts after the edit.
    let mut after = spans.len();
    let mut old_hi = o.len();
    for s in spans[before..].iter().rev() {
        match line_of(o, s.lo as usize) {
            Some(start) if start >= old_end && start > lo => {
                after -= 1;
                old_hi = start;
            }
            _ => break,
        }
    }
    if before == 0 && after == spans.len() {
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
    unit.items.truncate(before);
    shift(&mut tail, delta);
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
    Some(Reparsed {
        unit,
        inner_opens: out,
        parsed: lo..hi,
    })
}
