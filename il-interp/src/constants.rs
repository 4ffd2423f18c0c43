//! Default and initial values of variables, and IEC literals parsed as values.

use crate::Machine;
use crate::places::Step;
use crate::values::StdFb;
use crate::values::{Instance, Struct, Value};
use il_codegen::ir::types::{Elem, Ty};
use il_codegen::ir::{Init, TypeDef};

impl Machine {
    pub(crate) fn new_instance(&self, pou: usize) -> Result<Instance, String> {
        let p = &self.prog.pous[pou];
        let vars = p
            .vars
            .iter()
            .map(|v| self.init_of(&v.ty, v.init.as_ref()))
            .collect::<Result<_, _>>()?;
        Ok(Instance {
            pou,
            vars,
            edge_mem: vec![false; p.vars.len()],
        })
    }

    /// The user type `name` (as the IR names it; case-insensitive like IEC).
    pub(crate) fn type_def(&self, name: &str) -> Result<&TypeDef, String> {
        let named = |d: &&TypeDef| match d {
            TypeDef::Struct { name: n, .. } | TypeDef::Enum { name: n, .. } => {
                n.eq_ignore_ascii_case(name)
            }
        };
        self.prog
            .types
            .iter()
            .find(named)
            .ok_or_else(|| format!("internal: no user type `{name}` in the checked program"))
    }

    pub(crate) fn default_of(&self, t: &Ty) -> Result<Value, String> {
        Ok(match t {
            // As the generated `Default`: each field at its declared initial
            // value (a subrange field's lower limit is its IR `init`).
            Ty::Struct(n) => match self.type_def(n)? {
                TypeDef::Struct { name, fields } => {
                    let mut out = Vec::with_capacity(fields.len());
                    for f in fields {
                        out.push((f.name.clone(), self.init_of(&f.ty, f.init.as_ref())?));
                    }
                    Value::Struct(Box::new(Struct {
                        ty: name.clone(),
                        fields: out,
                    }))
                }
                TypeDef::Enum { .. } => return Err(format!("internal: `{n}` is not a STRUCT")),
            },
            // The value the IR marks as the default (`#[default]` in Rust).
            Ty::Enum(n) => match self.type_def(n)? {
                TypeDef::Enum {
                    name,
                    values,
                    default,
                } => Value::Enum {
                    ty: name.clone(),
                    value: values
                        .get(*default)
                        .map(|(v, _)| v.clone())
                        .ok_or_else(|| format!("internal: `{n}` has no default value"))?,
                },
                TypeDef::Struct { .. } => {
                    return Err(format!("internal: `{n}` is not an enumeration"));
                }
            },
            Ty::Elem(_) | Ty::Str { .. } => Value::from_const(&il_codegen::ir::default_const(t)),
            Ty::Array(a) => {
                let (dims, elem) = (&a.dims, &a.elem);
                let n: i64 = dims.iter().map(|(lo, hi)| hi - lo + 1).product();
                // An array of a subrange starts at its lower limit (`ir::element_start`).
                let d = match il_codegen::ir::element_start(t) {
                    Some(c) => Value::from_const(&c),
                    None => self.default_of(elem)?,
                };
                Value::Array(vec![d; n.max(0) as usize])
            }
            Ty::Fb(name) => {
                if let Some(b) = StdFb::new(&name.to_ascii_uppercase()) {
                    Value::StdFb(Box::new(b))
                } else if let Some(p) = self
                    .prog
                    .pous
                    .iter()
                    .position(|p| p.name.eq_ignore_ascii_case(name))
                {
                    Value::Fb(Box::new(self.new_instance(p)?))
                } else {
                    return Err(format!(
                        "the function block {name} is not supported by the interpreter"
                    ));
                }
            }
        })
    }

    pub(crate) fn init_of(&self, t: &Ty, init: Option<&Init>) -> Result<Value, String> {
        match (init, t) {
            (Some(Init::Const(c)), _) => Ok(Value::from_const(c)),
            (Some(Init::Array(items)), Ty::Array(a)) => {
                let elem = &a.elem;
                let mut v = self.default_of(t)?;
                if let Value::Array(slots) = &mut v {
                    // The slots already hold the default (`default_of`).
                    let mut k = 0;
                    for (n, init) in items {
                        let x = self.init_of(elem, Some(init))?;
                        for s in slots.iter_mut().skip(k).take(*n) {
                            *s = x.clone();
                        }
                        k += n;
                    }
                }
                Ok(v)
            }
            // The type's default, then each given field (`Init::Struct`).
            (Some(Init::Struct(fields)), Ty::Struct(_)) => {
                let mut v = self.default_of(t)?;
                for (n, fty, init) in fields {
                    let x = self.init_of(fty, Some(init))?;
                    match &mut v {
                        Value::Struct(s) => match s.field_mut(n) {
                            Some(slot) => *slot = x,
                            None => return Err(format!("internal: no field {n} to initialise")),
                        },
                        _ => return Err("internal: a structure initialiser".into()),
                    }
                }
                Ok(v)
            }
            (Some(Init::Fields(fields)), Ty::Fb(_)) => {
                let mut v = self.default_of(t)?;
                for (n, c) in fields {
                    let step = Step::Field(n.index as usize);
                    if !self.write_at(&mut v, &[step], Value::from_const(c)) {
                        return Err(format!("cannot initialise field {n}"));
                    }
                }
                Ok(v)
            }
            _ => self.default_of(t),
        }
    }
}

/// Parse an IEC literal as a value of type `ty`.
pub fn parse_literal(ty: &Ty, text: &str) -> Option<Value> {
    let t = text.trim();
    match ty {
        Ty::Elem(Elem::BOOL) => match t.to_ascii_uppercase().as_str() {
            "TRUE" | "1" | "BOOL#TRUE" | "BOOL#1" => Some(Value::Bool(true)),
            "FALSE" | "0" | "BOOL#FALSE" | "BOOL#0" => Some(Value::Bool(false)),
            _ => None,
        },
        Ty::Elem(e) if e.is_int() || e.is_bitstring() => {
            let body = match t.split_once('#') {
                Some((pre, rest)) if Elem::from_name(pre) == Some(*e) => rest,
                _ => t,
            };
            let v = il_std::literal::parse_int(body).ok()?;
            let (lo, hi) = e.int_range()?;
            (lo..=hi).contains(&v).then_some(Value::Int(v, *e))
        }
        Ty::Elem(e) if e.is_real() => {
            let body = match t.split_once('#') {
                Some((pre, rest)) if Elem::from_name(pre) == Some(*e) => rest,
                _ => t,
            };
            let v = il_std::literal::parse_real(body).ok()?;
            Some(if *e == Elem::REAL {
                Value::Real(v as f32)
            } else {
                Value::LReal(v)
            })
        }
        Ty::Elem(e @ (Elem::TIME | Elem::LTIME)) => {
            let up = t.to_ascii_uppercase();
            let body = ["LTIME#", "TIME#", "LT#", "T#"]
                .iter()
                .find_map(|p| up.strip_prefix(p).map(|_| &t[p.len()..]))
                .unwrap_or(t);
            il_std::literal::parse_duration(body)
                .ok()
                .map(|ns| Value::Time(ns, *e))
        }
        Ty::Str { wide, len } => {
            let q = if *wide { '"' } else { '\'' };
            let inner = t
                .strip_prefix(q)
                .and_then(|s| s.strip_suffix(q))
                .unwrap_or(t);
            Some(Value::Str {
                units: crate::values::str_units(inner, *wide, *len),
                wide: *wide,
            })
        }
        _ => None,
    }
}
