//! Places of a running CONFIGURATION named by a host (`ilc run --set`,
//! `--watch`): its globals (`g`, `Resource.g`), its VAR_ACCESS paths, the
//! variables of its program instances (`inst.v`, `Resource.inst.v`) and
//! direct addresses. Located globals are their place in the process image.

use crate::places::{io_read, io_write};
use crate::values::Value;
use crate::{ConfigMachine, find_var, held};
use il_codegen::sema::ir::{GlobalRef, Loc, Storage};
use il_codegen::sema::parse_address;
use il_codegen::sema::types::Ty;
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
    Global(GlobalRef),
    Addr(Loc),
    /// Index into the configuration's access paths.
    Access(usize),
    /// (resource, program instance, variable index).
    Program(usize, usize, usize),
}

impl ConfigMachine {
    /// Resolve `text`: a direct address, an access path, a global, or a
    /// variable of a program instance, in that order (an access path and a
    /// global are distinct names in one configuration).
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
        if let Some(i) = (self.def.access.iter()).position(|a| a.name.eq_ignore_ascii_case(text)) {
            let a = &self.def.access[i];
            return Ok(place(a.ty.clone(), None, Target::Access(i)));
        }
        if let Some(g) = self.find_global(text) {
            let v = self.var_of(g);
            return Ok(match &v.location {
                Some(l) => place(v.ty.clone(), v.range, Target::Addr(l.clone())),
                None => place(v.ty.clone(), v.range, Target::Global(g)),
            });
        }
        if let Some((inst, var)) = text.rsplit_once('.')
            && let Some((r, p)) = self.find_program(inst)
        {
            let pou = &self.m.prog.pous[self.programs[r][p].pou];
            let i = find_var(pou, var)
                .ok_or_else(|| format!("program `{}` has no variable `{var}`", pou.name))?;
            let v = &pou.vars[i];
            if v.storage == Storage::Located
                && let Some(l) = &v.location
            {
                return Ok(place(v.ty.clone(), v.range, Target::Addr(l.clone())));
            }
            if !held(v) {
                return Err(format!(
                    "`{text}` lives only during a run of {} (a temporary); it cannot be set or watched",
                    pou.name
                ));
            }
            return Ok(place(v.ty.clone(), v.range, Target::Program(r, p, i)));
        }
        Err(format!(
            "configuration `{}` has no global, access path or program variable `{text}` (globals and access paths: {}; a program's variable is `instance.var`, `Resource.instance.var` in a RESOURCE)",
            self.def.name,
            self.watchable().join(", ")
        ))
    }

    /// The current value of a place (the process image is the cycle's).
    pub fn get_at(&self, ctx: &Cycle, p: &ConfigPlace) -> Value {
        match &p.target {
            Target::Addr(l) => io_read(ctx, l),
            Target::Global(g) => self.slot(*g).clone(),
            Target::Access(i) => {
                let name = self.def.access[*i].name.clone();
                self.access(&name).unwrap_or(Value::Bool(false))
            }
            Target::Program(r, p, i) => self.programs[*r][*p].vars[*i].clone(),
        }
    }

    /// Write a place; the value must have its type (and stay in its
    /// subrange). A READ_ONLY access path is refused.
    pub fn set_at(&mut self, ctx: &mut Cycle, p: &ConfigPlace, v: Value) -> Result<(), String> {
        if !self.m.fits(&v, &p.ty)? {
            return Err(format!("`{}` is {}, not {}", p.text, p.ty, v.display()));
        }
        match &p.target {
            Target::Addr(l) => io_write(ctx, l, &v),
            Target::Global(g) => *self.slot_mut(*g) = v,
            Target::Access(i) => {
                let name = self.def.access[*i].name.clone();
                self.set_access(&name, v)?;
            }
            Target::Program(r, p, i) => self.programs[*r][*p].vars[*i] = v,
        }
        Ok(())
    }

    /// Parse `text` as a value for `p` (the literal forms of
    /// [`crate::Machine::parse_for`]); a READ_ONLY access path is refused here,
    /// before the run.
    pub fn parse_for(&self, p: &ConfigPlace, text: &str) -> Result<Value, String> {
        if let Target::Access(i) = &p.target
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
