//! What a host needs to bind I/O: the `ADDRESSES` table of a POU or
//! configuration, and typed accessors for its located variables, so that a
//! host writes `Tank::set_io_level(&mut ctx, 500)` with the variable's own
//! Rust type instead of byte offsets into `Cycle::io`. Variables declared
//! `AT %I*` / `%Q*` / `%M*` are ordinary fields, listed in the table as not
//! bound so that a host sees what it must bind (by reading or writing the
//! field).

use super::rust_ident;
use super::text::{doc, str_lit};
use super::values::{io_read, io_write};
use crate::ir::types::Elem;
use crate::ir::{CheckedPou, Loc, Var};

/// The `il_std::Located` entries of a POU: its located variables, then the
/// direct addresses its code uses.
pub(super) fn addresses(pou: &CheckedPou) -> Vec<String> {
    let located = pou
        .vars
        .iter()
        .filter_map(|v| v.location.as_ref().map(|l| (v.name.as_str(), l, v.retain)));
    let direct = pou.addresses.iter().map(|l| (l.text.as_str(), l, false));
    let mut out: Vec<String> = located
        .chain(direct)
        .map(|(name, l, retain)| self::located(name, l, retain))
        .collect();
    out.extend(unbound(&pou.vars));
    out
}

/// An `il_std::Located` entry of an `ADDRESSES` table; `retain`: declared
/// RETAIN, so a host keeps its bytes of the process image over a restart
/// (located variables are not in the generated RETAIN snapshots).
pub(super) fn located(name: &str, l: &Loc, retain: bool) -> String {
    let area = super::values::area(l);
    let (name, text, byte, ty) = (
        str_lit(name),
        str_lit(&l.text),
        l.byte,
        str_lit(l.elem.name()),
    );
    let bit = match l.bit {
        Some(b) => format!("::core::option::Option::Some({b})"),
        None => "::core::option::Option::None".to_string(),
    };
    format!(
        "::il_std::Located {{ name: {name}, address: {text}, area: {area}, byte: {byte}, bit: {bit}, ty: {ty}, bound: true, retain: {retain}, }}"
    )
}

/// One `il_std::Located { bound: false, .. }` per partly located variable.
fn unbound(vars: &[Var]) -> Vec<String> {
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
            let a = super::values::area(&loc);
            let (name, text, ty) = (str_lit(&v.name), str_lit(text), str_lit(&v.ty.to_string()));
            Some(format!(
                "::il_std::Located {{ name: {name}, address: {text}, area: {a}, byte: 0, bit: ::core::option::Option::None, ty: {ty}, bound: false, retain: false, }}"
            ))
        })
        .collect()
}

/// `io_NAME(ctx) -> T` and `set_io_NAME(ctx, v: T)` for every located
/// variable: the same reads and writes the generated code does, typed.
pub(super) fn accessors(vars: &[Var]) -> String {
    accessors_in("", vars)
}

/// [`accessors`] with the names prefixed (a RESOURCE's globals take
/// `RES_`, so that two resources may each locate a global `x`).
pub(super) fn accessors_in(prefix: &str, vars: &[Var]) -> String {
    let mut out = String::new();
    for v in vars {
        let Some(l) = &v.location else { continue };
        let get = rust_ident(&format!("io_{prefix}{}", v.name));
        let set = rust_ident(&format!("set_io_{prefix}{}", v.name));
        let ty = l.elem.rust();
        let (read, write) = (io_read(l), io_write(l, "__value".to_string()));
        let gdoc = doc(&format!(
            " `{}` ({} {}) as the process image holds it now.",
            v.name,
            l.text,
            l.elem.name()
        ));
        let sdoc = doc(&format!(
            " Writes `{}` ({} {}) into the process image.",
            v.name,
            l.text,
            l.elem.name()
        ));
        // A name with capitals (LogicLab's `Lamp`) makes a method name
        // rustc warns about in the user's crate.
        let allow = if v.name.chars().any(|c| c.is_ascii_uppercase()) {
            "#[allow(non_snake_case)] "
        } else {
            ""
        };
        out.push_str(&format!(
            "{gdoc}{allow}pub fn {get}(__ctx: &::il_std::Cycle) -> {ty} {{ {read} }} {sdoc}{allow}pub fn {set}(__ctx: &mut ::il_std::Cycle, __value: {ty}) {{ {write} }}"
        ));
    }
    out
}
