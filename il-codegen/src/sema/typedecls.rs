//! TYPE ... END_TYPE: every declaration resolved and checked once, whether
//! anything uses it or not. What a type names is resolved before it (with
//! an explicit stack: a long chain of aliases neither overflows the stack
//! nor is walked again per use), and the results go to `Names::resolved`,
//! which every use reads: an error in a type is reported once, at the type,
//! in the file that declares it.

use super::Cx;
use super::codes::*;
use super::env::*;
use super::init::*;
use super::ir::{Const, Field, Init, TypeDef};
use super::recursion::cyclic_structs;
use super::resolve::*;
use super::types::{Name, Ty};
use crate::ast::{self, Span, TypeDecl, TypeSpec, VarDecl};
use std::collections::{HashMap, HashSet};

/// Resolve and check every TYPE declaration, filling `types` (enumerations
/// and structures, with the items to emit) and `names.resolved`. `decls`:
/// the declarations `names` knows, with the index of their file; `dups`:
/// those whose name was already taken, checked all the same (as a POU
/// declared twice is), their results dropped.
pub(crate) fn collect(
    cxs: &mut [Cx],
    names: &Names,
    decls: &[(usize, &TypeDecl)],
    dups: &[(usize, &TypeDecl)],
    types: &mut TypeTables,
) {
    // Enumerations and structures are types by their name alone: one
    // shared name for the type, its table entry and its constants.
    let mut enums = Vec::new();
    let mut structs = Vec::new();
    for (f, d) in decls {
        let shared: Name = d.name.name.to_string().into();
        let ty = match &d.spec {
            TypeSpec::Enum { values, .. } => {
                let vals = enum_values(&mut cxs[*f], d, values);
                let value_names = vals.iter().map(|(n, _)| n.clone()).collect();
                types
                    .enums
                    .insert(d.name.key(), (shared.clone(), value_names));
                enums.push((*f, *d, vals));
                Ty::Enum(shared)
            }
            TypeSpec::Struct { .. } => {
                structs.push((*f, *d));
                Ty::Struct(shared)
            }
            _ => continue,
        };
        let r = Resolved {
            ty: Some(ty),
            range: None,
            init: None,
        };
        names.resolved.borrow_mut().insert(d.name.key(), r);
    }
    let aliases = resolve_aliases(cxs, names, decls);
    // Field types first, for every STRUCT: an initial value (of a type or
    // a field) may be a structure initialiser of any STRUCT, declared
    // before or after.
    let drafts: Vec<(usize, &TypeDecl, Draft)> = structs
        .iter()
        .map(|(f, d)| (*f, *d, draft(&mut cxs[*f], names, d)))
        .collect();
    for (_, d, draft) in &drafts {
        types.structs.insert(d.name.key(), draft.fields.clone());
    }
    // The types' own initial values: enumerations and structures name no
    // other type; an alias after the type it names, whose value it inherits.
    let plain = enums.iter().map(|(f, d, _)| (*f, *d));
    for (f, d) in plain.chain(structs.iter().copied()).chain(aliases) {
        let (ty, range) = {
            let r = names.resolved.borrow();
            let r = r.get(&d.name.key());
            (r.and_then(|r| r.ty.clone()), r.and_then(|r| r.range))
        };
        let init = match (&d.init, &ty) {
            (Some(i), Some(ty)) => init_value(&mut cxs[f], types, i, ty, range),
            (Some(_), None) => None,
            (None, _) => names.type_init(&d.spec),
        };
        if let Some(r) = names.resolved.borrow_mut().get_mut(&d.name.key()) {
            r.init = init;
        }
    }
    for (f, d, vals) in enums {
        let resolved = names.resolved.borrow();
        let default = match resolved.get(&d.name.key()).and_then(|r| r.init.as_ref()) {
            Some(Init::Const(Const::Enum(e))) => {
                vals.iter().position(|(n, _)| *n == e.value).unwrap_or(0)
            }
            _ => 0,
        };
        types.defs.push((
            f,
            TypeDef::Enum {
                name: d.name.name.to_string(),
                values: vals,
                default,
            },
        ));
    }
    let mut done = Vec::new();
    for (f, d, mut draft) in drafts {
        draft.fill_inits(&mut cxs[f], names, types, fields_of(d));
        done.push((f, d, draft.fields));
    }
    for (f, d, fields) in done {
        types.structs.insert(d.name.key(), fields.clone());
        types.defs.push((
            f,
            TypeDef::Struct {
                name: d.name.name.to_string(),
                fields,
            },
        ));
    }
    // A STRUCT that contains itself has no finite size.
    let cyclic = cyclic_structs(types);
    for (f, d) in &structs {
        if cyclic.contains(&d.name.key()) {
            cxs[*f].err(
                RECURSION,
                d.name.span,
                format!("STRUCT `{}` contains itself", d.name),
            );
        }
    }
    for (f, d) in dups {
        check_duplicate(&mut cxs[*f], names, types, d);
    }
}

