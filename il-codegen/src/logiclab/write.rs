//! The IL text of a LogicLab project: which elements are written (the
//! project's, and what it uses of its libraries), the warnings for what is
//! not compiled as written, and how a POU is written (its variables and
//! the data types: `decls`).

use std::collections::{HashMap, HashSet};

use roxmltree::Node;

use super::codes::{BAD_PROJECT, NOT_IL, STANDARD_NAME};
use super::config::{self, Needs};
use super::lx::{Lx, Selection};
use super::read::{self, Pou, Project, attr_span, is, kid, kids, tag};
use crate::ast::PouKind;
use crate::diag::Diagnostic;
use crate::plcopen::PouInfo;
use crate::plcopen::codes::BODY_ESCAPES;
use crate::plcopen::map::Writer;
use crate::plcopen::text::{attr_into, content_range, decode_content};
use crate::plcopen::translate::{Translation, escape};
use crate::plcopen::validate::{self, Kind, shown};
use crate::syntax::lexer::{self, Tok};

pub(crate) fn translate(doc: &roxmltree::Document, xml: &str) -> Translation {
    let mut diags = Vec::new();
    let p = read::read(doc.root_element(), xml, &mut diags);
    let mut lx = Lx {
        xml,
        w: Writer::default(),
        diags,
        renamed: HashMap::new(),
        lib_renamed: Vec::new(),
    };
    lx.lib_renamed = vec![Vec::new(); p.libs.len()];
    let sel = select(&p, &mut lx);
    lx.renamed_warnings(&p);
    let needs = config::needs(&p, &sel, &mut lx);
    for (k, t) in p.types.iter().enumerate() {
        if sel.types[k] {
            lx.data_type(t.node, t.kind, &t.name);
        }
    }
    lx.not_il_warnings(&p, &sel);
    let mut pous = Vec::new();
    for (k, pou) in p.pous.iter().enumerate() {
        if pou.origin.is_some() && !sel.pous[k] {
            continue;
        }
        let translated = sel.pous[k] && lx.pou(pou, &needs);
        pous.push(PouInfo {
            name: pou.name.clone(),
            kind: pou.kind.keyword(),
            language: pou.lang.clone(),
            translated,
        });
    }
    config::write(&p, &sel, &needs, &mut lx);
    let mut seen = HashSet::new();
    lx.diags
        .retain(|d| seen.insert((d.code, d.span.lo, d.span.hi, d.message.clone())));
    let (text, map) = lx.w.finish();
    // The project's POUs and types in a folder of its tree.
    let mut folders = Vec::new();
    let nodes = (p.pous.iter().map(|x| (x.node, &x.name, x.origin)))
        .chain(p.types.iter().map(|x| (x.node, &x.name, x.origin)));
    for (node, name, origin) in nodes {
        if let (None, Some(f)) = (origin, p.folders.get(&name.to_ascii_uppercase())) {
            folders.push((node.range(), shown(f)));
        }
    }
    // In document order, for the look-up by position.
    folders.sort_by_key(|(r, _): &(std::ops::Range<usize>, String)| r.start);
    let globals = (p.globals.iter().enumerate())
        .filter(|(k, g)| sel.globals[*k] && g.class != read::Class::Constant)
        .map(|(_, g)| g.name.to_ascii_uppercase())
        .collect();
    Translation {
        text,
        map,
        diags: lx.diags,
        pous,
        folders,
        globals,
    }
}

/// An element of the project a name can refer to.
#[derive(Clone, Copy)]
enum Item {
    Pou(usize),
    Type(usize),
    Global(usize),
}

