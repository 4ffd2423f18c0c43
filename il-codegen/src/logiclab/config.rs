//! The globals a LogicLab project's POUs use without declaring them, and the
//! CONFIGURATION that holds the project's globals and runs its tasks.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::ops::Range;

use roxmltree::Node;

use super::codes::{BAD_VALUE, SKIPPED, TARGET_GLOBAL};
use super::lx::{Lx, Selection};
use super::read::{Class, Project, attr_span, checked, is, kids, tag};
use crate::ast::PouKind;
use crate::diag::Diagnostic;
use crate::plcopen::text::start_tag;
use crate::plcopen::validate::{self, Kind, shown};

/// The name of the generated CONFIGURATION (as the `.EXP` import's).
const CONFIG_NAME: &str = "Project";

/// A global as the POUs that use it declare it.
struct Decl {
    name: String,
    ty: String,
    /// A constant's value (a POU declares it as a local `VAR CONSTANT`).
    constant: Option<String>,
    /// Its `<var>`'s start tag: what a POU's implicit declaration of it
    /// stands for (a definition look-up lands on the global).
    at: Range<usize>,
}

/// A piece of an implicit block: its text, and the global's `<var>` it
/// stands for (`None`: the POU's, for `VAR_EXTERNAL` and `END_VAR`).
pub(super) type Piece = (String, Option<Range<usize>>);

/// One IL POU as the implicit blocks need it.
struct Direct {
    kind: PouKind,
    /// The globals its body names and its VAR_EXTERNALs, by index.
    needed: BTreeSet<usize>,
    /// Its variables' type names (upper case): the blocks it holds.
    types: Vec<String>,
    /// Its own names (upper case).
    locals: BTreeSet<String>,
}

/// What the POUs need declared, and the target's globals they name.
#[derive(Default)]
pub(super) struct Needs<'a, 'i> {
    /// The implicit blocks (`VAR_EXTERNAL`, `VAR CONSTANT`) of each IL POU,
    /// by upper-case name.
    blocks: HashMap<String, Vec<Piece>>,
    /// Globals of the target: name, type, the first VAR_EXTERNAL of it.
    targets: Vec<(String, String, Node<'a, 'i>)>,
}

impl Needs<'_, '_> {
    pub(super) fn get(&self, pou: &str) -> Option<&Vec<Piece>> {
        self.blocks.get(pou)
    }
}

