//! The project as the XML holds it: POUs, data types, global variables and
//! tasks of `<main>` and of each library kept as XML, by element. Nothing is
//! written here; names are checked (a POU without a valid name cannot be
//! referred to, so it is left out now).

use roxmltree::Node;

use super::codes::{BAD_PROJECT, BAD_VALUE, SKIPPED};
use crate::ast::{PouKind, Span};
use crate::diag::Diagnostic;
use crate::plcopen::text::start_tag;
use crate::plcopen::validate::{self, Kind, shown};

/// Where an element comes from: the project itself, or library `k`.
pub(super) type Origin = Option<usize>;

/// A POU element (`<function>`, `<functionBlock>`, `<program>`).
pub(super) struct Pou<'a, 'i> {
    pub node: Node<'a, 'i>,
    pub name: String,
    pub kind: PouKind,
    /// `<sourceCode type="...">`: `IL`, `ST`, `LD2`, `EMBEDDED` ...
    pub lang: String,
    pub code: Option<Node<'a, 'i>>,
    pub origin: Origin,
}

/// What a data type element is.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum TypeKind {
    Struct,
    Enum,
    Typedef,
    Subrange,
}

/// A data type element (`<struct>`, `<enum>`, `<typedef>`, `<subrange>`).
pub(super) struct Type<'a, 'i> {
    pub node: Node<'a, 'i>,
    pub name: String,
    pub kind: TypeKind,
    pub origin: Origin,
}

/// The three global blocks of LogicLab.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
pub(super) enum Class {
    Var,
    Retain,
    Constant,
}

/// A global variable (`<var>` or `<const>` in a group of `<globalVars>`,
/// `<retainVars>` or `<constantVars>`).
pub(super) struct Global<'a, 'i> {
    pub node: Node<'a, 'i>,
    pub name: String,
    pub class: Class,
    pub origin: Origin,
}

/// A task of the resource and the programs it runs.
pub(super) struct Task<'a, 'i> {
    /// `<task name interval priority type>` of `<resources><resource>`.
    pub node: Node<'a, 'i>,
    pub name: String,
    /// `<program>` elements of `<tasks><task>` of that name.
    pub programs: Vec<Node<'a, 'i>>,
}

/// Everything read from the document.
#[derive(Default)]
pub(super) struct Project<'a, 'i> {
    pub pous: Vec<Pou<'a, 'i>>,
    pub types: Vec<Type<'a, 'i>>,
    pub globals: Vec<Global<'a, 'i>>,
    pub tasks: Vec<Task<'a, 'i>>,
    /// `<resource name>`.
    pub resource: Option<Node<'a, 'i>>,
    /// The libraries' file names (`Standard.plclib`), for messages, and
    /// their `<lib>` elements.
    pub libs: Vec<(String, Node<'a, 'i>)>,
    /// The element the CONFIGURATION is written for (`<main>`, `<lib>`).
    pub anchor: Option<Node<'a, 'i>>,
    /// The folder of each POU and type of the project's tree
    /// (`<workspace>`), by upper-case name, as `Lib/Time`.
    pub folders: std::collections::HashMap<String, String>,
}

/// Whether LogicLab leaves the element out of the build
/// (`excludeFromBuild="TRUE"`): the import does too.
fn excluded(n: &Node) -> bool {
    n.attribute("excludeFromBuild")
        .is_some_and(|v| v.eq_ignore_ascii_case("TRUE"))
}

pub(super) use crate::plcopen::nodes::{is, kid, kids};

/// The span of an element's start tag.
pub(super) fn tag(xml: &str, n: Node) -> Span {
    let r = start_tag(xml, n.range());
    Span::new(r.start, r.end)
}

/// The span of an attribute's value, or of the element's start tag.
pub(super) fn attr_span(xml: &str, n: Node, name: &str) -> Span {
    match n.attributes().find(|a| a.name() == name) {
        Some(a) => Span::new(a.range_value().start, a.range_value().end),
        None => tag(xml, n),
    }
}

