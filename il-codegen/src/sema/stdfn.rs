//! Standard functions: type-checks calls against il-std's signature table
//! (`il_std::signature`), the one table that the runtime, the checker and the
//! emitter share.

use super::ir::StdCall;
use super::literals::LitClass;
use super::types::{DEFAULT_STRING_LEN, Elem, Ty};
use crate::ast::{Ident, Span};
use il_std::signature::{self as sig, Class, Ext, ParamTy, Signature};

pub(crate) fn is_std(key: &str) -> bool {
    sig::lookup(key).is_some()
}

pub(crate) fn names() -> impl Iterator<Item = &'static str> {
    sig::SIGNATURES.iter().map(|s| s.name)
}

/// The shape of one argument before the call is resolved.
#[derive(Clone, Debug)]
pub(crate) enum ArgShape {
    Ty(Ty),
    Lit(LitClass),
}

pub(crate) struct Resolved {
    pub sig: &'static il_std::signature::Signature,
    pub call: StdCall,
    /// The type each argument must have.
    pub params: Vec<Ty>,
    pub ret: Ty,
    /// The fault the call may record (from the signature table).
    pub fault: Option<il_std::FaultKind>,
}

pub(crate) struct ResolveError {
    /// Wrong number of arguments (otherwise a type error).
    pub count: bool,
    pub message: String,
    pub signature: String,
}

fn to_ty(e: sig::Elem) -> Ty {
    Ty::of_std(e)
}

fn in_class(t: &Ty, c: Class) -> bool {
    match t {
        Ty::Elem(e) => sig::Elem::from(*e).class_member(c),
        Ty::Str { wide, .. } => {
            let s = if *wide {
                sig::Elem::WSTRING
            } else {
                sig::Elem::STRING
            };
            s.class_member(c)
        }
        _ => false,
    }
}

/// Derived types that the ANY-typed standard functions take besides the
/// elementary ones (docs/semantics.md, "Calls"): an enumeration for those
/// typed ANY (SEL, MUX, MOVE) and for EQ and NE (it is not ordered); a
/// structure or an array for those typed ANY, unless it holds FB instances
/// (they are not values). A subrange has its base type, so it is elementary.
fn takes_derived(name: &str, t: &Ty, c: Class) -> bool {
    match t {
        Ty::Enum(_) => {
            c == Class::Any || (c == Class::AnyElementary && matches!(name, "EQ" | "NE"))
        }
        Ty::Struct(_) => c == Class::Any,
        Ty::Array(a) => {
            c == Class::Any && !matches!(a.elem, Ty::Fb(_)) && takes_derived_elem(&a.elem)
        }
        _ => false,
    }
}

/// An array's element type is a value (not an FB instance), also nested.
fn takes_derived_elem(t: &Ty) -> bool {
    match t {
        Ty::Fb(_) => false,
        Ty::Array(a) => takes_derived_elem(&a.elem),
        _ => true,
    }
}

/// `LIMIT(MN : T, IN : T, MX : T) : T`
pub(crate) fn describe(s: &Signature) -> String {
    let ty = |p: &ParamTy| match p {
        ParamTy::Concrete(e) => e.name().to_string(),
        ParamTy::T(c) | ParamTy::Other(c) => class_name(*c).to_string(),
    };
    let params: Vec<String> = s
        .params
        .iter()
        .map(|p| format!("{} : {}", p.name, ty(&p.ty)))
        .collect();
    let more = if matches!(s.ext, Ext::Fixed) {
        ""
    } else {
        ", ..."
    };
    format!("{}({}{more}) : {}", s.name, params.join(", "), ty(&s.ret))
}

/// The parameter type of argument `i` (extensible functions repeat the last).
fn param_of(s: &Signature, i: usize) -> Option<&ParamTy> {
    match s.ext {
        Ext::Fixed => s.params.get(i).map(|p| &p.ty),
        _ => s.params.get(i).or(s.params.last()).map(|p| &p.ty),
    }
}

fn lit_default(l: &LitClass, c: Option<Class>) -> Option<Ty> {
    let pick = |t: Ty| (c.is_none_or(|c| in_class(&t, c))).then_some(t);
    match l {
        LitClass::Int(_) => pick(Ty::Elem(Elem::DINT))
            .or_else(|| pick(Ty::Elem(Elem::LREAL)))
            .or_else(|| pick(Ty::Elem(Elem::DWORD))),
        LitClass::Real(..) => pick(Ty::Elem(Elem::LREAL)),
        LitClass::Str(_, w) => pick(Ty::Str {
            wide: *w,
            len: DEFAULT_STRING_LEN,
        }),
        LitClass::Typed(c2) => pick(c2.ty()),
        LitClass::Unsupported(_) | LitClass::Invalid(_) | LitClass::Pending(_) => None,
    }
}

