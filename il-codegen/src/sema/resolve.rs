//! Resolving what a declaration names: types (elementary, user, arrays,
//! subranges, strings), direct addresses, and IEC identifiers.

use super::codes::*;
use super::env::*;
use super::ir::{Init, Loc};
use super::types::{ArrayTy, DEFAULT_STRING_LEN, Elem, Ty};
use super::{Cx, stdfb, suggest};
use crate::ast::{self, ConstExpr, LitKind, Literal, PouKind, Span, TypeSpec};

/// Resolve a direct address, checking it against the process image and,
/// for a located variable, against its declared type.
pub(crate) fn resolve_addr(
    cx: &mut Cx,
    a: &ast::DirectAddress,
    declared: Option<&Ty>,
) -> Option<Loc> {
    use ast::{AddrSize, Area};
    let text = cx.file.snippet(a.span).to_string();
    if a.partial {
        cx.err(
            UNSUPPORTED,
            a.span,
            "partly specified addresses (%I*, %Q*) are not supported yet",
        );
        return None;
    }
    let (width, default) = match a.size {
        AddrSize::Default | AddrSize::X => (0, Elem::BOOL),
        AddrSize::B => (1, Elem::BYTE),
        AddrSize::W => (2, Elem::WORD),
        AddrSize::D => (4, Elem::DWORD),
        AddrSize::L => (8, Elem::LWORD),
    };
    let (byte, bit) = match (width, a.path.as_slice()) {
        (0, [n]) => ((*n / 8) as usize, Some((*n % 8) as u8)),
        (0, [b, n]) if *n < 8 => (*b as usize, Some(*n as u8)),
        (0, [_, n]) => {
            cx.err(
                BAD_ADDRESS,
                a.span,
                format!("bit {n} does not exist: a byte has bits 0 to 7"),
            );
            return None;
        }
        (w, [n]) => ((*n as usize).saturating_mul(w), None),
        _ => {
            cx.err(BAD_ADDRESS, a.span, format!("`{text}`: only `%IXbyte.bit`, `%IXbit` and `%IBn`/`%IWn`/`%IDn`/`%ILn` addresses are supported"));
            return None;
        }
    };
    let (cap, area_name) = match a.area {
        Area::Input => (il_std::INPUT_BYTES, "inputs"),
        Area::Output => (il_std::OUTPUT_BYTES, "outputs"),
        Area::Memory => (il_std::MEMORY_BYTES, "memory"),
    };
    if byte.saturating_add(width.max(1)) > cap {
        cx.err(
            BAD_ADDRESS,
            a.span,
            format!("`{text}` is outside the process image ({cap} bytes of {area_name})"),
        );
        return None;
    }
    let elem = match declared {
        None => default,
        Some(Ty::Elem(e)) => {
            let fits = match width {
                0 => *e == Elem::BOOL,
                1 => matches!(e, Elem::BYTE | Elem::SINT | Elem::USINT),
                2 => matches!(e, Elem::WORD | Elem::INT | Elem::UINT),
                4 => matches!(e, Elem::DWORD | Elem::DINT | Elem::UDINT | Elem::REAL),
                _ => matches!(e, Elem::LWORD | Elem::LINT | Elem::ULINT | Elem::LREAL),
            };
            if !fits {
                let what = match width {
                    0 => "a bit (BOOL)",
                    1 => "a byte (BYTE, SINT, USINT)",
                    2 => "a word (WORD, INT, UINT)",
                    4 => "a double word (DWORD, DINT, UDINT, REAL)",
                    _ => "a long word (LWORD, LINT, ULINT, LREAL)",
                };
                cx.err(
                    BAD_ADDRESS,
                    a.span,
                    format!("`{text}` is {what}; it cannot hold {}", e.name()),
                );
                return None;
            }
            *e
        }
        Some(t) => {
            cx.err(
                BAD_ADDRESS,
                a.span,
                format!("a {t} cannot be located at a direct address"),
            );
            return None;
        }
    };
    Some(Loc {
        area: a.area,
        byte,
        bit,
        elem,
        text,
    })
}

/// Names with `__` or a trailing `_` are not IEC identifiers, and the generated
/// code relies on that to keep its own names apart.
pub(crate) fn check_ident(cx: &mut Cx, id: &ast::Ident) {
    // The lexer already refuses `_` alone; this also covers names that reach
    // the checker some other way.
    if id.name.bytes().all(|b| b == b'_') {
        cx.err(
            BAD_IDENT,
            id.span,
            format!("`{id}` is not an IEC identifier (it needs a letter or a digit)"),
        );
    } else if id.name.contains("__") || id.name.ends_with('_') {
        cx.err(
            BAD_IDENT,
            id.span,
            format!("`{id}` is not an IEC identifier (no `__`, no trailing `_`)"),
        );
    }
}

