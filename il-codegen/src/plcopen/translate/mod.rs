//! PLCopen TC6 XML → IL text: data types, POUs with IL bodies, configurations.
//! One file per construct: [types], [vars], [pous], [configurations].

mod configurations;
mod pous;
mod types;
mod vars;

pub(crate) use pous::escape;

use std::collections::HashMap;
use std::ops::Range;

use roxmltree::Node;

use super::codes::{
    BAD_ATTRIBUTE, BAD_PROJECT, BODY_ESCAPES, NOT_IL, NOT_TRANSLATED, TOO_DEEP, UNTRANSLATABLE,
};
use super::map::{SpanMap, Writer};
use super::text::{attr_into, content_range, decode_content, start_tag};
use super::validate::{self, Kind, shown};
use super::{LeftOut, PouInfo, language_name};
use crate::ast::Span;
use crate::diag::Diagnostic;
use crate::syntax::lexer::{self, Tok};

/// What the translation of one document produced.
pub(crate) struct Translation {
    pub text: String,
    pub map: SpanMap,
    pub diags: Vec<Diagnostic>,
    pub pous: Vec<PouInfo>,
    /// XML ranges of elements in a folder of the project's tree, with the
    /// folder's path (LogicLab's workspace; PLCopen has none).
    pub folders: Vec<(Range<usize>, String)>,
    /// Globals that POUs see without VAR_EXTERNAL (LogicLab's), upper case.
    pub globals: std::collections::HashSet<String>,
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

/// Types and values nest at most this deep in the XML (`<array>` in
/// `<array>`, `<arrayValue>` in `<arrayValue>` ...): the translation recurses
/// once per level, and no real project comes near.
pub(crate) const MAX_DEPTH: usize = 64;

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
    /// POUs left out (not IL), so that program instances find theirs
    /// without a scan per instance.
    left_out: LeftOut,
}

use super::nodes::{is, kid, kids};

fn first_element<'a, 'i>(n: Node<'a, 'i>) -> Option<Node<'a, 'i>> {
    n.children().find(|c| {
        crate::step_counter::add(1);
        c.is_element() && !is(c, "documentation") && !is(c, "addData")
    })
}

/// PLCopen's `<project>`: in a namespace of plcopen.org (`tc6_0200`,
/// `tc6_0201` ...) or in none (hand-written and older exports). Another
/// schema's `<project>` (a Maven POM) would otherwise import as an empty
/// program without a word.
fn is_plcopen_root(root: Node) -> bool {
    let tag = root.tag_name();
    tag.name() == "project"
        && tag
            .namespace()
            .is_none_or(|ns| ns.to_ascii_lowercase().contains("plcopen.org"))
}

