//! Values of the differential test: the generator's literals as interpreter
//! values, as Rust expressions and as IL text, and the canonical text both
//! sides print for a value.

use super::*;

pub(super) fn elem(t: T) -> Elem {
    Elem::from_name(t.name()).expect("elementary type")
}

pub(super) fn lit_value(t: T, l: &Lit) -> Value {
    match (t, l) {
        (_, Lit::Bool(b)) => Value::Bool(*b),
        (_, Lit::Int(v)) => Value::Int(*v, elem(t)),
        (T::Real, Lit::Real(f)) => Value::Real(*f as f32),
        (_, Lit::Real(f)) => Value::LReal(*f),
        (_, Lit::Time(ns)) => Value::Time(*ns, Elem::TIME),
    }
}

pub(super) fn lit_rust(t: T, l: &Lit) -> String {
    match (t, l) {
        (_, Lit::Bool(b)) => b.to_string(),
        (_, Lit::Int(v)) => format!("({v}i128) as {}", t.rust()),
        (T::Real, Lit::Real(f)) => format!("f32::from_bits({:#x})", (*f as f32).to_bits()),
        (_, Lit::Real(f)) => format!("f64::from_bits({:#x})", f.to_bits()),
        (_, Lit::Time(ns)) => format!("il_std::TIME({ns}i64)"),
    }
}

/// The canonical text of a value (the driver's `Canon` prints the same).
pub(super) fn canon(v: &Value) -> String {
    match v {
        Value::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Value::Int(x, _) => x.to_string(),
        Value::Real(f) => format!("{f:?}"),
        Value::LReal(f) => format!("{f:?}"),
        Value::Time(ns, _) => ns.to_string(),
        // Hex units: strings may hold line breaks, and the lines are the protocol.
        Value::Str { units, .. } => units.iter().map(|u| format!("{u:02x}")).collect(),
        Value::Array(items) => items.iter().map(canon).collect::<Vec<_>>().join(","),
        Value::Enum { value, .. } => value.clone(),
        Value::Struct(s) => {
            let fields: Vec<String> = s.fields.iter().map(|(_, v)| canon(v)).collect();
            format!("({})", fields.join(";"))
        }
        other => other.display(),
    }
}

pub(super) fn fault_text(ctx: &il_std::Cycle) -> String {
    format!(
        "faults={} last={:?} io={}",
        ctx.fault_count(),
        ctx.last_fault().map(|f| (f.kind, f.line)),
        io_text(ctx)
    )
}

/// The outputs and memory the generated programs use (the driver's `io`
/// prints the same): located variables and direct addresses, byte by byte.
pub(super) fn io_text(ctx: &il_std::Cycle) -> String {
    let mut s = String::new();
    for a in [il_std::Area::Output, il_std::Area::Memory] {
        for b in 0..IO_BYTES {
            let _ = write!(s, "{:02x}", ctx.io.byte(a, b));
        }
    }
    s
}

/// Bytes of each area that generated programs use (user.rs: slots of 8 bytes).
pub(super) const IO_BYTES: usize = 72;

pub(super) fn lit_text(l: &Lit) -> String {
    match l {
        Lit::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Lit::Int(v) => v.to_string(),
        Lit::Real(f) => format!("{f:?}"),
        Lit::Time(ns) => format!("T#{}", il_interp::fmt_dur(*ns)),
    }
}

pub(super) fn value_lit(v: &Value) -> Lit {
    match v {
        Value::Bool(b) => Lit::Bool(*b),
        Value::Int(x, _) => Lit::Int(*x),
        Value::Real(f) => Lit::Real(*f as f64),
        Value::LReal(f) => Lit::Real(*f),
        Value::Time(ns, _) => Lit::Time(*ns),
        other => panic!("not an input value: {other:?}"),
    }
}

pub(super) fn gen_type(t: &il_codegen::ir::types::Ty) -> T {
    let name = t.to_string();
    [
        T::Bool,
        T::Sint,
        T::Int,
        T::Dint,
        T::Lint,
        T::Usint,
        T::Uint,
        T::Udint,
        T::Ulint,
        T::Byte,
        T::Word,
        T::Dword,
        T::Lword,
        T::Real,
        T::Lreal,
        T::Time,
    ]
    .into_iter()
    .find(|g| g.name() == name)
    .unwrap_or_else(|| panic!("input of type {name}"))
}
