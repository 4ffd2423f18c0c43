//! VAR_CONFIG in the generated configuration: initial values set when it is
//! created, and addresses completing `AT %I*` / `%Q*` / `%M*` variables,
//! copied between the process image and the field around each run of the
//! program instance (inputs before, outputs after, memory both ways).

use super::{rust_ident, values};
use crate::ast::Area;
use crate::ir::{ConfigDef, InstancePath, PathElem};

/// `base.Res.prog.fb.x` (`base.Res.prog.a[1].b`) for an instance path
/// (`base` is `self` or `__s`); a standard block's member is its il-std
/// field (`tmr.PT`).
pub(super) fn place(c: &ConfigDef, base: &str, p: &InstancePath) -> String {
    let mut t = base.to_string();
    if let Some(r) = &c.resources[p.resource].name {
        t.push('.');
        t.push_str(&rust_ident(r));
    }
    t.push('.');
    t.push_str(&rust_ident(
        &c.resources[p.resource].programs[p.program].name,
    ));
    t.push_str(&steps(&p.steps));
    t
}

/// `.field[k]...` for the steps of a configuration path: members by their
/// Rust names, elements by literal offsets (the checker proved them inside
/// the bounds, so indexing cannot fail).
pub(super) fn steps(steps: &[PathElem]) -> String {
    let mut t = String::new();
    for e in steps {
        match e {
            PathElem::Field(f) => {
                t.push('.');
                t.push_str(&rust_ident(&f.name));
            }
            _ => {
                for k in e.constant_index().map(|(o, _)| o).unwrap_or_default() {
                    t.push_str(&format!("[{k}]"));
                }
            }
        }
    }
    t
}

/// Statements applying the VAR_CONFIG initial values to `__s`, the new
/// configuration.
pub(super) fn inits(c: &ConfigDef) -> String {
    let mut out = String::new();
    for v in &c.var_config {
        if let Some(i) = &v.init {
            let p = place(c, "__s", &v.target);
            let val = values::init_value(&v.target.ty, Some(i));
            out.push_str(&format!("{p} = {val};"));
        }
    }
    out
}

/// The copies into (`before`) or out of the fields of program `prog` of
/// resource `res`.
pub(super) fn copies(c: &ConfigDef, res: usize, prog: usize, before: bool) -> String {
    let mut out = String::new();
    for v in &c.var_config {
        let Some(l) = &v.location else { continue };
        if (v.target.resource, v.target.program) != (res, prog) {
            continue;
        }
        let p = place(c, "self", &v.target);
        match (before, l.area) {
            (true, Area::Input | Area::Memory) => {
                out.push_str(&format!("{p} = {};", values::io_read(l)));
            }
            (false, Area::Output | Area::Memory) => out.push_str(&values::io_write(l, p)),
            _ => {}
        }
    }
    out
}

/// `ADDRESSES` entries of the addresses VAR_CONFIG gives.
pub(super) fn located(c: &ConfigDef) -> Vec<String> {
    c.var_config
        .iter()
        .filter_map(|v| {
            Some(super::io::located(
                &v.target.text,
                v.location.as_ref()?,
                false,
            ))
        })
        .collect()
}
