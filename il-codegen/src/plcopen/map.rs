//! The IL text made from an XML file, and where each of its bytes came from.
//!
//! Text is appended in pieces: a piece *copied* from the XML (a run of IL
//! body text, a name in an attribute) maps byte for byte; a *generated* piece
//! (a keyword, `:`, a decoded `&lt;`) maps as a whole to the XML range it
//! stands for. [`SpanMap::to_xml`] turns a span in the IL text into a span in
//! the XML text.

use std::ops::Range;

use crate::ast::Span;

#[derive(Clone, Copy, Debug)]
struct Piece {
    /// Start in the IL text; the piece ends where the next one starts.
    il: u32,
    /// The XML range it came from.
    xml_lo: u32,
    xml_hi: u32,
    /// Byte-for-byte copy (then `xml_hi - xml_lo` is the piece's length).
    linear: bool,
}

/// IL text under construction, with its map back into the XML (or the
/// `.EXP` file: the CODESYS import writes one too).
#[derive(Debug, Default)]
pub(crate) struct Writer {
    pub(crate) text: String,
    pieces: Vec<Piece>,
}

fn u(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

// Without the `plcopen` feature only the EXP import writes, which never
// rolls back.
#[cfg_attr(not(feature = "plcopen"), allow(dead_code))]
impl Writer {
    /// Append generated text standing for the XML range `at`.
    pub(crate) fn gen_at(&mut self, s: &str, at: Range<usize>) {
        if s.is_empty() {
            return;
        }
        // One step per piece (a chunk of text), not per byte.
        crate::step_counter::add(1);
        let hi = at.end.max(at.start);
        self.pieces.push(Piece {
            il: u(self.text.len()),
            xml_lo: u(at.start),
            xml_hi: u(hi),
            linear: false,
        });
        self.text.push_str(s);
    }

    /// Append `s`, which is the XML text starting at byte `xml_start`.
    pub(crate) fn copy(&mut self, s: &str, xml_start: usize) {
        if s.is_empty() {
            return;
        }
        crate::step_counter::add(1);
        self.pieces.push(Piece {
            il: u(self.text.len()),
            xml_lo: u(xml_start),
            xml_hi: u(xml_start + s.len()),
            linear: true,
        });
        self.text.push_str(s);
    }

    /// Where the text ends now, for [`Writer::rollback`].
    pub(crate) fn mark(&self) -> (usize, usize) {
        (self.text.len(), self.pieces.len())
    }

    /// Drop everything written since `mark`: an element found invalid
    /// half-way is left out whole.
    pub(crate) fn rollback(&mut self, mark: (usize, usize)) {
        self.text.truncate(mark.0);
        self.pieces.truncate(mark.1);
    }

    /// The XML byte offset that IL byte `off` written so far came from (as
    /// [`SpanMap::offset_to_xml`], before the map is finished).
    pub(crate) fn xml_at(&self, off: usize) -> usize {
        let off = u(off);
        let i = piece_before(&self.pieces, off);
        match self.pieces.get(i) {
            Some(p) if p.linear => (p.xml_lo + (off - p.il.min(off))).min(p.xml_hi) as usize,
            Some(p) => p.xml_lo as usize,
            None => 0,
        }
    }

    /// Finish: the IL text and its map.
    pub(crate) fn finish(self) -> (String, SpanMap) {
        let end = u(self.text.len());
        (
            self.text,
            SpanMap {
                pieces: self.pieces,
                end,
            },
        )
    }
}

/// The last piece starting at or before IL byte `off` (0 when none does).
/// One step per piece compared: a binary search compares about log2 of
/// them, and a look-up that became a scan of the map (once per IL line in
/// `Import::xml_lines`) would grow with the square of the body in the
/// scaling tests.
fn piece_before(pieces: &[Piece], off: u32) -> usize {
    pieces
        .partition_point(|p| {
            crate::step_counter::add(1);
            p.il <= off
        })
        .saturating_sub(1)
}

/// Where each byte of a generated IL text came from in its XML file.
#[derive(Clone, Debug, Default)]
pub struct SpanMap {
    pieces: Vec<Piece>,
    end: u32,
}

impl SpanMap {
    fn piece_end(&self, i: usize) -> u32 {
        self.pieces.get(i + 1).map_or(self.end, |p| p.il)
    }

    /// The piece holding byte `off` (the last piece for the end of the text).
    fn find(&self, off: u32) -> Option<usize> {
        if self.pieces.is_empty() {
            return None;
        }
        Some(piece_before(&self.pieces, off))
    }

    fn lo(&self, off: u32) -> u32 {
        let Some(i) = self.find(off) else { return 0 };
        let p = self.pieces[i];
        if p.linear {
            (p.xml_lo + (off - p.il.min(off))).min(p.xml_hi)
        } else {
            p.xml_lo
        }
    }

    fn hi(&self, off: u32) -> u32 {
        // The piece that ends at or holds `off` from the left.
        let Some(i) = self.find(off.saturating_sub(1)) else {
            return 0;
        };
        let p = self.pieces[i];
        if off > self.piece_end(i) {
            return p.xml_hi;
        }
        if p.linear {
            (p.xml_lo + (off - p.il.min(off))).min(p.xml_hi)
        } else {
            p.xml_hi
        }
    }

    /// The XML span of an IL span.
    pub fn to_xml(&self, span: Span) -> Span {
        let lo = self.lo(span.lo);
        if span.hi <= span.lo {
            return Span { lo, hi: lo };
        }
        let hi = self.hi(span.hi);
        Span { lo, hi: hi.max(lo) }
    }

    /// The XML byte offset where IL byte `off` came from.
    pub fn offset_to_xml(&self, off: u32) -> u32 {
        self.lo(off)
    }
}

#[cfg(all(test, feature = "plcopen"))]
mod tests {
    use super::*;

    #[test]
    fn copied_text_maps_byte_for_byte_generated_as_a_whole() {
        let mut w = Writer::default();
        w.gen_at("PROGRAM ", 0..9);
        w.copy("main", 20);
        w.gen_at("<", 40..44);
        w.copy("LD x", 44);
        let (text, map) = w.finish();
        assert_eq!(text, "PROGRAM main<LD x");
        assert_eq!(map.to_xml(Span { lo: 8, hi: 12 }), Span { lo: 20, hi: 24 });
        assert_eq!(map.to_xml(Span { lo: 0, hi: 7 }), Span { lo: 0, hi: 9 });
        assert_eq!(map.to_xml(Span { lo: 12, hi: 13 }), Span { lo: 40, hi: 44 });
        assert_eq!(map.to_xml(Span { lo: 13, hi: 17 }), Span { lo: 44, hi: 48 });
        // Across pieces: from the first's start to the last's end.
        assert_eq!(map.to_xml(Span { lo: 9, hi: 15 }), Span { lo: 21, hi: 46 });
        // Empty spans, including at the very end.
        assert_eq!(map.to_xml(Span { lo: 17, hi: 17 }), Span { lo: 48, hi: 48 });
        assert_eq!(map.to_xml(Span { lo: 99, hi: 99 }), Span { lo: 48, hi: 48 });
        assert_eq!(
            SpanMap::default().to_xml(Span { lo: 3, hi: 5 }),
            Span { lo: 0, hi: 0 }
        );
    }
}
