//! Constants and initial values: literals of every type, defaults, array
//! initialisers (on the stack or the heap).

use super::*;

/// The CR local of type `t` (`__cr_int`, `__cr_string80`, `__cr_motor`):
/// a user type's name is part of it, so it goes through `rust_ident`.
pub(crate) fn cr_ident(t: &Ty) -> String {
    match t {
        Ty::Elem(e) => ["__cr_", e.mangle()].concat(),
        _ => rust_ident(&format!("__cr_{}", t.mangle())),
    }
}

/// A typed constant.
pub(crate) fn constant(c: &Const) -> String {
    match c {
        Const::Bool(true) => "true".to_string(),
        Const::Bool(false) => "false".to_string(),
        Const::Int(v, e) => {
            let v = v.get();
            match e {
                Elem::SINT => format!("{}i8", v as i8),
                Elem::INT => format!("{}i16", v as i16),
                Elem::DINT => format!("{}i32", v as i32),
                Elem::LINT => format!("{}i64", v as i64),
                Elem::USINT | Elem::BYTE => format!("{}u8", v as u8),
                Elem::UINT | Elem::WORD => format!("{}u16", v as u16),
                Elem::UDINT | Elem::DWORD => format!("{}u32", v as u32),
                _ => format!("{}u64", v as u64),
            }
        }
        Const::Real(v, e) => {
            // The checker only lets finite values through. `Display` of a
            // float is the shortest text that reads back as the same value,
            // never with an exponent (`1e20` is `100000000000000000000`).
            if *e == Elem::REAL {
                let f = *v as f32;
                format!("{}f32", if f.is_finite() { f } else { 0.0 })
            } else {
                format!("{}f64", if v.is_finite() { *v } else { 0.0 })
            }
        }
        Const::Time(v, e) => format!("{}({v}i64)", Elem::rust(*e)),
        Const::Enum(e) => format!("{}::{}", item_ident(&e.ty), rust_ident(&e.value)),
        Const::Str(s) => format!(
            "::il_std::{}::<{}>::from_str_truncating({}).0",
            if s.wide { "WSTRING" } else { "STRING" },
            s.len,
            str_lit(&s.value)
        ),
    }
}

/// The default value of a type (IEC: 0, FALSE, T#0s, '').
pub(crate) fn default_value(t: &Ty) -> String {
    match t {
        Ty::Array(a) => {
            // An array of a subrange starts at its lower limit.
            let mut v = match crate::ir::element_start(t) {
                Some(c) => constant(&c),
                None => default_value(&a.elem),
            };
            for _ in &a.dims {
                v = format!("::core::array::from_fn(|_| {v})");
            }
            v
        }
        Ty::Elem(_) | Ty::Str { .. } => constant(&crate::ir::default_const(t)),
        Ty::Fb(_) | Ty::Struct(_) | Ty::Enum(_) => {
            "::core::default::Default::default()".to_string()
        }
    }
}

/// The initial value of a variable.
pub(crate) fn init_value(t: &Ty, init: Option<&Init>) -> String {
    array_init(t, init, false)
}

/// The initial value of a heap field (`Var::heap`, an array over 64 KiB):
/// a `Box<[Row]>` built element by element on the heap, never as a whole
/// array on the stack.
pub(crate) fn heap_init_value(t: &Ty, init: Option<&Init>) -> String {
    match (init, t) {
        (Some(Init::Array(_)), Ty::Array { .. }) => array_init(t, init, true),
        (_, Ty::Array(a)) => {
            let dims = &a.dims;
            let n = dims.first().map_or(0, |(lo, hi)| (hi - lo + 1) as usize);
            // One dimension: the row is the element, which may start at a
            // subrange's lower limit.
            let d = match (dims.len(), crate::ir::element_start(t)) {
                (1, Some(c)) => constant(&c),
                _ => default_value(&t.row()),
            };
            format!("::il_std::heap::from_fn({n}, |_| {d})")
        }
        _ => default_value(t),
    }
}

/// [`init_value`]; with `heap`, the first dimension of an array with initial
/// values is built by `il_std::heap::from_fn`.
pub(super) fn array_init(t: &Ty, init: Option<&Init>, heap: bool) -> String {
    match (init, t) {
        (Some(Init::Const(c)), _) => constant(c),
        (Some(Init::Array(items)), Ty::Array(a)) => {
            let (dims, elem) = (&a.dims, &a.elem);
            // A `match` on the flat index, one arm per run of equal values
            // (neighbouring runs of one value merged), keeps `[1000(0)]` small.
            let mut arms = String::new();
            let mut start = 0usize;
            let mut k = 0;
            while k < items.len() {
                let (mut n, v) = (items[k].0, &items[k].1);
                while k + 1 < items.len() && items[k + 1].1 == *v {
                    k += 1;
                    n += items[k].0;
                }
                let (a, b) = (start, start + n - 1);
                let v = init_value(elem, Some(v));
                if a == b {
                    arms.push_str(&format!("{a} => {v}, "));
                } else {
                    arms.push_str(&format!("{a}..={b} => {v}, "));
                }
                start += n;
                k += 1;
            }
            let d = match crate::ir::element_start(t) {
                Some(c) => constant(&c),
                None => default_value(elem),
            };
            let sizes: Vec<usize> = dims.iter().map(|(lo, hi)| (hi - lo + 1) as usize).collect();
            // Row-major flat index: i0 * (n1 * n2) + i1 * n2 + i2.
            let terms = (0..dims.len()).map(|k| {
                let stride: usize = sizes[k + 1..].iter().product();
                format!("__i{k} * {stride}")
            });
            let flat = join(terms, " + ");
            let mut body = format!("match {flat} {{ {arms}_ => {d} }}");
            for k in (0..dims.len()).rev() {
                body = if heap && k == 0 {
                    let n = sizes[0];
                    format!("::il_std::heap::from_fn({n}, |__i{k}| {body})")
                } else {
                    format!("::core::array::from_fn(|__i{k}| {body})")
                };
            }
            body
        }
        (Some(Init::Struct(fields)), Ty::Struct(_)) => {
            let ty = rust_ty(t);
            let sets: String = fields
                .iter()
                .map(|(n, fty, init)| {
                    format!("__s.{} = {};", rust_ident(n), init_value(fty, Some(init)))
                })
                .collect();
            format!("{{ let mut __s = <{ty} as ::core::default::Default>::default(); {sets} __s }}")
        }
        (Some(Init::Fields(fields)), Ty::Fb(_)) => {
            let ty = rust_ty(t);
            let sets: String = fields
                .iter()
                .map(|(n, c)| format!("__fb.{} = {};", rust_ident(&n.name), constant(c)))
                .collect();
            format!(
                "{{ let mut __fb = <{ty} as ::core::default::Default>::default(); {sets} __fb }}"
            )
        }
        _ => default_value(t),
    }
}
