//! Literal typing: the class of an untyped literal, its value once a type
//! is known, and pending folds of untyped literals.

use super::ir::Const;
use super::types::{Elem, Ty};
use crate::ast::{LitKind, Literal, Span};

/// A literal before it meets a type.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum LitClass {
    Typed(Const),
    Int(i128),
    Real(f64, String),
    Str(String, bool),
    Unsupported(&'static str),
    /// A typed literal whose value does not fit its prefix (`SINT#300`).
    Invalid(String),
    /// A generic standard function applied to untyped literals only
    /// (`LD k / MUX 10, 20, 30`): like a literal, it gets its type from its
    /// first typed use, and its code is emitted then.
    Pending(Box<Pending>),
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Pending {
    pub key: String,
    pub args: Vec<(PendArg, Span)>,
    pub span: Span,
    /// `EN :=` of a formal call (see [`super::ir::Expr::CallStd`]).
    pub en: Option<super::ir::Value>,
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) enum PendArg {
    Typed(super::ir::Value, Ty),
    Lit(LitClass),
}

pub(crate) fn lit_class(lit: &Literal) -> LitClass {
    let untyped = match &lit.kind {
        LitKind::Int(v) => LitClass::Int(v.get()),
        LitKind::Real { value, text } => LitClass::Real(*value, text.to_string()),
        LitKind::Bool(b) => LitClass::Typed(Const::Bool(*b)),
        LitKind::Time { nanos, long } => LitClass::Typed(Const::Time(
            *nanos,
            if *long { Elem::LTIME } else { Elem::TIME },
        )),
        LitKind::Date(d) => LitClass::Typed(Const::Time(*d, Elem::DATE)),
        LitKind::Tod(t) => LitClass::Typed(Const::Time(*t, Elem::TOD)),
        LitKind::Dt(t) => LitClass::Typed(Const::Time(*t, Elem::DT)),
        LitKind::String { value, wide } => LitClass::Str(value.to_string(), *wide),
        LitKind::Enum(_) => LitClass::Unsupported("enumeration literals are not supported yet"),
    };
    let Some(prefix) = &lit.type_prefix else {
        return untyped;
    };
    if prefix.is("STRING") || prefix.is("WSTRING") {
        return untyped;
    }
    match Elem::from_name(&prefix.name) {
        Some(e) => match coerce(&untyped, &Ty::Elem(e)) {
            Ok(c) => LitClass::Typed(c),
            Err(m) => LitClass::Invalid(m),
        },
        None => LitClass::Invalid(format!("`{prefix}#` is not an elementary type")),
    }
}

/// Give a literal a type, or say why it does not fit.
pub(crate) fn coerce(lit: &LitClass, ty: &Ty) -> Result<Const, String> {
    let mismatch = || {
        Err(format!(
            "expected a value of type {ty}, found {}",
            describe(lit)
        ))
    };
    match (lit, ty) {
        (LitClass::Typed(c), _) if c.ty() == *ty => Ok(c.clone()),
        (LitClass::Typed(Const::Str(s)), Ty::Str { wide: w, len }) if s.wide == *w => {
            str_const(&s.value, s.wide, *len, ty)
        }
        (LitClass::Int(v), Ty::Elem(Elem::BOOL)) => match v {
            0 | 1 => Ok(Const::Bool(*v == 1)),
            _ => Err(format!("{v} is not a BOOL (only 0 and 1 are)")),
        },
        (LitClass::Int(v), Ty::Elem(e)) if e.int_range().is_some() => {
            let (lo, hi) = e.int_range().expect("checked");
            if (lo..=hi).contains(v) {
                Ok(Const::Int((*v).into(), *e))
            } else {
                Err(format!("{v} does not fit in {} ({lo}..{hi})", e.name()))
            }
        }
        (LitClass::Int(v), Ty::Elem(e)) if e.is_real() => Ok(Const::Real(*v as f64, *e)),
        (LitClass::Real(v, text), Ty::Elem(e @ (Elem::REAL | Elem::LREAL))) => {
            let v = if *e == Elem::REAL {
                text.replace('_', "")
                    .parse::<f32>()
                    .map(f64::from)
                    .unwrap_or(*v)
            } else {
                *v
            };
            if v.is_finite() {
                Ok(Const::Real(v, *e))
            } else {
                Err(format!("{text} is out of range for {}", e.name()))
            }
        }
        (LitClass::Str(s, wide), Ty::Str { wide: w, len }) if wide == w => {
            str_const(s, *wide, *len, ty)
        }
        (LitClass::Unsupported(msg), _) => Err((*msg).to_string()),
        (LitClass::Invalid(msg), _) => Err(msg.clone()),
        (LitClass::Pending(p), _) => Err(format!("the result of {} has no type here", p.key)),
        _ => mismatch(),
    }
}

/// The type a literal takes as the other operand of a string of type `t`
/// (strings are compared only): `t`, or for a string literal longer than
/// `t`'s capacity a capacity that holds it, since strings of any two lengths
/// compare by their contents (`LD s3 / EQ 'abcdef'` is FALSE, not an error).
pub(crate) fn operand_ty(l: &LitClass, t: &Ty) -> Ty {
    match (l, t) {
        (LitClass::Str(s, w), Ty::Str { wide, len }) if w == wide => {
            let n = if *w {
                s.encode_utf16().count()
            } else {
                s.len()
            };
            Ty::Str {
                wide: *wide,
                len: (*len).max(u32::try_from(n).unwrap_or(u32::MAX)),
            }
        }
        _ => t.clone(),
    }
}

pub(crate) fn str_const(s: &str, wide: bool, len: u32, ty: &Ty) -> Result<Const, String> {
    let n = if wide {
        s.encode_utf16().count()
    } else {
        s.len()
    };
    if n > len as usize {
        return Err(format!("the string has {n} characters; {ty} holds {len}"));
    }
    Ok(Const::Str(Box::new(crate::sema::ir::StrConst {
        value: s.to_string(),
        wide,
        len,
    })))
}

pub(crate) fn describe(lit: &LitClass) -> String {
    match lit {
        LitClass::Typed(c) => format!("a {} literal", c.ty()),
        LitClass::Int(v) => format!("the integer literal {v}"),
        LitClass::Real(_, t) => format!("the real literal {t}"),
        LitClass::Str(..) => "a string literal".to_string(),
        LitClass::Unsupported(m) => (*m).to_string(),
        LitClass::Invalid(m) => m.clone(),
        LitClass::Pending(p) => format!("the result of {} on untyped literals", p.key),
    }
}