/// A type declared under a name already taken: its errors are reported
/// (the name's is, elsewhere), nothing is kept.
fn check_duplicate(cx: &mut Cx, names: &Names, types: &TypeTables, d: &TypeDecl) {
    match &d.spec {
        TypeSpec::Enum { values, .. } => {
            enum_values(cx, d, values);
        }
        TypeSpec::Struct { fields, .. } => {
            draft(cx, names, d).fill_inits(cx, names, types, fields);
        }
        spec => {
            let ty = resolve_type(cx, names, spec);
            if let (Some(ty), Some(i)) = (ty, &d.init) {
                init_value(cx, types, i, &ty, names.range_of(spec));
            }
        }
    }
}

/// The values of an enumeration, each with its explicit integer, if any;
/// a value named twice is reported and kept once.
fn enum_values(
    cx: &mut Cx,
    d: &TypeDecl,
    values: &[ast::EnumValue],
) -> Vec<(String, Option<i128>)> {
    let mut vals = Vec::new();
    let mut seen: HashSet<String> = HashSet::new();
    for v in values {
        check_ident(cx, &v.name);
        if !seen.insert(v.name.key()) {
            cx.err(
                DUPLICATE_DECL,
                v.name.span,
                format!("`{}` appears twice in `{}`", v.name, d.name),
            );
            continue;
        }
        let disc = match &v.value {
            None => None,
            Some(ast::Literal {
                kind: ast::LitKind::Int(n),
                ..
            }) if i64::try_from(n.get()).is_ok() => Some(n.get()),
            Some(l) => {
                cx.err(
                    BAD_INIT,
                    l.span,
                    "an enumeration value must be a (64-bit) integer",
                );
                None
            }
        };
        vals.push((v.name.name.to_string(), disc));
    }
    vals
}

/// Whether a type is resolved through what it names (not an enumeration or
/// a structure, which are types by their name).
fn is_alias(d: &TypeDecl) -> bool {
    !matches!(d.spec, TypeSpec::Enum { .. } | TypeSpec::Struct { .. })
}

/// The aliases a type spec names, each with where it is named.
fn alias_deps(names: &Names, spec: &TypeSpec, out: &mut Vec<(String, Span)>) {
    match spec {
        TypeSpec::Named(id) => {
            let key = id.key();
            if names.types.get(&key).is_some_and(|d| is_alias(d)) {
                out.push((key, id.span));
            }
        }
        TypeSpec::Array { elem, .. } => alias_deps(names, elem, out),
        _ => {}
    }
}

/// A type being resolved: what it names that is left to resolve first.
struct Frame<'u> {
    key: String,
    file: usize,
    decl: &'u TypeDecl,
    deps: std::vec::IntoIter<(String, Span)>,
}

