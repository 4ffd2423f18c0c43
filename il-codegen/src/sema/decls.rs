//! Declarations: POU interfaces, variable types, initial values, literals.

use super::codes::*;
use super::env::*;
use super::init::*;
use super::ir::{Const, Field, Init, Storage, TypeDef, Var};
use super::recursion::*;
use super::resolve::*;
use super::types::{Elem, Ty};
use super::{Cx, stdfb};
use crate::ast::{self, Initializer, LitKind, Literal, Operand, PouKind, Span, TypeSpec};
use std::collections::{HashMap, HashSet};

pub(crate) fn collect(cxs: &mut [Cx], units: &[&ast::CompilationUnit]) -> Env {
    let mut env = Env {
        pous: HashMap::new(),
        types: TypeTables::default(),
        holds_retain: Default::default(),
        configs: Vec::new(),
    };
    let mut seen: HashMap<String, (usize, Span)> = HashMap::new();
    let pous: Vec<(usize, &ast::Pou)> = units
        .iter()
        .enumerate()
        .flat_map(|(f, u)| {
            u.items.iter().filter_map(move |i| match i {
                ast::Item::Pou(p) => Some((f, p)),
                _ => None,
            })
        })
        .collect();
    for (f, p) in &pous {
        let key = p.name.key();
        if let Some((pf, prev)) = seen.get(&key).copied() {
            let other = cxs[pf].file.name.clone();
            let d = cxs[*f].err(
                DUPLICATE_DECL,
                p.name.span,
                format!("`{}` is declared twice", p.name),
            );
            if pf == *f {
                d.add_secondary(prev, "first declared here");
            } else {
                d.add_note(format!("first declared in {other}"));
            }
        } else {
            seen.insert(key.clone(), (*f, p.name.span));
            if stdfb::lookup(&key).is_some() || super::stdfn::is_std(&key) {
                cxs[*f].err(
                    DUPLICATE_DECL,
                    p.name.span,
                    format!("`{}` is the name of a standard block or function", p.name),
                );
            }
        }
    }
    // Every POU and user type by upper-case key, across all files.
    let mut types: HashMap<String, &ast::TypeDecl> = HashMap::new();
    let mut type_file: Vec<(usize, &ast::TypeDecl)> = Vec::new();
    for (f, unit) in units.iter().enumerate() {
        for item in &unit.items {
            let ast::Item::Types(decls) = item else {
                continue;
            };
            for d in decls {
                let key = d.name.key();
                check_ident(&mut cxs[f], &d.name);
                if types.contains_key(&key)
                    || seen.contains_key(&key)
                    || Elem::from_name(&key).is_some()
                    || stdfb::lookup(&key).is_some()
                {
                    cxs[f].err(
                        DUPLICATE_DECL,
                        d.name.span,
                        format!("`{}` is already the name of a type or POU", d.name),
                    );
                    continue;
                }
                types.insert(key, d);
                type_file.push((f, d));
            }
        }
    }
    let fb_names = Names {
        pous: pous
            .iter()
            .map(|(_, p)| (p.name.key(), (p.name.name.clone(), p.kind)))
            .collect(),
        types,
        depth: std::cell::Cell::new(0),
    };
    // Enumerations first (struct fields and initial values refer to them).
    for (f, d) in &type_file {
        if let TypeSpec::Enum { values, .. } = &d.spec {
            let mut vals = Vec::new();
            let mut seen_vals: HashSet<String> = HashSet::new();
            for v in values {
                if !seen_vals.insert(v.name.key()) {
                    cxs[*f].err(
                        DUPLICATE_DECL,
                        v.name.span,
                        format!("`{}` appears twice in `{}`", v.name, d.name),
                    );
                    continue;
                }
                let disc = match &v.value {
                    None => None,
                    Some(Literal {
                        kind: LitKind::Int(n),
                        ..
                    }) if i64::try_from(*n).is_ok() => Some(*n),
                    Some(l) => {
                        cxs[*f].err(
                            BAD_INIT,
                            l.span,
                            "an enumeration value must be a (64-bit) integer",
                        );
                        None
                    }
                };
                vals.push((v.name.name.clone(), disc));
            }
            let default = match &d.init {
                Some(Initializer::Simple(Operand::Var(v))) => {
                    vals.iter().position(|(n, _)| v.base.is(n)).unwrap_or(0)
                }
                _ => 0,
            };
            env.types.enums.insert(
                d.name.key(),
                (
                    d.name.name.clone(),
                    vals.iter().map(|(n, _)| n.clone()).collect(),
                ),
            );
            env.types.defs.push((
                *f,
                TypeDef::Enum {
                    name: d.name.name.clone(),
                    values: vals,
                    default,
                },
            ));
        }
    }
    for (f, d) in &type_file {
        if let TypeSpec::Struct { fields, .. } = &d.spec {
            let mut out: Vec<Field> = Vec::new();
            for decl in fields {
                let Some(ty) = resolve_type(&mut cxs[*f], &fb_names, &decl.ty) else {
                    continue;
                };
                if matches!(ty, Ty::Fb(_)) {
                    cxs[*f].err(
                        BAD_OPERATOR_TYPE,
                        decl.ty.span(),
                        "a STRUCT field cannot be a function block instance",
                    );
                    continue;
                }
                let range = fb_names.range_of(&decl.ty);
                let init = decl
                    .init
                    .as_ref()
                    .or_else(|| fb_names.default_init(&decl.ty));
                let init = init.and_then(|i| init_value(&mut cxs[*f], &env.types, i, &ty, range));
                for n in &decl.names {
                    if out.iter().any(|o| n.is(&o.name)) {
                        cxs[*f].err(
                            DUPLICATE_DECL,
                            n.span,
                            format!("field `{n}` is declared twice"),
                        );
                        continue;
                    }
                    out.push(Field {
                        name: n.name.clone(),
                        ty: ty.clone(),
                        init: init.clone(),
                        range,
                    });
                }
            }
            env.types.structs.insert(d.name.key(), out.clone());
            env.types.defs.push((
                *f,
                TypeDef::Struct {
                    name: d.name.name.clone(),
                    fields: out,
                },
            ));
        }
    }
    // A STRUCT that contains itself has no finite size.
    let cyclic = cyclic_structs(&env.types);
    for (f, d) in &type_file {
        if matches!(d.spec, TypeSpec::Struct { .. }) && cyclic.contains(&d.name.key()) {
            cxs[*f].err(
                RECURSION,
                d.name.span,
                format!("STRUCT `{}` contains itself", d.name),
            );
        }
    }
    for (f, p) in &pous {
        if env.pous.contains_key(&p.name.key()) {
            continue;
        }
        let mut sig = pou_sig(&mut cxs[*f], &fb_names, &env.types, p);
        sig.file = *f;
        env.pous.insert(p.name.key(), sig);
    }
    env.configs = super::configuration::collect(cxs, units, &fb_names, &mut env);
    super::configuration::check_fb_externals(cxs, &pous, &env);
    env
}

