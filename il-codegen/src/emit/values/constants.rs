//! Constants and initial values: literals of every type, defaults, array
//! initialisers (on the stack or the heap).

use super::*;

pub(crate) fn cr_ident(t: &Ty) -> proc_macro2::Ident {
    // One of the most frequent identifiers: no `format_ident!` machinery.
    let name = match t {
        Ty::Elem(e) => ["__cr_", e.mangle()].concat(),
        _ => format!("__cr_{}", t.mangle()),
    };
    proc_macro2::Ident::new(&name, proc_macro2::Span::call_site())
}

/// A typed constant.
pub(crate) fn constant(c: &Const) -> TokenStream {
    match c {
        Const::Bool(true) => quote!(true),
        Const::Bool(false) => quote!(false),
        Const::Int(v, e) => {
            let v = *v;
            let lit = match e {
                Elem::SINT => Literal::i8_suffixed(v as i8),
                Elem::INT => Literal::i16_suffixed(v as i16),
                Elem::DINT => Literal::i32_suffixed(v as i32),
                Elem::LINT => Literal::i64_suffixed(v as i64),
                Elem::USINT | Elem::BYTE => Literal::u8_suffixed(v as u8),
                Elem::UINT | Elem::WORD => Literal::u16_suffixed(v as u16),
                Elem::UDINT | Elem::DWORD => Literal::u32_suffixed(v as u32),
                _ => Literal::u64_suffixed(v as u64),
            };
            quote!(#lit)
        }
        Const::Real(v, e) => {
            // The checker only lets finite values through.
            let lit = if *e == Elem::REAL {
                let f = *v as f32;
                Literal::f32_suffixed(if f.is_finite() { f } else { 0.0 })
            } else {
                Literal::f64_suffixed(if v.is_finite() { *v } else { 0.0 })
            };
            quote!(#lit)
        }
        Const::Time(v, e) => {
            let ty = Elem::rust(*e);
            let lit = Literal::i64_suffixed(*v);
            quote!(#ty(#lit))
        }
        Const::Enum { ty, value } => {
            let t = item_ident(ty);
            let v = rust_ident(value);
            quote!(#t::#v)
        }
        Const::Str {
            value,
            wide: false,
            len,
        } => {
            let n = *len as usize;
            quote!(::il_std::STRING::<#n>::from_str_truncating(#value).0)
        }
        Const::Str {
            value,
            wide: true,
            len,
        } => {
            let n = *len as usize;
            quote!(::il_std::WSTRING::<#n>::from_str_truncating(#value).0)
        }
    }
}

/// The default value of a type (IEC: 0, FALSE, T#0s, '').
pub(crate) fn default_value(t: &Ty) -> TokenStream {
    match t {
        Ty::Array { dims, elem, .. } => {
            // An array of a subrange starts at its lower limit.
            let mut v = match crate::sema::ir::element_start(t) {
                Some(c) => constant(&c),
                None => default_value(elem),
            };
            for _ in dims {
                v = quote!(::core::array::from_fn(|_| #v));
            }
            v
        }
        Ty::Elem(_) | Ty::Str { .. } => constant(&crate::sema::default_const(t)),
        Ty::Fb(_) | Ty::Struct(_) | Ty::Enum(_) => quote!(::core::default::Default::default()),
    }
}

/// The initial value of a variable.
pub(crate) fn init_value(t: &Ty, init: Option<&Init>) -> TokenStream {
    array_init(t, init, false)
}

/// The initial value of a heap field (`Var::heap`, an array over 64 KiB):
/// a `Box<[Row]>` built element by element on the heap, never as a whole
/// array on the stack.
pub(crate) fn heap_init_value(t: &Ty, init: Option<&Init>) -> TokenStream {
    match (init, t) {
        (Some(Init::Array(_)), Ty::Array { .. }) => array_init(t, init, true),
        (_, Ty::Array { dims, .. }) => {
            let n = dims.first().map_or(0, |(lo, hi)| (hi - lo + 1) as usize);
            // One dimension: the row is the element, which may start at a
            // subrange's lower limit.
            let d = match (dims.len(), crate::sema::ir::element_start(t)) {
                (1, Some(c)) => constant(&c),
                _ => default_value(&crate::sema::size::row(t)),
            };
            quote!(::il_std::heap::from_fn(#n, |_| #d))
        }
        _ => default_value(t),
    }
}

/// [`init_value`]; with `heap`, the first dimension of an array with initial
/// values is built by `il_std::heap::from_fn`.
pub(super) fn array_init(t: &Ty, init: Option<&Init>, heap: bool) -> TokenStream {
    match (init, t) {
        (Some(Init::Const(c)), _) => constant(c),
        (Some(Init::Array(items)), Ty::Array { dims, elem, .. }) => {
            // A `match` on the flat index, one arm per run of equal values
            // (neighbouring runs of one value merged), keeps `[1000(0)]` small.
            let mut arms = Vec::new();
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
                arms.push(if a == b {
                    quote!(#a => #v,)
                } else {
                    quote!(#a..=#b => #v,)
                });
                start += n;
                k += 1;
            }
            let d = match crate::sema::ir::element_start(t) {
                Some(c) => constant(&c),
                None => default_value(elem),
            };
            let sizes: Vec<usize> = dims.iter().map(|(lo, hi)| (hi - lo + 1) as usize).collect();
            let idx: Vec<_> = (0..dims.len()).map(|k| format_ident!("__i{}", k)).collect();
            // Row-major flat index: i0 * (n1 * n2) + i1 * n2 + i2.
            let terms = idx.iter().enumerate().map(|(k, id)| {
                let stride: usize = sizes[k + 1..].iter().product();
                quote!(#id * #stride)
            });
            let flat = quote!(#(#terms)+*);
            let mut body = quote!(match #flat { #(#arms)* _ => #d });
            for (k, id) in idx.iter().enumerate().rev() {
                body = if heap && k == 0 {
                    let n = sizes[0];
                    quote!(::il_std::heap::from_fn(#n, |#id| #body))
                } else {
                    quote!(::core::array::from_fn(|#id| #body))
                };
            }
            body
        }
        (Some(Init::Struct(fields)), Ty::Struct(_)) => {
            let ty = rust_ty(t);
            let sets = fields.iter().map(|(n, fty, init)| {
                let id = rust_ident(n);
                let v = init_value(fty, Some(init));
                quote!(__s.#id = #v;)
            });
            quote!({ let mut __s = <#ty as ::core::default::Default>::default(); #(#sets)* __s })
        }
        (Some(Init::Fields(fields)), Ty::Fb(_)) => {
            let ty = rust_ty(t);
            let sets = fields.iter().map(|(n, c)| {
                let id = format_ident!("{}", n);
                let v = constant(c);
                quote!(__fb.#id = #v;)
            });
            quote!({ let mut __fb = <#ty as ::core::default::Default>::default(); #(#sets)* __fb })
        }
        _ => default_value(t),
    }
}
