//! `(* ... *)` comments, and the `(*` written inside one.
//!
//! IEC comments do not nest (IL-SEMANTICS.md, "Lexical"): a comment ends at
//! the first `*)`, and `(* outer (* inner *) still comment? *)` leaves
//! `still comment? *)` to be read as IL, whose errors ("IL instructions must
//! be inside a PROGRAM", "`*` has no meaning") say nothing of the cause. So
//! the lexer notes each comment that holds a `(*` ([`InnerOpen`]), and once
//! the file is parsed [`name_nested`] replaces the errors in the text the
//! writer meant as comment with one that names the nesting. A comment that
//! holds a `(*` and whose rest reads as IL is accepted silently.
//!
//! [`scan`] takes whether comments nest, so that an import from a tool
//! where they do (CODESYS exports `@NESTEDCOMMENTS := 'Yes'`) could switch
//! it on; nothing does today.

use crate::ast::Span;
use crate::diag::Diagnostic;

/// At most this many comments holding a `(*` are noted per file (their
/// errors beyond it keep their own messages): each later step is linear
/// in them, and a file never needs more than the first ones explained.
pub(super) const MAX_NOTED: usize = 200;

/// A comment that holds a `(*`, by positions in the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct InnerOpen {
    /// The comment's own `(*`.
    pub open: usize,
    /// The first `(*` inside it.
    pub inner: usize,
    /// The `*)` that ended it.
    pub close: usize,
}

/// A comment read from its `(*` at `start`.
pub(crate) struct Comment {
    /// Just after its closing `*)`; `None` when it is never closed.
    pub end: Option<usize>,
    /// The first `(*` inside it (only where comments do not nest).
    pub inner: Option<usize>,
}

/// Read the comment that starts at `start` (at its `(*`). Where comments
/// nest (`nests`), each inner `(*` needs its own `*)`.
pub(crate) fn scan(src: &str, start: usize, nests: bool) -> Comment {
    let b = src.as_bytes();
    let mut depth = 1usize;
    let mut inner = None;
    let mut i = start + 2;
    while i + 1 < b.len() {
        match (b[i], b[i + 1]) {
            (b'*', b')') => {
                depth -= 1;
                if depth == 0 || !nests {
                    return Comment {
                        end: Some(i + 2),
                        inner,
                    };
                }
                i += 2;
            }
            (b'(', b'*') => {
                if nests {
                    depth += 1;
                } else {
                    inner.get_or_insert(i);
                }
                i += 2;
            }
            _ => i += 1,
        }
    }
    Comment { end: None, inner }
}

/// Replace the errors of the text each noted comment's writer meant as
/// comment with one error at the `*)` that ended it. That text runs from
/// that `*)` to where the comment would end if comments nested, or, when
/// its `(*` and `*)` never balance (`(* see (* here *) x`), to the end of
/// that line. Errors elsewhere, and a comment whose rest reads as IL, are
/// left as they are. (The checker's errors too: the rest of a line may
/// parse and name nothing that exists.)
pub fn name_nested(src: &str, noted: &[InnerOpen], diags: &mut Vec<Diagnostic>) {
    if noted.is_empty() || !diags.iter().any(|d| d.is_error() && d.code != TOO_MANY) {
        return;
    }
    // The meant text of each, outermost only (one inside another's is
    // explained by the outer one), in file order.
    let mut meant: Vec<(InnerOpen, usize, usize)> = Vec::new();
    for (c, end) in noted.iter().zip(nested_ends(src, noted)) {
        let from = c.close + 2;
        let end = end.unwrap_or_else(|| {
            src.get(from..)
                .and_then(|rest| rest.find('\n'))
                .map_or(src.len(), |n| from + n)
        });
        if meant.last().is_some_and(|&(_, _, e)| from < e) {
            continue;
        }
        meant.push((*c, from, end));
    }
    let mut hit = vec![false; meant.len()];
    diags.retain(|d| {
        if !d.is_error() || d.code == TOO_MANY {
            return true;
        }
        let lo = d.span.lo as usize;
        // The last meant text starting at or before `lo`.
        let i = meant.partition_point(|&(_, from, _)| from <= lo);
        match i.checked_sub(1) {
            Some(i) if lo < meant[i].2 => {
                hit[i] = true;
                false
            }
            _ => true,
        }
    });
    for ((c, _, _), _) in meant.iter().zip(&hit).filter(|(_, h)| **h) {
        diags.push(nested_error(c));
    }
}

const TOO_MANY: &str = crate::diag::codes::TOO_MANY;

/// The error that names a nested comment.
fn nested_error(c: &InnerOpen) -> Diagnostic {
    let at = |p: usize| Span::new(p, p + 2);
    Diagnostic::error(
        super::code::NESTED_COMMENT,
        at(c.close),
        "the comment ended at this `*)`: comments do not nest",
    )
    .with_label("the comment ends here")
    .with_secondary(at(c.inner), "this `(*` does not open a comment inside the comment")
    .with_note("the text after this `*)` is read as IL, not as comment")
    .with_help("remove the inner `(*` or its `*)`, or close the comment before the inner one and open another after it")
}

/// For each noted comment, where it would end if comments nested: just
/// after the `*)` that balances its `(*`, or `None`. One pass over the file
/// from the first of them (each `(*` and `*)` counted once, whatever the
/// number of comments), keeping the depth at which each noted one opened.
fn nested_ends(src: &str, noted: &[InnerOpen]) -> Vec<Option<usize>> {
    let mut ends = vec![None; noted.len()];
    let Some(first) = noted.first() else {
        return ends;
    };
    let b = src.as_bytes();
    // Indices into `noted` still open, with the depth before their `(*`.
    let mut open: Vec<(usize, usize)> = Vec::new();
    let mut next = 0;
    let mut depth = 0usize;
    let mut i = first.open;
    while i + 1 < b.len() {
        match (b[i], b[i + 1]) {
            (b'(', b'*') => {
                // A noted `(*` this count stepped over (it pairs `(*` and
                // `*)` as they come, as the lexer does outside strings) is
                // left without an end.
                while noted.get(next).is_some_and(|c| c.open < i) {
                    next += 1;
                }
                if noted.get(next).is_some_and(|c| c.open == i) {
                    open.push((next, depth));
                    next += 1;
                }
                depth += 1;
                i += 2;
            }
            (b'*', b')') => {
                depth = depth.saturating_sub(1);
                while let Some(&(k, d)) = open.last() {
                    if d < depth {
                        break;
                    }
                    ends[k] = Some(i + 2);
                    open.pop();
                }
                i += 2;
            }
            _ => i += 1,
        }
    }
    ends
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scan_ends_at_the_first_close_unless_comments_nest() {
        let s = "(* a (* b *) c *) d";
        let c = scan(s, 0, false);
        assert_eq!((c.end, c.inner), (Some(12), Some(5)));
        let c = scan(s, 0, true);
        assert_eq!((c.end, c.inner), (Some(17), None));
        let c = scan("(* a (* b", 0, false);
        assert_eq!((c.end, c.inner), (None, Some(5)));
        let c = scan("(*)", 0, false);
        assert_eq!(c.end, None);
    }

    #[test]
    fn nested_ends_balance_or_not() {
        let s = "(* a (* b *) c *) (* d (* e *) f";
        let noted = [
            InnerOpen {
                open: 0,
                inner: 5,
                close: 10,
            },
            InnerOpen {
                open: 18,
                inner: 23,
                close: 28,
            },
        ];
        assert_eq!(nested_ends(s, &noted), [Some(17), None]);
    }
}
