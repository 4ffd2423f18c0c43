//! Reading text out of the raw XML so that every character keeps its place:
//! the contents of an element (CDATA sections, escaped text, `<xhtml:p>`
//! wrappers) and attribute values.
//!
//! roxmltree has already checked that the document is well-formed; these
//! scanners only walk ranges it reported, and stop at the range's end.

use std::ops::Range;

use super::map::Writer;

/// The bytes between an element's start tag and its end tag (empty for `<e/>`).
pub(crate) fn content_range(xml: &str, element: Range<usize>) -> Range<usize> {
    let b = xml.as_bytes();
    let element = element.start.min(b.len())..element.end.min(b.len());
    let mut i = element.start;
    let mut quote = None;
    while i < element.end {
        let c = b[i];
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == b'"' || c == b'\'' => quote = Some(c),
            None if c == b'>' => break,
            None => {}
        }
        i += 1;
    }
    let start = (i + 1).min(element.end);
    if i > element.start && b.get(i - 1) == Some(&b'/') {
        return start..start;
    }
    let end = xml
        .get(start..element.end)
        .and_then(|s| s.rfind("</"))
        .map_or(start, |k| start + k);
    start..end
}

/// The start tag of an element (`<variable name="x">`), for anchoring.
pub(crate) fn start_tag(xml: &str, element: Range<usize>) -> Range<usize> {
    let c = content_range(xml, element.clone());
    if c.start == c.end && xml.get(element.clone()).is_some_and(|s| s.ends_with("/>")) {
        return element;
    }
    element.start..c.start.max(element.start)
}

/// Decode the text inside `range` (element content) into `w`: CDATA is
/// copied as is, character and entity references are decoded, markup is
/// dropped (the end of an `<xhtml:p>` or a `<br/>` becomes a line break).
pub(crate) fn decode_content(w: &mut Writer, xml: &str, range: Range<usize>) {
    let end = range.end.min(xml.len());
    let mut i = range.start;
    while i < end {
        let Some(rest) = xml.get(i..end) else { break };
        if let Some(body) = rest.strip_prefix("<![CDATA[") {
            let n = body.find("]]>").unwrap_or(body.len());
            w.copy(&body[..n], i + 9);
            i += 9 + n + 3;
        } else if rest.starts_with("<!--") {
            i += rest.find("-->").map_or(rest.len(), |k| k + 3);
        } else if rest.starts_with("<?") {
            i += rest.find("?>").map_or(rest.len(), |k| k + 2);
        } else if rest.starts_with('<') {
            let n = tag_len(rest);
            let tag = &rest[..n];
            let name = tag
                .trim_start_matches(['<', '/'])
                .split(|c: char| c.is_whitespace() || c == '/' || c == '>')
                .next()
                .unwrap_or("");
            let local = name.rsplit(':').next().unwrap_or(name);
            let closing = tag.starts_with("</");
            if (closing && matches!(local, "p" | "div")) || local == "br" {
                w.gen_at("\n", i..i + n);
            }
            i += n;
        } else if rest.starts_with('&') {
            let n = rest.find(';').map_or(rest.len(), |k| k + 1);
            match decode_entity(&rest[..n]) {
                Some(c) => w.gen_at(c.encode_utf8(&mut [0; 4]), i..i + n),
                None => w.copy(&rest[..n], i),
            }
            i += n;
        } else {
            let n = rest.find(['<', '&']).unwrap_or(rest.len());
            w.copy(&rest[..n], i);
            i += n;
        }
    }
}

/// Length of the tag at the start of `s` (to its `>`, outside quotes).
fn tag_len(s: &str) -> usize {
    let mut quote = None;
    for (k, c) in s.char_indices() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '"' || c == '\'' => quote = Some(c),
            None if c == '>' => return k + 1,
            None => {}
        }
    }
    s.len()
}

/// `&lt;` → `<`, `&#65;` → `A`, `&#x41;` → `A`.
fn decode_entity(e: &str) -> Option<char> {
    let name = e.strip_prefix('&')?.strip_suffix(';')?;
    match name {
        "lt" => Some('<'),
        "gt" => Some('>'),
        "amp" => Some('&'),
        "quot" => Some('"'),
        "apos" => Some('\''),
        _ => {
            let n = name.strip_prefix('#')?;
            let v = match n.strip_prefix('x').or_else(|| n.strip_prefix('X')) {
                Some(h) => u32::from_str_radix(h, 16).ok()?,
                None => n.parse().ok()?,
            };
            char::from_u32(v)
        }
    }
}

/// Append an attribute's value (the raw text at `raw`, whose decoded value is
/// `value`): copied when it needs no decoding, else decoded as a whole.
pub(crate) fn attr_into(w: &mut Writer, xml: &str, raw: Range<usize>, value: &str) {
    if xml.get(raw.clone()) == Some(value) {
        w.copy(value, raw.start);
    } else {
        w.gen_at(value, raw);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(xml: &str) -> (String, super::super::map::SpanMap) {
        let mut w = Writer::default();
        let el = 0..xml.len();
        decode_content(&mut w, xml, content_range(xml, el));
        w.finish()
    }

    #[test]
    fn cdata_and_escaped_text_decode_the_same() {
        let a = decode("<IL><xhtml:p><![CDATA[LD a\nLT b\n]]></xhtml:p></IL>").0;
        let b = decode("<IL><xhtml:p>LD a\nLT&#32;b&#x0A;</xhtml:p></IL>").0;
        assert_eq!(a, "LD a\nLT b\n\n");
        assert_eq!(b, "LD a\nLT b\n\n");
        let c = decode("<IL><p>x &lt; y &amp;&gt;<!-- no --></p></IL>").0;
        assert_eq!(c, "x < y &>\n");
    }

    #[test]
    fn positions_survive_decoding() {
        let xml = "<IL>LD &lt;\nST q</IL>";
        let (text, map) = decode(xml);
        assert_eq!(text, "LD <\nST q");
        let q = text.find('q').unwrap() as u32;
        let at = map.offset_to_xml(q) as usize;
        assert_eq!(&xml[at..at + 1], "q");
        let lt = map.to_xml(crate::ast::Span { lo: 3, hi: 4 });
        assert_eq!(&xml[lt.range()], "&lt;");
    }

    #[test]
    fn ranges_of_elements() {
        let xml = r#"<a x=">"><b/></a>"#;
        assert_eq!(&xml[content_range(xml, 0..xml.len())], "<b/>");
        assert_eq!(&xml[start_tag(xml, 0..xml.len())], r#"<a x=">">"#);
        assert_eq!(content_range(xml, 9..13), 13..13);
        assert_eq!(&xml[start_tag(xml, 9..13)], "<b/>");
    }
}