/// The implicit blocks of every IL PROGRAM, FUNCTION_BLOCK and FUNCTION:
/// the globals its body names (and, for a block, those the blocks it holds
/// instances of need: IEC's rule, which the checker keeps).
pub(super) fn needs<'a, 'i>(p: &Project<'a, 'i>, sel: &Selection, lx: &mut Lx) -> Needs<'a, 'i> {
    let mut out = Needs::default();
    let mut decls: Vec<Decl> = Vec::new();
    let mut keys: HashMap<String, usize> = HashMap::new();
    for (k, g) in p.globals.iter().enumerate() {
        if !sel.globals[k] || keys.contains_key(&g.name.to_ascii_uppercase()) {
            continue;
        }
        let mut scratch = std::mem::take(&mut lx.diags);
        let ty = lx.type_text(g.node);
        // Reported where the global itself is written.
        std::mem::swap(&mut scratch, &mut lx.diags);
        let Some(ty) = ty else { continue };
        let constant = (g.class == Class::Constant)
            .then(|| init_value(g.node))
            .flatten();
        keys.insert(g.name.to_ascii_uppercase(), decls.len());
        decls.push(Decl {
            name: g.name.clone(),
            ty,
            constant,
            at: start_tag(lx.xml, g.node.range()),
        });
    }
    // Per IL POU: the globals it names, its own names, its instances' types.
    let mut direct: BTreeMap<String, Direct> = BTreeMap::new();
    for (k, pou) in p.pous.iter().enumerate() {
        if !sel.pous[k] || pou.lang != "IL" {
            continue;
        }
        let mut locals = BTreeSet::new();
        let mut types = Vec::new();
        let mut needed = BTreeSet::new();
        for b in kids(pou.node, "vars")
            .flat_map(|v| v.children())
            .filter(Node::is_element)
        {
            let external = is(&b, "externalVars");
            for v in b.children().filter(|v| is(v, "var") || is(v, "const")) {
                let Some(name) = v.attribute("name") else {
                    continue;
                };
                let key = name.to_ascii_uppercase();
                locals.insert(key.clone());
                types.push(v.attribute("type").unwrap_or("").to_ascii_uppercase());
                if !external {
                    continue;
                }
                let g = match keys.get(&key) {
                    Some(&g) => g,
                    None => {
                        let Some(ty) = lx.type_text(v) else { continue };
                        lx.diags.push(
                            Diagnostic::warning(
                                TARGET_GLOBAL,
                                attr_span(lx.xml, v, "name"),
                                format!(
                                    "`{name}` is no global of the project: a global of the target, declared in the generated CONFIGURATION for the host to set"
                                ),
                            )
                            .with_label("global of the target"),
                        );
                        out.targets.push((name.to_string(), ty.clone(), v));
                        keys.insert(key, decls.len());
                        decls.push(Decl {
                            name: name.to_string(),
                            ty,
                            constant: None,
                            at: start_tag(lx.xml, v.range()),
                        });
                        decls.len() - 1
                    }
                };
                needed.insert(g);
            }
        }
        for u in &sel.used[k] {
            if let Some(&g) = keys.get(u)
                && !locals.contains(u)
            {
                needed.insert(g);
            }
        }
        direct.insert(
            pou.name.to_ascii_uppercase(),
            Direct {
                kind: pou.kind,
                needed,
                types,
                locals,
            },
        );
    }
    let mut needs: BTreeMap<String, BTreeSet<usize>> = direct
        .iter()
        .map(|(k, v)| (k.clone(), v.needed.clone()))
        .collect();
    for _ in 0..direct.len().min(64) {
        let mut changed = false;
        for (name, d) in &direct {
            if d.kind == PouKind::Function {
                continue;
            }
            let add: BTreeSet<usize> = d
                .types
                .iter()
                .filter(|t| {
                    direct
                        .get(*t)
                        .is_some_and(|c| c.kind == PouKind::FunctionBlock)
                })
                .filter_map(|t| needs.get(t))
                .flatten()
                .copied()
                .filter(|&g| decls[g].constant.is_none())
                .collect();
            let mine = needs.entry(name.clone()).or_default();
            let before = mine.len();
            mine.extend(add);
            changed |= mine.len() != before;
        }
        if !changed {
            break;
        }
    }
    for (name, set) in &needs {
        let Direct { kind, locals, .. } = &direct[name];
        let (mut ext, mut cons) = (Vec::new(), Vec::new());
        for &g in set {
            let d = &decls[g];
            if locals.contains(&d.name.to_ascii_uppercase()) {
                continue;
            }
            match &d.constant {
                Some(v) => cons.push((format!("\t{} : {} := {v};\n", d.name, d.ty), d.at.clone())),
                None if *kind != PouKind::Function => {
                    ext.push((format!("\t{} : {};\n", d.name, d.ty), d.at.clone()));
                }
                None => {}
            }
        }
        let mut pieces = Vec::new();
        for (head, lines) in [("VAR_EXTERNAL\n", ext), ("VAR CONSTANT\n", cons)] {
            if lines.is_empty() {
                continue;
            }
            pieces.push((head.to_string(), None));
            pieces.extend(lines.into_iter().map(|(t, at)| (t, Some(at))));
            pieces.push(("END_VAR\n".to_string(), None));
        }
        if !pieces.is_empty() {
            out.blocks.insert(name.clone(), pieces);
        }
    }
    out
}

/// A constant's value, when it is a value.
fn init_value(v: Node) -> Option<String> {
    let iv = v.children().find(|c| is(c, "initValue"))?;
    let t = iv.text()?.trim();
    validate::check(Kind::Value, t)
        .is_ok()
        .then(|| t.to_string())
}

