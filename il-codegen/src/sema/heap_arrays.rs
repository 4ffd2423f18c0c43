//! Large arrays: how many bytes a type takes, which arrays the generated code
//! keeps on the heap, and where a large array is refused.
//!
//! Creating an instance builds its value on the stack (`Default::default()`
//! returns it by value, and debug builds copy it more than once), and a
//! thread's stack is a few MiB: a PROGRAM holding `ARRAY[0..1999999] OF LREAL`
//! (16 MB) overflowed it. So an array of more than [`LARGE_ARRAY_BYTES`] that
//! is a variable of a FUNCTION_BLOCK or PROGRAM (VAR, VAR_INPUT, VAR_OUTPUT)
//! becomes a `Box<[Row]>` field, built element by element on the heap; a
//! large array anywhere else would be a stack value and is refused (IL0134),
//! as is any use of a large array as a whole (a load, store or argument copies
//! it through the stack).

use super::Cx;
use super::codes::TOO_LARGE;
use super::env::{Env, Sizes};
use super::types::{Elem, Ty};
use crate::ast::{self, PouKind, VarKind};

/// An array larger than this many bytes is large (64 KiB).
pub const LARGE_ARRAY_BYTES: u64 = 64 * 1024;

/// The bytes of an elementary value.
fn elem_bytes(e: Elem) -> u64 {
    use Elem::*;
    match e {
        BOOL | SINT | USINT | BYTE => 1,
        INT | UINT | WORD => 2,
        DINT | UDINT | DWORD | REAL => 4,
        _ => 8,
    }
}

fn key(t: &Ty) -> Option<String> {
    match t {
        Ty::Fb(n) => Some(format!("FB:{}", n.to_ascii_uppercase())),
        Ty::Struct(n) => Some(format!("S:{}", n.to_ascii_uppercase())),
        _ => None,
    }
}

/// Whether variable `v` of a POU of kind `kind` is a field of its struct.
fn is_field(kind: PouKind, v: &super::ir::Var) -> bool {
    kind != PouKind::Function
        && matches!(v.kind, VarKind::Input | VarKind::Output | VarKind::Var)
        && v.location.is_none()
}

/// The bytes of a value of `t` (an estimate: no padding), computing and
/// recording the sizes of the named types it holds. `depth` bounds the
/// recursion: nesting beyond IL0133's limit is refused anyway.
fn size(env: &Env, t: &Ty, memo: &mut Sizes, depth: u32) -> u64 {
    match t {
        Ty::Elem(e) => elem_bytes(*e),
        Ty::Str { wide, len } => (*len as u64 + 1) * if *wide { 2 } else { 1 } + 8,
        Ty::Enum(_) => 8,
        Ty::Array(a) => {
            let (dims, elem) = (&a.dims, &a.elem);
            let n = dims.iter().fold(1u64, |n, (lo, hi)| {
                n.saturating_mul((hi - lo + 1).max(0) as u64)
            });
            n.saturating_mul(size(env, elem, memo, depth))
        }
        Ty::Fb(name) if env.pou(name).is_none() => 64, // a standard FB
        Ty::Fb(_) | Ty::Struct(_) => {
            let k = key(t).unwrap_or_default();
            if let Some(s) = memo.get(&k) {
                return *s;
            }
            if depth > 256 {
                return 0;
            }
            memo.insert(k.clone(), 0); // a cycle (refused elsewhere) counts 0
            let s = match t {
                Ty::Fb(name) => {
                    let sig = env.pou(name);
                    let (kind, vars) =
                        sig.map_or((PouKind::Program, &[][..]), |s| (s.kind, &s.vars[..]));
                    vars.iter()
                        .filter(|v| is_field(kind, v))
                        .map(|v| {
                            let b = size(env, &v.ty, memo, depth + 1);
                            // A large array field is a boxed slice.
                            if matches!(v.ty, Ty::Array { .. }) && b > LARGE_ARRAY_BYTES {
                                16
                            } else {
                                b
                            }
                        })
                        .fold(0u64, u64::saturating_add)
                }
                Ty::Struct(n) => env
                    .types
                    .structs
                    .get(&n.to_ascii_uppercase())
                    .map_or(0, |fs| {
                        fs.iter()
                            .map(|f| size(env, &f.ty, memo, depth + 1))
                            .fold(0u64, u64::saturating_add)
                    }),
                _ => 0,
            };
            memo.insert(k, s);
            s
        }
    }
}

