//! The resolution table ([`ir::Resolutions`]): each name the checker
//! resolves is noted where it resolves it (a [`Key`] at a span), then the
//! keys become the symbols of the declarations. Only when asked: the
//! compiler never reads it.

use std::collections::HashMap;

use super::super::env::{Env, PouSig};
use super::Walk;
use crate::ast::{self, Span, TypeSpec};
use crate::ir::{Decl, Resolutions, Symbol, SymbolId, SymbolKind};

pub(crate) use super::keys::Key;

/// Names noted in one file.
pub(crate) type Noted = Vec<(Span, Key)>;

impl Walk<'_, '_> {
    /// Note that the name at `span` names `key()`: on the final pass, when
    /// the table is asked for (the closure builds nothing otherwise).
    pub(super) fn note(&mut self, span: Span, key: impl FnOnce(&Self) -> Option<Key>) {
        if self.final_pass
            && self.noting
            && let Some(k) = key(self)
        {
            self.noted.push((span, k));
        }
    }

    /// The POU being checked, as a key.
    pub(super) fn pou_key(&self) -> String {
        self.sig.name.to_ascii_uppercase()
    }

    /// The key of member `name` of FB or STRUCT type `fb`.
    pub(super) fn member_key(&self, fb: &str, name: &str) -> Option<Key> {
        if let Some(s) = il_std::signature::lookup_fb(fb) {
            let m = s
                .inputs
                .iter()
                .chain(s.outputs)
                .find(|p| p.name.eq_ignore_ascii_case(name))?;
            return Some(Key::StdMember(s.name, m.name));
        }
        let up = fb.to_ascii_uppercase();
        if let Some(fields) = self.env.types.structs.get(&up) {
            let i = fields
                .iter()
                .position(|f| f.name.eq_ignore_ascii_case(name))?;
            return Some(Key::Field(up, i));
        }
        let (i, _) = self.env.pou(fb)?.var(name)?;
        Some(Key::Var(up, i))
    }
}

impl Walk<'_, '_> {
    /// An instruction no path reaches is not checked, and one with an error
    /// is checked up to it, but their names are still the program's (an
    /// editor finds and renames them): noted from the declarations alone,
    /// as [`Walk::place`] resolves them (a name the check noted keeps its
    /// symbol: the table keeps the first note of a span).
    pub(super) fn note_dead(&mut self, i: &ast::Instr) {
        if !(self.final_pass && self.noting) {
            return;
        }
        use ast::InstrKind as K;
        match &i.kind {
            K::Deferred { body, .. } => {
                for s in body {
                    if let ast::Stmt::Instr(i) = s {
                        self.note_dead(i);
                    }
                }
            }
            K::Jump { label, .. } => {
                if let Some(&l) = self.labels.get(&label.key()) {
                    self.note(label.span, |w| Some(Key::Label(w.pou_key(), l)));
                }
            }
            K::Call { target, args, .. } => {
                let fb = match target {
                    ast::Operand::Var(v)
                        if v.path.is_empty()
                            && self.sig.var(&v.base.name).is_none()
                            && self.is_function(&v.base.name) =>
                    {
                        self.note_function(&v.base);
                        Some(v.base.name.to_string())
                    }
                    ast::Operand::Var(v) => match self.dead_ref(v) {
                        Some(super::Ty::Fb(t)) => Some(t.to_string()),
                        _ => None,
                    },
                    _ => None,
                };
                if let (Some(fb), Some(args)) = (fb, args) {
                    self.note_params(&fb, args);
                }
            }
            K::FnCall { name, args } => {
                self.note_function(name);
                self.note_params(&name.name, args);
            }
            _ => {}
        }
        let mut vars = Vec::new();
        operands_of(i, &mut vars);
        for v in vars {
            self.dead_ref(v);
        }
    }

    /// A function's name: a user FUNCTION or a standard one.
    fn note_function(&mut self, name: &ast::Ident) {
        self.note(name.span, |w| {
            if w.env.pou(&name.name).is_some() {
                return Some(Key::Pou(name.key()));
            }
            il_std::signature::lookup(&name.name).map(|s| Key::StdFn(s.name))
        });
    }

    /// The names of a formal list of a call of `callee` (an FB type or a
    /// function).
    fn note_params(&mut self, callee: &str, args: &ast::CallArgs) {
        if let ast::CallArgs::Formal(list) = args {
            for p in list {
                self.note(p.name.span, |w| w.member_key(callee, &p.name.name));
            }
        }
    }

    /// Note a variable reference's names; its type, as declared.
    fn dead_ref(&mut self, v: &ast::VarRef) -> Option<super::Ty> {
        self.note(v.base.span, |w| match w.sig.var(&v.base.name) {
            Some((i, _)) => Some(Key::Var(w.pou_key(), i)),
            None => (w.sig.kind == ast::PouKind::Function && v.base.is(&w.sig.name))
                .then(|| Key::Pou(w.pou_key())),
        });
        let (_, var) = self.sig.var(&v.base.name)?;
        let mut ty = var.ty.clone();
        for acc in &v.path {
            ty = match (acc, &ty) {
                (ast::Accessor::Field(f), super::Ty::Fb(t) | super::Ty::Struct(t)) => {
                    let t = t.clone();
                    self.note(f.span, |w| w.member_key(&t, &f.name));
                    self.find_member(&t, &f.name)?.1
                }
                (ast::Accessor::Index(..), super::Ty::Array(a)) => a.elem.clone(),
                _ => return None,
            };
        }
        Some(ty)
    }
}

