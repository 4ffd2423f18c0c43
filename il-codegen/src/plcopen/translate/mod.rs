//! PLCopen TC6 XML → IL text: data types, POUs with IL bodies, configurations.
//! One file per construct: [types], [vars], [pous], [configurations].

mod configurations;
mod pous;
mod types;
mod vars;

use std::collections::HashMap;
use std::ops::Range;

use roxmltree::Node;

use super::codes::{BAD_PROJECT, NOT_IL, NOT_TRANSLATED, UNTRANSLATABLE};
use super::map::{SpanMap, Writer};
use super::text::{attr_into, content_range, decode_content, start_tag};
use super::{PouInfo, language_name};
use crate::ast::Span;
use crate::diag::Diagnostic;

/// What the translation of one document produced.
pub(crate) struct Translation {
    pub text: String,
    pub map: SpanMap,
    pub diags: Vec<Diagnostic>,
    pub pous: Vec<PouInfo>,
}

/// The elementary types as TC6 spells them (elements without content).
const ELEMENTARY: &[(&str, &str)] = &[
    ("BOOL", "BOOL"),
    ("BYTE", "BYTE"),
    ("WORD", "WORD"),
    ("DWORD", "DWORD"),
    ("LWORD", "LWORD"),
    ("SINT", "SINT"),
    ("INT", "INT"),
    ("DINT", "DINT"),
    ("LINT", "LINT"),
    ("USINT", "USINT"),
    ("UINT", "UINT"),
    ("UDINT", "UDINT"),
    ("ULINT", "ULINT"),
    ("REAL", "REAL"),
    ("LREAL", "LREAL"),
    ("TIME", "TIME"),
    ("LTIME", "LTIME"),
    ("DATE", "DATE"),
    ("DT", "DT"),
    ("TOD", "TOD"),
    ("DATE_AND_TIME", "DT"),
    ("TIME_OF_DAY", "TOD"),
    ("CHAR", "CHAR"),
    ("WCHAR", "WCHAR"),
];

const BODY_LANGUAGES: &[&str] = &["IL", "ST", "FBD", "LD", "SFC"];

/// A global variable of some configuration or resource.
struct Global<'a, 'i> {
    constant: bool,
    var: Node<'a, 'i>,
    configuration: String,
}

struct Tr<'a, 'i> {
    xml: &'i str,
    w: Writer,
    diags: Vec<Diagnostic>,
    pous: Vec<PouInfo>,
    /// Globals by lower-case name, for `VAR_EXTERNAL CONSTANT`.
    globals: HashMap<String, Vec<Global<'a, 'i>>>,
}

fn is(n: &Node, name: &str) -> bool {
    n.is_element() && n.tag_name().name() == name
}

fn kids<'a, 'i>(n: Node<'a, 'i>, name: &'static str) -> impl Iterator<Item = Node<'a, 'i>> {
    n.children().filter(move |c| is(c, name))
}

fn kid<'a, 'i>(n: Node<'a, 'i>, name: &'static str) -> Option<Node<'a, 'i>> {
    kids(n, name).next()
}

fn first_element<'a, 'i>(n: Node<'a, 'i>) -> Option<Node<'a, 'i>> {
    n.children()
        .find(|c| c.is_element() && !is(c, "documentation") && !is(c, "addData"))
}

fn flag(n: Node, name: &str) -> bool {
    matches!(n.attribute(name), Some("true" | "1"))
}

pub(crate) fn translate(doc: &roxmltree::Document, xml: &str) -> Translation {
    let mut t = Tr {
        xml,
        w: Writer::default(),
        diags: Vec::new(),
        pous: Vec::new(),
        globals: HashMap::new(),
    };
    let root = doc.root_element();
    if root.tag_name().name() != "project" {
        let at = t.tag(root);
        t.diags.push(
            Diagnostic::error(
                BAD_PROJECT,
                at,
                format!(
                    "this is not a PLCopen TC6 project: the root element is `<{}>`, not `<project>`",
                    root.tag_name().name()
                ),
            )
            .with_label("expected `<project>`"),
        );
        return t.finish();
    }
    let types = kid(root, "types");
    let configurations: Vec<Node> = kids(root, "instances")
        .flat_map(|i| kids(i, "configurations"))
        .flat_map(|c| kids(c, "configuration"))
        .collect();
    t.collect_globals(&configurations);
    if let Some(dt) = types.and_then(|ty| kid(ty, "dataTypes")) {
        t.data_types(dt);
    }
    let pous: Vec<Node> = types
        .into_iter()
        .flat_map(|ty| kids(ty, "pous"))
        .flat_map(|p| kids(p, "pou"))
        .collect();
    for p in pous {
        t.pou(p);
    }
    for c in configurations {
        t.configuration(c);
    }
    t.finish()
}

impl<'a, 'i> Tr<'a, 'i> {
    fn finish(self) -> Translation {
        let (text, map) = self.w.finish();
        Translation {
            text,
            map,
            diags: self.diags,
            pous: self.pous,
        }
    }

    fn span(&self, r: Range<usize>) -> Span {
        Span::new(r.start, r.end)
    }

    /// The span of an element's start tag.
    fn tag(&self, n: Node) -> Span {
        self.span(self.tag_range(n))
    }

    fn tag_range(&self, n: Node) -> Range<usize> {
        start_tag(self.xml, n.range())
    }

    /// The span of an attribute's value, or of the element's start tag.
    fn attr_span(&self, n: Node, name: &str) -> Span {
        match n.attributes().find(|a| a.name() == name) {
            Some(a) => self.span(a.range_value()),
            None => self.tag(n),
        }
    }

    /// Generated text standing for element `n`.
    fn put(&mut self, s: &str, n: Node) {
        let at = self.tag_range(n);
        self.w.gen_at(s, at);
    }

    /// Write attribute `name` of `n`; report and return false when missing.
    fn attr(&mut self, n: Node, name: &str) -> bool {
        match n.attributes().find(|a| a.name() == name) {
            Some(a) => {
                attr_into(&mut self.w, self.xml, a.range_value(), a.value());
                true
            }
            None => {
                let at = self.tag(n);
                self.diags.push(
                    Diagnostic::error(
                        BAD_PROJECT,
                        at,
                        format!("`<{}>` has no `{name}` attribute", n.tag_name().name()),
                    )
                    .with_label(format!("`{name}` missing")),
                );
                false
            }
        }
    }

    fn collect_globals(&mut self, configurations: &[Node<'a, 'i>]) {
        for c in configurations {
            let cname = c.attribute("name").unwrap_or("").to_string();
            let blocks = kids(*c, "globalVars")
                .chain(kids(*c, "resource").flat_map(|r| kids(r, "globalVars")));
            for b in blocks {
                let constant = flag(b, "constant");
                for v in kids(b, "variable") {
                    if let Some(name) = v.attribute("name") {
                        self.globals
                            .entry(name.to_ascii_lowercase())
                            .or_default()
                            .push(Global {
                                constant,
                                var: v,
                                configuration: cname.clone(),
                            });
                    }
                }
            }
        }
    }

    fn missing(&mut self, n: Node, child: &str) -> bool {
        let at = self.tag(n);
        self.diags.push(
            Diagnostic::error(
                BAD_PROJECT,
                at,
                format!("`<{}>` has no `<{child}>`", n.tag_name().name()),
            )
            .with_label(format!("`<{child}>` missing")),
        );
        false
    }

    fn untranslatable(&mut self, n: Node, msg: &str) -> bool {
        let at = self.tag(n);
        self.diags
            .push(Diagnostic::error(UNTRANSLATABLE, at, msg).with_label("here"));
        false
    }
}
