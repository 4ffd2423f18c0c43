//! Places named by a host or a tool (`ilc run --set`, `--watch`): variables
//! of the instance with member and element paths (`tank.level`,
//! `valves[2].open`, `m[1, 2]`), located variables and direct addresses
//! (`%IX0.0`, `%QW1`), which live in the process image of the cycle, exactly
//! where generated code reads and writes them.

use crate::places::{Step, io_read, io_write};
use crate::values::Value;
use crate::{Machine, held};
use il_codegen::diag::suggest;
use il_codegen::ir::parse_address;
use il_codegen::ir::path::Rooted;
use il_codegen::ir::types::{Elem, Ty};
use il_codegen::ir::{Loc, Storage, TypeDef};
use il_std::Cycle;

/// A resolved host place: [`Machine::lookup`] makes one, [`Machine::get_at`]
/// and [`Machine::set_at`] use it.
#[derive(Clone, Debug)]
pub struct HostPlace {
    /// The name as the host gave it.
    pub text: String,
    /// The type of the place.
    pub ty: Ty,
    /// Subrange bounds a store must respect.
    pub range: Option<(i128, i128)>,
    target: Target,
}

#[derive(Clone, Debug)]
enum Target {
    /// A variable of the instance and the steps into it.
    Var(usize, Vec<Step>),
    /// A place of the process image.
    Addr(Loc),
}

impl HostPlace {
    /// The process image place, for a direct address or a located variable.
    pub fn location(&self) -> Option<&Loc> {
        match &self.target {
            Target::Addr(l) => Some(l),
            Target::Var(..) => None,
        }
    }
}

/// Where a path's parts lead: the steps, and the type and subrange bounds
/// of the place they end at.
pub(crate) type Resolved = (Vec<Step>, Ty, Option<(i128, i128)>);

/// One part of a path: `.name` or `[i, j]` (the subscripts' values).
pub(crate) use il_codegen::ir::path::PathPart as Part;

/// Split `a.b[1, 2].c` into its root and parts (the IR's host paths:
/// constant subscript expressions are folded there).
pub(crate) fn split(text: &str) -> Result<(String, Vec<Part>), String> {
    let p = il_codegen::ir::path::parse(text)?;
    Ok((p.root, p.parts))
}

/// The interpreter's steps for the IR's resolved ones.
pub(crate) fn steps_of(steps: Vec<il_codegen::ir::path::Step>) -> Vec<Step> {
    use il_codegen::ir::path::Step as S;
    (steps.into_iter())
        .map(|s| match s {
            S::Field(m) => Step::Field(m.index as usize),
            S::Element(k) => Step::Index(Some(k)),
        })
        .collect()
}

/// ", did you mean `x`?" when a candidate is close.
pub(crate) fn hint<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> String {
    suggest(name, candidates)
        .map(|s| format!("; did you mean `{s}`?"))
        .unwrap_or_default()
}

impl Machine {
    /// Resolve a variable path or a direct address of this instance. Every
    /// error names what is wrong and, where one is close, the name meant.
    pub fn lookup(&self, text: &str) -> Result<HostPlace, String> {
        let text = text.trim();
        let pou = self.pou();
        if text.starts_with('%') {
            let l = parse_address(text)?;
            return Ok(HostPlace {
                text: text.to_string(),
                ty: Ty::Elem(l.elem),
                range: None,
                target: Target::Addr(l),
            });
        }
        let (root, parts) = split(text)?;
        let root = root.as_str();
        let rooted = il_codegen::ir::path::resolve_var(
            &self.prog,
            pou,
            (root, &parts),
            text,
            il_codegen::ir::path::Scope::Held,
            |hint| format!("no variable `{root}` in {}{hint}", pou.name),
        )?;
        Ok(match rooted {
            Rooted::Located(l, ty, range) => HostPlace {
                text: text.to_string(),
                ty,
                range,
                target: Target::Addr(l),
            },
            Rooted::Var(i, r) => HostPlace {
                text: text.to_string(),
                ty: r.ty,
                range: r.range,
                target: Target::Var(i, steps_of(r.steps)),
            },
        })
    }