pub(crate) fn resolve_type(cx: &mut Cx, fb_names: &Names, spec: &TypeSpec) -> Option<Ty> {
    match spec {
        TypeSpec::Named(id) => {
            if let Some(names) = &mut cx.names
                && let Some(k) = super::flow::keys::type_key(fb_names, spec)
            {
                names.push((id.span, k));
            }
            if let Some(e) = Elem::from_name(&id.name) {
                return Some(Ty::Elem(e));
            }
            let key = id.key();
            match key.as_str() {
                "STRING" => {
                    return Some(Ty::Str {
                        wide: false,
                        len: DEFAULT_STRING_LEN,
                    });
                }
                "WSTRING" => {
                    return Some(Ty::Str {
                        wide: true,
                        len: DEFAULT_STRING_LEN,
                    });
                }
                _ => {}
            }
            if let Some(fb) = stdfb::lookup(&key) {
                return Some(Ty::Fb(fb.name.to_string().into()));
            }
            if let Some(t) = fb_names.user_type(cx, &key, id.span) {
                return t;
            }
            match fb_names.pous.get(&key) {
                Some((declared, PouKind::FunctionBlock)) => {
                    return Some(Ty::Fb(declared.clone().into()));
                }
                Some((declared, kind)) => {
                    let why = if *kind == PouKind::Program {
                        "programs are instances of a CONFIGURATION's resources, not variables of a POU"
                    } else {
                        "a FUNCTION is called, not instantiated"
                    };
                    cx.err(
                        UNKNOWN_TYPE,
                        id.span,
                        format!("`{declared}` is a {}, not a type: {why}", kind.keyword()),
                    );
                    return None;
                }
                None => {}
            }
            let names = super::types::ALL_ELEMS
                .iter()
                .map(|e| e.name())
                .chain(il_std::signature::FB_SIGNATURES.iter().map(|f| f.name));
            let d = cx
                .err(UNKNOWN_TYPE, id.span, format!("unknown type `{id}`"))
                .set_label("not an elementary type or function block");
            if let Some(s) = suggest(&id.name, names) {
                d.did_you_mean(id.span, s);
            }
            None
        }
        TypeSpec::String { wide, len, span } => {
            let len = match len {
                None => DEFAULT_STRING_LEN,
                Some(ConstExpr::Lit(Literal {
                    kind: LitKind::Int(n),
                    ..
                })) if (1..=65535).contains(&n.get()) => n.get() as u32,
                Some(other) => {
                    cx.err(
                        BAD_INIT,
                        other.span(),
                        "a string length must be an integer literal from 1 to 65535",
                    );
                    let _ = span;
                    return None;
                }
            };
            Some(Ty::Str { wide: *wide, len })
        }
        TypeSpec::Array { dims, elem, .. } => {
            // `ARRAY ... OF INT (0..9)` or of a named subrange: the bounds
            // go with the array type (elements start at the lower one, and
            // stores into them are checked).
            let range = fb_names.range_of(elem);
            let elem = resolve_type(cx, fb_names, elem)?;
            let mut out = Vec::new();
            let mut total: i128 = 1;
            for d in dims {
                let (Some(lo), Some(hi)) = (const_int(cx, &d.lo), const_int(cx, &d.hi)) else {
                    return None;
                };
                if hi < lo {
                    cx.err(
                        BAD_INDEX,
                        d.span,
                        format!("array bounds {lo}..{hi} are empty"),
                    );
                    return None;
                }
                // In i128: the extreme i64 bounds overflow an i64 difference.
                total = total.saturating_mul(i128::from(hi) - i128::from(lo) + 1);
                out.push((lo, hi));
            }
            if total > 1 << 24 {
                cx.err(
                    BAD_INDEX,
                    spec.span(),
                    "array too large (over 16 million elements)",
                );
                return None;
            }
            Some(Ty::Array(Box::new(ArrayTy {
                dims: out,
                elem,
                range,
            })))
        }
        TypeSpec::Subrange { base, range, .. } => subrange(cx, base, range).map(Ty::Elem),
        TypeSpec::Enum { span, .. } | TypeSpec::Struct { span, .. } => {
            cx.err(
                UNSUPPORTED,
                *span,
                "enumerations and structures are declared in TYPE ... END_TYPE and used by name",
            );
            None
        }
    }
}