/// The project's own elements, and those of its libraries that they use
/// (by a variable's type, or a name in an IL body), and so on. A POU with
/// the name of a standard function or program is never written; a function
/// block of a standard block's name is, under another name.
fn select(p: &Project, lx: &mut Lx) -> Selection {
    let mut index: HashMap<String, Item> = HashMap::new();
    let items = (p
        .pous
        .iter()
        .enumerate()
        .map(|(k, x)| (&x.name, Item::Pou(k))))
    .chain(
        p.types
            .iter()
            .enumerate()
            .map(|(k, x)| (&x.name, Item::Type(k))),
    )
    .chain(
        p.globals
            .iter()
            .enumerate()
            .map(|(k, x)| (&x.name, Item::Global(k))),
    );
    for (name, item) in items {
        // The first of a name: the project's before its libraries'.
        index.entry(name.to_ascii_uppercase()).or_insert(item);
    }
    let mut sel = Selection {
        pous: vec![false; p.pous.len()],
        types: vec![false; p.types.len()],
        globals: vec![false; p.globals.len()],
        used: vec![HashSet::new(); p.pous.len()],
    };
    let mut queue: Vec<Item> = Vec::new();
    queue.extend(
        (0..p.pous.len())
            .filter(|&k| p.pous[k].origin.is_none())
            .map(Item::Pou),
    );
    queue.extend(
        (0..p.types.len())
            .filter(|&k| p.types[k].origin.is_none())
            .map(Item::Type),
    );
    queue.extend(
        (0..p.globals.len())
            .filter(|&k| p.globals[k].origin.is_none())
            .map(Item::Global),
    );
    while let Some(item) = queue.pop() {
        crate::step_counter::add(1);
        let refs: Vec<String> = match item {
            Item::Pou(k) if !sel.pous[k] => {
                let pou = &p.pous[k];
                if crate::sema::is_standard_pou(&pou.name) {
                    lx.standard_name(p, pou);
                    if pou.kind != PouKind::FunctionBlock {
                        continue;
                    }
                }
                sel.pous[k] = true;
                let mut refs = type_refs(pou.node, pou.lang != "IL");
                if pou.lang == "IL" {
                    sel.used[k] = lx.body_names(pou);
                    refs.extend(sel.used[k].iter().cloned());
                }
                refs
            }
            Item::Type(k) if !sel.types[k] => {
                sel.types[k] = true;
                type_refs(p.types[k].node, false)
            }
            Item::Global(k) if !sel.globals[k] => {
                sel.globals[k] = true;
                type_refs(p.globals[k].node, false)
            }
            _ => continue,
        };
        queue.extend(refs.iter().filter_map(|r| index.get(r).copied()));
    }
    sel
}

/// The type names (upper case) that the written text of an element names:
/// its variables', members' and base type, a FUNCTION's result; of a POU
/// that is not IL, only its interface's (the rest is not written).
fn type_refs(n: Node, interface_only: bool) -> Vec<String> {
    let interface = ["inputVars", "outputVars", "inoutVars"];
    let vars = kids(n, "vars")
        .flat_map(|v| v.children())
        .filter(|b| b.is_element() && (!interface_only || interface.contains(&b.tag_name().name())))
        .flat_map(|b| b.children())
        // A struct's members are right in `<vars>`.
        .chain(kids(n, "vars").flat_map(|v| v.children()));
    vars.chain(std::iter::once(n))
        .filter_map(|d| {
            crate::step_counter::add(1);
            d.attribute("type")
                .filter(|_| d.is_element() && !is(&d, "sourceCode"))
        })
        .map(str::to_ascii_uppercase)
        .chain(
            kid(n, "returnValue")
                .and_then(|r| r.text())
                .map(|t| t.trim().to_ascii_uppercase()),
        )
        .collect()
}

