//! `visit`: generated blocks offer their variables to an
//! `il_std::trace::Visitor` (waveform recorders, loggers), with the IEC
//! type the checker knows (`u16` alone cannot tell `UINT` from `WORD`).

use super::text::{Out, join, str_lit};
use super::{item_ident, rust_ident};
use crate::ir::types::Ty;
use crate::ir::{Field, Var};

/// Offer the value at place `expr` (an lvalue of type `ty`) named `name`.
fn offer(name: &str, ty: &Ty, expr: &str) -> String {
    let lit = str_lit(name);
    match ty {
        Ty::Array(_) => {
            // All dimensions, through arrays of arrays, and the element type.
            let mut dims = Vec::new();
            let mut elem = ty;
            while let Ty::Array(a) = elem {
                dims.extend(a.dims.iter().copied());
                elem = &a.elem;
            }
            let at = format!("__e{}", dims.len());
            let inner = match elem {
                Ty::Struct(_) | Ty::Fb(_) => format!(
                    "v.enter_elem({lit}, &__ix); ::il_std::trace::Visit::visit({at}, v); v.leave();"
                ),
                _ => {
                    let t = str_lit(&ty_name(elem));
                    format!("v.elem({lit}, &__ix, {t}, ::il_std::trace::AsValue::as_value({at}));")
                }
            };
            let ix = dims
                .iter()
                .enumerate()
                .map(|(k, (lo, _))| format!("(__i{k} as i64).wrapping_add({lo}i64)"));
            let mut body = format!("let __ix = [{}]; {inner}", join(ix, ", "));
            for k in (0..dims.len()).rev() {
                let outer = if k == 0 {
                    expr.to_string()
                } else {
                    format!("__e{k}")
                };
                body = format!(
                    "for (__i{k}, __e{}) in {outer}.iter().enumerate() {{ {body} }}",
                    k + 1
                );
            }
            body
        }
        Ty::Struct(_) | Ty::Fb(_) => {
            format!("v.enter({lit}); ::il_std::trace::Visit::visit(&{expr}, v); v.leave();")
        }
        _ => {
            let t = str_lit(&ty_name(ty));
            format!("v.var({lit}, {t}, ::il_std::trace::AsValue::as_value(&{expr}));")
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
pub(crate) fn pou(o: &mut Out, name: &str, fields: &[&Var]) {
    let offers: String = fields
        .iter()
        .map(|v| offer(&v.name, &v.ty, &format!("self.{}", rust_ident(&v.name))))
        .collect();
    visit_items(o, name, &offers)
}

/// `impl Visit` for a user STRUCT (the host reaches it through its owner).
pub(crate) fn strukt(o: &mut Out, name: &str, fields: &[Field]) {
    let id = item_ident(name);
    let offers: String = fields
        .iter()
        .map(|f| offer(&f.name, &f.ty, &format!("self.{}", rust_ident(&f.name))))
        .collect();
    o.code(&format!(
        "#[allow(dead_code, unused_variables, clippy::all, clippy::pedantic)] impl ::il_std::trace::Visit for {id} {{ fn visit(&self, v: &mut dyn ::il_std::trace::Visitor) {{ {offers} }} }}"
    ));
}

/// `impl AsValue` for a user enumeration: its discriminant and its name.
pub(crate) fn enumeration(o: &mut Out, name: &str, values: &[(String, Option<i128>)]) {
    let id = item_ident(name);
    let arms: String = values
        .iter()
        .map(|(v, _)| format!("{id}::{} => {}, ", rust_ident(v), str_lit(v)))
        .collect();
    o.code(&format!(
        "#[allow(dead_code, clippy::all, clippy::pedantic)] impl ::il_std::trace::AsValue for {id} {{ fn as_value(&self) -> ::il_std::trace::Value<'_> {{ ::il_std::trace::Value::Enum {{ value: *self as i64, name: match self {{ {arms} }}, }} }} }}"
    ));
}

/// `visit` for a CONFIGURATION: its globals (not located), then each
/// resource and program instance as a scope.
pub(crate) fn config(
    o: &mut Out,
    name: &str,
    globals: &[&Var],
    programs: &[(Option<&str>, &str)],
    resources: &[(&str, Vec<&Var>, Vec<&str>)],
) {
    let mut body = String::new();
    let global =
        |path: &str, v: &Var| offer(&v.name, &v.ty, &format!("{path}.{}", rust_ident(&v.name)));
    let program = |path: &str, inst: &str| {
        offer(
            inst,
            &Ty::Fb(Default::default()),
            &format!("{path}.{}", rust_ident(inst)),
        )
    };
    for v in globals {
        body.push_str(&global("self", v));
    }
    for (_, inst) in programs {
        body.push_str(&program("self", inst));
    }
    for (rn, gs, ps) in resources {
        let path = format!("self.{}", rust_ident(rn));
        body.push_str(&format!("v.enter({});", str_lit(rn)));
        for v in gs {
            body.push_str(&global(&path, v));
        }
        for p in ps {
            body.push_str(&program(&path, p));
        }
        body.push_str("v.leave();");
    }
    visit_items(o, name, &body)
}

fn visit_items(o: &mut Out, name: &str, body: &str) {
    o.code(&format!(
        "#[allow(dead_code, unused_variables, clippy::all, clippy::pedantic)] impl {name} {{ \
         /// Offer every variable to `v` (see `il_std::trace`): name, IEC\n\
         /// type and value, going into instances, STRUCTs and arrays.\n\
         pub fn visit(&self, v: &mut dyn ::il_std::trace::Visitor) {{ {body} }} }} \
         impl ::il_std::trace::Visit for {name} {{ fn visit(&self, v: &mut dyn ::il_std::trace::Visitor) {{ {name}::visit(self, v); }} }}"
    ));
}