/// Whether a call's generic type can only come from its use: the result is
/// the generic T and every T argument is an untyped number.
pub(crate) fn needs_context(key: &str, args: &[ArgShape]) -> bool {
    let Some(s) = sig::lookup(key) else {
        return false;
    };
    if !matches!(s.ret, ParamTy::T(_)) {
        return false;
    }
    let mut literal = false;
    for (i, a) in args.iter().enumerate() {
        if let Some(ParamTy::T(_)) = param_of(s, i) {
            match a {
                ArgShape::Ty(_) => return false,
                ArgShape::Lit(LitClass::Int(_) | LitClass::Real(..)) => literal = true,
                ArgShape::Lit(_) => {}
            }
        }
    }
    literal
}

/// Resolve a call; `force` is the type the result must have when the
/// arguments leave the generic type open.
pub(crate) fn resolve(
    key: &str,
    args: &[ArgShape],
    force: Option<&Ty>,
) -> Result<Resolved, ResolveError> {
    let s = sig::lookup(key).ok_or_else(|| ResolveError {
        count: false,
        message: format!("unknown function {key}"),
        signature: String::new(),
    })?;
    let signature = describe(s);
    let err = |count: bool, message: String| ResolveError {
        count,
        message,
        signature: signature.clone(),
    };
    let n = args.len();
    let arity_ok = match s.ext {
        Ext::Fixed => n == s.params.len(),
        Ext::Fold | Ext::Chain => n >= 2,
        Ext::Mux => n >= 2,
    };
    if !arity_ok {
        let want = match s.ext {
            Ext::Fixed => format!("{}", s.params.len()),
            _ => "at least 2".to_string(),
        };
        let msg = if matches!(s.ext, Ext::Fixed) && s.params.len() == 1 {
            // `ABS y`: in IL the one argument is the current result.
            format!(
                "{} takes 1 argument, the current result; with the operand this call gives {n} (write `LD` of the value, then `{}` alone)",
                s.name, s.name
            )
        } else {
            format!("{} takes {want} arguments; this call gives {n}", s.name)
        };
        return Err(err(true, msg));
    }
    // Bind the generic T from the typed arguments.
    let mut t: Option<Ty> = None;
    let mut t_class = None;
    for (i, a) in args.iter().enumerate() {
        let Some(ParamTy::T(c)) = param_of(s, i) else {
            continue;
        };
        t_class = Some(*c);
        if let ArgShape::Ty(ty) = a {
            match &t {
                None => t = Some(ty.clone()),
                Some(u) if u == ty => {}
                // Strings of several lengths: the longest, which holds
                // every argument uncut (a shorter one is resized up).
                Some(u) if ty.resizes_to(u) => {
                    if let (Ty::Str { len: have, .. }, Ty::Str { len: bound, .. }) = (ty, u)
                        && have > bound
                    {
                        t = Some(ty.clone());
                    }
                }
                // Ed.3 implicit widening: the wider of the two, into which
                // each argument is then widened (`fit`; refused under
                // iec2003 there, naming the conversion).
                Some(u) if super::widen::wider(u, ty).is_some() => {
                    t = super::widen::wider(u, ty);
                }
                Some(u) => {
                    return Err(err(
                        false,
                        format!("{} needs arguments of one type; found {u} and {ty}", s.name),
                    ));
                }
            }
        }
    }
    if t.is_none()
        && let Some(c) = t_class
    {
        t = force.filter(|f| in_class(f, c)).cloned();
    }
    if t.is_none()
        && let Some(c) = t_class
    {
        t = args
            .iter()
            .enumerate()
            .find_map(|(i, a)| match (param_of(s, i), a) {
                (Some(ParamTy::T(_)), ArgShape::Lit(l)) => lit_default(l, Some(c)),
                _ => None,
            });
    }
    if let (Some(t), Some(c)) = (&t, t_class)
        && !in_class(t, c)
        && !takes_derived(s.name, t, c)
    {
        return Err(err(
            false,
            format!(
                "{} is not defined for {t} (needs {})",
                s.name,
                class_name(c)
            ),
        ));
    }
    let mut params = Vec::new();
    for (i, a) in args.iter().enumerate() {
        let p = param_of(s, i).ok_or_else(|| err(true, "too many arguments".into()))?;
        let ty = match p {
            ParamTy::Concrete(e) => match (e, a) {
                // Any string length fits a STRING parameter.
                (sig::Elem::STRING | sig::Elem::WSTRING, ArgShape::Ty(ty @ Ty::Str { .. }))
                    if in_class(ty, Class::AnyString) =>
                {
                    ty.clone()
                }
                _ => to_ty(*e),
            },
            ParamTy::T(_) => t
                .clone()
                .ok_or_else(|| err(false, "cannot tell the argument type".into()))?,
            ParamTy::Other(c) => match a {
                ArgShape::Ty(ty) if in_class(ty, *c) => ty.clone(),
                ArgShape::Ty(ty) => {
                    return Err(err(
                        false,
                        format!(
                            "argument {} of {} must be {}, not {ty}",
                            i + 1,
                            s.name,
                            class_name(*c)
                        ),
                    ));
                }
                ArgShape::Lit(l) => lit_default(l, Some(*c)).ok_or_else(|| {
                    err(
                        false,
                        format!(
                            "argument {} of {} must be {}",
                            i + 1,
                            s.name,
                            class_name(*c)
                        ),
                    )
                })?,
            },
        };
        // A narrower argument is widened into the parameter by the caller.
        if let ArgShape::Ty(have) = a
            && *have != ty
            && !have.resizes_to(&ty)
            && super::widen::widening(have, &ty).is_none()
        {
            return Err(err(
                false,
                format!("argument {} of {} must be {ty}, not {have}", i + 1, s.name),
            ));
        }
        params.push(ty);
    }
    let ret = match &s.ret {
        ParamTy::Concrete(e) => to_ty(*e),
        ParamTy::T(_) => t
            .clone()
            .ok_or_else(|| err(false, "cannot tell the result type".into()))?,
        ParamTy::Other(_) => {
            return Err(err(
                false,
                format!("{} has a result type that cannot be inferred", s.name),
            ));
        }
    };
    let call = match s.ext {
        Ext::Fixed => StdCall::Plain(s.name),
        Ext::Fold => StdCall::Fold(s.name),
        Ext::Chain => StdCall::Chain(s.name),
        Ext::Mux => StdCall::Mux,
    };
    let elems: Vec<sig::Elem> = params.iter().filter_map(sig_elem).collect();
    let fault = s.fault_for(&elems);
    Ok(Resolved {
        sig: s,
        call,
        params,
        ret,
        fault,
    })
}