/// Resolve every alias, subrange, array and string type after the aliases
/// it names, reporting a cycle once (at the name that closes it). Returns
/// them in that order.
fn resolve_aliases<'u>(
    cxs: &mut [Cx],
    names: &Names,
    decls: &[(usize, &'u TypeDecl)],
) -> Vec<(usize, &'u TypeDecl)> {
    let by_key: HashMap<String, (usize, &TypeDecl)> = decls
        .iter()
        .filter(|(_, d)| is_alias(d))
        .map(|(f, d)| (d.name.key(), (*f, *d)))
        .collect();
    let frame = |key: String, (file, decl): (usize, &'u TypeDecl)| {
        let mut deps = Vec::new();
        alias_deps(names, &decl.spec, &mut deps);
        Frame {
            key,
            file,
            decl,
            deps: deps.into_iter(),
        }
    };
    // Key → resolved (true) or on the stack (false).
    let mut state: HashMap<String, bool> = HashMap::new();
    let mut order = Vec::new();
    for (f, d) in decls.iter().filter(|(_, d)| is_alias(d)) {
        let root = d.name.key();
        if state.contains_key(&root) {
            continue;
        }
        state.insert(root.clone(), false);
        let mut stack = vec![frame(root, (*f, *d))];
        while let Some(top) = stack.last_mut() {
            if let Some((dep, span)) = top.deps.next() {
                match (state.get(&dep), by_key.get(&dep)) {
                    (None, Some(at)) => {
                        state.insert(dep.clone(), false);
                        let next = frame(dep, *at);
                        stack.push(next);
                    }
                    (Some(false), Some((_, named))) => {
                        cxs[top.file].err(
                            RECURSION,
                            span,
                            format!("type `{}` is defined in terms of itself", named.name),
                        );
                        // Its uses on the way back see an error, not a type.
                        let r = Resolved {
                            ty: None,
                            range: None,
                            init: None,
                        };
                        names.resolved.borrow_mut().insert(dep, r);
                    }
                    _ => {}
                }
                continue;
            }
            let Some(Frame {
                key, file, decl, ..
            }) = stack.pop()
            else {
                break;
            };
            let ty = resolve_type(&mut cxs[file], names, &decl.spec);
            let range = ty.as_ref().and(names.range_of(&decl.spec));
            let r = Resolved {
                ty,
                range,
                init: None,
            };
            names.resolved.borrow_mut().insert(key.clone(), r);
            state.insert(key, true);
            order.push((file, decl));
        }
    }
    order
}

/// A STRUCT's fields before their initial values: `from[i]` is the index of
/// the declaration of `fields[i]` (`a, b : INT := 1;` declares two).
struct Draft {
    fields: Vec<Field>,
    from: Vec<usize>,
}

fn fields_of(d: &TypeDecl) -> &[VarDecl] {
    match &d.spec {
        TypeSpec::Struct { fields, .. } => fields,
        _ => &[],
    }
}

/// The fields of a STRUCT with their types.
fn draft(cx: &mut Cx, names: &Names, d: &TypeDecl) -> Draft {
    let mut out = Draft {
        fields: Vec::new(),
        from: Vec::new(),
    };
    for (i, decl) in fields_of(d).iter().enumerate() {
        let Some(ty) = resolve_type(cx, names, &decl.ty) else {
            continue;
        };
        if matches!(ty, Ty::Fb(_)) {
            cx.err(
                BAD_OPERATOR_TYPE,
                decl.ty.span(),
                "a STRUCT field cannot be a function block instance",
            );
            continue;
        }
        let range = names.range_of(&decl.ty);
        for n in &decl.names {
            check_ident(cx, n);
            if out.fields.iter().any(|o| n.is(&o.name)) {
                cx.err(
                    DUPLICATE_DECL,
                    n.span,
                    format!("field `{n}` is declared twice"),
                );
                continue;
            }
            out.fields.push(Field {
                name: n.name.to_string(),
                ty: ty.clone(),
                init: None,
                range,
            });
            out.from.push(i);
        }
    }
    out
}

impl Draft {
    /// Check each field declaration's initial value once (its own, else
    /// its type's, else a subrange's lower limit) and give it to its fields.
    fn fill_inits(&mut self, cx: &mut Cx, names: &Names, types: &TypeTables, decls: &[VarDecl]) {
        let mut last: Option<(usize, Option<Init>)> = None;
        for (field, &i) in self.fields.iter_mut().zip(&self.from) {
            let init = match &last {
                Some((at, init)) if *at == i => init.clone(),
                _ => {
                    let Some(decl) = decls.get(i) else {
                        continue;
                    };
                    let init = match &decl.init {
                        Some(v) => init_value(cx, types, v, &field.ty, field.range),
                        None => names.type_init(&decl.ty),
                    }
                    .or_else(|| subrange_start(&field.ty, field.range));
                    last = Some((i, init.clone()));
                    init
                }
            };
            field.init = init;
        }
    }
}
