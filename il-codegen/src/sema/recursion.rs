//! What cannot be finite: POUs that call or hold themselves, STRUCTs that
//! contain themselves.

use super::Cx;
use super::codes::*;
use super::env::*;
use super::types::Ty;
use crate::ast::{self, Operand, PouKind, Span};
use std::collections::{HashMap, HashSet};

/// The STRUCTs (upper-case keys) that contain themselves through their
/// fields, arrays included: the nodes on a cycle of the field graph, found
/// once for all types (a walk from every STRUCT was quadratic on a chain of
/// thousands of types, and exponential before it was memoised).
pub(crate) fn cyclic_structs(t: &TypeTables) -> HashSet<String> {
    let mut keys: Vec<&String> = t.structs.keys().collect();
    keys.sort();
    let index: HashMap<&str, usize> = keys
        .iter()
        .enumerate()
        .map(|(i, k)| (k.as_str(), i))
        .collect();
    let succ: Vec<Vec<usize>> = keys
        .iter()
        .map(|k| {
            t.structs[*k]
                .iter()
                .filter_map(|f| {
                    let mut ty = &f.ty;
                    while let Ty::Array(a) = ty {
                        ty = &a.elem;
                    }
                    match ty {
                        Ty::Struct(n) => index.get(n.to_ascii_uppercase().as_str()).copied(),
                        _ => None,
                    }
                })
                .collect()
        })
        .collect();
    let on = super::graph::on_cycle(&succ);
    keys.into_iter()
        .zip(on)
        .filter(|(_, c)| *c)
        .map(|(k, _)| k.clone())
        .collect()
}

/// Refuse calls that lead back to the caller, and FBs that contain themselves.
pub(crate) fn check_recursion(cxs: &mut [Cx], env: &Env, units: &[&ast::CompilationUnit]) {
    // Edges: POU → POUs it calls (functions) or instantiates (FB types), with
    // the file and span of the reference.
    let mut edges: HashMap<String, Vec<(String, usize, Span)>> = HashMap::new();
    for (f, unit) in units.iter().enumerate() {
        for item in &unit.items {
            let ast::Item::Pou(p) = item else { continue };
            let me = p.name.key();
            let out = edges.entry(me.clone()).or_default();
            // Where each variable is declared: an instance that closes a
            // cycle is reported at its declaration, not at the POU's name.
            let mut decl_at: HashMap<String, Span> = HashMap::new();
            for n in p
                .var_blocks
                .iter()
                .flat_map(|b| &b.decls)
                .flat_map(|d| &d.names)
            {
                decl_at.entry(n.key()).or_insert(n.span);
            }
            if let Some(sig) = env.pou(&me) {
                for v in &sig.vars {
                    // An array of instances holds them too (`ARRAY OF Self`).
                    let mut ty = &v.ty;
                    while let Ty::Array(a) = ty {
                        ty = &a.elem;
                    }
                    if let Ty::Fb(t) = ty
                        && env.pou(t).is_some()
                    {
                        let at = decl_at.get(&v.name.to_ascii_uppercase());
                        out.push((t.to_ascii_uppercase(), f, *at.unwrap_or(&p.name.span)));
                    }
                }
            }
            let mut calls = Vec::new();
            collect_calls(&p.body, env, &mut calls);
            out.extend(calls.into_iter().map(|(k, s)| (k, f, s)));
        }
    }
    report_cycles(cxs, env, &edges);
}

/// Reported POUs per cycle: the rest of a large cycle is counted in a note,
/// so that a ring of thousands of POUs costs linear time, not quadratic.
pub(crate) const CYCLE_REPORTS: usize = 16;

/// One error for each POU that lies on a cycle of `edges` (up to
/// [`CYCLE_REPORTS`] per strongly connected component), at the reference that
/// closes its shortest cycle. Linear in the graph: the components come from
/// one pass of Kosaraju's algorithm, each path from a breadth-first search inside one
/// component. (A depth-first search per POU that copied its path was cubic:
/// 1,000 chained FUNCTIONs took 6 s.) Components: [`super::graph`].
pub(crate) fn report_cycles(
    cxs: &mut [Cx],
    env: &Env,
    edges: &HashMap<String, Vec<(String, usize, Span)>>,
) {
    let mut keys: Vec<&String> = edges.keys().collect();
    keys.sort();
    let index: HashMap<&str, usize> = keys
        .iter()
        .enumerate()
        .map(|(i, k)| (k.as_str(), i))
        .collect();
    // Successors by index (targets that are no POU of the program are dropped).
    let succ: Vec<Vec<(usize, usize, Span)>> = keys
        .iter()
        .map(|k| {
            edges[*k]
                .iter()
                .filter_map(|(t, f, sp)| index.get(t.as_str()).map(|&j| (j, *f, *sp)))
                .collect()
        })
        .collect();
    let plain: Vec<Vec<usize>> = succ
        .iter()
        .map(|out| out.iter().map(|e| e.0).collect())
        .collect();
    let (comp, comps) = super::graph::components(&plain);
    let name = |i: usize| env.pou(keys[i]).map_or(keys[i].clone(), |s| s.name.clone());
    for (c, members) in comps.iter().enumerate() {
        let cyclic = members.len() > 1 || succ[members[0]].iter().any(|e| e.0 == members[0]);
        if !cyclic {
            continue;
        }
        for &start in members.iter().take(CYCLE_REPORTS) {
            // Shortest path back to `start` inside its component.
            let mut parent: HashMap<usize, usize> = HashMap::new();
            let mut queue = std::collections::VecDeque::from([start]);
            let mut closing = None;
            'search: while let Some(v) = queue.pop_front() {
                for &(w, f, sp) in &succ[v] {
                    if comp[w] != c {
                        continue;
                    }
                    if w == start {
                        closing = Some((v, f, sp));
                        break 'search;
                    }
                    if w != start && !parent.contains_key(&w) {
                        parent.insert(w, v);
                        queue.push_back(w);
                    }
                }
            }
            let Some((last, f, span)) = closing else {
                continue;
            };
            let mut path = vec![start];
            let mut v = last;
            while v != start {
                path.push(v);
                v = parent[&v];
            }
            path[1..].reverse();
            path.push(start);
            let mut names: Vec<String> = path.iter().map(|&i| name(i)).collect();
            if names.len() > 12 {
                let cut = names.len() - 8;
                names.splice(4..cut, [format!("… {} more …", cut - 4)]);
            }
            let d = cxs[f].err(
                RECURSION,
                span,
                format!("recursion is not allowed: {}", names.join(" → ")),
            );
            if members.len() > CYCLE_REPORTS && start == members[0] {
                d.notes.push(format!(
                    "{} POUs lie on this cycle; {} of them are reported",
                    members.len(),
                    CYCLE_REPORTS
                ));
            }
        }
    }
}

pub(crate) fn collect_calls(body: &[ast::Stmt], env: &Env, out: &mut Vec<(String, Span)>) {
    for s in body {
        let ast::Stmt::Instr(i) = s else { continue };
        match &i.kind {
            ast::InstrKind::FnCall { name, .. } if env.pou(&name.name).is_some() => {
                out.push((name.key(), name.span))
            }
            ast::InstrKind::Call {
                target: Operand::Var(v),
                ..
            } if v.path.is_empty()
                && env
                    .pou(&v.base.name)
                    .is_some_and(|s| s.kind == PouKind::Function) =>
            {
                out.push((v.base.key(), v.base.span));
            }
            ast::InstrKind::Deferred { body, .. } => collect_calls(body, env, out),
            _ => {}
        }
    }
}
