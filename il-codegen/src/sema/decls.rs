//! Declarations: POU interfaces, variable types, initial values, literals.

use super::codes::*;
use super::env::*;
use super::init::*;
use super::ir::{Field, TypeDef};
use super::recursion::*;
use super::resolve::*;
use super::types::{Elem, Ty};
use super::{Cx, stdfb};
use crate::ast::{self, Initializer, LitKind, Literal, Operand, Span, TypeSpec};
use std::collections::{HashMap, HashSet};

pub(crate) fn collect(cxs: &mut [Cx], units: &[&ast::CompilationUnit]) -> Env {
    let mut env = Env {
        pous: Default::default(),
        types: TypeTables::default(),
        holds_retain: Default::default(),
        configs: Vec::new(),
        sizes: Default::default(),
        duplicates: Vec::new(),
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
            .map(|(_, p)| (p.name.key(), (p.name.name.to_string(), p.kind)))
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
                check_ident(&mut cxs[*f], &v.name);
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
                    }) if i64::try_from(n.get()).is_ok() => Some(n.get()),
                    Some(l) => {
                        cxs[*f].err(
                            BAD_INIT,
                            l.span,
                            "an enumeration value must be a (64-bit) integer",
                        );
                        None
                    }
                };
                vals.push((v.name.name.to_string(), disc));
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
                    d.name.name.to_string().into(),
                    vals.iter().map(|(n, _)| n.clone()).collect(),
                ),
            );
            env.types.defs.push((
                *f,
                TypeDef::Enum {
                    name: d.name.name.to_string(),
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
                let init = init
                    .and_then(|i| init_value(&mut cxs[*f], &env.types, i, &ty, range))
                    .or_else(|| subrange_start(&ty, range));
                for n in &decl.names {
                    check_ident(&mut cxs[*f], n);
                    if out.iter().any(|o| n.is(&o.name)) {
                        cxs[*f].err(
                            DUPLICATE_DECL,
                            n.span,
                            format!("field `{n}` is declared twice"),
                        );
                        continue;
                    }
                    out.push(Field {
                        name: n.name.to_string(),
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
                    name: d.name.name.to_string(),
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
        let mut sig = pou_sig(&mut cxs[*f], &fb_names, &env.types, p);
        sig.file = *f;
        match env.pous.entry(p.name.key()) {
            std::collections::hash_map::Entry::Occupied(_) => env.duplicates.push(sig),
            std::collections::hash_map::Entry::Vacant(e) => {
                e.insert(sig);
            }
        }
    }
    env.configs = super::configuration::collect(cxs, units, &fb_names, &mut env);
    super::configuration::check_fb_externals(cxs, &pous, &env);
    env
}
use super::interface::pou_sig;
