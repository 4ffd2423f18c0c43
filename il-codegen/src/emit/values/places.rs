//! Places: variables, members, array elements (checked indexes) and direct
//! addresses, read and written; recorded faults.

use super::*;

impl PouEmitter<'_> {
    /// `__ctx.fault(..)` of the kind a checked standard call carries.
    pub(crate) fn fault_of(&self, kind: FaultKind, line: u32) -> String {
        self.fault(&format!("{kind:?}"), line)
    }

    /// `__ctx.fault(::il_std::FaultKind::KIND, "Pou", line)`.
    pub(crate) fn fault(&self, kind: &str, line: u32) -> String {
        let kind = rust_ident(kind);
        let pou = str_lit(&self.pou.name);
        format!("__ctx.fault(::il_std::FaultKind::{kind}, {pou}, {line})")
    }

    /// A value in method-receiver position (`x.wrapping_add(..)`): a
    /// negative literal needs parentheses there, nothing else does.
    pub(crate) fn receiver(&self, v: &Value, line: u32) -> String {
        let t = self.value(v, line);
        match v {
            Value::Const(Const::Int(n, _)) if n.get() < 0 => format!("({t})"),
            Value::Const(Const::Real(f, _)) if *f < 0.0 => format!("({t})"),
            _ => t,
        }
    }

    pub(crate) fn value(&self, v: &Value, line: u32) -> String {
        match v {
            Value::Cr(i) => cr_ident(self.pou.cr_ty(*i)),
            Value::Const(c) => constant(c),
            Value::Read(p) => self.read(self.pou.place(*p), line),
            Value::Saved(i) => super::saved_ident(*i),
            Value::Widen(b) => widened(self.value(&b.0, line), &Some(b.1)),
            // As the operator of that name in that type.
            Value::Arith(a) => {
                let l = self.receiver(&a.lhs, line);
                let r = self.value(&a.rhs, line);
                let nonzero = matches!(&a.rhs, Value::Const(Const::Int(n, _)) if n.get() != 0);
                self.binary(a.op, Some(a.elem), l, r, nonzero, line)
            }
            Value::Resized(r) => {
                let (v, to) = &**r;
                let v = self.value(v, line);
                self.resized(v, to, line)
            }
        }
    }

    /// `v` (a string) cut to the capacity of `to`, with a `StringOverflow`
    /// fault when it is longer.
    fn resized(&self, v: String, to: &Ty, line: u32) -> String {
        let t = rust_ty(to);
        let fault = self.fault("StringOverflow", line);
        format!(
            "{{ let (__s, __cut): ({t}, bool) = ::il_std::func::resize_checked({v}); if __cut {{ {fault}; }} __s }}"
        )
    }

    pub(super) fn root(&self, r: &Root) -> String {
        match r {
            Root::Ret => "__ret".to_string(),
            // Reads and writes of the process image go through `read`/`write`.
            Root::Addr(_) => "__ctx.io".to_string(),
            Root::Var(i) => {
                let v = &self.pou.vars[*i];
                if v.edge.is_some() {
                    // The edge seen in this call, computed on entry.
                    return rust_ident(&format!("__edge_{}", v.name));
                }
                if self.cached(*i) {
                    return super::super::names::cache_ident(&v.name);
                }
                match v.storage {
                    Storage::Instance => format!("self.{}", rust_ident(&v.name)),
                    // A global, through the reference the caller passed.
                    Storage::External => format!("(*__ext.{})", rust_ident(&v.name)),
                    Storage::InOut | Storage::OutParam => {
                        format!("(*{})", local_ident(&v.name))
                    }
                    Storage::Temp | Storage::Param | Storage::Located | Storage::Global => {
                        local_ident(&v.name)
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
        on_place: impl FnOnce(String) -> String,
        on_fault: String,
    ) -> String {
        let mut lets = String::new();
        // (binding, scrutinee) of each `match`, outermost first.
        let mut matches: Vec<(String, String)> = Vec::new();
        let mut cur = self.root(&p.root);
        // Whether `cur` is exactly the innermost binding (a reference).
        let mut at_binding = false;
        let mut n_lets: usize = 0;
        for e in &p.path {
            match e {
                PathElem::Field(f) => {
                    cur = format!("{cur}.{}", rust_ident(&f.name));
                    at_binding = false;
                }
                PathElem::Index { dims, subs } => {
                    for (s, &(lo, hi)) in subs.iter().zip(dims) {
                        if let Value::Const(Const::Int(n, _)) = s
                            && let n = n.get()
                            && n >= lo as i128
                            && n <= hi as i128
                        {
                            let k = (n - lo as i128) as usize;
                            cur = format!("{cur}[{k}]");
                            at_binding = false;
                            continue;
                        }
                        let ix = if self.inline_subscript(s, p, matches.is_empty()) {
                            index_usize(self.value(s, line), self.pou.value_elem(s), lo)
                        } else {
                            let id = format!("__ix{n_lets}");
                            n_lets += 1;
                            let v = index_usize(self.value(s, line), self.pou.value_elem(s), lo);
                            lets.push_str(&format!("let {id}: usize = {v};"));
                            id
                        };
                        let b = format!("__p{}", matches.len());
                        let scrutinee = if mutable {
                            format!("{cur}.get_mut({ix})")
                        } else {
                            format!("{cur}.get({ix})")
                        };
                        matches.push((b.clone(), scrutinee));
                        cur = b;
                        at_binding = true;
                    }
                }
                // `read`/`write` split a partial access off before they get here.
                PathElem::Part { .. } => {}
            }
        }
        // `__pK` alone is a reference; with a path after it, auto-deref applies.
        let place = if at_binding { format!("*{cur}") } else { cur };
        let mut out = on_place(place);
        for (b, scrutinee) in matches.into_iter().rev() {
            // A block arm needs no comma (rustfmt writes none).
            let comma = if is_block(&out) { "" } else { "," };
            let comma2 = if is_block(&on_fault) { "" } else { "," };
            out = format!(
                "match {scrutinee} {{ ::core::option::Option::Some({b}) => {out}{comma} ::core::option::Option::None => {on_fault}{comma2} }}"
            );
        }
        if lets.is_empty() {
            out
        } else {
            format!("{{ {lets} {out} }}")
        }
    }

    /// Whether some subscript of the place is checked at run time (not a
    /// literal inside the bounds).
    pub(super) fn checked_index(p: &Place) -> bool {
        p.path.iter().any(|e| {
            match e {
            PathElem::Index { dims, subs } => subs.iter().zip(dims).any(|(s, &(lo, hi))| {
                !matches!(s, Value::Const(Const::Int(n, _)) if n.get() >= lo as i128 && n.get() <= hi as i128)
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
            Value::Widen(b) => self.inline_subscript(&b.0, p, first),
            Value::Resized(..) => false,
            // A division by a variable may record a fault.
            Value::Arith(a) => {
                (!matches!(a.op, BinOp::Div | BinOp::Mod)
                    || matches!(&a.rhs, Value::Const(Const::Int(n, _)) if n.get() != 0))
                    && self.inline_subscript(&a.lhs, p, first)
                    && self.inline_subscript(&a.rhs, p, first)
            }
            Value::Read(q) => {
                let q = self.pou.place(*q);
                !Self::has_index(q)
                    && (first || q.root != p.root)
                    && !matches!(q.root, Root::Addr(_))
            }
        }
    }

    pub(crate) fn simple_path(&self, p: &Place) -> String {
        let mut t = self.root(&p.root);
        for e in &p.path {
            if let PathElem::Field(f) = e {
                t.push('.');
                t.push_str(&rust_ident(&f.name));
            }
        }
        t
    }

    pub(crate) fn read(&self, p: &Place, line: u32) -> String {
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
        self.access(p, false, line, |place| place, format!("{{ {fault}; {d} }}"))
    }

    /// An output (text of a value read from a block or function) going to
    /// `target`: a string target of another capacity gets it cut at its
    /// length, with a `StringOverflow` fault (`from`: the output's type, when
    /// known; a string target is always fitted otherwise, which is a plain
    /// copy for the same capacity).
    pub(crate) fn fit_output(
        &self,
        v: String,
        from: Option<&Ty>,
        target: &Place,
        line: u32,
    ) -> String {
        let Ty::Str { .. } = &target.ty else {
            return v;
        };
        if from.is_some_and(|t| !t.resizes_to(&target.ty)) {
            return v;
        }
        self.resized(v, &target.ty, line)
    }

    /// Store `value` (already evaluated text) into a place.
    pub(crate) fn write(&self, p: &Place, value: String, line: u32) -> String {
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
            return [path.as_str(), " = ", value.as_str(), ";"].concat();
        }
        let fault = self.fault("IndexOutOfRange", line);
        let access = |v: String| {
            self.access(
                p,
                true,
                line,
                |place| format!("{{ {place} = {v}; }}"),
                format!("{{ {fault}; }}"),
            )
        };
        // A plain value (`__cr_int`, `!__cr_bool`, a literal) goes straight
        // into the slot; anything else is evaluated before the place is
        // borrowed.
        if plain(&value) || !Self::checked_index(p) {
            access(value)
        } else {
            let a = access("__v".to_string());
            format!("{{ let __v = {value}; {a} }}")
        }
    }

    /// Run `f` on the FB instance at `p` (`__fb` in the text of `f`).
    pub(crate) fn with_fb(&self, p: &Place, body: String, line: u32) -> String {
        if !Self::has_index(p) {
            let path = self.simple_path(p);
            return format!("{{ let __fb = &mut {path}; {body} }}");
        }
        let fault = self.fault("IndexOutOfRange", line);
        self.access(
            p,
            true,
            line,
            |place| format!("{{ let __fb = &mut {place}; {body} }}"),
            format!("{{ {fault}; }}"),
        )
    }
}

/// A subscript as a `usize` position in an array whose first index is `lo`:
/// every value outside the array maps to a position past its end (a
/// negative 8/16-bit value sign-extends to a huge `usize`; wider values go
/// through `try_from`, so no truncation on 16/32-bit targets).
pub(super) fn index_usize(v: String, elem: Option<Elem>, lo: i64) -> String {
    let small = matches!(
        elem,
        Some(Elem::SINT | Elem::INT | Elem::USINT | Elem::UINT)
    );
    let wide = matches!(elem, Some(Elem::LINT | Elem::ULINT) | None);
    // `-1i16 as usize` would be `-(1i16 as usize)`.
    let v = if v.starts_with('-') {
        format!("({v})")
    } else {
        v
    };
    if lo == 0 && small {
        return format!("{v} as usize");
    }
    let off = if lo == 0 {
        v
    } else if wide {
        format!("({v} as i128 - {lo}i128)")
    } else {
        format!("({v} as i64).wrapping_sub({lo}i64)")
    };
    format!("usize::try_from({off}).unwrap_or(usize::MAX)")
}

/// Whether `s` is one block `{ ... }` (its first brace closes at its end),
/// reading string literals as such.
fn is_block(s: &str) -> bool {
    let b = s.as_bytes();
    if b.first() != Some(&b'{') {
        return false;
    }
    let (mut depth, mut i) = (0usize, 0);
    while i < b.len() {
        match b[i] {
            b'"' => {
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
            }
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return i + 1 == b.len();
                }
            }
            _ => {}
        }
        i += 1;
    }
    false
}

/// Whether a value's text is one plain token (a name, a literal), maybe
/// after `!`: it can go into a slot while the slot is borrowed.
fn plain(v: &str) -> bool {
    let v = v.strip_prefix('!').unwrap_or(v);
    let v = v
        .strip_prefix('-')
        .filter(|r| r.starts_with(|c: char| c.is_ascii_digit()))
        .unwrap_or(v);
    let number = v.starts_with(|c: char| c.is_ascii_digit());
    let v = v.strip_prefix("r#").unwrap_or(v);
    !v.is_empty()
        && v.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || (number && c == '.'))
}

pub(crate) fn area(l: &Loc) -> &'static str {
    match l.area {
        Area::Input => "::il_std::Area::Input",
        Area::Output => "::il_std::Area::Output",
        Area::Memory => "::il_std::Area::Memory",
    }
}

/// Read a located value from the process image.
pub(crate) fn io_read(l: &Loc) -> String {
    let a = area(l);
    let b = l.byte;
    if let Some(bit) = l.bit {
        return format!("__ctx.io.bit({a}, {b}, {bit})");
    }
    match l.elem {
        Elem::BYTE | Elem::USINT => format!("__ctx.io.byte({a}, {b})"),
        Elem::SINT => format!("__ctx.io.byte({a}, {b}).cast_signed()"),
        Elem::WORD | Elem::UINT => format!("__ctx.io.word({a}, {b})"),
        Elem::INT => format!("__ctx.io.word({a}, {b}).cast_signed()"),
        Elem::DWORD | Elem::UDINT => format!("__ctx.io.dword({a}, {b})"),
        Elem::DINT => format!("__ctx.io.dword({a}, {b}).cast_signed()"),
        Elem::REAL => format!("f32::from_bits(__ctx.io.dword({a}, {b}))"),
        Elem::LWORD | Elem::ULINT => format!("__ctx.io.lword({a}, {b})"),
        Elem::LINT => format!("__ctx.io.lword({a}, {b}).cast_signed()"),
        _ => format!("f64::from_bits(__ctx.io.lword({a}, {b}))"),
    }
}

/// Store a value (text of its Rust type) into the process image.
pub(crate) fn io_write(l: &Loc, v: String) -> String {
    let a = area(l);
    let b = l.byte;
    if let Some(bit) = l.bit {
        return format!("{{ let __v: bool = {v}; __ctx.io.set_bit({a}, {b}, {bit}, __v); }}");
    }
    let ty = l.elem.rust();
    let (set, conv) = match l.elem {
        Elem::BYTE | Elem::USINT | Elem::SINT => ("set_byte", "__v as u8"),
        Elem::WORD | Elem::UINT | Elem::INT => ("set_word", "__v as u16"),
        Elem::DWORD | Elem::UDINT | Elem::DINT => ("set_dword", "__v as u32"),
        Elem::REAL => ("set_dword", "__v.to_bits()"),
        Elem::LREAL => ("set_lword", "__v.to_bits()"),
        _ => ("set_lword", "__v as u64"),
    };
    format!("{{ let __v: {ty} = {v}; __ctx.io.{set}({a}, {b}, {conv}); }}")
}

/// A `u64` mask as a hex literal (what a reader of the generated code expects).
fn hex(v: u64) -> String {
    format!("{v:#x}u64")
}

/// Part `index` of the value `w` of type `whole`: a shift and a mask in
/// `u64` (the checker proved the part lies inside the whole, so neither
/// can overflow).
pub(super) fn part_read(w: String, part: Elem, index: u32) -> String {
    let (mask, shift) = PathElem::part_mask(part, index);
    if part == Elem::BOOL {
        return format!("{{ let __w = {w}; ((__w as u64 >> {shift}) & 1) != 0 }}");
    }
    let mask = hex(mask);
    let t = part.rust();
    format!("{{ let __w = {w}; ((__w as u64 >> {shift}) & {mask}) as {t} }}")
}

/// The value `w` of type `whole` with part `index` replaced by `v`.
pub(super) fn part_write(w: String, v: String, whole: Elem, part: Elem, index: u32) -> String {
    let (mask, shift) = PathElem::part_mask(part, index);
    let keep = hex(!(mask << shift));
    let mask = hex(mask);
    let t = whole.rust();
    format!(
        "{{ let __w = {w}; let __v = {v}; ((__w as u64 & {keep}) | ((__v as u64 & {mask}) << {shift})) as {t} }}"
    )
}
