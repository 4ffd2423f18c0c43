//! `ADDRESSES` entries of variables declared `AT %I*` / `%Q*` / `%M*`:
//! ordinary fields, listed as not bound so that a host sees what it must
//! bind (by reading or writing the field).

use super::text::str_lit;
use super::values;
use crate::sema::ir::{Loc, Var};
use crate::sema::types::Elem;

/// One `il_std::Located { bound: false, .. }` per partly located variable.
pub(super) fn unbound(vars: &[Var]) -> Vec<String> {
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
            let (name, text, ty) = (str_lit(&v.name), str_lit(text), str_lit(&v.ty.to_string()));
            Some(format!(
                "::il_std::Located {{ name: {name}, address: {text}, area: {a}, byte: 0, bit: ::core::option::Option::None, ty: {ty}, bound: false, }}"
            ))
        })
        .collect()
}
