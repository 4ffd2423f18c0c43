//! PLCopen TC6 XML → IL text: data types, POUs with IL bodies, configurations.

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

    // ---- types ----------------------------------------------------------

    /// Write the type held by `holder` (`<type>`, `<baseType>`, `<returnType>`).
    fn ty(&mut self, holder: Node) -> bool {
        let Some(t) = first_element(holder) else {
            let at = self.tag(holder);
            self.diags.push(
                Diagnostic::error(
                    BAD_PROJECT,
                    at,
                    format!("`<{}>` names no type", holder.tag_name().name()),
                )
                .with_label("empty type"),
            );
            return false;
        };
        let name = t.tag_name().name();
        if let Some((_, il)) = ELEMENTARY.iter().find(|(x, _)| *x == name) {
            self.put(il, t);
            return true;
        }
        match name {
            "string" | "wstring" => {
                self.put(
                    if name == "string" {
                        "STRING"
                    } else {
                        "WSTRING"
                    },
                    t,
                );
                if t.attribute("length").is_some() {
                    self.put("[", t);
                    self.attr(t, "length");
                    self.put("]", t);
                }
                true
            }
            "derived" => self.attr(t, "name"),
            "array" => {
                self.put("ARRAY [", t);
                let mut ok = true;
                for (k, d) in kids(t, "dimension").enumerate() {
                    if k > 0 {
                        self.put(", ", d);
                    }
                    ok &= self.attr(d, "lower");
                    self.put("..", d);
                    ok &= self.attr(d, "upper");
                }
                self.put("] OF ", t);
                match kid(t, "baseType") {
                    Some(b) => ok && self.ty(b),
                    None => self.missing(t, "baseType"),
                }
            }
            "subrangeSigned" | "subrangeUnsigned" => {
                let ok = match kid(t, "baseType") {
                    Some(b) => self.ty(b),
                    None => self.missing(t, "baseType"),
                };
                let Some(r) = kid(t, "range") else {
                    return self.missing(t, "range");
                };
                self.put(" (", r);
                let lo = self.attr(r, "lower");
                self.put("..", r);
                let hi = self.attr(r, "upper");
                self.put(")", r);
                ok && lo && hi
            }
            "enum" => {
                self.put("(", t);
                let values: Vec<Node> = kids(t, "values").flat_map(|v| kids(v, "value")).collect();
                let mut ok = !values.is_empty();
                for (k, v) in values.iter().enumerate() {
                    if k > 0 {
                        self.put(", ", *v);
                    }
                    ok &= self.attr(*v, "name");
                    if v.attribute("value").is_some() {
                        self.put(" := ", *v);
                        self.attr(*v, "value");
                    }
                }
                self.put(")", t);
                if values.is_empty() {
                    let at = self.tag(t);
                    self.diags.push(
                        Diagnostic::error(BAD_PROJECT, at, "an enumeration without values")
                            .with_label("no `<value>`"),
                    );
                }
                ok
            }
            "struct" => {
                self.put("\n    STRUCT\n", t);
                let mut ok = true;
                for v in kids(t, "variable") {
                    ok &= self.var_decl(v, None);
                }
                self.put("    END_STRUCT", t);
                ok
            }
            "pointer" => self.untranslatable(
                t,
                "pointer types cannot be translated: IEC 61131-3 IL has no pointers",
            ),
            other => {
                let msg = format!("the type `<{other}>` cannot be translated");
                self.untranslatable(t, &msg)
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

    fn data_types(&mut self, dts: Node) {
        let types: Vec<Node> = kids(dts, "dataType").collect();
        if types.is_empty() {
            return;
        }
        self.put("TYPE\n", dts);
        for d in types {
            self.put("  ", d);
            self.attr(d, "name");
            self.put(" : ", d);
            match kid(d, "baseType") {
                Some(b) => {
                    self.ty(b);
                }
                None => {
                    self.missing(d, "baseType");
                }
            }
            if let Some(iv) = kid(d, "initialValue") {
                self.put(" := ", iv);
                self.value(iv);
            }
            self.put(";\n", d);
        }
        self.put("END_TYPE\n\n", dts);
    }

    // ---- values and declarations ------------------------------------------

    /// Write the value held by `holder` (`<initialValue>` or an array's or
    /// structure's `<value>`).
    fn value(&mut self, holder: Node) -> bool {
        let Some(v) = first_element(holder) else {
            return self.missing(holder, "simpleValue");
        };
        match v.tag_name().name() {
            "simpleValue" => self.attr(v, "value"),
            "arrayValue" => {
                self.put("[", v);
                let mut ok = true;
                for (k, e) in kids(v, "value").enumerate() {
                    if k > 0 {
                        self.put(", ", e);
                    }
                    if e.attribute("repetitionValue").is_some() {
                        self.attr(e, "repetitionValue");
                        self.put("(", e);
                        ok &= self.value(e);
                        self.put(")", e);
                    } else {
                        ok &= self.value(e);
                    }
                }
                self.put("]", v);
                ok
            }
            "structValue" => {
                self.put("(", v);
                let mut ok = true;
                for (k, e) in kids(v, "value").enumerate() {
                    if k > 0 {
                        self.put(", ", e);
                    }
                    ok &= self.attr(e, "member");
                    self.put(" := ", e);
                    ok &= self.value(e);
                }
                self.put(")", v);
                ok
            }
            other => {
                let msg = format!("the initial value `<{other}>` cannot be translated");
                self.untranslatable(v, &msg)
            }
        }
    }

    /// `name AT %IX0.0 : TYPE := value;` — `init` replaces the variable's
    /// own initial value (for a lowered external constant).
    fn var_decl(&mut self, v: Node, init: Option<Node>) -> bool {
        self.put("    ", v);
        let mut ok = self.attr(v, "name");
        if v.attribute("address").is_some() {
            self.put(" AT ", v);
            self.attr(v, "address");
        }
        self.put(" : ", v);
        ok &= match kid(v, "type") {
            Some(t) => self.ty(t),
            None => self.missing(v, "type"),
        };
        if let Some(iv) = init.or_else(|| kid(v, "initialValue")) {
            self.put(" := ", iv);
            ok &= self.value(iv);
        }
        self.put(";\n", v);
        ok
    }

    fn var_block(&mut self, b: Node, keyword: &str, constant: bool, vars: &[(Node, Option<Node>)]) {
        if vars.is_empty() {
            return;
        }
        self.put(keyword, b);
        if constant {
            self.put(" CONSTANT", b);
        }
        if flag(b, "retain") {
            self.put(" RETAIN", b);
        }
        if flag(b, "nonretain") {
            self.put(" NON_RETAIN", b);
        }
        self.put("\n", b);
        for (v, init) in vars {
            self.var_decl(*v, *init);
        }
        self.put("END_VAR\n", b);
    }

    /// A variable block of an interface or a configuration.
    fn block(&mut self, b: Node) {
        let keyword = match b.tag_name().name() {
            "inputVars" => "VAR_INPUT",
            "outputVars" => "VAR_OUTPUT",
            "inOutVars" => "VAR_IN_OUT",
            "localVars" => "VAR",
            "tempVars" => "VAR_TEMP",
            "externalVars" => "VAR_EXTERNAL",
            "globalVars" => "VAR_GLOBAL",
            "returnType" | "documentation" | "addData" => return,
            other => {
                let at = self.tag(b);
                self.diags.push(
                    Diagnostic::warning(
                        NOT_TRANSLATED,
                        at,
                        format!("`<{other}>` is not translated"),
                    )
                    .with_label("skipped"),
                );
                return;
            }
        };
        let constant = flag(b, "constant");
        let vars: Vec<Node> = kids(b, "variable").collect();
        if keyword != "VAR_EXTERNAL" || !constant {
            let vars: Vec<_> = vars.into_iter().map(|v| (v, None)).collect();
            self.var_block(b, keyword, constant, &vars);
            return;
        }
        // VAR_EXTERNAL CONSTANT naming exactly one VAR_GLOBAL CONSTANT of the
        // project: a local constant with the global's value (the same thing,
        // since neither can change).
        let mut lowered = Vec::new();
        let mut kept = Vec::new();
        for v in vars {
            let key = v.attribute("name").unwrap_or("").to_ascii_lowercase();
            match self.globals.get(&key).map(Vec::as_slice) {
                Some([g]) if g.constant => {
                    lowered.push((v, kid(g.var, "initialValue"), g.configuration.clone()))
                }
                _ => kept.push((v, None)),
            }
        }
        if !lowered.is_empty() {
            let configs: Vec<&str> = lowered.iter().map(|(_, _, c)| c.as_str()).collect();
            let mut configs = configs;
            configs.dedup();
            self.put(
                &format!(
                    "(* VAR_EXTERNAL CONSTANT: the values of VAR_GLOBAL CONSTANT of CONFIGURATION {} *)\n",
                    configs.join(", ")
                ),
                b,
            );
            let vars: Vec<_> = lowered.iter().map(|(v, i, _)| (*v, *i)).collect();
            self.var_block(b, "VAR", true, &vars);
        }
        self.var_block(b, "VAR_EXTERNAL", true, &kept);
    }

    // ---- POUs -------------------------------------------------------------

    fn pou(&mut self, p: Node) {
        let name = p.attribute("name").unwrap_or("").to_string();
        let name_span = self.attr_span(p, "name");
        let keyword = match p.attribute("pouType") {
            Some("program") => "PROGRAM",
            Some("functionBlock") => "FUNCTION_BLOCK",
            Some("function") => "FUNCTION",
            other => {
                let what =
                    other.map_or("no `pouType`".to_string(), |o| format!("`pouType=\"{o}\"`"));
                self.diags.push(
                    Diagnostic::error(
                        BAD_PROJECT,
                        self.attr_span(p, "pouType"),
                        format!(
                            "POU `{name}` has {what}: expected program, functionBlock or function"
                        ),
                    )
                    .with_label("unknown POU type"),
                );
                return;
            }
        };
        let body = kid(p, "body");
        let lang = body.and_then(|b| {
            b.children()
                .find(|c| c.is_element() && BODY_LANGUAGES.contains(&c.tag_name().name()))
        });
        let Some(lang) = lang else {
            self.diags.push(
                Diagnostic::error(
                    BAD_PROJECT,
                    name_span,
                    format!("POU `{name}` has no body in IL, ST, FBD, LD or SFC"),
                )
                .with_label("no `<body>`"),
            );
            return;
        };
        let language = lang.tag_name().name().to_string();
        if name.is_empty() {
            self.attr(p, "name");
            return;
        }
        if language != "IL" {
            self.diags.push(
                Diagnostic::warning(
                    NOT_IL,
                    name_span,
                    format!(
                        "POU `{name}` is not translated: its body is {} ({language}); only IL bodies are",
                        language_name(&language)
                    ),
                )
                .with_label(format!("{language} body"))
                .with_secondary(self.tag(lang), format!("the {language} body")),
            );
            self.pous.push(PouInfo {
                name,
                kind: keyword,
                language,
                translated: false,
            });
            return;
        }
        for extra in ["actions", "transitions"] {
            if let Some(a) = kid(p, extra).filter(|a| a.children().any(|c| c.is_element())) {
                let at = self.tag(a);
                self.diags.push(
                    Diagnostic::warning(
                        NOT_TRANSLATED,
                        at,
                        format!("the {extra} of POU `{name}` are not translated"),
                    )
                    .with_label("skipped"),
                );
            }
        }
        self.put(keyword, p);
        self.put(" ", p);
        self.attr(p, "name");
        let iface = kid(p, "interface");
        if keyword == "FUNCTION" {
            match iface.and_then(|i| kid(i, "returnType")) {
                Some(r) => {
                    self.put(" : ", r);
                    self.ty(r);
                }
                None => {
                    self.diags.push(
                        Diagnostic::error(
                            BAD_PROJECT,
                            name_span,
                            format!("FUNCTION `{name}` has no `<returnType>`"),
                        )
                        .with_label("no result type"),
                    );
                }
            }
        }
        self.put("\n", p);
        if let Some(i) = iface {
            for b in i.children().filter(|c| c.is_element()) {
                self.block(b);
            }
        }
        // The body starts on a line of its own, so its lines stay whole.
        self.put("\n", lang);
        decode_content(&mut self.w, self.xml, content_range(self.xml, lang.range()));
        let end = lang.range().end;
        let end_tag = self
            .xml
            .get(..end)
            .and_then(|s| s.rfind("</"))
            .unwrap_or(lang.range().start);
        self.w.gen_at(&format!("\nEND_{keyword}\n\n"), end_tag..end);
        self.pous.push(PouInfo {
            name,
            kind: keyword,
            language,
            translated: true,
        });
    }

    // ---- configurations ---------------------------------------------------

    fn configuration(&mut self, c: Node) {
        let name = c.attribute("name").unwrap_or("").to_string();
        let resources: Vec<Node> = kids(c, "resource").collect();
        // Program instances of POUs that were not translated: the
        // configuration cannot be compiled, say so once.
        for r in &resources {
            let instances = kids(*r, "pouInstance")
                .chain(kids(*r, "task").flat_map(|t| kids(t, "pouInstance")));
            for i in instances {
                let ty = i.attribute("typeName").unwrap_or("");
                if let Some(p) = self
                    .pous
                    .iter()
                    .find(|p| !p.translated && p.name.eq_ignore_ascii_case(ty))
                {
                    let msg = format!(
                        "CONFIGURATION `{name}` is not translated: its instance `{}` runs POU `{}`, whose body is {} ({})",
                        i.attribute("name").unwrap_or(""),
                        p.name,
                        language_name(&p.language),
                        p.language
                    );
                    let at = self.attr_span(i, "typeName");
                    let cfg = self.attr_span(c, "name");
                    self.diags.push(
                        Diagnostic::warning(NOT_TRANSLATED, cfg, msg)
                            .with_label("skipped")
                            .with_secondary(at, "this POU is not translated"),
                    );
                    return;
                }
            }
        }
        for extra in kids(c, "accessVars").chain(kids(c, "configVars")) {
            let at = self.tag(extra);
            self.diags.push(
                Diagnostic::warning(
                    NOT_TRANSLATED,
                    at,
                    format!(
                        "`<{}>` of CONFIGURATION `{name}` is not translated",
                        extra.tag_name().name()
                    ),
                )
                .with_label("skipped"),
            );
        }
        self.put("CONFIGURATION ", c);
        self.attr(c, "name");
        self.put("\n", c);
        for b in kids(c, "globalVars") {
            self.block(b);
        }
        for r in resources {
            self.put("RESOURCE ", r);
            self.attr(r, "name");
            self.put(" ON PLC\n", r);
            for b in kids(r, "globalVars") {
                self.block(b);
            }
            let tasks: Vec<Node> = kids(r, "task").collect();
            for t in &tasks {
                self.put("    TASK ", *t);
                self.attr(*t, "name");
                self.put(" (", *t);
                let mut first = true;
                for (attr, param) in [
                    ("single", "SINGLE"),
                    ("interval", "INTERVAL"),
                    ("priority", "PRIORITY"),
                ] {
                    if t.attribute(attr).is_some() {
                        if !first {
                            self.put(", ", *t);
                        }
                        first = false;
                        self.put(&format!("{param} := "), *t);
                        self.attr(*t, attr);
                    }
                }
                if first {
                    // TC6 requires a priority; IL needs at least one parameter.
                    self.put("PRIORITY := 0", *t);
                }
                self.put(");\n", *t);
            }
            for t in &tasks {
                for i in kids(*t, "pouInstance") {
                    self.program_instance(i, Some(*t));
                }
            }
            for i in kids(r, "pouInstance") {
                self.program_instance(i, None);
            }
            self.put("END_RESOURCE\n", r);
        }
        self.put("END_CONFIGURATION\n\n", c);
    }

    fn program_instance(&mut self, i: Node, task: Option<Node>) {
        self.put("    PROGRAM ", i);
        self.attr(i, "name");
        if let Some(t) = task {
            self.put(" WITH ", i);
            self.attr(t, "name");
        }
        self.put(" : ", i);
        self.attr(i, "typeName");
        self.put(";\n", i);
    }
}