impl Lx<'_> {
    /// A POU with a standard block's or function's name: a function block
    /// is compiled under another name, which the project's variables of
    /// its type take; a function or program is left out (il-std's is used).
    fn standard_name(&mut self, p: &Project, pou: &Pou) {
        let from = match pou.origin {
            Some(l) => format!("of library `{}`", shown(&p.libs[l].0)),
            None => "of this project".to_string(),
        };
        let kind = pou.kind.keyword();
        let name = &pou.name;
        let at = attr_span(self.xml, pou.node, "name");
        let d = if pou.kind == PouKind::FunctionBlock {
            let new = format!("{name}_LogicLab");
            self.renamed.insert(name.to_ascii_uppercase(), new.clone());
            if let Some(l) = pou.origin {
                // Said once for the library (`Standard.plclib` has 16).
                self.lib_renamed[l].push(name.clone());
                return;
            }
            let mut d = Diagnostic::warning(
                STANDARD_NAME,
                at,
                format!(
                    "{kind} `{name}` {from} has the name of a standard function block: compiled as `{new}`, the type of the project's variables of type `{name}`"
                ),
            )
            .with_label(format!("compiled as `{new}`"));
            if ["TON", "TOF", "TP"].contains(&name.to_ascii_uppercase().as_str()) {
                d = d.with_note(TIMERS);
            }
            d
        } else {
            Diagnostic::warning(
                STANDARD_NAME,
                at,
                format!(
                    "{kind} `{name}` {from} has the name of a standard function: il-std's is used instead"
                ),
            )
            .with_label("left out")
        };
        self.diags.push(d);
    }

    /// One warning per library whose blocks of standard names the project
    /// uses (compiled renamed: see `standard_name`).
    fn renamed_warnings(&mut self, p: &Project) {
        for (l, names) in self.lib_renamed.iter().enumerate() {
            if names.is_empty() {
                continue;
            }
            let list: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
            let mut d = Diagnostic::warning(
                STANDARD_NAME,
                tag(self.xml, p.libs[l].1),
                format!(
                    "{} function block(s) of library `{}` that the project uses have standard blocks' names: {}; each is compiled as `NAME_LogicLab`, the type of the project's variables of type `NAME`",
                    names.len(),
                    shown(&p.libs[l].0),
                    list.join(", ")
                ),
            )
            .with_label("blocks of standard names");
            if names
                .iter()
                .any(|n| ["TON", "TOF", "TP"].contains(&n.to_ascii_uppercase().as_str()))
            {
                d = d.with_note(TIMERS);
            }
            self.diags.push(d);
        }
    }

    /// The names an IL body uses, upper case (a member after `.` is not one).
    fn body_names(&self, pou: &Pou) -> HashSet<String> {
        let Some(code) = pou.code else {
            return HashSet::new();
        };
        let mut scratch = Writer::default();
        decode_content(
            &mut scratch,
            self.xml,
            content_range(self.xml, code.range()),
        );
        let (toks, _) = lexer::lex(&scratch.text);
        let mut out = HashSet::new();
        let mut after_dot = false;
        for (_, t, _) in &toks {
            if let (Tok::Ident(s), false) = (t, after_dot) {
                out.insert(s.to_ascii_uppercase());
            }
            after_dot = *t == Tok::Dot;
        }
        out
    }

    /// One warning per POU of the project that is not IL, one per library
    /// for those of the library that the project uses.
    fn not_il_warnings(&mut self, p: &Project, sel: &Selection) {
        let mut per_lib: Vec<Vec<&Pou>> = vec![Vec::new(); p.libs.len()];
        for (k, pou) in p.pous.iter().enumerate() {
            if !sel.pous[k] || pou.lang == "IL" {
                continue;
            }
            match pou.origin {
                Some(l) => per_lib[l].push(pou),
                None => {
                    let at = attr_span(self.xml, pou.node, "name");
                    let mut d = Diagnostic::warning(
                        NOT_IL,
                        at,
                        format!(
                            "{} `{}` is in {}: its interface is compiled, its body is not (host-provided)",
                            pou.kind.keyword(),
                            pou.name,
                            language(&pou.lang)
                        ),
                    )
                    .with_label("body not in IL")
                    .with_note(
                        "in generated Rust the crate supplies its body, as for an `{extern}` POU; `ilc run` runs its interface only",
                    );
                    if let Some(c) = pou.code {
                        d = d.with_secondary(tag(self.xml, c), "its body");
                    }
                    self.diags.push(d);
                }
            }
        }
        for (l, list) in per_lib.iter().enumerate().filter(|(_, l)| !l.is_empty()) {
            let names: Vec<String> = list
                .iter()
                .take(8)
                .map(|p| format!("`{}`", p.name))
                .collect();
            let more = if list.len() > 8 {
                format!(" and {} more", list.len() - 8)
            } else {
                String::new()
            };
            self.diags.push(
                Diagnostic::warning(
                    NOT_IL,
                    tag(self.xml, p.libs[l].1),
                    format!(
                        "{} POU(s) of library `{}` that the project uses are not in IL: {}{more}; their interfaces are compiled, their bodies are host-provided",
                        list.len(),
                        shown(&p.libs[l].0),
                        names.join(", ")
                    ),
                )
                .with_label("library POUs not in IL"),
            );
        }
    }

    /// Write a POU; false when it is left out (reported).
    fn pou(&mut self, p: &Pou, needs: &Needs) -> bool {
        let il = p.lang == "IL";
        let keyword = p.kind.keyword();
        let start = self.w.mark();
        if !il {
            self.put("{extern} ", p.node);
        }
        let head = self.w.mark();
        self.put(&format!("{keyword} "), p.node);
        let name_at = attr_span(self.xml, p.node, "name").range();
        match self.renamed.get(&p.name.to_ascii_uppercase()) {
            Some(new) if p.kind == PouKind::FunctionBlock => {
                let new = new.clone();
                self.w.gen_at(&new, name_at);
            }
            _ => attr_into(&mut self.w, self.xml, name_at, &p.name),
        }
        if p.kind == PouKind::Function {
            let ret = kid(p.node, "returnValue");
            let ty = ret.map(|r| r.text().unwrap_or("").trim()).unwrap_or("");
            if let Err(why) = validate::check(Kind::Name, ty) {
                let at =
                    ret.map_or_else(|| attr_span(self.xml, p.node, "name"), |r| tag(self.xml, r));
                self.diags.push(
                    Diagnostic::error(
                        BAD_PROJECT,
                        at,
                        format!("FUNCTION `{}` has no valid `<returnValue>`: {why}", p.name),
                    )
                    .with_label("no result type")
                    .with_note(format!("FUNCTION `{}` is left out", p.name)),
                );
                self.w.rollback(start);
                return false;
            }
            self.put(&format!(" : {ty}"), ret.unwrap_or(p.node));
        }
        self.put("\n", p.node);
        for b in kids(p.node, "vars")
            .flat_map(|v| v.children())
            .filter(Node::is_element)
        {
            self.var_block(b, il);
        }
        if il {
            for (text, at) in needs
                .get(&p.name.to_ascii_uppercase())
                .into_iter()
                .flatten()
            {
                match at {
                    Some(at) => self.w.gen_at(text, at.clone()),
                    None => self.put(text, p.node),
                }
            }
            let Some(code) = p.code else {
                return self.no_body(p, start);
            };
            self.put("\n", code);
            decode_content(&mut self.w, self.xml, content_range(self.xml, code.range()));
        }
        let end = p.node.range().end;
        let end_tag = self
            .xml
            .get(..end)
            .and_then(|s| s.rfind("</"))
            .unwrap_or(p.node.range().start);
        self.w.gen_at(&format!("\nEND_{keyword}\n\n"), end_tag..end);
        if let Err(at) = escape(&self.w, head.0) {
            let at = at.unwrap_or_else(|| {
                p.code
                    .map_or_else(|| tag(self.xml, p.node), |c| tag(self.xml, c))
            });
            self.diags.push(
                Diagnostic::error(
                    BODY_ESCAPES,
                    at,
                    format!(
                        "the IL body of POU `{}` reaches outside its POU: it ends the POU early or opens a comment it does not close",
                        p.name
                    ),
                )
                .with_label("the POU would end here")
                .with_note(format!("POU `{}` is left out", p.name)),
            );
            self.w.rollback(start);
            return false;
        }
        true
    }

    fn no_body(&mut self, p: &Pou, start: (usize, usize)) -> bool {
        self.diags.push(
            Diagnostic::error(
                BAD_PROJECT,
                attr_span(self.xml, p.node, "name"),
                format!("POU `{}` has no `<sourceCode>`", p.name),
            )
            .with_label("no body"),
        );
        self.w.rollback(start);
        false
    }

    /// A variable block of a POU (`<inputVars>` ...); a host-provided POU
    /// keeps its interface only.
    fn var_block(&mut self, b: Node, il: bool) {
        let keyword = match b.tag_name().name() {
            "inputVars" => "VAR_INPUT",
            "outputVars" => "VAR_OUTPUT",
            "inoutVars" => "VAR_IN_OUT",
            "externalVars" => "VAR_EXTERNAL",
            "localVars" => "VAR",
            "localConsts" => "VAR CONSTANT",
            "tempVars" => "VAR_TEMP",
            other => {
                self.diags.push(
                    Diagnostic::warning(
                        super::codes::SKIPPED,
                        tag(self.xml, b),
                        format!("variable block `<{}>` is not translated", shown(other)),
                    )
                    .with_label("unknown block"),
                );
                return;
            }
        };
        let interface = matches!(keyword, "VAR_INPUT" | "VAR_OUTPUT" | "VAR_IN_OUT");
        let vars: Vec<Node> = b
            .children()
            .filter(|v| is(v, "var") || is(v, "const"))
            .collect();
        if vars.is_empty() || (!il && !interface) {
            return;
        }
        self.put(&format!("{keyword}\n"), b);
        for v in vars {
            self.var_line(v);
        }
        self.put("END_VAR\n", b);
    }
}

/// What LogicLab's timers differ in.
const TIMERS: &str = "LogicLab's timers take `PT` and give `ET` as UDINT milliseconds, counted from the target's `sysTimer`, which the host sets";

/// A LogicLab body language in words.
fn language(lang: &str) -> String {
    let name = crate::plcopen::language_name(lang);
    if lang.is_empty() {
        "no language (no `<sourceCode>`)".to_string()
    } else {
        format!("{name} ({lang})")
    }
}
