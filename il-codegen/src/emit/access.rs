//! VAR_ACCESS in the generated configuration: a typed getter per access
//! path and, for READ_WRITE, a setter.

use super::text::doc;
use super::values::constant;
use super::{rust_ident, rust_ty};
use crate::ir::{AccessTarget, ConfigDef, Const, PathElem, Value};

/// `access_NAME(&self) -> T` and (READ_WRITE) `set_access_NAME(&mut self, v: T)`.
pub(super) fn methods(c: &ConfigDef) -> String {
    let mut out = String::new();
    for a in &c.access {
        let (path, what) = match &a.target {
            AccessTarget::Global { global: g, steps } => {
                let (v, base) = match g.resource {
                    None => (&c.globals[g.index], "self".to_string()),
                    Some(r) => {
                        let v = &c.resources[r].globals[g.index];
                        match &c.resources[r].name {
                            Some(n) => (v, format!("self.{}", rust_ident(n))),
                            None => (v, "self".to_string()),
                        }
                    }
                };
                (
                    format!(
                        "{base}.{}{}",
                        rust_ident(&v.name),
                        super::config_vars::steps(steps)
                    ),
                    format!("the global `{}`", written(&v.name, steps)),
                )
            }
            AccessTarget::Instance(p) => (
                super::config_vars::place(c, "self", p),
                format!("`{}`", p.text),
            ),
        };
        let ty = rust_ty(&a.ty);
        let get = rust_ident(&format!("access_{}", a.name));
        let d = doc(&format!(
            " VAR_ACCESS `{}` : {what} : {} {}.",
            a.name,
            a.ty,
            if a.writable {
                "READ_WRITE"
            } else {
                "READ_ONLY"
            }
        ));
        out.push_str(&format!(
            "{d}pub fn {get}(&self) -> {ty} {{ ::core::clone::Clone::clone(&{path}) }}"
        ));
        if !a.writable {
            continue;
        }
        let set = rust_ident(&format!("set_access_{}", a.name));
        match (a.range, a.ty.elem()) {
            // A subrange place keeps its value when the host's is outside
            // it, as a store in a body skips it; the host is told.
            (Some((lo, hi)), Some(e)) => {
                let d = doc(&format!(
                    " Writes VAR_ACCESS `{}` (READ_WRITE). A value outside the subrange {lo}..{hi} is not written: `Err(FaultKind::SubrangeViolation)`.",
                    a.name
                ));
                let (lo, hi) = (
                    constant(&Const::Int(lo.into(), e)),
                    constant(&Const::Int(hi.into(), e)),
                );
                out.push_str(&format!(
                    "{d}pub fn {set}(&mut self, value: {ty}) -> ::core::result::Result<(), ::il_std::FaultKind> {{ if !({lo}..={hi}).contains(&value) {{ return ::core::result::Result::Err(::il_std::FaultKind::SubrangeViolation); }} {path} = value; ::core::result::Result::Ok(()) }}"
                ));
            }
            _ => {
                let d = doc(&format!(" Writes VAR_ACCESS `{}` (READ_WRITE).", a.name));
                out.push_str(&format!(
                    "{d}pub fn {set}(&mut self, value: {ty}) {{ {path} = value; }}"
                ));
            }
        }
    }
    out
}

/// `g.x`, `h[3]`: a global's path as IEC writes it, for the doc comment.
fn written(global: &str, steps: &[PathElem]) -> String {
    let mut t = global.to_string();
    for e in steps {
        match e {
            PathElem::Field(f) => {
                t.push('.');
                t.push_str(&f.name);
            }
            PathElem::Index { subs, .. } => {
                let subs: Vec<String> = subs
                    .iter()
                    .map(|s| match s {
                        Value::Const(Const::Int(n, _)) => n.get().to_string(),
                        _ => "?".to_string(),
                    })
                    .collect();
                t.push_str(&format!("[{}]", subs.join(", ")));
            }
            PathElem::Part { index, .. } => t.push_str(&format!(".{index}")),
        }
    }
    t
}