/// The CONFIGURATION: the globals (project, libraries used, target), the
/// resource's tasks and the programs they run.
pub(super) fn write(p: &Project, sel: &Selection, needs: &Needs, lx: &mut Lx) {
    let Some(anchor) = p.anchor else { return };
    let written: Vec<&str> = p
        .pous
        .iter()
        .enumerate()
        .filter(|(k, x)| sel.pous[*k] && x.kind == PouKind::Program)
        .map(|(_, x)| x.name.as_str())
        .collect();
    let tasks = tasks(p, &written, lx);
    let globals: Vec<usize> = (0..p.globals.len()).filter(|&k| sel.globals[k]).collect();
    if globals.is_empty() && needs.targets.is_empty() && tasks.is_empty() {
        return;
    }
    lx.put(&format!("CONFIGURATION {CONFIG_NAME}\n"), anchor);
    for class in [Class::Var, Class::Retain, Class::Constant] {
        let of: Vec<usize> = globals
            .iter()
            .copied()
            .filter(|&k| p.globals[k].class == class)
            .collect();
        let targets = if class == Class::Var {
            &needs.targets[..]
        } else {
            &[]
        };
        if of.is_empty() && targets.is_empty() {
            continue;
        }
        let head = match class {
            Class::Var => "VAR_GLOBAL\n",
            Class::Retain => "VAR_GLOBAL RETAIN\n",
            Class::Constant => "VAR_GLOBAL CONSTANT\n",
        };
        lx.put(head, anchor);
        for k in of {
            lx.var_line(p.globals[k].node);
        }
        for (name, ty, v) in targets {
            lx.put(&format!("\t{name} : {ty};\n"), *v);
        }
        lx.put("END_VAR\n", anchor);
    }
    if !tasks.is_empty() {
        let res = p
            .resource
            .and_then(|r| {
                r.attribute("name")
                    .filter(|n| validate::check(Kind::Name, n).is_ok())
            })
            .unwrap_or("PLC");
        lx.put(
            &format!("RESOURCE {res} ON PLC\n"),
            p.resource.unwrap_or(anchor),
        );
        for (t, line, _) in &tasks {
            lx.put(line, *t);
        }
        for (_, _, programs) in &tasks {
            for (n, line) in programs {
                lx.put(line, *n);
            }
        }
        lx.put("END_RESOURCE\n", p.resource.unwrap_or(anchor));
    }
    lx.put("END_CONFIGURATION\n", anchor);
}

/// A task's declaration and its program instances.
type TaskLines<'a, 'i> = (Node<'a, 'i>, String, Vec<(Node<'a, 'i>, String)>);

/// The tasks that run programs of the project, written as IL lines.
fn tasks<'a, 'i>(p: &Project<'a, 'i>, written: &[&str], lx: &mut Lx) -> Vec<TaskLines<'a, 'i>> {
    let mut out = Vec::new();
    for t in &p.tasks {
        if t.programs.is_empty() {
            continue;
        }
        // A task's name is written into the IL text: checked (and reported)
        // as every name is.
        if checked(lx.xml, t.node, "name", Kind::Name, &mut lx.diags).is_none() {
            continue;
        }
        let mut params = Vec::new();
        let single = match t.node.attribute("type").unwrap_or("cyclic") {
            "cyclic" => false,
            "single" => true,
            other => {
                lx.diags.push(
                    Diagnostic::warning(
                        SKIPPED,
                        tag(lx.xml, t.node),
                        format!(
                            "task `{}` is of type `{}`: only cyclic and single tasks are translated; its programs do not run",
                            shown(&t.name),
                            shown(other)
                        ),
                    )
                    .with_label("not translated"),
                );
                continue;
            }
        };
        let interval = t.node.attribute("interval").unwrap_or("");
        if single {
            params.push("SINGLE := TRUE".to_string());
        } else if interval.chars().any(|c| ('1'..='9').contains(&c)) {
            if validate::check(Kind::Duration, interval).is_err() {
                lx.diags.push(
                    Diagnostic::error(
                        BAD_VALUE,
                        attr_span(lx.xml, t.node, "interval"),
                        format!(
                            "task `{}` has the interval `{}`, which is not a duration",
                            shown(&t.name),
                            shown(interval)
                        ),
                    )
                    .with_label("expected a duration such as `t#10ms`"),
                );
                continue;
            }
            params.push(format!("INTERVAL := {interval}"));
        }
        if let Some(pr) = t.node.attribute("priority") {
            if validate::check(Kind::Count, pr).is_err() {
                lx.diags.push(
                    Diagnostic::error(
                        BAD_VALUE,
                        attr_span(lx.xml, t.node, "priority"),
                        format!(
                            "task `{}` has the priority `{}`, which is not a number",
                            shown(&t.name),
                            shown(pr)
                        ),
                    )
                    .with_label("expected a number"),
                );
                continue;
            }
            params.push(format!("PRIORITY := {pr}"));
        }
        let mut programs = Vec::new();
        for n in &t.programs {
            let prog = n.text().unwrap_or("").trim();
            match written.iter().find(|w| w.eq_ignore_ascii_case(prog)) {
                Some(w) => programs.push((*n, format!("PROGRAM {w} WITH {} : {w};\n", t.name))),
                None => lx.diags.push(
                    Diagnostic::warning(
                        SKIPPED,
                        tag(lx.xml, *n),
                        format!(
                            "task `{}` runs `{}`, which is no PROGRAM of the project that is translated: it does not run",
                            t.name,
                            shown(prog)
                        ),
                    )
                    .with_label("not run"),
                ),
            }
        }
        if !programs.is_empty() {
            out.push((
                t.node,
                format!("TASK {}({});\n", t.name, params.join(", ")),
                programs,
            ));
        }
    }
    out
}