    /// The steps `parts` take into a place of type `ty` (subrange `range`):
    /// the steps, the type and subrange of the place they end at, as the
    /// one path resolver of the IR finds them. `text` is the whole path, for
    /// the messages.
    pub(crate) fn resolve_parts(
        &self,
        ty: Ty,
        range: Option<(i128, i128)>,
        parts: &[Part],
        text: &str,
    ) -> Result<Resolved, String> {
        let r = il_codegen::ir::path::resolve(&self.prog, (ty, range), parts, text)?;
        Ok((steps_of(r.steps), r.ty, r.range))
    }

    /// The current value of a host place (the process image is the cycle's).
    pub fn get_at(&self, ctx: &Cycle, p: &HostPlace) -> Value {
        match &p.target {
            // A located variable's `Loc` has its declared type (`AT %IW2 :
            // INT` reads as INT), as the checker resolved it.
            Target::Addr(l) => io_read(ctx, l),
            Target::Var(i, steps) => self
                .read_at(&self.inst.vars[*i], steps)
                .unwrap_or(Value::Bool(false)),
        }
    }

    /// Write a host place; the value must have its type (and stay in its subrange).
    pub fn set_at(&mut self, ctx: &mut Cycle, p: &HostPlace, v: Value) -> Result<(), String> {
        if !self.fits(&v, &p.ty)? {
            return Err(format!("`{}` is {}, not {}", p.text, p.ty, v.display()));
        }
        if let (Some((lo, hi)), Value::Int(x, _)) = (p.range, &v)
            && !(lo..=hi).contains(x)
        {
            return Err(format!(
                "`{}`: {x} is outside its subrange {lo}..{hi}",
                p.text
            ));
        }
        match &p.target {
            Target::Addr(l) => {
                io_write(ctx, l, &v);
                Ok(())
            }
            Target::Var(i, steps) => {
                let mut root = std::mem::replace(&mut self.inst.vars[*i], Value::Bool(false));
                let ok = self.write_at(&mut root, steps, v);
                self.inst.vars[*i] = root;
                if ok {
                    Ok(())
                } else {
                    Err(format!("cannot write `{}`", p.text))
                }
            }
        }
    }

    /// Parse `text` as a value for a host place: IEC literal forms (`TRUE`,
    /// `42`, `16#FF`, `T#10ms`, `'text'`) and enumeration values
    /// (`TankState#Filling` or `Filling`).
    pub fn parse_for(&self, p: &HostPlace, text: &str) -> Result<Value, String> {
        self.parse_typed(&p.text, &p.ty, p.range, text)
    }