/// The variable references of an instruction (not of those inside its
/// parentheses), subscripts included.
fn operands_of<'i>(i: &'i ast::Instr, out: &mut Vec<&'i ast::VarRef>) {
    fn op<'i>(o: &'i ast::Operand, out: &mut Vec<&'i ast::VarRef>) {
        if let ast::Operand::Var(v) = o {
            out.push(v);
            for a in &v.path {
                if let ast::Accessor::Index(subs, _) = a {
                    for s in subs {
                        s.operands().into_iter().for_each(|o| op(o, out));
                    }
                }
            }
        }
    }
    fn args<'i>(a: &'i ast::CallArgs, out: &mut Vec<&'i ast::VarRef>) {
        match a {
            ast::CallArgs::NonFormal(list) => list.iter().for_each(|o| op(o, out)),
            ast::CallArgs::Formal(list) => {
                for p in list {
                    match &p.kind {
                        ast::ParamKind::Input(o) | ast::ParamKind::Output { target: o, .. } => {
                            op(o, out)
                        }
                    }
                }
            }
        }
    }
    use ast::InstrKind as K;
    match &i.kind {
        K::Load { operand: o, .. }
        | K::Expr { operand: o, .. }
        | K::Store { target: o, .. }
        | K::Set { target: o }
        | K::Reset { target: o }
        | K::FbInput { instance: o, .. } => op(o, out),
        K::Deferred { first, .. } => {
            if let Some(o) = first {
                op(o, out);
            }
        }
        K::Call {
            target, args: a, ..
        } => {
            op(target, out);
            if let Some(a) = a {
                args(a, out);
            }
        }
        K::FnCall { args: a, .. } => args(a, out),
        K::Not | K::Jump { .. } | K::Return { .. } => {}
    }
}

/// The symbols of the declarations of every unit, then every noted name
/// as a use of its symbol. `spans` moves a span of input `f`'s IL text to
/// the file the user wrote (the pipeline's business: see
/// [`crate::Checked::resolutions`]).
/// `noted`: per file, the names noted, in pieces (the declarations', each
/// POU's), in the order they were noted.
pub(crate) fn table(
    env: &Env,
    units: &[&ast::CompilationUnit],
    noted: &[Vec<&[(Span, Key)]>],
) -> Resolutions {
    let mut t = Table::default();
    t.out.uses = vec![Vec::new(); units.len()];
    for (f, unit) in units.iter().enumerate() {
        for item in &unit.items {
            match item {
                ast::Item::Pou(p) => {
                    if let Some(sig) = env
                        .pou(&p.name.name)
                        .filter(|s| s.file == f && s.span == p.name.span)
                    {
                        t.pou(f, p, sig);
                    }
                }
                ast::Item::Types(decls) => {
                    for d in decls {
                        t.type_decl(env, f, d);
                    }
                }
                ast::Item::Configuration(c) => t.config(env, f, c),
            }
        }
    }
    t.externals();
    let late = std::mem::take(&mut t.late);
    let noted = noted.iter().enumerate().flat_map(|(f, pieces)| {
        pieces
            .iter()
            .flat_map(|l| l.iter())
            .map(move |(s, k)| (f, *s, k))
    });
    for (f, span, key) in late.iter().map(|(f, s, k)| (*f, *s, k)).chain(noted) {
        if let Some(id) = t.id(key) {
            t.out.uses[f].push((span, id));
        }
    }
    for u in &mut t.out.uses {
        u.sort_by_key(|(s, _)| (s.lo, s.hi));
        u.dedup_by_key(|(s, _)| *s);
    }
    t.out
}

#[derive(Default)]
struct Table {
    out: Resolutions,
    // Fx: the table looks up every name of the program here.
    ids: rustc_hash::FxHashMap<Key, SymbolId>,
    /// Global name (upper case) → its first symbol, for VAR_EXTERNALs.
    globals: HashMap<String, SymbolId>,
    externals: Vec<(SymbolId, String)>,
    /// Names of declarations that name other declarations: (file, span, key).
    late: Vec<(usize, Span, Key)>,
}

impl Table {
    /// Declare `key` at `name` of file `f` (the first declaration wins:
    /// the checker reports the others).
    fn declare(
        &mut self,
        f: usize,
        name: &ast::Ident,
        key: Key,
        kind: SymbolKind,
    ) -> Option<SymbolId> {
        if self.ids.contains_key(&key) {
            return None;
        }
        let id = self.out.symbols.len();
        self.out.symbols.push(Symbol {
            name: name.name.to_string(),
            kind,
            decl: Some(Decl {
                file: f,
                span: name.span,
            }),
        });
        self.ids.insert(key, id);
        self.out.uses[f].push((name.span, id));
        Some(id)
    }

