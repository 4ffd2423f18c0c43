//! What the editor asks about, indexed once per check. What a name names
//! is the checker's answer: its resolution table ([`ir::Resolutions`]),
//! which definition, references, rename, highlight and hover read. Kept
//! here is what that table does not hold: each declaration as text (hover),
//! the scopes completion offers while the text is not yet valid IL (a
//! POU's variables, a type's members, a POU's labels), each file's outline,
//! and the CR the checker proved at every instruction.

mod declare;
mod moved;

use std::collections::HashMap;

use il_codegen::Checked;
use il_codegen::Input;
use il_codegen::ast::{self, Span, TypeSpec};
use il_codegen::ir;
use il_codegen::ir::types::Ty;
use il_interp::il_std::signature::{self as sig, FbSignature};
use lsp_types::SymbolKind;

pub type SymId = usize;

/// What a symbol is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Pou(ast::PouKind),
    Var(ast::VarKind),
    Label,
    Type,
    Field,
    Config,
}

/// A declared name.
#[derive(Debug)]
pub struct Symbol {
    pub name: String,
    pub kind: Kind,
    pub file: usize,
    /// The name where it is declared, in the user's file.
    pub span: Span,
    /// The POU (or type, configuration) it belongs to.
    pub container: Option<SymId>,
    /// Its declaration as IL text (hover).
    pub decl: String,
    /// Markdown lines after the declaration (section, resolved type).
    pub note: String,
    /// For an instance of a FUNCTION_BLOCK or STRUCT (or an array of them):
    /// the type's name, upper case, for its members.
    pub ty: Option<String>,
}

/// A member of a type, for completion.
#[derive(Clone, Copy, Debug)]
pub enum Member {
    Sym(SymId),
    /// An input or output of a standard block.
    Std,
}

/// Where the checker recorded the CR at one instruction or label: its
/// place in the user's file, and which [`ir::CrStep`] of the checked
/// program it is (`Workspace::cr_step` reads it there: copied here, the
/// steps of a large program cost a third of the index).
#[derive(Debug, Clone, Copy)]
pub struct Step {
    pub span: Span,
    pub label: bool,
    /// The program's file, the POU among its checked ones, the step.
    pub file: u32,
    pub pou: u32,
    pub at: u32,
}

/// One entry of a file's outline (document symbols).
#[derive(Debug)]
pub struct Outline {
    pub name: String,
    pub detail: Option<String>,
    pub kind: SymbolKind,
    pub span: Span,
    pub sel: Span,
    pub children: Vec<Outline>,
}

#[derive(Debug, Default)]
pub struct FileIndex {
    /// Sorted by position.
    pub steps: Vec<Step>,
    /// Each POU's whole text and symbol, sorted.
    pub pous: Vec<(Span, SymId)>,
    pub outline: Vec<Outline>,
}

#[derive(Debug, Default)]
pub struct Index {
    pub symbols: Vec<Symbol>,
    /// Per file of the program checked, in the order of `docs`.
    pub files: Vec<FileIndex>,
    /// The workspace document of each file (see [`Index::relocate`]);
    /// [`Symbol::file`] and the table's declarations hold these numbers.
    pub docs: Vec<usize>,
    /// The checker's resolution table (its uses numbered by the program's
    /// files: [`Index::name_at`] and [`Index::uses`] take documents).
    pub table: ir::Resolutions,
    /// (document, start of the name) of each declaration → its symbol here.
    by_decl: HashMap<(usize, u32), SymId>,
    pub pou_by_name: HashMap<String, SymId>,
    pub type_by_name: HashMap<String, SymId>,
    /// (POU, STRUCT type or configuration, NAME) → its variable or field.
    pub scope: HashMap<(SymId, String), SymId>,
    /// (POU, LABEL) → the label.
    pub labels: HashMap<(SymId, String), SymId>,
    /// A POU's variables / a type's fields / a POU's labels, in order.
    pub members: HashMap<SymId, Vec<SymId>>,
    pub pou_labels: HashMap<SymId, Vec<SymId>>,
}