    /// [`Self::parse_for`] for a place named `place` of type `ty` (also the
    /// places of a configuration).
    pub(crate) fn parse_typed(
        &self,
        place: &str,
        ty: &Ty,
        range: Option<(i128, i128)>,
        text: &str,
    ) -> Result<Value, String> {
        let p = HostPlace {
            text: place.to_string(),
            ty: ty.clone(),
            range,
            target: Target::Var(0, Vec::new()),
        };
        let t = text.trim();
        if let Ty::Enum(n) = &p.ty {
            let TypeDef::Enum { name, values, .. } = self.type_def(n)? else {
                return Err(format!("internal: `{n}` is not an enumeration"));
            };
            let bare = match t.split_once('#') {
                Some((ty, v)) if ty.eq_ignore_ascii_case(name) => v,
                Some((ty, _)) => {
                    return Err(format!("`{t}` is a value of {ty}; `{}` is {name}", p.text));
                }
                None => t,
            };
            let names = || values.iter().map(|(v, _)| v.as_str());
            return names()
                .find(|v| v.eq_ignore_ascii_case(bare))
                .map(|v| Value::Enum {
                    ty: name.clone(),
                    value: v.to_string(),
                })
                .ok_or_else(|| {
                    format!(
                        "`{t}` is not a value of {name} ({}){}",
                        names().collect::<Vec<_>>().join(", "),
                        hint(bare, names())
                    )
                });
        }
        if matches!(p.ty, Ty::Struct(_) | Ty::Array { .. } | Ty::Fb(_)) {
            return Err(format!(
                "`{}` is {}: set its members or elements one by one",
                p.text, p.ty
            ));
        }
        let v = crate::parse_literal(&p.ty, t).ok_or_else(|| {
            let mut msg = format!("`{t}` is not a valid {} value (for `{}`)", p.ty, p.text);
            // A signed number into a bit string (`%IW1` is a WORD): say how.
            let bits = match p.ty.to_string().as_str() {
                "BYTE" => 8,
                "WORD" => 16,
                "DWORD" => 32,
                "LWORD" => 64,
                _ => 0,
            };
            if let Ok(n) = t.trim().parse::<i128>()
                && n < 0
                && bits > 0
                && n >= -(1i128 << (bits - 1))
            {
                let twos = (1i128 << bits) + n;
                msg.push_str(&format!(
                    ": a {} has no sign; set the signed variable declared AT it \
                     (`--set NAME={n}`), or write its two's complement (`--set {}={twos}`)",
                    p.ty, p.text
                ));
            }
            msg
        })?;
        if let (Some((lo, hi)), Value::Int(x, _)) = (p.range, &v)
            && !(lo..=hi).contains(x)
        {
            return Err(format!(
                "`{t}` is outside the subrange {lo}..{hi} of `{}`",
                p.text
            ));
        }
        Ok(v)
    }

    /// Whether `v` is a value of type `t`.
    pub(crate) fn fits(&self, v: &Value, t: &Ty) -> Result<bool, String> {
        Ok(match (v, t) {
            (Value::Enum { ty, .. }, Ty::Enum(n)) => ty.eq_ignore_ascii_case(n),
            (Value::Struct(s), Ty::Struct(n)) => s.ty.eq_ignore_ascii_case(n),
            (Value::Array(items), Ty::Array(a)) => {
                let (dims, elem) = (&a.dims, &a.elem);
                let n: i64 = dims.iter().map(|(lo, hi)| hi - lo + 1).product();
                items.len() as i64 == n && {
                    let mut all = true;
                    for x in items {
                        all &= self.fits(x, elem)?;
                    }
                    all
                }
            }
            (Value::Int(_, a), Ty::Elem(b)) | (Value::Time(_, a), Ty::Elem(b)) => a == b,
            (Value::Bool(_), Ty::Elem(Elem::BOOL)) => true,
            (Value::Real(_), Ty::Elem(Elem::REAL)) | (Value::LReal(_), Ty::Elem(Elem::LREAL)) => {
                true
            }
            (Value::Str { wide, .. }, Ty::Str { wide: w, .. }) => wide == w,
            (Value::Fb(_) | Value::StdFb(_), Ty::Fb(_)) => {
                std::mem::discriminant(v) == std::mem::discriminant(&self.default_of(t)?)
            }
            _ => false,
        })
    }

    /// The names a host can watch by default: every variable of the instance
    /// that is not a function block instance, located ones included, in
    /// declaration order.
    pub fn watchable(&self) -> Vec<String> {
        self.pou()
            .vars
            .iter()
            .filter(|v| visible(v) && !is_instance(&v.ty))
            .map(|v| v.name.clone())
            .collect()
    }
}

/// A variable a host can name: the instance's memory and its located variables.
fn visible(v: &il_codegen::ir::Var) -> bool {
    held(v) || v.storage == Storage::Located
}

/// An FB instance, or an array of them.
fn is_instance(t: &Ty) -> bool {
    match t {
        Ty::Fb(_) => true,
        Ty::Array(a) => is_instance(&a.elem),
        _ => false,
    }
}
