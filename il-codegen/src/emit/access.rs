//! VAR_ACCESS in the generated configuration: a typed getter per access
//! path and, for READ_WRITE, a setter.

use super::{rust_ident, rust_ty};
use crate::sema::ir::{AccessTarget, ConfigDef};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// `access_NAME(&self) -> T` and (READ_WRITE) `set_access_NAME(&mut self, v: T)`.
pub(super) fn methods(c: &ConfigDef) -> TokenStream {
    let mut out = TokenStream::new();
    for a in &c.access {
        let (path, what) = match &a.target {
            AccessTarget::Global(g) => {
                let (v, base) = match g.resource {
                    None => (&c.globals[g.index], quote!(self)),
                    Some(r) => {
                        let v = &c.resources[r].globals[g.index];
                        match &c.resources[r].name {
                            Some(n) => {
                                let id = rust_ident(n);
                                (v, quote!(self.#id))
                            }
                            None => (v, quote!(self)),
                        }
                    }
                };
                let id = rust_ident(&v.name);
                (quote!(#base.#id), format!("the global `{}`", v.name))
            }
            AccessTarget::Instance(p) => (
                super::config_vars::place(c, quote!(self), p),
                format!("`{}`", p.text),
            ),
        };
        let ty = rust_ty(&a.ty);
        let get = format_ident!("access_{}", a.name);
        let doc = format!(
            " VAR_ACCESS `{}` : {what} : {} {}.",
            a.name,
            a.ty,
            if a.writable {
                "READ_WRITE"
            } else {
                "READ_ONLY"
            }
        );
        out.extend(quote! {
            #[doc = #doc]
            pub fn #get(&self) -> #ty {
                ::core::clone::Clone::clone(&#path)
            }
        });
        if a.writable {
            let set = format_ident!("set_access_{}", a.name);
            let doc = format!(" Writes VAR_ACCESS `{}` (READ_WRITE).", a.name);
            out.extend(quote! {
                #[doc = #doc]
                pub fn #set(&mut self, value: #ty) {
                    #path = value;
                }
            });
        }
    }
    out
}
