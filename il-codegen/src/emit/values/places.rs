//! Places: variables, members, array elements (checked indexes) and direct
//! addresses, read and written; recorded faults.

use super::*;

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
            Value::Widen(inner, w) => widened(self.value(inner, line), &Some(*w)),
            Value::Arith { op, lhs, rhs } => {
                let l = self.value(lhs, line);
                let r = self.value(rhs, line);
                let f = match op {
                    BinOp::Add => quote!(wrapping_add),
                    BinOp::Sub => quote!(wrapping_sub),
                    _ => quote!(wrapping_mul),
                };
                quote!((#l as i64).#f(#r as i64))
            }
            Value::Resized(v, to) => {
                let v = self.value(v, line);
                let t = rust_ty(to);
                let fault = self.fault("StringOverflow", line);
                quote!({
                    let (__s, __cut): (#t, bool) = ::il_std::func::resize_checked(#v);
                    if __cut { #fault; }
                    __s
                })
            }
        }
    }

    pub(super) fn root(&self, r: &Root) -> TokenStream {
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
                    let id = super::super::names::cache_ident(&v.name);
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

    pub(super) fn has_index(p: &Place) -> bool {
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
    pub(super) fn access(
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
                // `read`/`write` split a partial access off before they get here.
                PathElem::Part { .. } => {}
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
    pub(super) fn checked_index(p: &Place) -> bool {
        p.path.iter().any(|e| {
            match e {
            PathElem::Index { dims, subs } => subs.iter().zip(dims).any(|(s, &(lo, hi))| {
                !matches!(s, Value::Const(Const::Int(n, _)) if *n >= lo as i128 && *n <= hi as i128)
            }),
            PathElem::Field(_) | PathElem::Part { .. } => false,
        }
        })
    }

    /// Whether a subscript can be evaluated inside the `match` scrutinee:
    /// it records no fault and reads nothing that the borrow of the place
    /// (at the first level: a two-phase borrow, so any read is fine) holds.
    pub(super) fn inline_subscript(&self, s: &Value, p: &Place, first: bool) -> bool {
        match s {
            Value::Cr(_) | Value::Const(_) | Value::Saved(..) => true,
            Value::Widen(v, _) => self.inline_subscript(v, p, first),
            Value::Resized(..) => false,
            Value::Arith { lhs, rhs, .. } => {
                self.inline_subscript(lhs, p, first) && self.inline_subscript(rhs, p, first)
            }
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
        if let Some((whole_place, whole, part, index)) = p.split_part() {
            let w = self.read(&whole_place, line);
            let _ = whole;
            return part_read(w, part, index);
        }
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

    /// An output (tokens of a value read from a block or function) going to
    /// `target`: a string target of another capacity gets it cut at its
    /// length, with a `StringOverflow` fault (`from`: the output's type, when
    /// known; a string target is always fitted otherwise, which is a plain
    /// copy for the same capacity).
    pub(crate) fn fit_output(
        &self,
        v: TokenStream,
        from: Option<&Ty>,
        target: &Place,
        line: u32,
    ) -> TokenStream {
        let Ty::Str { .. } = &target.ty else {
            return v;
        };
        if from.is_some_and(|t| !t.resizes_to(&target.ty)) {
            return v;
        }
        let t = rust_ty(&target.ty);
        let fault = self.fault("StringOverflow", line);
        quote!({
            let (__s, __cut): (#t, bool) = ::il_std::func::resize_checked(#v);
            if __cut { #fault; }
            __s
        })
    }

    /// Store `value` (already evaluated tokens) into a place.
    pub(crate) fn write(&self, p: &Place, value: TokenStream, line: u32) -> TokenStream {
        if let Some((whole_place, whole, part, index)) = p.split_part() {
            // Read the whole, replace the part, write the whole back.
            let w = self.read(&whole_place, line);
            let new = part_write(w, value, whole, part, index);
            return self.write(&whole_place, new, line);
        }
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
}

/// The element type of a subscript value.
pub(super) fn value_elem(v: &Value) -> Option<Elem> {
    match v {
        Value::Cr(t) | Value::Saved(_, t) => t.elem(),
        Value::Const(c) => c.ty().elem(),
        Value::Read(p) => p.ty.elem(),
        Value::Widen(_, w) => Some(w.to),
        Value::Resized(_, t) => t.elem(),
        Value::Arith { .. } => Some(Elem::LINT),
    }
}

/// A subscript as a `usize` position in an array whose first index is `lo`:
/// every value outside the array maps to a position past its end (a
/// negative 8/16-bit value sign-extends to a huge `usize`; wider values go
/// through `try_from`, so no truncation on 16/32-bit targets).
pub(super) fn index_usize(v: TokenStream, elem: Option<Elem>, lo: i64) -> TokenStream {
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

pub(crate) fn area(l: &Loc) -> TokenStream {
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

/// A `u64` mask as a hex literal (what a reader of the generated code expects).
fn hex(v: u64) -> Literal {
    format!("{v:#x}u64")
        .parse()
        .unwrap_or_else(|_| Literal::u64_suffixed(v))
}

/// The mask of a part's bits and its shift in the whole.
fn part_mask(part: Elem, index: u32) -> (u64, u32) {
    let bits = PathElem::part_bits(part);
    let mask = if bits >= 64 {
        u64::MAX
    } else {
        (1u64 << bits) - 1
    };
    (mask, index * bits)
}

/// Part `index` of the value `w` of type `whole`: a shift and a mask in
/// `u64` (the checker proved the part lies inside the whole, so neither
/// can overflow).
pub(super) fn part_read(w: TokenStream, part: Elem, index: u32) -> TokenStream {
    let (mask, shift) = part_mask(part, index);
    let shift = Literal::u32_unsuffixed(shift);
    if part == Elem::BOOL {
        return quote!({ let __w = #w; ((__w as u64 >> #shift) & 1) != 0 });
    }
    let mask = hex(mask);
    let t = part.rust();
    quote!({ let __w = #w; ((__w as u64 >> #shift) & #mask) as #t })
}

/// The value `w` of type `whole` with part `index` replaced by `v`.
pub(super) fn part_write(
    w: TokenStream,
    v: TokenStream,
    whole: Elem,
    part: Elem,
    index: u32,
) -> TokenStream {
    let (mask, shift) = part_mask(part, index);
    let keep = hex(!(mask << shift));
    let mask = hex(mask);
    let shift = Literal::u32_unsuffixed(shift);
    let t = whole.rust();
    quote!({
        let __w = #w;
        let __v = #v;
        ((__w as u64 & #keep) | ((__v as u64 & #mask) << #shift)) as #t
    })
}
