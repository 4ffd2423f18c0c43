//! Declarations: POUs with their variables, sections and labels, types
//! with their fields, configurations with their globals; and the outline.

use std::collections::HashMap;

use il_codegen::ast::{self, Span, TypeSpec};
use il_codegen::ir;
use il_interp::il_std::signature as sig;
use lsp_types::SymbolKind;

use super::*;

impl Builder<'_> {
    /// Declarations: POUs with their variables and labels, types with
    /// their fields, configurations with their globals.
    pub(super) fn declare(
        &self,
        ix: &mut Index,
        unit: &ast::CompilationUnit,
        ir_pous: &HashMap<String, &ir::CheckedPou>,
    ) {
        for item in &unit.items {
            match item {
                ast::Item::Pou(p) => {
                    self.declare_pou(ix, p, ir_pous);
                }
                ast::Item::Types(decls) => {
                    for d in decls {
                        self.declare_type(ix, d);
                    }
                }
                ast::Item::Configuration(c) => self.declare_config(ix, c),
            }
        }
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
                name: p.name.name.to_string(),
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
                        name: l.name.to_string(),
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
                    name: l.name.to_string(),
                    detail: Some("label".into()),
                    kind: SymbolKind::KEY,
                    span,
                    sel: span,
                    children: Vec::new(),
                });
            }
        }
        ix.pou_labels.insert(id, labels);
        // A POU of a CODESYS export shows its project folder (`@PATH`).
        let folder = match self.input {
            il_codegen::Input::Exp(e) => e
                .folder_at(self.map(p.span).lo)
                .map(|f| format!(" · {f}"))
                .unwrap_or_default(),
            _ => String::new(),
        };
        ix.files[self.f].outline.push(Outline {
            name: p.name.name.to_string(),
            detail: Some(format!("{}{ret}{folder}", p.kind.keyword())),
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
                        name: name.name.to_string(),
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
        let mut s = name.name.to_string();
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
                        name: s.name.to_string(),
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
                name: d.name.name.to_string(),
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
                            name: name.name.to_string(),
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
                        name: name.name.to_string(),
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
            name: d.name.name.to_string(),
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
                name: c.name.name.to_string(),
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
                            name: name.name.to_string(),
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
                        name: name.name.to_string(),
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
            name: c.name.name.to_string(),
            detail: Some("CONFIGURATION".into()),
            kind: SymbolKind::PACKAGE,
            span: self.map(c.span),
            sel: self.map(c.name.span),
            children,
        });
    }
}