impl Index {
    /// Index a checked program.
    pub fn build(checked: &Checked) -> Index {
        let mut ix = Index::default();
        let n = checked.inputs().len();
        ix.files = (0..n).map(|_| FileIndex::default()).collect();
        ix.docs = (0..n).collect();
        let empty = ast::CompilationUnit::default();
        let units = checked.syntax();
        let irs = checked.partial_ir();
        for (f, input) in checked.inputs().iter().enumerate() {
            let unit = units.get(f).unwrap_or(&empty);
            let ir_pous: HashMap<String, &ir::CheckedPou> = irs
                .get(f)
                .map(|p| {
                    p.pous
                        .iter()
                        .map(|c| (c.name.to_ascii_uppercase(), c))
                        .collect()
                })
                .unwrap_or_default();
            let b = Builder { input, f };
            b.declare(&mut ix, unit, &ir_pous);
            if let Some(p) = irs.get(f) {
                for (pou, c) in p.pous.iter().enumerate() {
                    for (at, s) in c.cr_steps.iter().enumerate() {
                        ix.files[f].steps.push(Step {
                            span: b.map(s.span),
                            label: s.label,
                            file: f as u32,
                            pou: pou as u32,
                            at: at as u32,
                        });
                    }
                }
            }
            let file = &mut ix.files[f];
            file.steps
                .sort_by_key(|s| (s.span.lo, std::cmp::Reverse(s.span.hi)));
            file.pous.sort_by_key(|(s, _)| s.lo);
        }
        ix.table = checked.resolutions().cloned().unwrap_or_default();
        ix.index_decls();
        ix
    }

    fn index_decls(&mut self) {
        self.by_decl = (self.symbols.iter().enumerate())
            .map(|(id, s)| ((s.file, s.span.lo), id))
            .collect();
    }

    /// The index of workspace document `doc`, if this program holds it.
    pub fn file(&self, doc: usize) -> Option<&FileIndex> {
        let k = self.docs.binary_search(&doc).ok()?;
        self.files.get(k)
    }

    /// Number the files as the workspace's documents `docs` (ascending; the
    /// program's file `k` is document `docs[k]`), so that every file number
    /// the index hands out is a document's.
    pub fn relocate(&mut self, docs: Vec<usize>) {
        for s in &mut self.symbols {
            s.file = docs[s.file];
        }
        for d in self
            .table
            .symbols
            .iter_mut()
            .filter_map(|s| s.decl.as_mut())
        {
            d.file = docs[d.file];
        }
        self.docs = docs;
        self.index_decls();
    }

    /// The name at byte `off` of document `doc` (a name holding it, or
    /// ending right at it: the cursor after a name) and its symbol in the
    /// table.
    pub fn name_at(&self, doc: usize, off: usize) -> Option<(Span, ir::SymbolId)> {
        let k = self.docs.binary_search(&doc).ok()?;
        self.table.at(k, off)
    }

