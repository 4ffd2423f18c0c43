//! The data sources of TASK inputs (`SINGLE :=`, `INTERVAL :=`): a literal,
//! a global of the configuration or a direct address, read at the instant
//! every task's release is decided.

use super::values;
use crate::sema::ir::{GlobalRef, TaskSource};
use proc_macro2::TokenStream;
use quote::quote;

/// The `Option<bool>` SINGLE argument of `TaskState::due`.
pub(super) fn single(
    s: Option<&TaskSource<bool>>,
    read_global: &dyn Fn(&GlobalRef) -> TokenStream,
) -> TokenStream {
    let v = match s {
        None => return quote!(::core::option::Option::None),
        Some(TaskSource::Fixed(b)) => quote!(#b),
        Some(TaskSource::Global(g)) => read_global(g),
        Some(TaskSource::Addr(l)) => values::io_read(l),
    };
    quote!(::core::option::Option::Some(#v))
}

/// The `TIME` INTERVAL argument of `TaskState::due`.
pub(super) fn interval(
    s: &TaskSource<i64>,
    read_global: &dyn Fn(&GlobalRef) -> TokenStream,
) -> TokenStream {
    match s {
        TaskSource::Fixed(ns) => quote!(::il_std::TIME(#ns)),
        TaskSource::Global(g) => read_global(g),
        // The checker refuses an address (it holds no TIME); none reaches here.
        TaskSource::Addr(_) => quote!(::il_std::TIME(0)),
    }
}

/// `TaskInfo`'s static description of a source: the literal INTERVAL (0
/// when it is read from a variable) and the name or address read, if any.
pub(super) fn info<T: Copy + Default>(
    s: Option<&TaskSource<T>>,
    global_name: &dyn Fn(&GlobalRef) -> String,
) -> (T, TokenStream) {
    let (fixed, name) = match s {
        None => (T::default(), None),
        Some(TaskSource::Fixed(v)) => (*v, None),
        Some(TaskSource::Global(g)) => (T::default(), Some(global_name(g))),
        Some(TaskSource::Addr(l)) => (T::default(), Some(l.text.clone())),
    };
    let name = match name {
        Some(n) => quote!(::core::option::Option::Some(#n)),
        None => quote!(::core::option::Option::None),
    };
    (fixed, name)
}