/// Whether `t` is an array of more than [`LARGE_ARRAY_BYTES`], with the
/// sizes of named types that [`mark_heap`] recorded in `env`.
pub(crate) fn is_large(env: &Env, t: &Ty) -> bool {
    fn bytes(env: &Env, t: &Ty) -> u64 {
        match t {
            Ty::Array(a) => a
                .dims
                .iter()
                .fold(1u64, |n, (lo, hi)| {
                    n.saturating_mul((hi - lo + 1).max(0) as u64)
                })
                .saturating_mul(bytes(env, &a.elem)),
            Ty::Fb(n) if env.pou(n).is_none() => 64,
            Ty::Fb(_) | Ty::Struct(_) => {
                key(t).and_then(|k| env.sizes.get(&k).copied()).unwrap_or(0)
            }
            Ty::Elem(e) => elem_bytes(*e),
            Ty::Str { wide, len } => (*len as u64 + 1) * if *wide { 2 } else { 1 } + 8,
            Ty::Enum(_) => 8,
        }
    }
    matches!(t, Ty::Array { .. }) && bytes(env, t) > LARGE_ARRAY_BYTES
}

/// Compute every named type's size, mark the large array fields of FBs and
/// PROGRAMs as heap fields, and refuse large arrays where they would be stack
/// values: FUNCTION variables and results, VAR_TEMP, VAR_IN_OUT, VAR_EXTERNAL,
/// VAR_GLOBAL, STRUCT fields, and arrays whose rows are large.
pub(crate) fn mark_heap(cxs: &mut [Cx], env: &mut Env, units: &[&ast::CompilationUnit]) {
    let mut memo = Sizes::new();
    let mut named: Vec<Ty> = env
        .pous
        .values()
        .map(|s| Ty::Fb(s.name.clone().into()))
        .collect();
    named.extend(
        env.types
            .structs
            .keys()
            .map(|k| Ty::Struct(k.clone().into())),
    );
    for t in &named {
        size(env, t, &mut memo, 0);
    }
    let mut heap: Vec<(String, usize)> = Vec::new();
    let refuse = |cx: &mut Cx, span: crate::ast::Span, name: &str, bytes: u64, why: &str| {
        cx.err(
            TOO_LARGE,
            span,
            format!("`{name}` is an array of {bytes} bytes, more than 64 KiB, {why}"),
        )
        .notes
        .push("an array over 64 KiB can only be a VAR, VAR_INPUT or VAR_OUTPUT of a FUNCTION_BLOCK or PROGRAM, whose instance keeps it on the heap".into());
    };
    for (f, unit) in units.iter().enumerate() {
        for item in &unit.items {
            match item {
                ast::Item::Pou(p) => {
                    let Some(sig) = env
                        .pou(&p.name.name)
                        .filter(|s| s.file == f && s.span == p.name.span)
                    else {
                        continue;
                    };
                    for d in p.var_blocks.iter().flat_map(|b| &b.decls) {
                        for n in &d.names {
                            let Some((i, v)) = sig.var(&n.name) else {
                                continue;
                            };
                            if !matches!(v.ty, Ty::Array { .. }) {
                                continue;
                            }
                            let bytes = size(env, &v.ty, &mut memo, 0);
                            if bytes <= LARGE_ARRAY_BYTES {
                                continue;
                            }
                            let row_bytes = size(env, &v.ty.row(), &mut memo, 0);
                            if !is_field(sig.kind, v) {
                                let why = match (sig.kind, v.kind) {
                                    (PouKind::Function, _) => {
                                        "too large for a FUNCTION, whose variables live on the stack"
                                    }
                                    (_, VarKind::Temp) => {
                                        "too large for VAR_TEMP, which lives on the stack"
                                    }
                                    _ => {
                                        "too large for a VAR_IN_OUT, VAR_EXTERNAL or located variable"
                                    }
                                };
                                refuse(&mut cxs[f], n.span, &n.name, bytes, why);
                            } else if row_bytes > LARGE_ARRAY_BYTES {
                                refuse(
                                    &mut cxs[f],
                                    n.span,
                                    &n.name,
                                    bytes,
                                    &format!(
                                        "whose rows (the elements of its first dimension) are {row_bytes} bytes each, over 64 KiB too: only the first dimension can be on the heap"
                                    ),
                                );
                            } else {
                                heap.push((p.name.key(), i));
                            }
                        }
                    }
                    if let (Some(r), Some(spec)) = (&sig.ret, &p.return_type)
                        && matches!(r, Ty::Array { .. })
                    {
                        let bytes = size(env, r, &mut memo, 0);
                        if bytes > LARGE_ARRAY_BYTES {
                            refuse(
                                &mut cxs[f],
                                spec.span(),
                                &p.name.name,
                                bytes,
                                "too large for a FUNCTION result, which is returned on the stack",
                            );
                        }
                    }
                }
                ast::Item::Types(decls) => {
                    for d in decls {
                        let ast::TypeSpec::Struct { fields, .. } = &d.spec else {
                            continue;
                        };
                        let Some(resolved) = env.types.structs.get(&d.name.key()) else {
                            continue;
                        };
                        for fd in fields {
                            for n in &fd.names {
                                let Some(field) = resolved.iter().find(|x| n.is(&x.name)) else {
                                    continue;
                                };
                                if matches!(field.ty, Ty::Array { .. }) {
                                    let bytes = size(env, &field.ty, &mut memo, 0);
                                    if bytes > LARGE_ARRAY_BYTES {
                                        refuse(
                                            &mut cxs[f],
                                            n.span,
                                            &n.name,
                                            bytes,
                                            "too large for a STRUCT field (a STRUCT is a value, copied on the stack)",
                                        );
                                    }
                                }
                            }
                        }
                    }
                }
                ast::Item::Configuration(c) => {
                    let blocks = c
                        .globals
                        .iter()
                        .chain(c.resources.iter().flat_map(|r| &r.globals));
                    let defs = env
                        .configs
                        .iter()
                        .filter(|(cf, d)| *cf == f && c.name.is(&d.name));
                    let globals: Vec<&super::ir::Var> = defs
                        .flat_map(|(_, d)| {
                            d.globals
                                .iter()
                                .chain(d.resources.iter().flat_map(|r| &r.globals))
                        })
                        .collect();
                    for d in blocks.flat_map(|b| &b.decls) {
                        for n in &d.names {
                            let Some(v) = globals.iter().find(|v| n.is(&v.name)) else {
                                continue;
                            };
                            if matches!(v.ty, Ty::Array { .. }) {
                                let bytes = size(env, &v.ty, &mut memo, 0);
                                if bytes > LARGE_ARRAY_BYTES {
                                    refuse(
                                        &mut cxs[f],
                                        n.span,
                                        &n.name,
                                        bytes,
                                        "too large for a VAR_GLOBAL (not supported yet: declare it in the PROGRAM that uses it)",
                                    );
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    for (pou, i) in heap {
        if let Some(v) = env.pous.get_mut(&pou).and_then(|s| s.vars.get_mut(i)) {
            v.heap = true;
        }
    }
    env.sizes = memo;
}
