//! Limits checked on the raw XML before roxmltree parses it, in one linear
//! pass: roxmltree compares every attribute of an element with every other
//! (duplicate check) and copies the namespaces in scope into each element
//! that declares one, so an element with 30,000 attributes, or 20,000 nested
//! elements each declaring a namespace, costs quadratic time. No PLCopen
//! file comes near either limit.

use std::ops::Range;

/// Attributes of one element, at most.
pub(crate) const MAX_ATTRIBUTES: usize = 128;
/// Namespace declarations (`xmlns`, `xmlns:p`) in scope at once, at most.
pub(crate) const MAX_NAMESPACES: usize = 64;

/// A limit the XML exceeds: where, and what.
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct Exceeded {
    pub at: Range<usize>,
    pub message: String,
    pub label: &'static str,
}

/// Scan `xml` for an element with too many attributes or too many
/// namespaces in scope. Markup that is not well-formed ends the scan
/// (`None`): roxmltree reports it properly.
pub(crate) fn check(xml: &str) -> Option<Exceeded> {
    let b = xml.as_bytes();
    // Namespace declarations of each open element, and their sum.
    let mut open: Vec<u8> = Vec::new();
    let mut in_scope = 0usize;
    let mut i = 0;
    loop {
        i += xml.get(i..)?.find('<')?;
        let rest = &xml[i..];
        let skip_to =
            |end: &str, from: usize| rest[from..].find(end).map(|k| i + from + k + end.len());
        if rest.starts_with("<!--") {
            i = skip_to("-->", 4)?;
        } else if rest.starts_with("<![CDATA[") {
            i = skip_to("]]>", 9)?;
        } else if rest.starts_with("<?") {
            i = skip_to("?>", 2)?;
        } else if rest.starts_with("<!") || rest.starts_with("</") {
            if rest.starts_with("</") {
                in_scope -= usize::from(open.pop().unwrap_or(0));
            }
            i = skip_to(">", 1)?;
        } else {
            // A start tag: its name, then `name = "value"` pairs (each
            // counted, for the scaling tests).
            let tag = i;
            let mut j = i + 1;
            while j < b.len() && !b[j].is_ascii_whitespace() && b[j] != b'>' && b[j] != b'/' {
                j += 1;
            }
            let name_end = j;
            let (mut attrs, mut ns) = (0usize, 0usize);
            loop {
                while j < b.len() && b[j].is_ascii_whitespace() {
                    j += 1;
                }
                match b.get(j)? {
                    b'>' => {
                        open.push(u8::try_from(ns).ok()?);
                        i = j + 1;
                        break;
                    }
                    b'/' => {
                        in_scope -= ns;
                        i = j + 1;
                        break;
                    }
                    _ => {}
                }
                let an = j;
                while j < b.len() && !b[j].is_ascii_whitespace() && b[j] != b'=' {
                    j += 1;
                }
                let attr_name = &xml[an..j];
                while j < b.len() && b[j].is_ascii_whitespace() {
                    j += 1;
                }
                if b.get(j) != Some(&b'=') {
                    return None;
                }
                j += 1;
                while j < b.len() && b[j].is_ascii_whitespace() {
                    j += 1;
                }
                let q = *b.get(j)?;
                if q != b'"' && q != b'\'' {
                    return None;
                }
                j += 1 + xml[j + 1..].find(char::from(q))? + 1;
                attrs += 1;
                crate::step_counter::add(1);
                if attrs > MAX_ATTRIBUTES {
                    return Some(Exceeded {
                        at: tag..name_end,
                        message: format!(
                            "`{}` has more than {MAX_ATTRIBUTES} attributes",
                            &xml[tag..name_end]
                        ),
                        label: "too many attributes",
                    });
                }
                if attr_name == "xmlns" || attr_name.starts_with("xmlns:") {
                    ns += 1;
                    in_scope += 1;
                    if in_scope > MAX_NAMESPACES {
                        return Some(Exceeded {
                            at: an..j,
                            message: format!(
                                "more than {MAX_NAMESPACES} namespace declarations are in scope here"
                            ),
                            label: "too many namespaces",
                        });
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_attributes_and_namespaces_in_scope() {
        let many = |n: usize| (0..n).map(|k| format!(" a{k}='1'")).collect::<String>();
        let ok = format!(
            "<a{}><!-- <b {} --><c x=\">\"/></a>",
            many(MAX_ATTRIBUTES),
            many(999)
        );
        assert_eq!(check(&ok), None);
        let bad = format!("<a>\n<b{}/></a>", many(MAX_ATTRIBUTES + 1));
        let e = check(&bad).expect("too many");
        assert_eq!(&bad[e.at], "<b");
        // Namespaces: siblings release theirs, nesting accumulates.
        let ns = |k: usize| format!("<e xmlns:p{k}='u'>");
        let siblings: String = (0..1000).map(|k| ns(k) + "</e>").collect();
        assert_eq!(check(&format!("<r>{siblings}</r>")), None);
        let nested: String = (0..=MAX_NAMESPACES).map(ns).collect();
        let e = check(&nested).expect("too many namespaces");
        assert!(nested[e.at].starts_with(&format!("xmlns:p{MAX_NAMESPACES}=")));
        // Not well-formed: left to the parser.
        assert_eq!(check("<a b=c>"), None);
        assert_eq!(check("<a b='1"), None);
    }
}
