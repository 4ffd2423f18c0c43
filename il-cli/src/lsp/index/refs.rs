//! References: every written name resolved to its symbol (or to a
//! standard function or block), as the checker resolves it.

use il_codegen::ast::{self, Accessor, CallArgs, InstrKind, Operand, ParamKind, Span, TypeSpec};
use il_interp::il_std::signature as sig;

use super::*;

impl Builder<'_> {
    /// References: types in declarations, names in bodies, program types
    /// of configurations.
    pub(super) fn resolve(
        &self,
        ix: &mut Index,
        unit: &ast::CompilationUnit,
        pous: &[Option<SymId>],
    ) {
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
                Accessor::Index(subs, _) => {
                    for o in subs.iter().flat_map(|s| s.operands()) {
                        self.operand(ix, pou, o);
                    }
                }
                Accessor::Part { .. } => ty = None,
            }
        }
        ty
    }
}