/// Attribute `attr` of `n` when it holds a `kind`; else an error (IL0421
/// when it is missing, IL0422 when it holds anything else).
pub(super) fn checked<'n>(
    xml: &str,
    n: Node<'n, '_>,
    attr: &str,
    kind: Kind,
    diags: &mut Vec<Diagnostic>,
) -> Option<&'n str> {
    crate::step_counter::add(1);
    let elem = n.tag_name().name();
    let Some(a) = n.attributes().find(|a| a.name() == attr) else {
        diags.push(
            Diagnostic::error(
                BAD_PROJECT,
                tag(xml, n),
                format!("`<{elem}>` has no `{attr}` attribute"),
            )
            .with_label(format!("`{attr}` missing"))
            .with_note("the element is left out"),
        );
        return None;
    };
    if let Err(why) = validate::check(kind, a.value()) {
        let r = if a.value().is_empty() {
            a.range()
        } else {
            a.range_value()
        };
        diags.push(
            Diagnostic::error(
                BAD_VALUE,
                Span::new(r.start, r.end),
                format!(
                    "`{attr}=\"{}\"` of `<{elem}>` is not {}: {why}",
                    shown(a.value()),
                    kind.what()
                ),
            )
            .with_label(format!("expected {}", kind.what()))
            .with_note("the element is left out"),
        );
        return None;
    }
    Some(a.value())
}

/// Read the document whose root is `root` (a `<plcProject>` or a
/// `<plcLibrary>`).
pub(super) fn read<'a, 'i>(
    root: Node<'a, 'i>,
    xml: &'i str,
    diags: &mut Vec<Diagnostic>,
) -> Project<'a, 'i> {
    let mut p = Project::default();
    if is(&root, "plcLibrary") {
        match kid(root, "lib") {
            Some(lib) => {
                p.anchor = Some(lib);
                container(&mut p, lib, None, xml, diags);
            }
            None => diags.push(missing(xml, root, "lib")),
        }
        return p;
    }
    let sources = kid(root, "sources");
    let Some(main) = sources.and_then(|s| kid(s, "main")) else {
        diags.push(missing(xml, sources.unwrap_or(root), "main"));
        return p;
    };
    if !main.children().any(|c| c.is_element()) && main.text().is_some_and(|t| !t.trim().is_empty())
    {
        diags.push(
            Diagnostic::error(
                BAD_PROJECT,
                tag(xml, main),
                "this is a LogicLab 3 project (`.ppjs`): its `<main>` holds IEC text, not XML elements",
            )
            .with_label("sources as text")
            .with_help("open it in LogicLab 5 or the Arduino PLC IDE and save it as a `.plcprj` project"),
        );
        return p;
    }
    p.anchor = Some(main);
    container(&mut p, main, None, xml, diags);
    if let Some(root) = sources
        .and_then(|s| kid(s, "workspace"))
        .and_then(|w| kid(w, "root"))
    {
        p.folders = folders(root);
    }
    tasks(&mut p, main, xml, diags);
    for lib in sources
        .into_iter()
        .flat_map(|s| kids(s, "libraries"))
        .flat_map(|l| kids(l, "lib"))
    {
        let path = lib.attribute("name").unwrap_or("");
        let name = path.rsplit(['\\', '/']).next().unwrap_or(path).to_string();
        if lib.attribute("fullXml") != Some("true") {
            diags.push(
                Diagnostic::warning(
                    SKIPPED,
                    tag(xml, lib),
                    format!(
                        "library `{}` is kept as text (LogicLab 3's `.pll`), not as XML: its POUs, types and globals are not read",
                        shown(&name)
                    ),
                )
                .with_label("library as text"),
            );
            continue;
        }
        p.libs.push((name, lib));
        let k = p.libs.len() - 1;
        container(&mut p, lib, Some(k), xml, diags);
    }
    p
}

/// The folder path of every `<Pou>` and `<Definition>` of the project's
/// tree that is in a folder (walked with a stack: the tree is the file's).
fn folders(root: Node) -> std::collections::HashMap<String, String> {
    let mut out = std::collections::HashMap::new();
    let mut stack: Vec<(Node, String)> = vec![(root, String::new())];
    while let Some((n, path)) = stack.pop() {
        for c in n.children().filter(Node::is_element) {
            crate::step_counter::add(1);
            let name = c.attribute("name").unwrap_or("");
            match c.tag_name().name() {
                "folder" => {
                    let sub = if path.is_empty() {
                        name.to_string()
                    } else {
                        format!("{path}/{name}")
                    };
                    stack.push((c, sub));
                }
                "Pou" | "Definition" if !path.is_empty() => {
                    out.insert(name.to_ascii_uppercase(), path.clone());
                }
                _ => {}
            }
        }
    }
    out
}

fn missing(xml: &str, n: Node, child: &str) -> Diagnostic {
    Diagnostic::error(
        BAD_PROJECT,
        tag(xml, n),
        format!("`<{}>` has no `<{child}>`", n.tag_name().name()),
    )
    .with_label(format!("`<{child}>` missing"))
}