    /// The symbol of a key; a standard one is made on its first use.
    fn id(&mut self, key: &Key) -> Option<SymbolId> {
        if let Some(&id) = self.ids.get(key) {
            return Some(id);
        }
        let (name, kind) = match *key {
            Key::StdFn(n) => (n, SymbolKind::StdFunction),
            Key::StdFb(n) => (n, SymbolKind::StdBlock),
            Key::StdMember(b, m) => {
                let block = self.id(&Key::StdFb(b))?;
                let input = il_std::signature::lookup_fb(b)
                    .is_some_and(|s| s.inputs.iter().any(|p| p.name == m));
                (m, SymbolKind::StdMember { block, input })
            }
            _ => return None,
        };
        let id = self.out.symbols.len();
        self.out.symbols.push(Symbol {
            name: name.to_string(),
            kind,
            decl: None,
        });
        self.ids.insert(key.clone(), id);
        Some(id)
    }

    fn pou(&mut self, f: usize, p: &ast::Pou, sig: &PouSig) {
        let key = p.name.key();
        let Some(pou) = self.declare(f, &p.name, Key::Pou(key.clone()), SymbolKind::Pou(p.kind))
        else {
            return;
        };
        for block in &p.var_blocks {
            for d in &block.decls {
                for name in &d.names {
                    let Some((index, var)) = sig.var(&name.name) else {
                        continue;
                    };
                    let kind = SymbolKind::Var {
                        pou,
                        index,
                        kind: var.kind,
                        global: None,
                    };
                    let id = self.declare(f, name, Key::Var(key.clone(), index), kind);
                    if let Some(id) = id
                        && var.kind == ast::VarKind::External
                    {
                        self.externals.push((id, name.key()));
                    }
                }
            }
        }
        // Numbered as the body checker numbers them.
        let mut labels: HashMap<String, usize> = HashMap::new();
        for s in &p.body {
            if let ast::Stmt::Label(l) = s {
                let n = labels.len();
                if let std::collections::hash_map::Entry::Vacant(e) = labels.entry(l.key()) {
                    e.insert(n);
                    self.declare(f, l, Key::Label(key.clone(), n), SymbolKind::Label { pou });
                }
            }
        }
    }

    fn type_decl(&mut self, env: &Env, f: usize, d: &ast::TypeDecl) {
        let key = d.name.key();
        let Some(ty) = self.declare(f, &d.name, Key::Type(key.clone()), SymbolKind::Type) else {
            return;
        };
        match &d.spec {
            TypeSpec::Struct { fields, .. } => {
                let names = fields.iter().flat_map(|fd| &fd.names);
                let declared = env.types.structs.get(&key);
                for name in names {
                    let Some(i) = declared.and_then(|fs| fs.iter().position(|x| name.is(&x.name)))
                    else {
                        continue;
                    };
                    self.declare(
                        f,
                        name,
                        Key::Field(key.clone(), i),
                        SymbolKind::Field { ty },
                    );
                }
            }
            TypeSpec::Enum { values, .. } => {
                for (i, v) in values.iter().enumerate() {
                    self.declare(
                        f,
                        &v.name,
                        Key::EnumValue(key.clone(), i),
                        SymbolKind::EnumValue { ty },
                    );
                }
            }
            _ => {}
        }
    }

    fn config(&mut self, env: &Env, f: usize, c: &ast::Configuration) {
        let key = c.name.key();
        let Some(config) = self.declare(f, &c.name, Key::Config(key.clone()), SymbolKind::Config)
        else {
            return;
        };
        let blocks = c
            .globals
            .iter()
            .chain(c.resources.iter().flat_map(|r| &r.globals));
        for block in blocks {
            for name in block.decls.iter().flat_map(|d| &d.names) {
                let id = self.declare(
                    f,
                    name,
                    Key::Global(key.clone(), name.key()),
                    SymbolKind::Global { config },
                );
                if let Some(id) = id {
                    self.globals.entry(name.key()).or_insert(id);
                }
            }
        }
        for r in &c.resources {
            if let Some(n) = &r.name {
                self.declare(
                    f,
                    n,
                    Key::Resource(key.clone(), n.key()),
                    SymbolKind::Resource { config },
                );
            }
            for pi in &r.programs {
                let kind = SymbolKind::ProgramInstance { config };
                self.declare(f, &pi.name, Key::Instance(key.clone(), pi.name.key()), kind);
                // The program type, looked up once every POU is declared.
                if env.pou(&pi.program.name).is_some() {
                    self.late
                        .push((f, pi.program.span, Key::Pou(pi.program.key())));
                }
            }
        }
    }

    /// A VAR_EXTERNAL refers to the global of its name.
    fn externals(&mut self) {
        for (id, name) in std::mem::take(&mut self.externals) {
            let g = self.globals.get(&name).copied();
            if let SymbolKind::Var { global, .. } = &mut self.out.symbols[id].kind {
                *global = g;
            }
        }
    }
}
