//! A POU's interface: its variables, their sections, types, initial values
//! and addresses, as the callers and the body checker see it.

use super::Cx;
use super::codes::*;
use super::env::*;
use super::init::*;
use super::ir::{Const, Init, Storage, Var};
use super::resolve::*;
use super::types::Ty;
use crate::ast::{self, Operand, PouKind, Span};
use std::collections::{HashMap, HashSet};

pub(crate) fn pou_sig(cx: &mut Cx, fb_names: &Names, types: &TypeTables, p: &ast::Pou) -> PouSig {
    check_ident(cx, &p.name);
    let mut sig = PouSig {
        kind: p.kind,
        name: p.name.name.to_string(),
        vars: Vec::new(),
        index: Default::default(),
        ret: None,
        file: 0,
        poisoned: HashSet::new(),
        span: p.name.span,
    };
    if p.kind == PouKind::Function {
        sig.ret = p
            .return_type
            .as_ref()
            .and_then(|t| resolve_type(cx, fb_names, t));
        if let Some(Ty::Fb(_)) = sig.ret {
            cx.err(
                BAD_OPERATOR_TYPE,
                p.name.span,
                "a FUNCTION cannot return a function block",
            );
            sig.ret = None;
        }
    }
    let mut spans: HashMap<String, Span> = HashMap::new();
    for block in &p.var_blocks {
        // Every declared name is poisoned: uses of a name whose declaration
        // is refused below stay silent (the lookup finds real variables first).
        for decl in &block.decls {
            sig.poisoned.extend(decl.names.iter().map(|n| n.key()));
        }
        let refused = match (p.kind, block.kind) {
            (_, ast::VarKind::Global) => Some((
                BAD_SECTION,
                "VAR_GLOBAL belongs in a CONFIGURATION or RESOURCE: declare the variable there and use it here through VAR_EXTERNAL",
            )),
            (PouKind::Function, ast::VarKind::External) => Some((
                BAD_SECTION,
                "a FUNCTION cannot use globals (VAR_EXTERNAL): pass the value as an input or a VAR_IN_OUT",
            )),
            _ => None,
        };
        if let Some((code, msg)) = refused {
            cx.err(code, block.span, msg);
            continue;
        }
        let by_ref = matches!(block.kind, ast::VarKind::InOut | ast::VarKind::External);
        if by_ref && block.retain == ast::Retain::Retain {
            cx.err(
                BAD_SECTION,
                block.span,
                format!(
                    "{} cannot be RETAIN: the variable it refers to decides",
                    block.kind.keyword()
                ),
            );
        }
        for decl in &block.decls {
            if by_ref && (decl.init.is_some() || decl.location.is_some()) {
                cx.err(
                    BAD_SECTION,
                    decl.span,
                    format!(
                        "a {} refers to a variable declared elsewhere: it takes no initial value and no address",
                        block.kind.keyword()
                    ),
                );
                continue;
            }
            if decl.edge.is_some()
                && (p.kind == PouKind::Function || block.kind != ast::VarKind::Input)
            {
                cx.err(BAD_OPERATOR_TYPE, decl.span, "R_EDGE and F_EDGE apply to VAR_INPUTs of a FUNCTION_BLOCK or PROGRAM (a FUNCTION has no memory)");
                continue;
            }
            let Some(ty) = resolve_type(cx, fb_names, &decl.ty) else {
                // Already reported; uses of these names stay silent.
                sig.poisoned.extend(decl.names.iter().map(|n| n.key()));
                continue;
            };
            if p.kind == PouKind::Function && matches!(ty, Ty::Fb(_)) {
                cx.err(
                    BAD_OPERATOR_TYPE,
                    decl.ty.span(),
                    "a FUNCTION cannot hold function block instances (it has no memory)",
                );
                continue;
            }
            let partly = match &decl.location {
                Some(a) if a.partial => {
                    if !super::partial_address::allowed(cx, p.kind, block.kind, a, &ty) {
                        sig.poisoned.extend(decl.names.iter().map(|n| n.key()));
                        continue;
                    }
                    Some((a.area, cx.file.snippet(a.span).to_string()))
                }
                _ => None,
            };
            let location = match &decl.location {
                None => None,
                Some(a) if a.partial => None,
                Some(_) if p.kind == PouKind::Function => {
                    cx.err(
                        BAD_ADDRESS,
                        decl.span,
                        "a FUNCTION cannot have located variables (AT %...)",
                    );
                    continue;
                }
                Some(a) => match resolve_addr(cx, a, Some(&ty)) {
                    Some(l) => Some(l),
                    None => {
                        sig.poisoned.extend(decl.names.iter().map(|n| n.key()));
                        continue;
                    }
                },
            };
            if location.is_some() && decl.init.is_some() {
                cx.warn(BAD_INIT, decl.span, "the initial value of a located variable is not applied: the host owns the process image");
            }
            let range = fb_names.range_of(&decl.ty);
            let init = match &decl.init {
                Some(i) => init_value(cx, types, i, &ty, range),
                // Checked once, where the type is declared.
                None => fb_names.type_init(&decl.ty),
            }
            .or_else(|| subrange_start(&ty, range));
            for name in &decl.names {
                check_ident(cx, name);
                let key = name.key();
                let clash = p.kind == PouKind::Function
                    && (key == p.name.key() || key == "ENO" || key == "EN");
                if let Some(prev) = spans.get(&key) {
                    cx.err(
                        DUPLICATE_DECL,
                        name.span,
                        format!("`{name}` is declared twice"),
                    )
                    .add_secondary(*prev, "first declared here");
                    continue;
                }
                if clash {
                    cx.err(
                        DUPLICATE_DECL,
                        name.span,
                        format!("`{name}` is reserved in a FUNCTION (its result, EN or ENO)"),
                    );
                    continue;
                }
                spans.insert(key.clone(), name.span);
                sig.index.insert(&key, sig.vars.len());
                sig.vars.push(Var {
                    name: name.name.to_string(),
                    location: location.clone(),
                    partly: partly.clone(),
                    edge: decl.edge,
                    range,
                    kind: block.kind,
                    storage: Storage::of(p.kind, block.kind, location.is_some()),
                    ty: ty.clone(),
                    init: init.clone(),
                    constant: block.constant,
                    retain: block.retain == ast::Retain::Retain,
                    heap: false,
                    line: cx.line(name.span),
                    doc: super::docs::trailing(cx.file, name.span),
                });
            }
        }
    }
    if p.kind == PouKind::Function && mentions(&p.body, "ENO") {
        // ENO exists on every function; it is an output (TRUE on entry) of
        // those whose body sets it.
        sig.index.insert("ENO", sig.vars.len());
        sig.vars.push(Var {
            name: "ENO".into(),
            location: None,
            partly: None,
            edge: None,
            range: None,
            kind: ast::VarKind::Output,
            storage: Storage::OutParam,
            ty: Ty::BOOL,
            init: Some(Init::Const(Const::Bool(true))),
            constant: false,
            retain: false,
            heap: false,
            line: cx.line(p.name.span),
            doc: None,
        });
    }
    sig
}

/// Whether any operand of the body names `name`.
pub(crate) fn mentions(body: &[ast::Stmt], name: &str) -> bool {
    let op = |o: &Operand| matches!(o, Operand::Var(v) if v.base.is(name));
    body.iter().any(|s| match s {
        ast::Stmt::Instr(i) => match &i.kind {
            ast::InstrKind::Load { operand, .. } | ast::InstrKind::Expr { operand, .. } => {
                op(operand)
            }
            ast::InstrKind::Store { target, .. }
            | ast::InstrKind::Set { target }
            | ast::InstrKind::Reset { target } => op(target),
            ast::InstrKind::Deferred { first, body, .. } => {
                first.as_deref().is_some_and(op) || mentions(body, name)
            }
            ast::InstrKind::FnCall {
                args: ast::CallArgs::NonFormal(l),
                ..
            } => l.iter().any(op),
            _ => false,
        },
        ast::Stmt::Label(_) => false,
    })
}