    /// Every place symbol `s` of the table is written, its declaration
    /// included: (document, span).
    pub fn uses(&self, s: ir::SymbolId) -> impl Iterator<Item = (usize, Span)> + '_ {
        self.table.uses_of(s).map(|(k, span)| (self.docs[k], span))
    }

    /// The declaration here of symbol `s` of the table.
    pub fn declared(&self, s: ir::SymbolId) -> Option<SymId> {
        let d = self.table.symbols.get(s)?.decl?;
        self.by_decl.get(&(d.file, d.span.lo)).copied()
    }

    /// The innermost instruction or label at byte `off` of file `f`.
    pub fn step_at(&self, f: usize, off: usize) -> Option<&Step> {
        let steps = &self.file(f)?.steps;
        let off = off as u32;
        let i = steps.partition_point(|s| s.span.lo <= off);
        // Steps are sorted by start: the innermost holding `off` is the
        // last one starting before it, unless that one ended already (the
        // `)` of a group); groups nest, so a few steps back suffice.
        steps[..i]
            .iter()
            .rev()
            .take(256)
            .find(|s| off >= s.span.lo && off <= s.span.hi)
    }

    /// The POU whose text holds byte `off` of file `f`.
    pub fn pou_at(&self, f: usize, off: usize) -> Option<SymId> {
        let pous = &self.file(f)?.pous;
        let off = off as u32;
        let i = pous.partition_point(|(s, _)| s.lo <= off);
        let (s, id) = *pous.get(i.checked_sub(1)?)?;
        (off <= s.hi).then_some(id)
    }

    /// A variable of POU `pou` by name, or the FUNCTION's own name (its result).
    pub fn var_in(&self, pou: SymId, name: &str) -> Option<SymId> {
        let key = name.to_ascii_uppercase();
        self.scope.get(&(pou, key.clone())).copied().or_else(|| {
            let p = &self.symbols[pou];
            (p.kind == Kind::Pou(ast::PouKind::Function) && p.name.eq_ignore_ascii_case(name))
                .then_some(pou)
        })
    }

    /// The POU or STRUCT type named `key` (upper case).
    pub fn type_sym(&self, key: &str) -> Option<SymId> {
        self.pou_by_name
            .get(key)
            .or_else(|| self.type_by_name.get(key))
            .copied()
    }

    /// Member `name` of an instance of type `key` (upper case).
    pub fn member(&self, key: &str, name: &str) -> Option<Member> {
        if let Some(t) = self.type_sym(key) {
            return self
                .scope
                .get(&(t, name.to_ascii_uppercase()))
                .map(|&m| Member::Sym(m));
        }
        let fb = sig::lookup_fb(key)?;
        fb.inputs
            .iter()
            .chain(fb.outputs)
            .any(|p| p.name.eq_ignore_ascii_case(name))
            .then_some(Member::Std)
    }
}

/// The type name of an instance of an FB or STRUCT (or an array of them).
fn ty_key(t: &Ty) -> Option<String> {
    match t {
        Ty::Fb(n) | Ty::Struct(n) => Some(n.to_ascii_uppercase()),
        Ty::Array(a) => ty_key(&a.elem),
        _ => None,
    }
}

fn spec_key(t: &TypeSpec) -> Option<String> {
    match t {
        TypeSpec::Named(id) => Some(id.key()),
        TypeSpec::Array { elem, .. } => spec_key(elem),
        _ => None,
    }
}

pub fn pou_symbol_kind(k: ast::PouKind) -> SymbolKind {
    match k {
        ast::PouKind::Function => SymbolKind::FUNCTION,
        ast::PouKind::FunctionBlock => SymbolKind::CLASS,
        ast::PouKind::Program => SymbolKind::MODULE,
    }
}

/// Indexes one input; [`declare`] adds its methods.
struct Builder<'a> {
    input: &'a Input,
    f: usize,
}

impl Builder<'_> {
    /// A span of the IL text in the user's file.
    fn map(&self, s: Span) -> Span {
        self.input.to_source(s)
    }

    fn text(&self, s: Span) -> &str {
        self.input.il_text().snippet(s)
    }

    fn add(&self, ix: &mut Index, sym: Symbol) -> SymId {
        ix.symbols.push(sym);
        ix.symbols.len() - 1
    }
}

/// `TON (IN : BOOL, PT : TIME) → (Q : BOOL, ET : TIME)`, markdown.
pub fn fb_signature(fb: &FbSignature) -> String {
    let list = |ps: &[sig::FbParam]| {
        ps.iter()
            .map(|p| format!("{} : {}", p.name, p.ty.name()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    format!(
        "standard function block `{}`\n\n```il\nFUNCTION_BLOCK {}\n    VAR_INPUT {} END_VAR\n    VAR_OUTPUT {} END_VAR\n```",
        fb.name,
        fb.name,
        list(fb.inputs),
        list(fb.outputs)
    )
}