/// The one error for XML that is not a PLCopen project (a SoMachine Basic
/// `.smbp`, a TwinCAT `.TcPOU` ...): its root, and what is read instead.
fn not_plcopen(root: Node, at: Span) -> Diagnostic {
    let tag = root.tag_name();
    let ns = match tag.namespace() {
        Some(ns) => format!(" in namespace `{}`", shown(ns)),
        None => " (no namespace)".to_string(),
    };
    Diagnostic::error(
        BAD_PROJECT,
        at,
        format!(
            "this XML is not a PLCopen TC6 project: its root element is `<{}>`{ns}, not PLCopen's `<project>`",
            shown(tag.name())
        ),
    )
    .with_label("not PLCopen's `<project>`")
    .with_note(
        "the IL compiler reads IL source text, PLCopen TC6 XML projects \
         (`<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">`, as Beremiz, OpenPLC and CODESYS export them) \
         LogicLab / Arduino PLC IDE projects (`<plcProject>`, `.plcprj`) \
         and Modicon M221 projects (`<ProjectDescriptor>`, `.smbp`); \
         a file whose text starts with `<` is read as XML whatever its name",
    )
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
        left_out: LeftOut::default(),
    };
    let root = doc.root_element();
    // An Axel LogicLab / Arduino PLC IDE project or library: its own
    // schema, its own translation (same parser, limits and map).
    if crate::logiclab::is_root(root) {
        return crate::logiclab::translate(doc, xml);
    }
    // A Modicon M221 project (Machine Expert Basic `.smbp`): its rungs'
    // Instruction List, translated to IEC IL.
    if crate::m221::is_root(root) {
        return crate::m221::translate(doc, xml);
    }
    if !is_plcopen_root(root) {
        let at = t.tag(root);
        t.diags.push(not_plcopen(root, at));
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
    fn finish(mut self) -> Translation {
        // A global constant's value is written (and checked) once per
        // VAR_EXTERNAL that takes it: report each problem once.
        let mut seen = std::collections::HashSet::new();
        self.diags
            .retain(|d| seen.insert((d.code, d.span.lo, d.span.hi, d.message.clone())));
        let (text, map) = self.w.finish();
        Translation {
            text,
            map,
            diags: self.diags,
            pous: self.pous,
            folders: Vec::new(),
            globals: Default::default(),
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

    /// Attribute `name` of `n` when it holds a `kind`; reported (and `None`)
    /// when it is missing or holds anything else.
    fn checked<'n, 'x>(
        &mut self,
        n: Node<'n, 'x>,
        name: &str,
        kind: Kind,
    ) -> Option<roxmltree::Attribute<'n, 'x>> {
        crate::step_counter::add(1);
        let Some(a) = n.attributes().find(|a| a.name() == name) else {
            let at = self.tag(n);
            self.diags.push(
                Diagnostic::error(
                    BAD_PROJECT,
                    at,
                    format!("`<{}>` has no `{name}` attribute", n.tag_name().name()),
                )
                .with_label(format!("`{name}` missing")),
            );
            return None;
        };
        if let Err(why) = validate::check(kind, a.value()) {
            // An empty value has an empty range: point at `name=""` instead.
            let at = if a.value().is_empty() {
                a.range()
            } else {
                a.range_value()
            };
            self.diags.push(
                Diagnostic::error(
                    BAD_ATTRIBUTE,
                    self.span(at),
                    format!(
                        "`{name}=\"{}\"` of `<{}>` is not {}: {why}",
                        shown(a.value()),
                        n.tag_name().name(),
                        kind.what()
                    ),
                )
                .with_label(format!("expected {}", kind.what()))
                .with_note(
                    "the variable, type, POU, task or configuration it belongs to is left out",
                ),
            );
            return None;
        }
        Some(a)
    }

    /// Write attribute `name` of `n` when it holds a `kind`; report and
    /// return false (writing nothing) when it is missing or holds anything
    /// else.
    fn attr(&mut self, n: Node, name: &str, kind: Kind) -> bool {
        let Some(a) = self.checked(n, name, kind) else {
            return false;
        };
        attr_into(&mut self.w, self.xml, a.range_value(), a.value());
        true
    }

    /// Whether attribute `name` of `n` holds a `kind` (no report).
    fn attr_ok(n: Node, name: &str, kind: Kind) -> bool {
        n.attribute(name)
            .is_some_and(|v| validate::check(kind, v).is_ok())
    }

    /// Report `n` as nested deeper than [`MAX_DEPTH`] and return false.
    fn too_deep(&mut self, n: Node) -> bool {
        let at = self.tag(n);
        self.diags.push(
            Diagnostic::error(
                TOO_DEEP,
                at,
                format!(
                    "`<{}>` is nested more than {MAX_DEPTH} levels deep",
                    n.tag_name().name()
                ),
            )
            .with_label("too deep"),
        );
        false
    }

    fn collect_globals(&mut self, configurations: &[Node<'a, 'i>]) {
        for c in configurations {
            // Only names that are identifiers: the configuration's name is
            // written into a comment, and a variable's is looked up by name.
            let Some(cname) = c
                .attribute("name")
                .filter(|_| Self::attr_ok(*c, "name", Kind::Name))
            else {
                continue;
            };
            let blocks = kids(*c, "globalVars")
                .chain(kids(*c, "resource").flat_map(|r| kids(r, "globalVars")));
            for b in blocks {
                let constant = flag(b, "constant");
                for v in kids(b, "variable") {
                    if let Some(name) = v
                        .attribute("name")
                        .filter(|_| Self::attr_ok(v, "name", Kind::Name))
                    {
                        self.globals
                            .entry(name.to_ascii_lowercase())
                            .or_default()
                            .push(Global {
                                constant,
                                var: v,
                                configuration: cname.to_string(),
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
