//! Declarations: the names of POUs and types, then the types
//! (`typedecls.rs`), every POU's interface and the configurations.

use super::codes::*;
use super::env::*;
use super::resolve::*;
use super::types::Elem;
use super::{Cx, stdfb};
use crate::ast::{self, Span};
use std::collections::HashMap;

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
    let mut dups: Vec<(usize, &ast::TypeDecl)> = Vec::new();
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
                    dups.push((f, d));
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
        resolved: Default::default(),
        depth: std::cell::Cell::new(0),
    };
    super::typedecls::collect(cxs, &fb_names, &type_file, &dups, &mut env.types);
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
    env.configs = super::config::collect(cxs, units, &fb_names, &mut env);
    super::config::check_fb_externals(cxs, &pous, &env);
    env
}
use super::interface::pou_sig;
