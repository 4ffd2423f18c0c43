//! What the editor asks about, indexed once per check: every declared name
//! (a [`Symbol`]), every place a name is written (a reference to its
//! symbol or to a standard function or block), the CR the checker proved at
//! every instruction, and each file's outline. Requests then look a position
//! up by binary search instead of walking the tree.
//!
//! Names are resolved as the checker resolves them (case-insensitively, in
//! the POU's own variables; members through the instance's type, which
//! comes from the checked IR when the POU could be checked and from the
//! declaration as written otherwise).

use std::collections::HashMap;

use il_codegen::Checked;
use il_codegen::Input;
use il_codegen::ast::{self, Accessor, CallArgs, InstrKind, Operand, ParamKind, Span, TypeSpec};
use il_codegen::sema::ir::{self, CrState};
use il_codegen::sema::types::Ty;
use il_interp::il_std::signature::{self as sig, FbSignature, Signature};
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

/// What a written name refers to.
#[derive(Clone, Copy, Debug)]
pub enum Target {
    Sym(SymId),
    StdFn(&'static Signature),
    StdFb(&'static FbSignature),
    /// An input (index below `inputs.len()`) or output of a standard block.
    StdMember(&'static FbSignature, usize),
}

/// The CR at one instruction or label ([`ir::CrStep`] in the user's file).
#[derive(Debug)]
pub struct Step {
    pub span: Span,
    pub label: bool,
    pub before: CrState,
    pub after: CrState,
    pub paths: Option<String>,
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
    /// Every written name with what it refers to, sorted by position
    /// (declarations included: they refer to themselves).
    pub refs: Vec<(Span, Target)>,
    /// Sorted by position.
    pub steps: Vec<Step>,
    /// Each POU's whole text and symbol, sorted.
    pub pous: Vec<(Span, SymId)>,
    pub outline: Vec<Outline>,
}

#[derive(Debug, Default)]
pub struct Index {
    pub symbols: Vec<Symbol>,
    pub files: Vec<FileIndex>,
    /// Every place each symbol is written: (file, span).
    pub uses: Vec<Vec<(usize, Span)>>,
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
        let empty = ast::CompilationUnit::default();
        let units = checked.syntax();
        let irs = checked.partial_ir();
        let mut pous_of_file = Vec::new();
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
            pous_of_file.push(b.declare(&mut ix, unit, &ir_pous));
        }
        for (f, input) in checked.inputs().iter().enumerate() {
            let unit = units.get(f).unwrap_or(&empty);
            let b = Builder { input, f };
            b.resolve(&mut ix, unit, &pous_of_file[f]);
            if let Some(p) = irs.get(f) {
                for c in &p.pous {
                    for s in &c.cr_steps {
                        ix.files[f].steps.push(Step {
                            span: b.map(s.span),
                            label: s.label,
                            before: s.before.clone(),
                            after: s.after.clone(),
                            paths: s.paths.clone(),
                        });
                    }
                }
            }
            let file = &mut ix.files[f];
            file.steps
                .sort_by_key(|s| (s.span.lo, std::cmp::Reverse(s.span.hi)));
            file.refs.sort_by_key(|(s, _)| (s.lo, s.hi));
            file.refs.dedup_by_key(|(s, _)| *s);
            file.pous.sort_by_key(|(s, _)| s.lo);
        }
        ix.uses = (0..ix.symbols.len()).map(|_| Vec::new()).collect();
        for (f, file) in ix.files.iter().enumerate() {
            for (span, t) in &file.refs {
                if let Target::Sym(s) = t {
                    ix.uses[*s].push((f, *span));
                }
            }
        }
        ix
    }

    /// The reference at byte `off` of file `f` (a name containing it, or
    /// ending right at it: the cursor after a name).
    pub fn ref_at(&self, f: usize, off: usize) -> Option<(Span, Target)> {
        let refs = &self.files.get(f)?.refs;
        let off = off as u32;
        let i = refs.partition_point(|(s, _)| s.lo <= off);
        let (s, t) = *refs.get(i.checked_sub(1)?)?;
        (off >= s.lo && off <= s.hi).then_some((s, t))
    }

    /// The innermost instruction or label at byte `off` of file `f`.
    pub fn step_at(&self, f: usize, off: usize) -> Option<&Step> {
        let steps = &self.files.get(f)?.steps;
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
        let pous = &self.files.get(f)?.pous;
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
    pub fn member(&self, key: &str, name: &str) -> Option<Target> {
        if let Some(t) = self.type_sym(key) {
            return self
                .scope
                .get(&(t, name.to_ascii_uppercase()))
                .map(|&m| Target::Sym(m));
        }
        let fb = sig::lookup_fb(key)?;
        fb.inputs
            .iter()
            .chain(fb.outputs)
            .position(|p| p.name.eq_ignore_ascii_case(name))
            .map(|i| Target::StdMember(fb, i))
    }
}

/// The type name of an instance of an FB or STRUCT (or an array of them).
fn ty_key(t: &Ty) -> Option<String> {
    match t {
        Ty::Fb(n) | Ty::Struct(n) => Some(n.to_ascii_uppercase()),
        Ty::Array { elem, .. } => ty_key(elem),
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

fn pou_symbol_kind(k: ast::PouKind) -> SymbolKind {
    match k {
        ast::PouKind::Function => SymbolKind::FUNCTION,
        ast::PouKind::FunctionBlock => SymbolKind::CLASS,
        ast::PouKind::Program => SymbolKind::MODULE,
    }
}

struct Builder<'a> {
    input: &'a Input,
    f: usize,
}

impl Builder<'_> {
    /// A span of the IL text in the user's file.
    fn map(&self, s: Span) -> Span {
        match self.input {
            Input::Il(_) => s,
            Input::PlcOpen(i) => i.map.to_xml(s),
        }
    }

    fn text(&self, s: Span) -> &str {
        self.input.il_text().snippet(s)
    }

    fn add(&self, ix: &mut Index, sym: Symbol) -> SymId {
        let id = ix.symbols.len();
        ix.files[self.f].refs.push((sym.span, Target::Sym(id)));
        ix.symbols.push(sym);
        id
    }

    /// Declarations: POUs with their variables and labels, types with
    /// their fields, configurations with their globals. Returns each POU of
    /// the unit (in item order) with its symbol.
    fn declare(
        &self,
        ix: &mut Index,
        unit: &ast::CompilationUnit,
        ir_pous: &HashMap<String, &ir::CheckedPou>,
    ) -> Vec<Option<SymId>> {
        let mut pous = Vec::new();
        for item in &unit.items {
            match item {
                ast::Item::Pou(p) => pous.push(Some(self.declare_pou(ix, p, ir_pous))),
                ast::Item::Types(decls) => {
                    for d in decls {
                        self.declare_type(ix, d);
                    }
                }
                ast::Item::Configuration(c) => self.declare_config(ix, c),
            }
        }
        pous
    }

    fn declare_pou(
        &self,
        ix: &mut Index,
        p: &ast::Pou,
        ir_pous: &HashMap<String, &ir::CheckedPou>,
    ) -> SymId {
        let ret = p
            .return_type
            .as_ref()
            .map(|t| format!(" : {}", self.text(t.span())))
            .unwrap_or_default();
        let id = self.add(
            ix,
            Symbol {
                name: p.name.name.clone(),
                kind: Kind::Pou(p.kind),
                file: self.f,
                span: self.map(p.name.span),
                container: None,
                decl: format!("{} {}{ret}", p.kind.keyword(), p.name),
                note: String::new(),
                ty: None,
            },
        );
        ix.pou_by_name.entry(p.name.key()).or_insert(id);
        ix.files[self.f].pous.push((self.map(p.span), id));
        let ir_pou = ir_pous.get(&p.name.key()).filter(|c| c.kind == p.kind);
        let ir_vars: HashMap<String, &ir::Var> = ir_pou
            .map(|c| {
                c.vars
                    .iter()
                    .map(|v| (v.name.to_ascii_uppercase(), v))
                    .collect()
            })
            .unwrap_or_default();
        let mut children = Vec::new();
        for block in &p.var_blocks {
            let vars = self.declare_block(ix, id, p, block, &ir_vars);
            children.push(self.section_outline(ix, block, vars));
        }
        let mut labels = Vec::new();
        for s in &p.body {
            if let ast::Stmt::Label(l) = s {
                let key = (id, l.key());
                if ix.labels.contains_key(&key) {
                    continue; // defined twice: the checker reports it
                }
                let lid = self.add(
                    ix,
                    Symbol {
                        name: l.name.clone(),
                        kind: Kind::Label,
                        file: self.f,
                        span: self.map(l.span),
                        container: Some(id),
                        decl: format!("{}:", l.name),
                        note: format!("label of {} `{}`", p.kind.keyword(), p.name),
                        ty: None,
                    },
                );
                ix.labels.insert(key, lid);
                labels.push(lid);
                let span = self.map(l.span);
                children.push(Outline {
                    name: l.name.clone(),
                    detail: Some("label".into()),
                    kind: SymbolKind::KEY,
                    span,
                    sel: span,
                    children: Vec::new(),
                });
            }
        }
        ix.pou_labels.insert(id, labels);
        ix.files[self.f].outline.push(Outline {
            name: p.name.name.clone(),
            detail: Some(format!("{}{ret}", p.kind.keyword())),
            kind: pou_symbol_kind(p.kind),
            span: self.map(p.span),
            sel: self.map(p.name.span),
            children,
        });
        id
    }

    fn declare_block(
        &self,
        ix: &mut Index,
        owner: SymId,
        p: &ast::Pou,
        block: &ast::VarBlock,
        ir_vars: &HashMap<String, &ir::Var>,
    ) -> Vec<SymId> {
        let mut out = Vec::new();
        let mut head = block.kind.keyword().to_string();
        if block.constant {
            head.push_str(" CONSTANT");
        }
        match block.retain {
            ast::Retain::Retain => head.push_str(" RETAIN"),
            ast::Retain::NonRetain => head.push_str(" NON_RETAIN"),
            ast::Retain::Unspecified => {}
        }
        for d in &block.decls {
            for name in &d.names {
                let key = (owner, name.key());
                if ix.scope.contains_key(&key) {
                    continue; // declared twice: the checker reports it
                }
                let ir_var = ir_vars.get(&name.key());
                let mut note = format!(
                    "`{}` of {} `{}`",
                    block.kind.keyword(),
                    p.kind.keyword(),
                    p.name
                );
                let written = self.text(d.ty.span());
                if let Some(v) = ir_var
                    && !v.ty.to_string().eq_ignore_ascii_case(written)
                {
                    note.push_str(&format!("\n\ntype: `{}`", v.ty));
                }
                if let Some(loc) = &d.location {
                    note.push_str(&format!("\n\naddress: `{}`", self.text(loc.span)));
                }
                if let Some(fb) = spec_key(&d.ty).and_then(|k| sig::lookup_fb(&k)) {
                    note.push_str(&format!("\n\n{}", fb_signature(fb)));
                }
                let ty = ir_var
                    .and_then(|v| ty_key(&v.ty))
                    .or_else(|| spec_key(&d.ty));
                let id = self.add(
                    ix,
                    Symbol {
                        name: name.name.clone(),
                        kind: Kind::Var(block.kind),
                        file: self.f,
                        span: self.map(name.span),
                        container: Some(owner),
                        decl: format!("{head}\n    {}\nEND_VAR", self.decl_line(name, d)),
                        note,
                        ty,
                    },
                );
                ix.scope.insert(key, id);
                ix.members.entry(owner).or_default().push(id);
                out.push(id);
            }
        }
        out
    }

    /// `name AT %IX0.0 : BOOL := TRUE;` as written.
    fn decl_line(&self, name: &ast::Ident, d: &ast::VarDecl) -> String {
        let mut s = name.name.clone();
        if let Some(loc) = &d.location {
            s.push_str(&format!(" AT {}", self.text(loc.span)));
        }
        s.push_str(&format!(" : {}", self.text(d.ty.span())));
        match d.edge {
            Some(ast::Edge::Rising) => s.push_str(" R_EDGE"),
            Some(ast::Edge::Falling) => s.push_str(" F_EDGE"),
            None => {}
        }
        if let Some(init) = &d.init {
            s.push_str(&format!(" := {}", self.text(init.span())));
        }
        s.push(';');
        s
    }

    fn section_outline(&self, ix: &Index, block: &ast::VarBlock, vars: Vec<SymId>) -> Outline {
        Outline {
            name: block.kind.keyword().to_string(),
            detail: None,
            kind: SymbolKind::NAMESPACE,
            span: self.map(block.span),
            sel: self.map(Span::new(block.span.lo as usize, block.span.lo as usize)),
            children: vars
                .into_iter()
                .map(|v| {
                    let s = &ix.symbols[v];
                    Outline {
                        name: s.name.clone(),
                        detail: s.decl.lines().nth(1).map(|l| l.trim().to_string()),
                        kind: SymbolKind::VARIABLE,
                        span: s.span,
                        sel: s.span,
                        children: Vec::new(),
                    }
                })
                .collect(),
        }
    }

    fn declare_type(&self, ix: &mut Index, d: &ast::TypeDecl) {
        let id = self.add(
            ix,
            Symbol {
                name: d.name.name.clone(),
                kind: Kind::Type,
                file: self.f,
                span: self.map(d.name.span),
                container: None,
                decl: format!("TYPE {} : {} END_TYPE", d.name, self.text(d.spec.span())),
                note: String::new(),
                ty: None,
            },
        );
        ix.type_by_name.entry(d.name.key()).or_insert(id);
        let mut children = Vec::new();
        if let TypeSpec::Struct { fields, .. } = &d.spec {
            for fd in fields {
                for name in &fd.names {
                    let key = (id, name.key());
                    if ix.scope.contains_key(&key) {
                        continue;
                    }
                    let span = self.map(name.span);
                    let fid = self.add(
                        ix,
                        Symbol {
                            name: name.name.clone(),
                            kind: Kind::Field,
                            file: self.f,
                            span,
                            container: Some(id),
                            decl: self.decl_line(name, fd),
                            note: format!("field of STRUCT `{}`", d.name),
                            ty: spec_key(&fd.ty),
                        },
                    );
                    ix.scope.insert(key, fid);
                    ix.members.entry(id).or_default().push(fid);
                    children.push(Outline {
                        name: name.name.clone(),
                        detail: Some(self.text(fd.ty.span()).to_string()),
                        kind: SymbolKind::FIELD,
                        span,
                        sel: span,
                        children: Vec::new(),
                    });
                }
            }
        }
        ix.files[self.f].outline.push(Outline {
            name: d.name.name.clone(),
            detail: Some("TYPE".into()),
            kind: SymbolKind::STRUCT,
            span: self.map(d.span),
            sel: self.map(d.name.span),
            children,
        });
    }

    fn declare_config(&self, ix: &mut Index, c: &ast::Configuration) {
        let id = self.add(
            ix,
            Symbol {
                name: c.name.name.clone(),
                kind: Kind::Config,
                file: self.f,
                span: self.map(c.name.span),
                container: None,
                decl: format!("CONFIGURATION {}", c.name),
                note: String::new(),
                ty: None,
            },
        );
        let mut children = Vec::new();
        let blocks = c
            .globals
            .iter()
            .chain(c.resources.iter().flat_map(|r| &r.globals));
        for block in blocks {
            for d in &block.decls {
                for name in &d.names {
                    let key = (id, name.key());
                    if ix.scope.contains_key(&key) {
                        continue;
                    }
                    let span = self.map(name.span);
                    let gid = self.add(
                        ix,
                        Symbol {
                            name: name.name.clone(),
                            kind: Kind::Var(block.kind),
                            file: self.f,
                            span,
                            container: Some(id),
                            decl: format!("VAR_GLOBAL\n    {}\nEND_VAR", self.decl_line(name, d)),
                            note: format!("global of CONFIGURATION `{}`", c.name),
                            ty: spec_key(&d.ty),
                        },
                    );
                    ix.scope.insert(key, gid);
                    children.push(Outline {
                        name: name.name.clone(),
                        detail: Some(self.text(d.ty.span()).to_string()),
                        kind: SymbolKind::VARIABLE,
                        span,
                        sel: span,
                        children: Vec::new(),
                    });
                }
            }
        }
        ix.files[self.f].outline.push(Outline {
            name: c.name.name.clone(),
            detail: Some("CONFIGURATION".into()),
            kind: SymbolKind::PACKAGE,
            span: self.map(c.span),
            sel: self.map(c.name.span),
            children,
        });
    }

    /// References: types in declarations, names in bodies, program types
    /// of configurations.
    fn resolve(&self, ix: &mut Index, unit: &ast::CompilationUnit, pous: &[Option<SymId>]) {
        let mut k = 0;
        for item in &unit.items {
            match item {
                ast::Item::Pou(p) => {
                    let id = pous.get(k).copied().flatten();
                    k += 1;
                    let Some(id) = id else { continue };
                    if let Some(t) = &p.return_type {
                        self.type_ref(ix, t);
                    }
                    for b in &p.var_blocks {
                        for d in &b.decls {
                            self.type_ref(ix, &d.ty);
                        }
                    }
                    self.stmts(ix, id, &p.body);
                }
                ast::Item::Types(decls) => {
                    for d in decls {
                        if let TypeSpec::Struct { fields, .. } = &d.spec {
                            for fd in fields {
                                self.type_ref(ix, &fd.ty);
                            }
                        }
                    }
                }
                ast::Item::Configuration(c) => {
                    for r in &c.resources {
                        for pi in &r.programs {
                            if let Some(&s) = ix.pou_by_name.get(&pi.program.key()) {
                                self.push(ix, pi.program.span, Target::Sym(s));
                            }
                        }
                    }
                }
            }
        }
    }

    fn push(&self, ix: &mut Index, span: Span, t: Target) {
        let span = self.map(span);
        ix.files[self.f].refs.push((span, t));
    }

    fn type_ref(&self, ix: &mut Index, t: &TypeSpec) {
        match t {
            TypeSpec::Named(id) => {
                if let Some(s) = ix.type_sym(&id.key()) {
                    self.push(ix, id.span, Target::Sym(s));
                } else if let Some(fb) = sig::lookup_fb(&id.name) {
                    self.push(ix, id.span, Target::StdFb(fb));
                }
            }
            TypeSpec::Array { elem, .. } => self.type_ref(ix, elem),
            _ => {}
        }
    }

    fn stmts(&self, ix: &mut Index, pou: SymId, body: &[ast::Stmt]) {
        for s in body {
            if let ast::Stmt::Instr(i) = s {
                self.instr(ix, pou, i);
            }
        }
    }

    fn instr(&self, ix: &mut Index, pou: SymId, i: &ast::Instr) {
        match &i.kind {
            InstrKind::Load { operand: o, .. }
            | InstrKind::Store { target: o, .. }
            | InstrKind::Set { target: o }
            | InstrKind::Reset { target: o }
            | InstrKind::Expr { operand: o, .. }
            | InstrKind::FbInput { instance: o, .. } => {
                self.operand(ix, pou, o);
            }
            InstrKind::Deferred { first, body, .. } => {
                if let Some(o) = first {
                    self.operand(ix, pou, o);
                }
                self.stmts(ix, pou, body);
            }
            InstrKind::Jump { label, .. } => {
                if let Some(&l) = ix.labels.get(&(pou, label.key())) {
                    self.push(ix, label.span, Target::Sym(l));
                }
            }
            InstrKind::Call { target, args, .. } => {
                let ty = match target {
                    Operand::Var(v)
                        if v.path.is_empty() && ix.var_in(pou, &v.base.name).is_none() =>
                    {
                        // `CAL LIMIT(...)`: a function with a formal list.
                        self.function(ix, &v.base);
                        Some(v.base.key())
                    }
                    _ => self.operand(ix, pou, target),
                };
                if let Some(a) = args {
                    self.args(ix, pou, ty.as_deref(), a);
                }
            }
            InstrKind::FnCall { name, args } => {
                self.function(ix, name);
                self.args(ix, pou, Some(&name.key()), args);
            }
            InstrKind::Not | InstrKind::Return { .. } => {}
        }
    }

    /// A function's name: a user FUNCTION or a standard one.
    fn function(&self, ix: &mut Index, name: &ast::Ident) {
        if let Some(&s) = ix.pou_by_name.get(&name.key()) {
            self.push(ix, name.span, Target::Sym(s));
        } else if let Some(f) = sig::lookup(&name.name) {
            self.push(ix, name.span, Target::StdFn(f));
        }
    }

    /// An argument list of a call of `callee` (the instance's type or the
    /// function's name, upper case).
    fn args(&self, ix: &mut Index, pou: SymId, callee: Option<&str>, args: &CallArgs) {
        match args {
            CallArgs::NonFormal(ops) => {
                for o in ops {
                    self.operand(ix, pou, o);
                }
            }
            CallArgs::Formal(list) => {
                for a in list {
                    if let Some(t) = callee.and_then(|c| ix.member(c, &a.name.name)) {
                        self.push(ix, a.name.span, t);
                    }
                    match &a.kind {
                        ParamKind::Input(o) | ParamKind::Output { target: o, .. } => {
                            self.operand(ix, pou, o);
                        }
                    }
                }
            }
        }
    }

    /// An operand; returns the type of an FB or STRUCT it names.
    fn operand(&self, ix: &mut Index, pou: SymId, o: &Operand) -> Option<String> {
        let Operand::Var(v) = o else { return None };
        let base = ix.var_in(pou, &v.base.name);
        let mut ty = None;
        if let Some(s) = base {
            self.push(ix, v.base.span, Target::Sym(s));
            ty = ix.symbols[s].ty.clone();
        }
        for acc in &v.path {
            match acc {
                Accessor::Field(id) => {
                    let t = ty.take().and_then(|k| ix.member(&k, &id.name));
                    if let Some(t) = t {
                        self.push(ix, id.span, t);
                        if let Target::Sym(m) = t {
                            ty = ix.symbols[m].ty.clone();
                        }
                    }
                }
                Accessor::Index(ops, _) => {
                    for o in ops {
                        self.operand(ix, pou, o);
                    }
                }
                Accessor::Bit(..) => ty = None,
            }
        }
        ty
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