/// The signature table's name of an elementary or string type.
fn sig_elem(t: &Ty) -> Option<sig::Elem> {
    match t {
        Ty::Elem(e) => Some(sig::Elem::from(*e)),
        Ty::Str { wide: false, .. } => Some(sig::Elem::STRING),
        Ty::Str { wide: true, .. } => Some(sig::Elem::WSTRING),
        _ => None,
    }
}

/// The position of the parameter `name` in a formal call of `key` with
/// `count` parameters (`LIMIT(MN := 0, IN := x, MX := 9)`), or why there is
/// none.
pub(crate) fn formal_slot(key: &str, name: &Ident, count: usize) -> Result<usize, String> {
    let Some(s) = sig::lookup(key) else {
        return Err(format!("unknown function {key}"));
    };
    let extensible = !matches!(s.ext, Ext::Fixed);
    let pos = s.params.iter().position(|p| name.is(p.name)).or_else(|| {
        // IN1, IN2, ... beyond the listed ones for extensible functions.
        let up = name.key();
        let n: usize = up.strip_prefix("IN")?.parse().ok()?;
        let first = s
            .params
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case("IN1"))?;
        // `IN0` does not exist (`then_some` computed `first + n - 1` even
        // then, and `IN0 := x` underflowed: found by fuzzing), and `INn`
        // beyond the number of arguments given leaves a gap (some IN below
        // it is missing): no such parameter. Bounding `n` also keeps the
        // slots from being resized to `n` (`IN99999999999 := x` asked for
        // terabytes).
        (extensible && (1..=count).contains(&n)).then(|| first + n - 1)
    });
    pos.ok_or_else(|| {
        let names: Vec<&str> = s.params.iter().map(|p| p.name).collect();
        format!(
            "{} has no parameter `{name}` (it has {})",
            s.name,
            names.join(", ")
        )
    })
}

/// The arguments of a formal call of `key` in parameter order, from their
/// positions ([`formal_slot`]; each given once): or the first parameter
/// that is missing.
pub(crate) fn order_slots<A>(
    key: &str,
    given: Vec<(usize, A, Span)>,
) -> Result<Vec<(A, Span)>, String> {
    let Some(s) = sig::lookup(key) else {
        return Err(format!("unknown function {key}"));
    };
    let extensible = !matches!(s.ext, Ext::Fixed);
    let mut slots: Vec<Option<(A, Span)>> = Vec::new();
    for (pos, a, sp) in given {
        if slots.len() <= pos {
            slots.resize_with(pos + 1, || None);
        }
        slots[pos] = Some((a, sp));
    }
    let n = slots.len();
    let mut out = Vec::new();
    for (i, slot) in slots.into_iter().enumerate() {
        match slot {
            Some(x) => out.push(x),
            None => {
                return Err(format!(
                    "{} needs parameter `{}`",
                    s.name,
                    s.params.get(i).map_or("?", |p| p.name)
                ));
            }
        }
    }
    if !extensible && n < s.params.len() {
        return Err(format!("{} needs parameter `{}`", s.name, s.params[n].name));
    }
    Ok(out)
}

/// The IEC name of a generic type class.
fn class_name(c: Class) -> &'static str {
    match c {
        Class::AnyNum => "ANY_NUM",
        Class::AnyInt => "ANY_INT",
        Class::AnyReal => "ANY_REAL",
        Class::AnyBit => "ANY_BIT",
        Class::AnyBitString => "ANY_BIT (except BOOL)",
        Class::AnyMagnitude => "ANY_MAGNITUDE",
        Class::AnyElementary => "ANY_ELEMENTARY",
        Class::AnyString => "ANY_STRING",
        Class::AnyDate => "ANY_DATE",
        Class::Bool => "BOOL",
        _ => "ANY",
    }
}
