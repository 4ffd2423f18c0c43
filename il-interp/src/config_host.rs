//! Places of a running CONFIGURATION named by a host (`ilc run --set`,
//! `--watch`): its globals (`g`, `Resource.g`), its VAR_ACCESS paths, the
//! variables of its program instances (`inst.v`, `Resource.inst.v`), each
//! with members and elements after it (`g.field`, `Res.inst.v.f[2]`), and
//! direct addresses. Located globals are their place in the process image.

use crate::ConfigMachine;
use crate::host::{Part, hint, split};
use crate::places::{Step, io_read, io_write};
use crate::values::Value;
use il_codegen::ir::parse_address;
use il_codegen::ir::path::Rooted;
use il_codegen::ir::types::Ty;
use il_codegen::ir::{GlobalRef, Loc};
use il_std::Cycle;

/// A resolved place of a configuration: [`ConfigMachine::lookup`] makes one.
#[derive(Clone, Debug)]
pub struct ConfigPlace {
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
    /// A global and the steps into it (`g`, `g.field`, `Res.h[3]`).
    Global(GlobalRef, Vec<Step>),
    Addr(Loc),
    /// Index into the configuration's access paths, and the steps into
    /// the value it names (`Ap.field`).
    Access(usize, Vec<Step>),
    /// (resource, program instance, variable index) and the steps into the
    /// variable (`Res.inst.var.field[2]`).
    Program(usize, usize, usize, Vec<Step>),
}

impl ConfigMachine {
    /// Resolve `text`: a direct address, an access path, a global, or a
    /// variable of a program instance (`inst.v`, `Resource.inst.v`), each
    /// followed by members and elements (`g.field`, `Res.inst.v.f[2]`).
    /// Every error names what is wrong and, where one is close, the name
    /// meant.
    pub fn lookup(&self, text: &str) -> Result<ConfigPlace, String> {
        let text = text.trim();
        let place = |ty: Ty, range, target| ConfigPlace {
            text: text.to_string(),
            ty,
            range,
            target,
        };
        if text.starts_with('%') {
            let l = parse_address(text)?;
            return Ok(place(Ty::Elem(l.elem), None, Target::Addr(l)));
        }
        let (root, parts) = split(text)?;
        let root = root.as_str();
        if let Some(i) = (self.def.access.iter()).position(|a| a.name.eq_ignore_ascii_case(root)) {
            let (ty, range) = (self.def.access[i].ty.clone(), self.def.access[i].range);
            let (steps, ty, range) = self.m.resolve_parts(ty, range, &parts, text)?;
            return Ok(place(ty, range, Target::Access(i, steps)));
        }
        // `Res.x...`: x is a global or a program instance of that resource.
        let res = (self.def.resources.iter()).position(|r| {
            r.name
                .as_ref()
                .is_some_and(|n| n.eq_ignore_ascii_case(root))
        });
        let (scope, name, rest) = match (res, parts.split_first()) {
            (Some(r), Some((Part::Field(n), rest))) => (Some(r), n.as_str(), rest),
            (Some(r), _) => {
                return Err(format!(
                    "`{text}` names the resource `{root}`: add one of its globals or program instances ({})",
                    self.scope_names(Some(r)).join(", ")
                ));
            }
            (None, _) => (None, root, &parts[..]),
        };
        let full = match scope {
            Some(r) => format!(
                "{}.{name}",
                self.def.resources[r].name.as_deref().unwrap_or_default()
            ),
            None => name.to_string(),
        };
        // A resource sees the configuration's globals too (`Res.g`, as the
        // checker's access paths).
        let global = self.find_global(&full).or_else(|| {
            scope?;
            self.find_global(name).filter(|g| g.resource.is_none())
        });
        if let Some(g) = global {
            let v = self.var_of(g);
            if let Some(l) = &v.location {
                if !rest.is_empty() {
                    return Err(format!(
                        "`{full}` is located at {}: it has no members",
                        l.text
                    ));
                }
                return Ok(place(v.ty.clone(), v.range, Target::Addr(l.clone())));
            }
            let (steps, ty, range) = self.m.resolve_parts(v.ty.clone(), v.range, rest, text)?;
            return Ok(place(ty, range, Target::Global(g, steps)));
        }
        if let Some((r, p)) = self.find_program(&full) {
            let Some((Part::Field(var), rest)) = rest.split_first() else {
                return Err(format!(
                    "`{text}` names the program instance `{full}`: add one of its variables (`{full}.var`)"
                ));
            };
            let pou = &self.m.prog.pous[self.programs[r][p].pou];
            let var = var.as_str();
            let rooted = il_codegen::ir::path::resolve_var(
                &self.m.prog,
                pou,
                (var, rest),
                text,
                il_codegen::ir::path::Scope::Held,
                |hint| {
                    format!(
                        "program `{}` (instance `{full}`) has no variable `{var}`{hint}",
                        pou.name
                    )
                },
            )?;
            return Ok(match rooted {
                Rooted::Located(l, ty, range) => place(ty, range, Target::Addr(l)),
                Rooted::Var(i, res) => place(
                    res.ty,
                    res.range,
                    Target::Program(r, p, i, crate::host::steps_of(res.steps)),
                ),
            });
        }
        let names = self.scope_names(scope);
        let near = hint(name, names.iter().map(String::as_str));
        Err(match scope {
            Some(r) => format!(
                "resource `{}` has no global or program instance `{name}`{near}",
                self.def.resources[r].name.as_deref().unwrap_or_default()
            ),
            None => format!(
                "configuration `{}` has no global, access path, resource or program instance `{name}`{near} (a program's variable is `instance.var`, `Resource.instance.var` in a RESOURCE)",
                self.def.name
            ),
        })
    }

