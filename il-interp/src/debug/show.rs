//! How a debugger shows values: the members of an instance, a structure
//! or an array, the subscripts of an element, the type of a value.

use crate::Machine;
use crate::values::Value;
use il_codegen::ir::TypeDef;
use il_codegen::ir::types::Ty;

/// A variable (or member, element) to show: its name, value and type.
#[derive(Clone, Debug)]
pub struct Shown {
    /// The name (`start`), member (`Q`) or subscripts (`[2, 3]`).
    pub name: String,
    /// Its value.
    pub value: Value,
    /// Its type as IEC writes it (`INT`, `R_TRIG`, `ARRAY [1..3] OF INT`).
    pub ty: String,
}

/// [`Here::members`].
pub(super) fn members(m: &Machine, v: &Value, ty: &Ty) -> Vec<Shown> {
    match (v, ty) {
        (Value::Fb(inst), _) => {
            let pou = &m.prog.pous[inst.pou];
            pou.vars
                .iter()
                .zip(&inst.vars)
                .filter(|(d, _)| crate::held(d))
                .map(|(d, x)| Shown {
                    name: d.name.clone(),
                    value: x.clone(),
                    ty: d.ty.to_string(),
                })
                .collect()
        }
        (Value::StdFb(b), _) => b
            .fields()
            .into_iter()
            .map(|(n, x)| Shown {
                name: n.to_string(),
                ty: type_of_value(&x),
                value: x,
            })
            .collect(),
        (Value::Struct(s), Ty::Struct(n)) => {
            let types: Vec<Ty> = match m.type_def(n) {
                Ok(TypeDef::Struct { fields, .. }) => fields.iter().map(|f| f.ty.clone()).collect(),
                _ => Vec::new(),
            };
            s.fields
                .iter()
                .enumerate()
                .map(|(k, (n, x))| Shown {
                    name: n.clone(),
                    value: x.clone(),
                    ty: types
                        .get(k)
                        .map_or_else(|| type_of_value(x), |t| t.to_string()),
                })
                .collect()
        }
        (Value::Array(items), Ty::Array(a)) => items
            .iter()
            .enumerate()
            .map(|(k, x)| Shown {
                name: subscripts(&a.dims, k),
                value: x.clone(),
                ty: a.elem.to_string(),
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// `[2, 3]`: the subscripts of flat (row-major) element `k` of an array
/// with these bounds.
pub(crate) fn subscripts(dims: &[(i64, i64)], mut k: usize) -> String {
    let mut subs = vec![0i64; dims.len()];
    for (d, &(lo, hi)) in dims.iter().enumerate().rev() {
        let n = (hi - lo + 1).max(1) as usize;
        subs[d] = lo + (k % n) as i64;
        k /= n;
    }
    let s: Vec<String> = subs.iter().map(|x| x.to_string()).collect();
    format!("[{}]", s.join(", "))
}

/// The IEC type of a value whose declaration is not at hand (a standard
/// block's members carry their type in the value).
pub fn type_of_value(v: &Value) -> String {
    use il_codegen::ir::types::Elem;
    match v {
        Value::Bool(_) => "BOOL".into(),
        Value::Int(_, e) | Value::Time(_, e) => e.name().into(),
        Value::Real(_) => Elem::REAL.name().into(),
        Value::LReal(_) => Elem::LREAL.name().into(),
        Value::Str { wide, .. } => if *wide { "WSTRING" } else { "STRING" }.into(),
        Value::Array(_) => "ARRAY".into(),
        Value::Enum { ty, .. } => ty.clone(),
        Value::Struct(s) => s.ty.clone(),
        Value::Fb(_) => "FUNCTION_BLOCK".into(),
        Value::StdFb(b) => b.name().into(),
    }
}
