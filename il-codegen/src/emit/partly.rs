//! `ADDRESSES` entries of variables declared `AT %I*` / `%Q*` / `%M*`:
//! ordinary fields, listed as not bound so that a host sees what it must
//! bind (by reading or writing the field).

use super::values;
use crate::sema::ir::{Loc, Var};
use crate::sema::types::Elem;
use proc_macro2::TokenStream;
use quote::quote;

/// One `il_std::Located { bound: false, .. }` per partly located variable.
pub(super) fn unbound(vars: &[Var]) -> Vec<TokenStream> {
    vars.iter()
        .filter_map(|v| {
            let (area, text) = v.partly.as_ref()?;
            let loc = Loc {
                area: *area,
                byte: 0,
                bit: None,
                elem: Elem::BOOL,
                text: text.clone(),
            };
            let a = values::area(&loc);
            let name = &v.name;
            let ty = v.ty.to_string();
            Some(quote!(::il_std::Located {
                name: #name, address: #text, area: #a, byte: 0usize,
                bit: ::core::option::Option::None, ty: #ty, bound: false
            }))
        })
        .collect()
}