    /// The names a path may start with in `scope` (a named resource), or at
    /// the top: globals, access paths, resources and program instances.
    fn scope_names(&self, scope: Option<usize>) -> Vec<String> {
        let d = &self.def;
        let mut names: Vec<String> = Vec::new();
        let res_names = |r: &il_codegen::ir::ResourceDef| -> Vec<String> {
            (r.globals.iter().map(|v| v.name.clone()))
                .chain(r.programs.iter().map(|p| p.name.clone()))
                .collect()
        };
        match scope {
            Some(r) => {
                names.extend(res_names(&d.resources[r]));
                names.extend(d.globals.iter().map(|v| v.name.clone()));
            }
            None => {
                names.extend(d.globals.iter().map(|v| v.name.clone()));
                names.extend(d.access.iter().map(|a| a.name.clone()));
                for r in &d.resources {
                    match &r.name {
                        Some(n) => names.push(n.clone()),
                        None => names.extend(res_names(r)),
                    }
                }
            }
        }
        names
    }

    /// The current value of a place (the process image is the cycle's).
    pub fn get_at(&self, ctx: &Cycle, p: &ConfigPlace) -> Value {
        let got = match &p.target {
            Target::Addr(l) => Some(io_read(ctx, l)),
            Target::Global(g, steps) => self.m.read_at(self.slot(*g), steps),
            Target::Access(i, steps) => {
                let name = self.def.access[*i].name.clone();
                self.access(&name).and_then(|v| self.m.read_at(&v, steps))
            }
            Target::Program(r, p, i, steps) => {
                self.m.read_at(&self.programs[*r][*p].vars[*i], steps)
            }
        };
        got.unwrap_or(Value::Bool(false))
    }

    /// Write a place; the value must have its type (and stay in its
    /// subrange). A READ_ONLY access path is refused.
    pub fn set_at(&mut self, ctx: &mut Cycle, p: &ConfigPlace, v: Value) -> Result<(), String> {
        if !self.m.fits(&v, &p.ty)? {
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
        let cannot = || format!("cannot write `{}`", p.text);
        match &p.target {
            Target::Addr(l) => io_write(ctx, l, &v),
            Target::Global(g, steps) => {
                let mut slot = std::mem::replace(self.slot_mut(*g), Value::Bool(false));
                let ok = self.m.write_at(&mut slot, steps, v);
                *self.slot_mut(*g) = slot;
                ok.then_some(()).ok_or_else(cannot)?;
            }
            Target::Access(i, steps) => {
                let name = self.def.access[*i].name.clone();
                let mut whole = self.access(&name).ok_or_else(cannot)?;
                self.m
                    .write_at(&mut whole, steps, v)
                    .then_some(())
                    .ok_or_else(cannot)?;
                self.set_access(&name, whole)?;
            }
            Target::Program(r, p, i, steps) => {
                let slot = &mut self.programs[*r][*p].vars[*i];
                self.m
                    .write_at(slot, steps, v)
                    .then_some(())
                    .ok_or_else(cannot)?;
            }
        }
        Ok(())
    }

    /// Parse `text` as a value for `p` (the literal forms of
    /// [`crate::Machine::parse_for`]); a READ_ONLY access path is refused here,
    /// before the run.
    pub fn parse_for(&self, p: &ConfigPlace, text: &str) -> Result<Value, String> {
        if let Target::Access(i, _) = &p.target
            && !self.def.access[*i].writable
        {
            return Err(format!(
                "the access path `{}` is READ_ONLY",
                self.def.access[*i].name
            ));
        }
        self.m.parse_typed(&p.text, &p.ty, p.range, text)
    }

    /// The names watched by default: the unlocated globals (`Resource.g`
    /// for a named resource's), then the access paths, in declaration order.
    pub fn watchable(&self) -> Vec<String> {
        let scalar = |t: &Ty| !matches!(t, Ty::Fb(_) | Ty::Array { .. } | Ty::Struct(_));
        let mut names: Vec<String> = (self.def.globals.iter())
            .filter(|v| v.location.is_none() && scalar(&v.ty))
            .map(|v| v.name.clone())
            .collect();
        for r in &self.def.resources {
            for v in r
                .globals
                .iter()
                .filter(|v| v.location.is_none() && scalar(&v.ty))
            {
                names.push(match &r.name {
                    Some(n) => format!("{n}.{}", v.name),
                    None => v.name.clone(),
                });
            }
        }
        // An access path may be spelt as a global (`Mode : mode`): once.
        for a in self.def.access.iter().filter(|a| scalar(&a.ty)) {
            if !names.iter().any(|n| n.eq_ignore_ascii_case(&a.name)) {
                names.push(a.name.clone());
            }
        }
        names
    }
}
