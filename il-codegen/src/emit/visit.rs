//! `visit`: generated blocks offer their variables to an
//! `il_std::trace::Visitor` (waveform recorders, loggers), with the IEC
//! type the checker knows (`u16` alone cannot tell `UINT` from `WORD`).

use super::{item_ident, rust_ident};
use crate::sema::ir::{Field, Var};
use crate::sema::types::Ty;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// Offer the value at place `expr` (an lvalue of type `ty`) named `name`.
fn offer(name: &str, ty: &Ty, expr: TokenStream) -> TokenStream {
    match ty {
        Ty::Array { .. } => {
            // All dimensions, through arrays of arrays, and the element type.
            let mut dims = Vec::new();
            let mut elem = ty;
            while let Ty::Array {
                dims: d, elem: e, ..
            } = elem
            {
                dims.extend(d.iter().copied());
                elem = e;
            }
            let at = format_ident!("__e{}", dims.len());
            let inner = match elem {
                Ty::Struct(_) | Ty::Fb(_) => quote! {
                    v.enter_elem(#name, &__ix);
                    ::il_std::trace::Visit::visit(#at, v);
                    v.leave();
                },
                _ => {
                    let t = ty_name(elem);
                    quote!(v.elem(#name, &__ix, #t, ::il_std::trace::AsValue::as_value(#at));)
                }
            };
            let ix = dims.iter().enumerate().map(|(k, (lo, _))| {
                let i = format_ident!("__i{}", k);
                quote!((#i as i64).wrapping_add(#lo))
            });
            let mut body = quote! {
                let __ix = [#(#ix),*];
                #inner
            };
            for k in (0..dims.len()).rev() {
                let (i, e) = (format_ident!("__i{}", k), format_ident!("__e{}", k + 1));
                let outer = if k == 0 {
                    quote!(#expr)
                } else {
                    let p = format_ident!("__e{}", k);
                    quote!(#p)
                };
                body = quote! {
                    for (#i, #e) in #outer.iter().enumerate() { #body }
                };
            }
            body
        }
        Ty::Struct(_) | Ty::Fb(_) => quote! {
            v.enter(#name);
            ::il_std::trace::Visit::visit(&#expr, v);
            v.leave();
        },
        _ => {
            let t = ty_name(ty);
            quote!(v.var(#name, #t, ::il_std::trace::AsValue::as_value(&#expr));)
        }
    }
}

/// The IEC type as written in declarations (`INT`, `STRING[10]`, `TankState`).
fn ty_name(t: &Ty) -> String {
    t.to_string()
}

/// `visit` and `impl Visit` for an FB/PROGRAM with these fields (the
/// instance memory; located variables live in `Cycle::io`, and VAR_IN_OUT
/// and VAR_EXTERNAL belong to the caller).
pub(crate) fn pou(name: &proc_macro2::Ident, fields: &[&Var]) -> TokenStream {
    let offers = fields.iter().map(|v| {
        let id = rust_ident(&v.name);
        offer(&v.name, &v.ty, quote!(self.#id))
    });
    visit_items(name, quote!(#(#offers)*))
}

/// `impl Visit` for a user STRUCT (the host reaches it through its owner).
pub(crate) fn strukt(name: &str, fields: &[Field]) -> TokenStream {
    let id = item_ident(name);
    let offers = fields.iter().map(|f| {
        let fid = rust_ident(&f.name);
        offer(&f.name, &f.ty, quote!(self.#fid))
    });
    quote! {
        #[allow(dead_code, unused_variables, clippy::all)]
        impl ::il_std::trace::Visit for #id {
            fn visit(&self, v: &mut dyn ::il_std::trace::Visitor) {
                #(#offers)*
            }
        }
    }
}

/// `impl AsValue` for a user enumeration: its discriminant and its name.
pub(crate) fn enumeration(name: &str, values: &[(String, Option<i128>)]) -> TokenStream {
    let id = item_ident(name);
    let arms = values.iter().map(|(v, _)| {
        let vid = rust_ident(v);
        quote!(#id::#vid => #v,)
    });
    quote! {
        #[allow(dead_code, clippy::all)]
        impl ::il_std::trace::AsValue for #id {
            fn as_value(&self) -> ::il_std::trace::Value<'_> {
                ::il_std::trace::Value::Enum {
                    value: *self as i64,
                    name: match self { #(#arms)* },
                }
            }
        }
    }
}

/// `visit` for a CONFIGURATION: its globals (not located), then each
/// resource and program instance as a scope.
pub(crate) fn config(
    name: &proc_macro2::Ident,
    globals: &[&Var],
    programs: &[(Option<&str>, &str)],
    resources: &[(&str, Vec<&Var>, Vec<&str>)],
) -> TokenStream {
    let mut body = TokenStream::new();
    let global = |path: TokenStream, v: &Var| {
        let id = rust_ident(&v.name);
        offer(&v.name, &v.ty, quote!(#path.#id))
    };
    let program = |path: TokenStream, inst: &str| {
        let id = rust_ident(inst);
        offer(inst, &Ty::Fb(String::new()), quote!(#path.#id))
    };
    for v in globals {
        body.extend(global(quote!(self), v));
    }
    for (_, inst) in programs {
        body.extend(program(quote!(self), inst));
    }
    for (rn, gs, ps) in resources {
        let rid = rust_ident(rn);
        let mut inner = TokenStream::new();
        for v in gs {
            inner.extend(global(quote!(self.#rid), v));
        }
        for p in ps {
            inner.extend(program(quote!(self.#rid), p));
        }
        body.extend(quote! { v.enter(#rn); #inner v.leave(); });
    }
    visit_items(name, body)
}

fn visit_items(name: &proc_macro2::Ident, body: TokenStream) -> TokenStream {
    quote! {
        #[allow(dead_code, unused_variables, clippy::all)]
        impl #name {
            /// Offer every variable to `v` (see `il_std::trace`): name, IEC
            /// type and value, going into instances, STRUCTs and arrays.
            pub fn visit(&self, v: &mut dyn ::il_std::trace::Visitor) {
                #body
            }
        }
        impl ::il_std::trace::Visit for #name {
            fn visit(&self, v: &mut dyn ::il_std::trace::Visitor) {
                #name::visit(self, v)
            }
        }
    }
}
