//! Values the emitter writes: constants and initial values, places,
//! expressions and calls (the interpreter's partners: il-interp's
//! constants.rs, places.rs, expressions.rs and calls.rs).

use super::text::{join, str_lit, tail};
use super::{PouEmitter, item_ident, local_ident, rust_ident, rust_ty};
use crate::ast::Area;
use crate::ir::types::{Elem, Ty};
use crate::ir::{
    BinOp, Const, Expr, Init, Loc, PathElem, Place, Root, StdCall, Storage, Value, Widen,
};
use il_std::FaultKind;

mod calls;
mod constants;
mod expressions;
mod places;

pub(crate) use constants::{constant, cr_ident, default_value, heap_init_value, init_value};
pub(crate) use places::{area, io_read, io_write};

/// `v` converted by the checker's implicit widening, if it recorded one:
/// every widening of its table is a `From` in Rust (`i32::from(i16)`,
/// `u8::from(bool)`, `f64::from(u32)`, `LTIME::from(TIME)`).
pub(crate) fn widened(v: String, w: &Option<Widen>) -> String {
    match w {
        Some(w) => format!("<{}>::from({v})", w.to.rust()),
        None => v,
    }
}

/// The local `__save_N` that holds the CR across a parenthesis (one per
/// `(`; written without `format!`, it is on many IL lines).
pub(crate) fn saved_ident(slot: u32) -> String {
    let mut s = String::with_capacity(27);
    s.push_str("__save_");
    super::text::push_decimal(&mut s, u64::from(slot));
    s
}