/// The base type of a subrange `base (lo..hi)`, after checking it (an
/// integer type, not a bit string: subranges are of integer types, Ed.2
/// 2.3.3.1) and its limits (literals inside the base type, not reversed).
fn subrange(cx: &mut Cx, base: &ast::Ident, range: &ast::Subrange) -> Option<Elem> {
    let e = match Elem::from_name(&base.name) {
        Some(e) if e.is_int() => e,
        Some(e) if e.is_bitstring() => {
            cx.err(
                BAD_INIT,
                base.span,
                format!(
                    "a subrange needs an integer base type, not the bit string {}",
                    e.name()
                ),
            );
            return None;
        }
        _ => {
            cx.err(
                BAD_INIT,
                base.span,
                format!("a subrange needs an integer base type, not `{base}`"),
            );
            return None;
        }
    };
    let (min, max) = e.int_range().unwrap_or_default();
    let mut limit = |c: &ConstExpr| match c {
        ConstExpr::Lit(Literal {
            kind: LitKind::Int(n),
            span,
            ..
        }) => {
            let n = n.get();
            if n < min || n > max {
                cx.err(
                    BAD_INIT,
                    *span,
                    format!(
                        "the subrange limit {n} is outside {} ({min}..{max})",
                        e.name()
                    ),
                );
                return None;
            }
            Some(n)
        }
        other => {
            cx.err(
                BAD_INIT,
                other.span(),
                "subrange limits must be integer literals",
            );
            None
        }
    };
    let (lo, hi) = (limit(&range.lo), limit(&range.hi));
    let (lo, hi) = (lo?, hi?);
    if lo > hi {
        cx.err(
            BAD_INIT,
            range.span,
            format!("the subrange {lo}..{hi} is empty: its lower limit is above its upper limit"),
        );
        return None;
    }
    Some(e)
}

pub(crate) fn const_int(cx: &mut Cx, c: &ConstExpr) -> Option<i64> {
    match c {
        ConstExpr::Lit(Literal {
            kind: LitKind::Int(n),
            ..
        }) if i64::try_from(n.get()).is_ok() => Some(n.get() as i64),
        other => {
            cx.err(
                UNSUPPORTED,
                other.span(),
                "array bounds must be integer literals",
            );
            None
        }
    }
}

// How `Names` resolves a user type: here beside `resolve_type`, which
// calls it and which it calls.
impl Names<'_> {
    /// A user type by key: `Some(Some(ty))` when resolved, `Some(None)` after
    /// an error, `None` when no user type has that name.
    pub(crate) fn user_type(&self, cx: &mut Cx, key: &str, span: Span) -> Option<Option<Ty>> {
        let decl = self.types.get(key)?;
        if let Some(r) = self.resolved.borrow().get(key) {
            return Some(r.ty.clone());
        }
        Some(match &decl.spec {
            TypeSpec::Struct { .. } => Some(Ty::Struct(decl.name.name.to_string().into())),
            TypeSpec::Enum { .. } => Some(Ty::Enum(decl.name.name.to_string().into())),
            spec => {
                // Not resolved yet: `typedecls` resolves what a type names
                // before it, so this is a safety net only (aliases may chain).
                if self.depth.get() > 32 {
                    cx.err(
                        RECURSION,
                        span,
                        format!("type `{}` is defined in terms of itself", decl.name),
                    );
                    return Some(None);
                }
                self.depth.set(self.depth.get() + 1);
                // The spec is the declaration's (maybe of another file):
                // its names are noted where the declaration is checked.
                let names = cx.names.take();
                let t = resolve_type(cx, self, spec);
                cx.names = names;
                self.depth.set(self.depth.get() - 1);
                t
            }
        })
    }

    /// Subrange bounds of a type spec (inline, or of the named type).
    pub fn range_of(&self, spec: &TypeSpec) -> Option<(i128, i128)> {
        match spec {
            TypeSpec::Subrange { range, .. } => match (&range.lo, &range.hi) {
                (
                    ConstExpr::Lit(Literal {
                        kind: LitKind::Int(lo),
                        ..
                    }),
                    ConstExpr::Lit(Literal {
                        kind: LitKind::Int(hi),
                        ..
                    }),
                ) => Some((lo.get(), hi.get())),
                _ => None,
            },
            TypeSpec::Named(id) => self.resolved.borrow().get(&id.key())?.range,
            _ => None,
        }
    }

    /// The initial value a named type gives its variables (`TYPE T : INT :=
    /// 5`), checked where the type is declared.
    pub fn type_init(&self, spec: &TypeSpec) -> Option<Init> {
        let TypeSpec::Named(id) = spec else {
            return None;
        };
        self.resolved.borrow().get(&id.key())?.init.clone()
    }
}
