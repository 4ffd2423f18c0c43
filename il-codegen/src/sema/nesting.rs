//! How deeply FB instances, STRUCTs and arrays nest: rustc stops at its
//! recursion limit (128) when it looks through nested types ("reached the
//! recursion limit finding the struct tail", "overflow while checking whether
//! `FB` requires drop"), so a program it would refuse is refused here first.

use super::Cx;
use super::codes::TOO_DEEP;
use super::env::Env;
use super::types::Ty;
use crate::ast;
use std::collections::HashMap;

/// The deepest nesting accepted, in levels: each user FUNCTION_BLOCK,
/// PROGRAM or STRUCT is one, each array dimension one, a standard FB counts
/// as 3, STRING as 2, other elementary types and enumerations as 1. rustc
/// compiles 128 nested structs and 65 levels of FB-in-array (131 levels by
/// this count); 120 leaves room for what the generated code adds around a
/// program (a CONFIGURATION and its RESOURCE, RETAIN snapshots).
pub const MAX_NESTING: u32 = 120;

/// A named type whose nesting is measured: user FBs/PROGRAMs and STRUCTs.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
enum Node<'a> {
    Pou(&'a str),
    Struct(&'a str),
}

/// The named types inside `ty`, each with the levels its arrays add, and the
/// depth of the rest (elementary values, standard FBs).
fn parts<'a>(ty: &'a Ty, env: &Env, out: &mut Vec<(Node<'a>, u32)>) -> u32 {
    let (mut t, mut dims) = (ty, 0u32);
    while let Ty::Array(a) = t {
        dims = dims.saturating_add(a.dims.len() as u32);
        t = &a.elem;
    }
    let leaf = match t {
        Ty::Fb(n) if env.pou(n).is_some() => {
            out.push((Node::Pou(n), dims));
            return 0;
        }
        Ty::Struct(n) => {
            out.push((Node::Struct(n), dims));
            return 0;
        }
        Ty::Fb(_) => 3,
        Ty::Str { .. } => 2,
        Ty::Elem(_) | Ty::Enum(_) | Ty::Array(_) => 1,
    };
    dims.saturating_add(leaf)
}

/// The fields' types of a node.
fn field_types<'a>(env: &'a Env, n: Node<'_>) -> Vec<&'a Ty> {
    match n {
        Node::Pou(p) => env
            .pou(p)
            .map(|s| s.vars.iter().map(|v| &v.ty).collect())
            .unwrap_or_default(),
        Node::Struct(s) => env
            .types
            .structs
            .get(&s.to_ascii_uppercase())
            .map(|f| f.iter().map(|f| &f.ty).collect())
            .unwrap_or_default(),
    }
}

/// Refuse every FUNCTION_BLOCK, PROGRAM and STRUCT nested deeper than
/// [`MAX_NESTING`], at the outermost type that is still within the limit's
/// reach (the one whose parts all fit), so a long chain is reported once.
/// Each type's depth is computed once (an explicit stack, no recursion: a
/// chain of a million types neither overflows the stack nor takes long).
pub(crate) fn check_nesting(cxs: &mut [Cx], env: &Env, units: &[&ast::CompilationUnit]) {
    // Memo: upper-case key → depth; `None` while being computed (a cycle,
    // which check_recursion reports, counts as depth 0 here).
    let mut memo: HashMap<(bool, String), Option<u32>> = HashMap::new();
    let key = |n: Node| match n {
        Node::Pou(p) => (true, p.to_ascii_uppercase()),
        Node::Struct(s) => (false, s.to_ascii_uppercase()),
    };
    let mut depth_of = |root: Node| -> u32 {
        // (node, whether its parts were pushed)
        let mut stack = vec![(root, false)];
        while let Some((n, expanded)) = stack.pop() {
            let k = key(n);
            if !expanded {
                if memo.contains_key(&k) {
                    continue;
                }
                // One step per type resolved: the memo makes it once each.
                crate::step_counter::add(1);
                memo.insert(k, None);
                stack.push((n, true));
                let mut ps = Vec::new();
                for t in field_types(env, n) {
                    parts(t, env, &mut ps);
                }
                stack.extend(ps.into_iter().map(|(c, _)| (c, false)));
            } else {
                let mut ps = Vec::new();
                let mut d = 0u32;
                for t in field_types(env, n) {
                    d = d.max(parts(t, env, &mut ps));
                }
                for (c, dims) in ps {
                    let cd = memo.get(&key(c)).copied().flatten().unwrap_or(0);
                    d = d.max(cd.saturating_add(dims));
                }
                memo.insert(k, Some(d.saturating_add(1)));
            }
        }
        memo.get(&key(root)).copied().flatten().unwrap_or(0)
    };
    let mut found = Vec::new();
    for (f, unit) in units.iter().enumerate() {
        for item in &unit.items {
            match item {
                // A duplicate POU has no signature of its own.
                ast::Item::Pou(p)
                    if p.kind != ast::PouKind::Function
                        && env
                            .pou(&p.name.name)
                            .is_some_and(|s| s.file == f && s.span == p.name.span) =>
                {
                    found.push((f, Node::Pou(p.name.name.as_ref()), p.name.span));
                }
                ast::Item::Types(decls) => {
                    for d in decls {
                        if matches!(d.spec, ast::TypeSpec::Struct { .. }) {
                            found.push((f, Node::Struct(d.name.name.as_ref()), d.name.span));
                        }
                    }
                }
                _ => {}
            }
        }
    }
    for (f, n, span) in found {
        let d = depth_of(n);
        if d <= MAX_NESTING {
            continue;
        }
        // The part that makes it too deep, if that part itself fits.
        let mut ps = Vec::new();
        for t in field_types(env, n) {
            parts(t, env, &mut ps);
        }
        let deepest = ps
            .iter()
            .map(|(c, dims)| (*c, depth_of(*c).saturating_add(*dims)))
            .max_by_key(|(_, d)| *d);
        if deepest.is_some_and(|(c, _)| depth_of(c) > MAX_NESTING) {
            continue; // reported at that part
        }
        let (what, name) = match n {
            Node::Pou(p) => ("the block", p),
            Node::Struct(s) => ("STRUCT", s),
        };
        let through = deepest.map_or(String::new(), |(c, _)| {
            let (Node::Pou(c) | Node::Struct(c)) = c;
            format!(" (through `{c}`)")
        });
        cxs[f]
            .err(
                TOO_DEEP,
                span,
                format!(
                    "{what} `{name}` nests instances, STRUCTs and arrays {d} levels deep{through}; at most {MAX_NESTING} levels are supported"
                ),
            )
            .notes
            .push(
                "rustc cannot compile types nested much deeper (its recursion limit is 128); \
                 flatten the hierarchy: hold the inner blocks side by side"
                    .to_string(),
            );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::SourceFile;

    /// IL0133 diagnostics of `src`, through declaration collection and this
    /// check only (the flow checks are not needed here).
    fn too_deep(src: &str) -> Vec<String> {
        let file = SourceFile::new("t.il", src);
        let (unit, _) = crate::syntax::parse(&file);
        let mut cxs = vec![Cx {
            file: &file,
            diags: Vec::new(),
            standard: Default::default(),
            cr_steps: false,
            names: None,
        }];
        let env = super::super::decls::collect(&mut cxs, &[&unit]);
        check_nesting(&mut cxs, &env, &[&unit]);
        cxs[0]
            .diags
            .iter()
            .filter(|d| d.code == TOO_DEEP)
            .map(|d| d.message.clone())
            .collect()
    }

    /// Each level holds two instances of the next: 2^n instances in the
    /// tree, but n types; the walk is linear in the types (a walk over the
    /// instances would not finish), and the chain is reported once.
    #[test]
    fn a_diamond_of_instances_is_measured_once_per_type() {
        let n = 2000;
        let mut src = String::new();
        for k in 1..=n {
            let inner = if k < n {
                format!("a : D{0}; b : D{0}; ", k + 1)
            } else {
                String::new()
            };
            src.push_str(&format!(
                "FUNCTION_BLOCK D{k}\nVAR x : INT; {inner}END_VAR\n LD x\n ST x\nEND_FUNCTION_BLOCK\n"
            ));
        }
        let t = std::time::Instant::now();
        let d = too_deep(&src);
        assert_eq!(d.len(), 1, "{d:?}");
        assert!(d[0].contains(&format!("`D{}`", n - 119)), "{d:?}");
        assert!(d[0].contains("121 levels"), "{d:?}");
        assert!(t.elapsed() < std::time::Duration::from_secs(20));
    }

    /// A cycle (reported as IL0117 elsewhere) does not loop here.
    #[test]
    fn a_cycle_ends() {
        let src = "FUNCTION_BLOCK A\nVAR b : B; END_VAR\nEND_FUNCTION_BLOCK\n\
                   FUNCTION_BLOCK B\nVAR a : A; END_VAR\nEND_FUNCTION_BLOCK\n\
                   TYPE S : STRUCT s : S; END_STRUCT; END_TYPE\n";
        assert_eq!(too_deep(src), Vec::<String>::new());
    }
}