pub(crate) fn pou_sig(cx: &mut Cx, fb_names: &Names, types: &TypeTables, p: &ast::Pou) -> PouSig {
    check_ident(cx, &p.name);
    let mut sig = PouSig {
        kind: p.kind,
        name: p.name.name.clone(),
        vars: Vec::new(),
        index: HashMap::new(),
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
            (PouKind::Program, ast::VarKind::InOut) => Some((
                UNSUPPORTED,
                "VAR_IN_OUT of a PROGRAM is not supported: share the variable through VAR_GLOBAL/VAR_EXTERNAL",
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
            let location = match &decl.location {
                None => None,
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
            let init = decl
                .init
                .as_ref()
                .or_else(|| fb_names.default_init(&decl.ty));
            let init = init.and_then(|i| init_value(cx, types, i, &ty, range));
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
                sig.index.insert(key, sig.vars.len());
                sig.vars.push(Var {
                    name: name.name.clone(),
                    location: location.clone(),
                    edge: decl.edge,
                    range,
                    kind: block.kind,
                    storage: Storage::of(p.kind, block.kind, location.is_some()),
                    ty: ty.clone(),
                    init: init.clone(),
                    constant: block.constant,
                    retain: block.retain == ast::Retain::Retain,
                    line: cx.line(name.span),
                });
            }
        }
    }
    if p.kind == PouKind::Function && mentions(&p.body, "ENO") {
        // ENO exists on every function; it is an output (TRUE on entry) of
        // those whose body sets it.
        sig.index.insert("ENO".into(), sig.vars.len());
        sig.vars.push(Var {
            name: "ENO".into(),
            location: None,
            edge: None,
            range: None,
            kind: ast::VarKind::Output,
            storage: Storage::OutParam,
            ty: Ty::BOOL,
            init: Some(Init::Const(Const::Bool(true))),
            constant: false,
            retain: false,
            line: cx.line(p.name.span),
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
                first.as_ref().is_some_and(op) || mentions(body, name)
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
