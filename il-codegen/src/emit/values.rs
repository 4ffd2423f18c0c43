//! Values, places and expressions.

use super::{PouEmitter, item_ident, local_ident, rust_ident, rust_ty};
use crate::ast::Area;
use crate::sema::ir::{
    BinOp, Const, Expr, Init, Loc, PathElem, Place, Root, StdCall, Storage, Value,
};
use crate::sema::types::{Elem, Ty};
use il_std::FaultKind;
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

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
        Ty::Array { dims, elem } => {
            let mut v = default_value(elem);
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
            let d = default_value(&crate::sema::size::row(t));
            quote!(::il_std::heap::from_fn(#n, |_| #d))
        }
        _ => default_value(t),
    }
}

/// [`init_value`]; with `heap`, the first dimension of an array with initial
/// values is built by `il_std::heap::from_fn`.
fn array_init(t: &Ty, init: Option<&Init>, heap: bool) -> TokenStream {
    match (init, t) {
        (Some(Init::Const(c)), _) => constant(c),
        (Some(Init::Array(items)), Ty::Array { dims, elem }) => {
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
                let v = constant(v);
                arms.push(if a == b {
                    quote!(#a => #v,)
                } else {
                    quote!(#a..=#b => #v,)
                });
                start += n;
                k += 1;
            }
            let d = default_value(elem);
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

impl PouEmitter<'_> {
    /// `__ctx.fault(..)` of the kind a checked standard call carries.
    pub(crate) fn fault_of(&self, kind: FaultKind, line: u32) -> TokenStream {
        self.fault(&format!("{kind:?}"), line)
    }

    /// `__ctx.fault(::il_std::FaultKind::KIND, "Pou", line)`.
    pub(crate) fn fault(&self, kind: &str, line: u32) -> TokenStream {
        let kind = format_ident!("{}", kind);
        let pou = &self.pou.name;
        quote!(__ctx.fault(::il_std::FaultKind::#kind, #pou, #line))
    }

    /// A value in method-receiver position (`x.wrapping_add(..)`): a
    /// negative literal needs parentheses there, nothing else does.
    pub(crate) fn receiver(&self, v: &Value, line: u32) -> TokenStream {
        let t = self.value(v, line);
        match v {
            Value::Const(Const::Int(n, _)) if *n < 0 => quote!((#t)),
            Value::Const(Const::Real(f, _)) if *f < 0.0 => quote!((#t)),
            _ => t,
        }
    }

    pub(crate) fn value(&self, v: &Value, line: u32) -> TokenStream {
        match v {
            Value::Cr(t) => {
                let id = cr_ident(t);
                quote!(#id)
            }
            Value::Const(c) => constant(c),
            Value::Read(p) => self.read(p, line),
            Value::Saved(i, _) => {
                let id = format_ident!("__save_{}", i);
                quote!(#id)
            }
        }
    }

    fn root(&self, r: &Root) -> TokenStream {
        match r {
            Root::Ret => quote!(__ret),
            // Reads and writes of the process image go through `read`/`write`.
            Root::Addr(_) => quote!(__ctx.io),
            Root::Var(i) => {
                let v = &self.pou.vars[*i];
                if v.edge.is_some() {
                    // The edge seen in this call, computed on entry.
                    let id = rust_ident(&format!("__edge_{}", v.name));
                    return quote!(#id);
                }
                if self.cached(*i) {
                    let id = super::names::cache_ident(&v.name);
                    return quote!(#id);
                }
                match v.storage {
                    Storage::Instance => {
                        let id = rust_ident(&v.name);
                        quote!(self.#id)
                    }
                    // A global, through the reference the caller passed.
                    Storage::External => {
                        let id = rust_ident(&v.name);
                        quote!((*__ext.#id))
                    }
                    Storage::InOut | Storage::OutParam => {
                        let id = local_ident(&v.name);
                        quote!((*#id))
                    }
                    Storage::Temp | Storage::Param | Storage::Located | Storage::Global => {
                        let id = local_ident(&v.name);
                        quote!(#id)
                    }
                }
            }
        }
    }

    fn has_index(p: &Place) -> bool {
        p.path.iter().any(|e| matches!(e, PathElem::Index { .. }))
    }

    /// Walk an indexed place: `on_place` gets the Rust place expression at
    /// the end of the path (the reference bound by the innermost `match` is
    /// `*__pK`); `on_fault` is what each out-of-range branch evaluates to.
    ///
    /// A literal subscript inside the bounds (checked here, whatever the
    /// checker did) is a plain `[k]`, which cannot fail. Any other subscript
    /// becomes `match place.get(i) { Some(__pK) => ..., None => fault }`, with
    /// `i` a `usize` that is out of range for every value outside the bounds.
    /// Subscripts that could conflict with the borrow are evaluated first
    /// into `let`s (they may read the same variable or record a fault).
    fn access(
        &self,
        p: &Place,
        mutable: bool,
        line: u32,
        on_place: impl FnOnce(TokenStream) -> TokenStream,
        on_fault: TokenStream,
    ) -> TokenStream {
        let mut lets = TokenStream::new();
        // (binding, scrutinee) of each `match`, outermost first.
        let mut matches: Vec<(proc_macro2::Ident, TokenStream)> = Vec::new();
        let mut cur = self.root(&p.root);
        // Whether `cur` is exactly the innermost binding (a reference).
        let mut at_binding = false;
        let mut n_lets: usize = 0;
        for e in &p.path {
            match e {
                PathElem::Field(f) => {
                    let f = rust_ident(f);
                    cur = quote!(#cur.#f);
                    at_binding = false;
                }
                PathElem::Index { dims, subs } => {
                    for (s, &(lo, hi)) in subs.iter().zip(dims) {
                        if let Value::Const(Const::Int(n, _)) = s
                            && *n >= lo as i128
                            && *n <= hi as i128
                        {
                            let k = (*n - lo as i128) as usize;
                            cur = quote!(#cur[#k]);
                            at_binding = false;
                            continue;
                        }
                        let ix = if self.inline_subscript(s, p, matches.is_empty()) {
                            index_usize(self.value(s, line), value_elem(s), lo)
                        } else {
                            let id = format_ident!("__ix{}", n_lets);
                            n_lets += 1;
                            let v = index_usize(self.value(s, line), value_elem(s), lo);
                            lets.extend(quote!(let #id: usize = #v;));
                            quote!(#id)
                        };
                        let b = format_ident!("__p{}", matches.len());
                        let scrutinee = if mutable {
                            quote!(#cur.get_mut(#ix))
                        } else {
                            quote!(#cur.get(#ix))
                        };
                        matches.push((b.clone(), scrutinee));
                        cur = quote!(#b);
                        at_binding = true;
                    }
                }
            }
        }
        // `__pK` alone is a reference; with a path after it, auto-deref applies.
        let place = if at_binding { quote!(*#cur) } else { cur };
        let mut out = on_place(place);
        for (b, scrutinee) in matches.into_iter().rev() {
            out = quote!(match #scrutinee {
                ::core::option::Option::Some(#b) => #out,
                ::core::option::Option::None => #on_fault,
            });
        }
        if lets.is_empty() {
            out
        } else {
            quote!({ #lets #out })
        }
    }

    /// Whether some subscript of the place is checked at run time (not a
    /// literal inside the bounds).
    fn checked_index(p: &Place) -> bool {
        p.path.iter().any(|e| {
            match e {
            PathElem::Index { dims, subs } => subs.iter().zip(dims).any(|(s, &(lo, hi))| {
                !matches!(s, Value::Const(Const::Int(n, _)) if *n >= lo as i128 && *n <= hi as i128)
            }),
            PathElem::Field(_) => false,
        }
        })
    }

    /// Whether a subscript can be evaluated inside the `match` scrutinee:
    /// it records no fault and reads nothing that the borrow of the place
    /// (at the first level: a two-phase borrow, so any read is fine) holds.
    fn inline_subscript(&self, s: &Value, p: &Place, first: bool) -> bool {
        match s {
            Value::Cr(_) | Value::Const(_) | Value::Saved(..) => true,
            Value::Read(q) => {
                !Self::has_index(q)
                    && (first || q.root != p.root)
                    && !matches!(q.root, Root::Addr(_))
            }
        }
    }

    pub(crate) fn simple_path(&self, p: &Place) -> TokenStream {
        let mut t = self.root(&p.root);
        for e in &p.path {
            if let PathElem::Field(f) = e {
                let f = rust_ident(f);
                t = quote!(#t.#f);
            }
        }
        t
    }

    pub(crate) fn read(&self, p: &Place, line: u32) -> TokenStream {
        if let Root::Addr(l) = &p.root {
            return io_read(l);
        }
        if !Self::has_index(p) {
            return self.simple_path(p);
        }
        let fault = self.fault("IndexOutOfRange", line);
        let d = default_value(&p.ty);
        self.access(p, false, line, |place| place, quote!({ #fault; #d }))
    }

    /// Store `value` (already evaluated tokens) into a place.
    pub(crate) fn write(&self, p: &Place, value: TokenStream, line: u32) -> TokenStream {
        if let Root::Addr(l) = &p.root {
            return io_write(l, value);
        }
        if !Self::has_index(p) {
            let path = self.simple_path(p);
            return quote!(#path = #value;);
        }
        let fault = self.fault("IndexOutOfRange", line);
        let access = |v: TokenStream| {
            self.access(
                p,
                true,
                line,
                |place| quote!({ #place = #v; }),
                quote!({ #fault; }),
            )
        };
        // A value of one or two plain tokens (`__cr_int`, `!__cr_bool`, a
        // literal) goes straight into the slot; anything else is evaluated
        // before the place is borrowed.
        let plain = {
            let mut n = 0;
            value.clone().into_iter().all(|t| {
                n += 1;
                n <= 2 && !matches!(t, proc_macro2::TokenTree::Group(_))
            })
        };
        if plain || !Self::checked_index(p) {
            access(value)
        } else {
            let a = access(quote!(__v));
            quote!({ let __v = #value; #a })
        }
    }

    /// Run `f` on the FB instance at `p` (`__fb` in the tokens of `f`).
    pub(crate) fn with_fb(&self, p: &Place, body: TokenStream, line: u32) -> TokenStream {
        if !Self::has_index(p) {
            let path = self.simple_path(p);
            return quote!({ let __fb = &mut #path; #body });
        }
        let fault = self.fault("IndexOutOfRange", line);
        self.access(
            p,
            true,
            line,
            |place| quote!({ let __fb = &mut #place; #body }),
            quote!({ #fault; }),
        )
    }

    pub(crate) fn expr(&self, e: &Expr, line: u32) -> TokenStream {
        match e {
            Expr::Value(v) => self.value(v, line),
            Expr::Not(v) => {
                let v = self.value(v, line);
                quote!(!#v)
            }
            Expr::Bin {
                op,
                ty,
                lhs,
                rhs,
                negate_rhs,
            } => {
                let l = self.receiver(lhs, line);
                let mut r = self.value(rhs, line);
                if *negate_rhs {
                    r = quote!(!#r);
                }
                // A literal divisor other than 0 needs no zero check.
                let nonzero =
                    !*negate_rhs && matches!(rhs, Value::Const(Const::Int(n, _)) if *n != 0);
                self.binary(*op, ty, l, r, nonzero, line)
            }
            Expr::TimeScale {
                div,
                time,
                lhs,
                num,
                rhs,
            } => {
                let t = time.rust();
                let l = self.receiver(lhs, line);
                let r = self.receiver(rhs, line);
                // TIME: the operator and MUL_TIME/DIV_TIME are one rule.
                if *time == Elem::TIME {
                    if !*div {
                        return quote!(::il_std::func::MUL_TIME(#l, #r));
                    }
                    let fault = self.fault("DivisionByZero", line);
                    return quote!({
                        let (__v, __bad) = ::il_std::func::div_time_checked(#l, #r);
                        if __bad { #fault; }
                        __v
                    });
                }
                match (div, num.is_real()) {
                    (false, false) => quote!(#t(#l.0.wrapping_mul(#r as i64))),
                    (false, true) => quote!(#t(((#l.0 as f64) * (#r as f64)) as i64)),
                    (true, true) => quote!(#t(((#l.0 as f64) / (#r as f64)) as i64)),
                    (true, false) => {
                        let fault = self.fault("DivisionByZero", line);
                        quote!({
                            let __d = #r as i64;
                            if __d == 0 { #fault; #t(0) } else { #t(#l.0.wrapping_div(__d)) }
                        })
                    }
                }
            }
            Expr::CallUser {
                name,
                args,
                inouts,
                outputs,
                out_types,
                en,
                eno,
                ret,
            } => {
                let call = self.user_call(name, args, inouts, outputs, out_types, line);
                let Some(en) = en else { return call };
                // EN = FALSE: the function does not run; its result is the
                // default and ENO (if read with `=>`) is FALSE.
                let en = self.value(en, line);
                let d = default_value(ret);
                let eno_false =
                    outputs
                        .iter()
                        .filter(|(k, _, _)| Some(*k) == *eno)
                        .map(|(_, place, neg)| {
                            self.write(place, if *neg { quote!(true) } else { quote!(false) }, line)
                        });
                quote!(if #en { #call } else { #(#eno_false)* #d })
            }
            Expr::CallStd {
                call,
                args,
                arg_types: _,
                ret,
                fault,
            } => {
                let args: Vec<_> = args.iter().map(|a| self.value(a, line)).collect();
                match (call, fault) {
                    // REAL → integer out of range (or NaN) saturates, as the
                    // plain function does, and is recorded as a fault.
                    (StdCall::Plain(n), Some(k @ FaultKind::ConversionOutOfRange)) => {
                        let t = rust_ty(ret);
                        // The fault is the table's; the rounding is the
                        // function's: TRUNC and REAL_TRUNC_* truncate.
                        let f = if n.contains("TRUNC") {
                            quote!(trunc_to_int_checked)
                        } else {
                            quote!(real_to_int_checked)
                        };
                        let a = &args[0];
                        let fault = self.fault_of(*k, line);
                        quote!({
                            let (__v, __bad) = ::il_std::conv::#f::<#t>(#a as f64);
                            if __bad { #fault; }
                            __v
                        })
                    }
                    // DIV, MOD, DIV_TIME by an integer zero: the `*_checked`
                    // companion gives the result and the flag.
                    (StdCall::Plain(n), Some(k @ FaultKind::DivisionByZero)) => {
                        let f = format_ident!("{}_checked", n.to_ascii_lowercase());
                        let fault = self.fault_of(*k, line);
                        quote!({
                            let (__v, __bad) = ::il_std::func::#f(#(#args),*);
                            if __bad { #fault; }
                            __v
                        })
                    }
                    (StdCall::Plain(n), _) => {
                        let f = format_ident!("{}", n);
                        quote!(::il_std::func::#f(#(#args),*))
                    }
                    // A result longer than the first string's capacity is
                    // truncated and recorded (CONCAT, step by step).
                    (StdCall::Fold(n), Some(k @ FaultKind::StringOverflow)) => {
                        let checked = format_ident!("{}_checked", n.to_ascii_lowercase());
                        let fault = self.fault_of(*k, line);
                        let mut it = args.into_iter();
                        let mut acc = it.next().unwrap_or_default();
                        for a in it {
                            acc = quote!({
                                let (__v, __bad) = ::il_std::func::#checked(#acc, #a);
                                if __bad { #fault; }
                                __v
                            });
                        }
                        acc
                    }
                    (StdCall::Fold(n), _) => {
                        let f = format_ident!("{}", n);
                        let mut it = args.into_iter();
                        let mut acc = it.next().unwrap_or_default();
                        for a in it {
                            acc = quote!(::il_std::func::#f(#acc, #a));
                        }
                        acc
                    }
                    (StdCall::Chain(n), _) => {
                        let f = format_ident!("{}", n);
                        let pairs = args.windows(2).map(|w| {
                            let (a, b) = (&w[0], &w[1]);
                            quote!(::il_std::func::#f(#a, #b))
                        });
                        quote!(#(#pairs)&*)
                    }
                    // MUX returns the flag with the value: a selector out of
                    // range (the table's InvalidArgument) is recorded.
                    (StdCall::Mux, k) => {
                        let fault = self.fault_of(k.unwrap_or(FaultKind::InvalidArgument), line);
                        let k = &args[0];
                        let ins = &args[1..];
                        quote!({
                            let (__v, __bad) = ::il_std::func::MUX(#k as i64, &[#(#ins),*]);
                            if __bad { #fault; }
                            __v
                        })
                    }
                }
            }
        }
    }

    /// A call of a user FUNCTION; every output gets a place, read by `=>` or not.
    fn user_call(
        &self,
        name: &str,
        args: &[Value],
        inouts: &[Place],
        outputs: &[(usize, Place, bool)],
        out_types: &[Ty],
        line: u32,
    ) -> TokenStream {
        let f = item_ident(name);
        // Arguments are evaluated into locals first: an indexed read may record
        // a fault in `__ctx`, which the call itself borrows.
        let ids: Vec<_> = (0..args.len()).map(|k| format_ident!("__a{}", k)).collect();
        let arg_lets: Vec<_> = args
            .iter()
            .zip(&ids)
            .map(|(a, id)| {
                let v = self.value(a, line);
                quote!(let #id = #v;)
            })
            .collect();
        let args = ids;
        let (io_lets, io_args, io_back) = self.bind_inouts(inouts, None, line);
        if out_types.is_empty() {
            if arg_lets.is_empty() && inouts.is_empty() {
                return quote!(#f(__ctx));
            }
            if inouts.is_empty() {
                return quote!({ #(#arg_lets)* #f(__ctx, #(#args,)*) });
            }
            return quote!({
                #(#arg_lets)* #io_lets
                let __r = #f(__ctx, #(#args,)* #(#io_args,)*);
                #io_back
                __r
            });
        }
        // Every output needs a place, read by `=>` or not.
        let ids: Vec<_> = (0..out_types.len())
            .map(|k| format_ident!("__o{}", k))
            .collect();
        let lets = out_types.iter().zip(&ids).map(|(t, id)| {
            let ty = rust_ty(t);
            let d = default_value(t);
            quote!(let mut #id: #ty = #d;)
        });
        let stores = outputs.iter().map(|(k, place, neg)| {
            let id = &ids[*k];
            let v = if *neg { quote!(!#id) } else { quote!(#id) };
            self.write(place, v, line)
        });
        quote!({
            #(#arg_lets)*
            #io_lets
            #(#lets)*
            let __r = #f(__ctx, #(#args,)* #(#io_args,)* #(&mut #ids,)*);
            #io_back
            #(#stores)*
            __r
        })
    }

    /// The arguments for VAR_IN_OUT parameters: `&mut place` where the place
    /// is a plain path that no other argument (nor the called instance
    /// `avoid`) shares; otherwise a copy in a local written back after the
    /// call (array elements, the process image, aliased variables).
    pub(crate) fn bind_inouts(
        &self,
        places: &[Place],
        avoid: Option<&Place>,
        line: u32,
    ) -> (TokenStream, Vec<TokenStream>, TokenStream) {
        let mut lets = TokenStream::new();
        let mut back = TokenStream::new();
        let mut args = Vec::new();
        for (k, p) in places.iter().enumerate() {
            let shares = |q: &Place| q.root == p.root;
            let direct = !matches!(p.root, Root::Addr(_))
                && !Self::has_index(p)
                && !avoid.is_some_and(shares)
                && !places.iter().enumerate().any(|(j, q)| j != k && shares(q));
            if direct {
                let path = self.simple_path(p);
                args.push(quote!(&mut #path));
            } else {
                let id = format_ident!("__io{}", k);
                let ty = rust_ty(&p.ty);
                let v = self.read(p, line);
                lets.extend(quote!(let mut #id: #ty = #v;));
                back.extend(self.write(p, quote!(#id), line));
                args.push(quote!(&mut #id));
            }
        }
        (lets, args, back)
    }

    fn binary(
        &self,
        op: BinOp,
        ty: &Ty,
        l: TokenStream,
        r: TokenStream,
        nonzero: bool,
        line: u32,
    ) -> TokenStream {
        let e = ty.elem();
        let int = e.is_some_and(|e| e.is_int() || e.is_bitstring());
        let dur = e.filter(|e| e.is_duration()).map(Elem::rust);
        match op {
            BinOp::And => quote!(#l & #r),
            BinOp::Or => quote!(#l | #r),
            BinOp::Xor => quote!(#l ^ #r),
            BinOp::Gt => quote!(#l > #r),
            BinOp::Ge => quote!(#l >= #r),
            BinOp::Eq => quote!(#l == #r),
            BinOp::Ne => quote!(#l != #r),
            BinOp::Le => quote!(#l <= #r),
            BinOp::Lt => quote!(#l < #r),
            BinOp::Add | BinOp::Sub if dur.is_some() => {
                let t = dur.unwrap_or_default();
                if op == BinOp::Add {
                    quote!(#t(#l.0.wrapping_add(#r.0)))
                } else {
                    quote!(#t(#l.0.wrapping_sub(#r.0)))
                }
            }
            BinOp::Add if int => quote!(#l.wrapping_add(#r)),
            BinOp::Sub if int => quote!(#l.wrapping_sub(#r)),
            BinOp::Mul if int => quote!(#l.wrapping_mul(#r)),
            BinOp::Div if int && nonzero => quote!(#l.wrapping_div(#r)),
            BinOp::Mod if int && nonzero => quote!(#l.wrapping_rem(#r)),
            BinOp::Div | BinOp::Mod if int => {
                let fault = self.fault("DivisionByZero", line);
                let f = if op == BinOp::Div {
                    quote!(wrapping_div)
                } else {
                    quote!(wrapping_rem)
                };
                quote!({
                    let __d = #r;
                    if __d == 0 { #fault; 0 } else { #l.#f(__d) }
                })
            }
            BinOp::Add => quote!(#l + #r),
            BinOp::Sub => quote!(#l - #r),
            BinOp::Mul => quote!(#l * #r),
            BinOp::Div => quote!(#l / #r),
            BinOp::Mod => quote!(#l % #r),
        }
    }
}

/// The element type of a subscript value.
fn value_elem(v: &Value) -> Option<Elem> {
    match v {
        Value::Cr(t) | Value::Saved(_, t) => t.elem(),
        Value::Const(c) => c.ty().elem(),
        Value::Read(p) => p.ty.elem(),
    }
}

/// A subscript as a `usize` position in an array whose first index is `lo`:
/// every value outside the array maps to a position past its end (a
/// negative 8/16-bit value sign-extends to a huge `usize`; wider values go
/// through `try_from`, so no truncation on 16/32-bit targets).
fn index_usize(v: TokenStream, elem: Option<Elem>, lo: i64) -> TokenStream {
    let small = matches!(
        elem,
        Some(Elem::SINT | Elem::INT | Elem::USINT | Elem::UINT)
    );
    let wide = matches!(elem, Some(Elem::LINT | Elem::ULINT) | None);
    if lo == 0 && small {
        return quote!(#v as usize);
    }
    let off = if lo == 0 {
        v
    } else if wide {
        let lo = lo as i128;
        quote!((#v as i128 - #lo))
    } else {
        quote!((#v as i64).wrapping_sub(#lo))
    };
    quote!(usize::try_from(#off).unwrap_or(usize::MAX))
}

fn area(l: &Loc) -> TokenStream {
    match l.area {
        Area::Input => quote!(::il_std::Area::Input),
        Area::Output => quote!(::il_std::Area::Output),
        Area::Memory => quote!(::il_std::Area::Memory),
    }
}

/// Read a located value from the process image.
pub(crate) fn io_read(l: &Loc) -> TokenStream {
    let a = area(l);
    let b = l.byte;
    if let Some(bit) = l.bit {
        return quote!(__ctx.io.bit(#a, #b, #bit));
    }
    match l.elem {
        Elem::BYTE | Elem::USINT => quote!(__ctx.io.byte(#a, #b)),
        Elem::SINT => quote!(__ctx.io.byte(#a, #b).cast_signed()),
        Elem::WORD | Elem::UINT => quote!(__ctx.io.word(#a, #b)),
        Elem::INT => quote!(__ctx.io.word(#a, #b).cast_signed()),
        Elem::DWORD | Elem::UDINT => quote!(__ctx.io.dword(#a, #b)),
        Elem::DINT => quote!(__ctx.io.dword(#a, #b).cast_signed()),
        Elem::REAL => quote!(f32::from_bits(__ctx.io.dword(#a, #b))),
        Elem::LWORD | Elem::ULINT => quote!(__ctx.io.lword(#a, #b)),
        Elem::LINT => quote!(__ctx.io.lword(#a, #b).cast_signed()),
        _ => quote!(f64::from_bits(__ctx.io.lword(#a, #b))),
    }
}

/// Store a value (tokens of its Rust type) into the process image.
pub(crate) fn io_write(l: &Loc, v: TokenStream) -> TokenStream {
    let a = area(l);
    let b = l.byte;
    if let Some(bit) = l.bit {
        return quote!({ let __v: bool = #v; __ctx.io.set_bit(#a, #b, #bit, __v); });
    }
    let ty = l.elem.rust();
    let (set, conv) = match l.elem {
        Elem::BYTE | Elem::USINT | Elem::SINT => (quote!(set_byte), quote!(__v as u8)),
        Elem::WORD | Elem::UINT | Elem::INT => (quote!(set_word), quote!(__v as u16)),
        Elem::DWORD | Elem::UDINT | Elem::DINT => (quote!(set_dword), quote!(__v as u32)),
        Elem::REAL => (quote!(set_dword), quote!(__v.to_bits())),
        Elem::LREAL => (quote!(set_lword), quote!(__v.to_bits())),
        _ => (quote!(set_lword), quote!(__v as u64)),
    };
    quote!({ let __v: #ty = #v; __ctx.io.#set(#a, #b, #conv); })
}
