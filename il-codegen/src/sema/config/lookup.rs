//! A global of a configuration by name, for every step that names one.

use crate::ast;
use crate::ir::{ConfigDef, GlobalRef, Var};
use crate::sema::codes::*;
use crate::sema::{Cx, suggest};

/// A global by name: the resource's first, then the configuration's.
pub(super) fn lookup(def: &ConfigDef, res: usize, name: &str) -> Option<(GlobalRef, Var)> {
    let find = |vars: &[Var]| vars.iter().position(|v| v.name.eq_ignore_ascii_case(name));
    if let Some(r) = def.resources.get(res)
        && let Some(i) = find(&r.globals)
    {
        return Some((
            GlobalRef {
                resource: Some(res),
                index: i,
            },
            r.globals[i].clone(),
        ));
    }
    let i = find(&def.globals)?;
    Some((
        GlobalRef {
            resource: None,
            index: i,
        },
        def.globals[i].clone(),
    ))
}

/// The names of the globals that resource `res` sees.
pub(super) fn all_global_names(def: &ConfigDef, res: usize) -> Vec<&str> {
    def.globals
        .iter()
        .chain(
            def.resources
                .get(res)
                .map(|r| r.globals.as_slice())
                .unwrap_or(&[]),
        )
        .map(|v| v.name.as_str())
        .collect()
}

/// `name` is no global here: an error, with the closest name as help.
pub(super) fn unknown_global(
    cx: &mut Cx,
    def: &ConfigDef,
    res: usize,
    name: &ast::Ident,
    what: &str,
) {
    let names = all_global_names(def, res);
    let hint = suggest(&name.name, names).map(|s| format!("did you mean `{s}`?"));
    let d = cx.err(
        BAD_GLOBAL,
        name.span,
        format!(
            "{what}: configuration `{}` has no global `{name}`",
            def.name
        ),
    );
    d.help = hint;
}