/// The POUs, types and globals of `<main>` or of a `<lib>`.
fn container<'a, 'i>(
    p: &mut Project<'a, 'i>,
    c: Node<'a, 'i>,
    origin: Origin,
    xml: &str,
    diags: &mut Vec<Diagnostic>,
) {
    let groups = [
        ("functions", "function", PouKind::Function),
        ("functionBlocks", "functionBlock", PouKind::FunctionBlock),
        ("programs", "program", PouKind::Program),
    ];
    for (outer, inner, kind) in groups {
        for n in kids(c, outer).flat_map(|o| kids(o, inner)) {
            if excluded(&n) {
                continue;
            }
            let Some(name) = checked(xml, n, "name", Kind::Name, diags) else {
                continue;
            };
            // Object-oriented parts of a block have no IL form.
            for part in ["methods", "interfaces"] {
                if let Some(m) = kid(n, part).filter(|m| m.children().any(|k| k.is_element())) {
                    diags.push(
                        Diagnostic::warning(
                            SKIPPED,
                            tag(xml, m),
                            format!("the {part} of `{name}` are not translated"),
                        )
                        .with_label("skipped"),
                    );
                }
            }
            let code = kid(n, "sourceCode");
            let lang = code
                .and_then(|s| s.attribute("type"))
                .unwrap_or("")
                .to_ascii_uppercase();
            p.pous.push(Pou {
                node: n,
                name: name.to_string(),
                kind,
                lang,
                code,
                origin,
            });
        }
    }
    let types = [
        ("structs", "struct", TypeKind::Struct),
        ("enums", "enum", TypeKind::Enum),
        ("typedefs", "typedef", TypeKind::Typedef),
        ("subranges", "subrange", TypeKind::Subrange),
    ];
    for (outer, inner, kind) in types {
        for n in kids(c, outer).flat_map(|o| kids(o, inner)) {
            if excluded(&n) {
                continue;
            }
            if let Some(name) = checked(xml, n, "name", Kind::Name, diags) {
                p.types.push(Type {
                    node: n,
                    name: name.to_string(),
                    kind,
                    origin,
                });
            }
        }
    }
    let classes = [
        ("globalVars", Class::Var),
        ("retainVars", Class::Retain),
        ("constantVars", Class::Constant),
    ];
    for (outer, class) in classes {
        for block in kids(c, outer) {
            // Variables in named groups, or (hand-written) right in the block.
            let vars = kids(block, "group")
                .filter(|g| !excluded(g))
                .flat_map(|g| g.children())
                .chain(block.children())
                .filter(|v| is(v, "var") || is(v, "const"));
            for v in vars {
                if let Some(name) = checked(xml, v, "name", Kind::Name, diags) {
                    p.globals.push(Global {
                        node: v,
                        name: name.to_string(),
                        class,
                        origin,
                    });
                }
            }
        }
    }
    // Parts that have no IL form: said once per container.
    for (outer, what) in [("macros", "macros"), ("interfaces", "interfaces")] {
        if let Some(m) = kid(c, outer).filter(|m| m.children().any(|k| k.is_element())) {
            diags.push(
                Diagnostic::warning(
                    SKIPPED,
                    tag(xml, m),
                    format!("the {what} of this {} are not translated", place(origin)),
                )
                .with_label("skipped"),
            );
        }
    }
}

fn place(origin: Origin) -> &'static str {
    if origin.is_some() {
        "library"
    } else {
        "project"
    }
}

/// The tasks of the project's resource and the programs each runs.
fn tasks<'a, 'i>(
    p: &mut Project<'a, 'i>,
    main: Node<'a, 'i>,
    xml: &str,
    diags: &mut Vec<Diagnostic>,
) {
    let resource = kids(main, "resources")
        .flat_map(|r| kids(r, "resource"))
        .next();
    p.resource = resource;
    let assigned: Vec<Node> = kids(main, "tasks").flat_map(|t| kids(t, "task")).collect();
    for t in resource.into_iter().flat_map(|r| kids(r, "task")) {
        let Some(name) = t.attribute("name") else {
            diags.push(missing_attr(xml, t, "name"));
            continue;
        };
        let programs: Vec<Node> = assigned
            .iter()
            .filter(|a| {
                a.attribute("name")
                    .is_some_and(|n| n.eq_ignore_ascii_case(name))
            })
            .flat_map(|a| kids(*a, "program"))
            .collect();
        p.tasks.push(Task {
            node: t,
            name: name.to_string(),
            programs,
        });
    }
}

fn missing_attr(xml: &str, n: Node, attr: &str) -> Diagnostic {
    Diagnostic::error(
        BAD_PROJECT,
        tag(xml, n),
        format!("`<{}>` has no `{attr}` attribute", n.tag_name().name()),
    )
    .with_label(format!("`{attr}` missing"))
}
