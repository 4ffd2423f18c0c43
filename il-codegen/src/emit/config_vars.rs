//! VAR_CONFIG in the generated configuration: initial values set when it is
//! created, and addresses completing `AT %I*` / `%Q*` / `%M*` variables,
//! copied between the process image and the field around each run of the
//! program instance (inputs before, outputs after, memory both ways).

use super::{rust_ident, values};
use crate::ast::Area;
use crate::sema::ir::{ConfigDef, InstancePath};
use proc_macro2::TokenStream;
use quote::quote;

/// `base.Res.prog.fb.x` for an instance path (`base` is `self` or `__s`).
pub(super) fn place(c: &ConfigDef, base: TokenStream, p: &InstancePath) -> TokenStream {
    let mut t = base;
    if let Some(r) = &c.resources[p.resource].name {
        let id = rust_ident(r);
        t = quote!(#t.#id);
    }
    let inst = rust_ident(&c.resources[p.resource].programs[p.program].name);
    t = quote!(#t.#inst);
    for f in &p.fields {
        let id = rust_ident(f);
        t = quote!(#t.#id);
    }
    t
}

/// Statements applying the VAR_CONFIG initial values to `__s`, the new
/// configuration.
pub(super) fn inits(c: &ConfigDef) -> TokenStream {
    let mut out = TokenStream::new();
    for v in &c.var_config {
        if let Some(i) = &v.init {
            let p = place(c, quote!(__s), &v.target);
            let val = values::init_value(&v.target.ty, Some(i));
            out.extend(quote!(#p = #val;));
        }
    }
    out
}

/// The copies into (`before`) or out of the fields of program `prog` of
/// resource `res`.
pub(super) fn copies(c: &ConfigDef, res: usize, prog: usize, before: bool) -> TokenStream {
    let mut out = TokenStream::new();
    for v in &c.var_config {
        let Some(l) = &v.location else { continue };
        if (v.target.resource, v.target.program) != (res, prog) {
            continue;
        }
        let p = place(c, quote!(self), &v.target);
        match (before, l.area) {
            (true, Area::Input | Area::Memory) => {
                let r = values::io_read(l);
                out.extend(quote!(#p = #r;));
            }
            (false, Area::Output | Area::Memory) => out.extend(values::io_write(l, p)),
            _ => {}
        }
    }
    out
}

/// `ADDRESSES` entries of the addresses VAR_CONFIG gives.
pub(super) fn located(c: &ConfigDef) -> Vec<TokenStream> {
    c.var_config
        .iter()
        .filter_map(|v| Some(super::io::located(&v.target.text, v.location.as_ref()?)))
        .collect()
}
