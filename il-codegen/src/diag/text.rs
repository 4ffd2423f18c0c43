//! What the renderers of diagnostics share: spans made safe to slice and
//! show, and the characters that must never reach a terminal from a message.

use crate::ast::Span;

/// A span made safe to slice `text` with: inside the text, `lo <= hi`, both on
/// char boundaries (`lo` rounded down, `hi` rounded up).
pub(crate) fn clamp_span(text: &str, span: Span) -> (usize, usize) {
    let len = text.len();
    let lo = floor_char(text, (span.lo as usize).min(len));
    let mut hi = ceil_char(text, (span.hi as usize).min(len).max(lo));
    if span.hi <= span.lo {
        hi = lo; // empty (or reversed) stays empty
    }
    (lo, hi)
}

/// Where an empty span at `pos` is best shown. A position after the last line
/// break of the file (an empty last "line") or on a line break itself is shown
/// at the end of the line before it, the way rustc points at "end of file".
fn visible_point(text: &str, pos: usize) -> usize {
    let mut p = pos;
    // At the very end after a trailing newline: step back over line breaks.
    if p == text.len() {
        while p > 0 && matches!(text.as_bytes()[p - 1], b'\n' | b'\r') {
            p -= 1;
        }
    }
    p
}

/// A span as shown: clamped ([`clamp_span`]), without the line breaks it ends
/// with, and, when empty, moved to a visible point ([`visible_point`]).
pub(crate) fn display_span(text: &str, span: Span) -> (usize, usize) {
    let (lo, mut hi) = clamp_span(text, span);
    // A span that ends with a line break is shown on the line it ends.
    while hi > lo + 1 && matches!(text.as_bytes()[hi - 1], b'\n' | b'\r') {
        hi -= 1;
    }
    if lo == hi {
        let p = visible_point(text, lo);
        (p, p)
    } else {
        (lo, hi)
    }
}

pub(crate) fn floor_char(text: &str, mut i: usize) -> usize {
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

pub(crate) fn ceil_char(text: &str, mut i: usize) -> usize {
    while !text.is_char_boundary(i) {
        i += 1;
    }
    i
}

/// Characters that must not reach a terminal from a message: they start a
/// new line, move the cursor, or reorder what is shown (C0 and C1 controls,
/// DEL, line and paragraph separators, bidirectional controls).
pub(crate) fn unsafe_char(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{2028}'
                | '\u{2029}'
                | '\u{200e}'
                | '\u{200f}'
                | '\u{061c}'
                | '\u{202a}'..='\u{202e}'
                | '\u{2066}'..='\u{2069}'
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clamp_handles_everything() {
        let t = "aé b"; // é is 2 bytes at 1..3
        assert_eq!(clamp_span(t, Span::new(2, 2)), (1, 1));
        assert_eq!(clamp_span(t, Span::new(2, 3)), (1, 3));
        assert_eq!(clamp_span(t, Span::new(0, 2)), (0, 3));
        assert_eq!(clamp_span(t, Span::new(9, 20)), (5, 5));
        assert_eq!(clamp_span(t, Span::new(4, 1)), (4, 4));
        assert_eq!(clamp_span("", Span::new(3, 7)), (0, 0));
    }
}
