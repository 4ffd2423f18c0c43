//! The data sources of TASK inputs (`SINGLE :=`, `INTERVAL :=`): a literal,
//! a global of the configuration or a direct address, read at the instant
//! every task's release is decided.

use super::text::str_lit;
use super::values;
use crate::ir::{GlobalRef, TaskSource};

/// The `Option<bool>` SINGLE argument of `TaskState::due`.
pub(super) fn single(
    s: Option<&TaskSource<bool>>,
    read_global: &dyn Fn(&GlobalRef) -> String,
) -> String {
    let v = match s {
        None => return "::core::option::Option::None".to_string(),
        Some(TaskSource::Fixed(b)) => b.to_string(),
        Some(TaskSource::Global(g)) => read_global(g),
        Some(TaskSource::Addr(l)) => values::io_read(l),
    };
    format!("::core::option::Option::Some({v})")
}

/// The `TIME` INTERVAL argument of `TaskState::due`.
pub(super) fn interval(s: &TaskSource<i64>, read_global: &dyn Fn(&GlobalRef) -> String) -> String {
    match s {
        TaskSource::Fixed(ns) => format!("::il_std::TIME({ns}i64)"),
        TaskSource::Global(g) => read_global(g),
        // The checker refuses an address (it holds no TIME); none reaches here.
        TaskSource::Addr(_) => "::il_std::TIME(0)".to_string(),
    }
}

/// `TaskInfo`'s static description of a source: the literal INTERVAL (0
/// when it is read from a variable) and the name or address read, if any.
pub(super) fn info<T: Copy + Default>(
    s: Option<&TaskSource<T>>,
    global_name: &dyn Fn(&GlobalRef) -> String,
) -> (T, String) {
    let (fixed, name) = match s {
        None => (T::default(), None),
        Some(TaskSource::Fixed(v)) => (*v, None),
        Some(TaskSource::Global(g)) => (T::default(), Some(global_name(g))),
        Some(TaskSource::Addr(l)) => (T::default(), Some(l.text.clone())),
    };
    let name = match name {
        Some(n) => format!("::core::option::Option::Some({})", str_lit(&n)),
        None => "::core::option::Option::None".to_string(),
    };
    (fixed, name)
}
