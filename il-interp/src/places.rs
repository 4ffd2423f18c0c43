//! Places and operands: variables, members, array elements and the process image,
//! read and written as the emitter's place expressions are.

use crate::values::Value;
use crate::{Frame, Machine};
use il_codegen::ir::types::{Elem, Ty};
use il_codegen::ir::{Loc, PathElem, Place, Root, Value as IrValue};
use il_std::{Cycle, FaultKind};

/// A resolved step of a place's path.
#[derive(Clone, Debug)]
pub(crate) enum Step {
    /// A member by its index ([`il_codegen::ir::Member::index`]): of a user
    /// FB, the variable; of a standard block, its table's member; of a
    /// STRUCT, the field.
    Field(usize),
    /// Flat index, or `None` when a subscript is out of range.
    Index(Option<usize>),
}

pub(crate) fn io_read(ctx: &Cycle, l: &Loc) -> Value {
    let (a, b) = (l.area, l.byte);
    if let Some(bit) = l.bit {
        return Value::Bool(ctx.io.bit(a, b, bit));
    }
    let e = l.elem;
    match e {
        Elem::BYTE | Elem::USINT => Value::Int(ctx.io.byte(a, b) as i128, e),
        Elem::SINT => Value::Int(ctx.io.byte(a, b) as i8 as i128, e),
        Elem::WORD | Elem::UINT => Value::Int(ctx.io.word(a, b) as i128, e),
        Elem::INT => Value::Int(ctx.io.word(a, b) as i16 as i128, e),
        Elem::DWORD | Elem::UDINT => Value::Int(ctx.io.dword(a, b) as i128, e),
        Elem::DINT => Value::Int(ctx.io.dword(a, b) as i32 as i128, e),
        Elem::REAL => Value::Real(f32::from_bits(ctx.io.dword(a, b))),
        Elem::LWORD | Elem::ULINT => Value::Int(ctx.io.lword(a, b) as i128, e),
        Elem::LINT => Value::Int(ctx.io.lword(a, b) as i64 as i128, e),
        _ => Value::LReal(f64::from_bits(ctx.io.lword(a, b))),
    }
}

pub(crate) fn io_write(ctx: &mut Cycle, l: &Loc, v: &Value) {
    let (a, b) = (l.area, l.byte);
    if let Some(bit) = l.bit {
        ctx.io.set_bit(a, b, bit, v.as_bool());
        return;
    }
    match (l.elem, v) {
        (Elem::REAL, Value::Real(f)) => ctx.io.set_dword(a, b, f.to_bits()),
        (Elem::LREAL, Value::LReal(f)) => ctx.io.set_lword(a, b, f.to_bits()),
        (e, v) => {
            let x = match v {
                Value::Int(x, _) => *x,
                other => other.as_i64() as i128,
            };
            match crate::values::bits(e) {
                8 => ctx.io.set_byte(a, b, x as u8),
                16 => ctx.io.set_word(a, b, x as u16),
                32 => ctx.io.set_dword(a, b, x as u32),
                _ => ctx.io.set_lword(a, b, x as u64),
            }
        }
    }
}

impl Machine {
    pub(crate) fn read_at(&self, v: &Value, steps: &[Step]) -> Option<Value> {
        let Some((first, rest)) = steps.split_first() else {
            return Some(v.clone());
        };
        match (first, v) {
            (Step::Field(i), Value::Fb(inst)) => self.read_at(inst.vars.get(*i)?, rest),
            (Step::Field(i), Value::StdFb(b)) if rest.is_empty() => b.get_at(*i),
            (Step::Field(i), Value::Struct(s)) => self.read_at(&s.fields.get(*i)?.1, rest),
            (Step::Index(Some(k)), Value::Array(items)) => self.read_at(items.get(*k)?, rest),
            _ => None,
        }
    }

    pub(crate) fn write_at(&self, v: &mut Value, steps: &[Step], new: Value) -> bool {
        let Some((first, rest)) = steps.split_first() else {
            *v = new;
            return true;
        };
        match (first, v) {
            (Step::Field(i), Value::Fb(inst)) => match inst.vars.get_mut(*i) {
                Some(slot) => self.write_at(slot, rest, new),
                None => false,
            },
            (Step::Field(i), Value::StdFb(b)) if rest.is_empty() => b.set_at(*i, &new),
            (Step::Field(i), Value::Struct(s)) => match s.fields.get_mut(*i) {
                Some(slot) => self.write_at(&mut slot.1, rest, new),
                None => false,
            },
            (Step::Index(Some(k)), Value::Array(items)) => match items.get_mut(*k) {
                Some(slot) => self.write_at(slot, rest, new),
                None => false,
            },
            _ => false,
        }
    }

    /// A string value in a place of string type `to`: cut at its length, with
    /// a `StringOverflow` fault when that cuts something off (as
    /// `il_std::func::resize_checked` in generated code).
    pub(crate) fn cut_string(
        &self,
        f: &Frame,
        v: Value,
        to: &Ty,
        ctx: &mut Cycle,
        line: u32,
    ) -> Value {
        match (v, to) {
            (Value::Str { mut units, wide }, Ty::Str { len, .. }) => {
                if units.len() > *len as usize {
                    units.truncate(*len as usize);
                    self.fault(ctx, f, FaultKind::StringOverflow, line);
                }
                Value::Str { units, wide }
            }
            (v, _) => v,
        }
    }

    pub(crate) fn fault(&self, ctx: &mut Cycle, f: &Frame, kind: FaultKind, line: u32) {
        ctx.fault(kind, self.names[f.pou], line);
    }

    pub(crate) fn value(
        &self,
        f: &mut Frame,
        v: &IrValue,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Value, String> {
        Ok(match v {
            IrValue::Cr(i) => f.cr[Self::cr_slot(f, *i)?].clone(),
            IrValue::Const(c) => Value::from_const(c),
            IrValue::Read(p) => self.read(f, self.prog.pous[f.pou].place(*p), ctx, line)?,
            IrValue::Saved(i) => f
                .saves
                .get(*i as usize)
                .cloned()
                .ok_or("internal: no such save slot")?,
            // The checker's implicit widening, converted as `FROM_TO_TO` does.
            IrValue::Widen(b) => {
                let (inner, w) = &**b;
                let x = self.value(f, inner, ctx, line)?;
                crate::stdfn::convert(w.from, w.to, &x)
                    .ok_or("internal: a widening the interpreter cannot convert")?
            }
            IrValue::Arith(a) => {
                return self.binary(f, a.op, Some(a.elem), (&a.lhs, &a.rhs, false), ctx, line);
            }
            IrValue::Resized(r) => {
                let (v, to) = &**r;
                let v = self.value(f, v, ctx, line)?;
                self.cut_string(f, v, to, ctx, line)
            }
        })
    }

    /// Resolve a place's path, evaluating every subscript first (`PathElem::Index`).
    pub(crate) fn steps(
        &self,
        f: &mut Frame,
        p: &Place,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<(Vec<Step>, bool), String> {
        let mut steps = Vec::new();
        let mut ok = true;
        for e in &p.path {
            match e {
                PathElem::Field(m) => steps.push(Step::Field(m.index as usize)),
                // `read`/`write` split a partial access off before they get here.
                PathElem::Part { .. } => {}
                PathElem::Index { dims, subs } => {
                    let mut flat: Option<usize> = Some(0);
                    for (s, (lo, hi)) in subs.iter().zip(dims) {
                        let v = self.value(f, s, ctx, line)?;
                        let size = (hi - lo + 1).max(0) as usize;
                        let k = usize::try_from(v.as_i64().wrapping_sub(*lo))
                            .ok()
                            .filter(|k| *k < size);
                        flat = match (flat, k) {
                            (Some(acc), Some(k)) => Some(acc * size + k),
                            _ => None,
                        };
                    }
                    ok &= flat.is_some();
                    steps.push(Step::Index(flat));
                }
            }
        }
        Ok((steps, ok))
    }

    pub(crate) fn root_value<'a>(
        &self,
        f: &'a mut Frame,
        r: &Root,
    ) -> Result<&'a mut Value, String> {
        match r {
            Root::Ret => Ok(&mut f.ret),
            Root::Var(i) => f
                .vars
                .get_mut(*i)
                .ok_or_else(|| "internal: bad variable".into()),
            Root::Addr(_) => Err("internal: process image is not a variable".into()),
        }
    }

    pub(crate) fn read(
        &self,
        f: &mut Frame,
        p: &Place,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<Value, String> {
        if let Some((whole_place, _, part, index)) = p.split_part() {
            let w = self.read(f, &whole_place, ctx, line)?;
            return Ok(part_read(&w, part, index));
        }
        if let Root::Addr(l) = &p.root {
            return Ok(io_read(ctx, l));
        }
        if let Root::Var(i) = &p.root
            && let Some(e) = f.edges.get(*i).copied().flatten()
        {
            return Ok(Value::Bool(e));
        }
        let (steps, ok) = self.steps(f, p, ctx, line)?;
        let root = self.root_value(f, &p.root)?;
        let got = if ok { self.read_at(root, &steps) } else { None };
        match got {
            Some(v) => Ok(v),
            None if !ok => {
                self.fault(ctx, f, FaultKind::IndexOutOfRange, line);
                self.default_of(&p.ty)
            }
            None => Err(format!("internal: cannot read {p:?}")),
        }
    }

    pub(crate) fn write(
        &self,
        f: &mut Frame,
        p: &Place,
        v: Value,
        ctx: &mut Cycle,
        line: u32,
    ) -> Result<(), String> {
        if let Some((whole_place, whole, part, index)) = p.split_part() {
            // Read the whole, replace the part, write it back (`Place::split_part`).
            let w = self.read(f, &whole_place, ctx, line)?;
            let new = part_write(&w, &v, whole, part, index);
            return self.write(f, &whole_place, new, ctx, line);
        }
        if let Root::Addr(l) = &p.root {
            io_write(ctx, l, &v);
            return Ok(());
        }
        if let Root::Var(i) = &p.root
            && f.edges.get(*i).copied().flatten().is_some()
        {
            f.edges[*i] = Some(v.as_bool());
            return Ok(());
        }
        let (steps, ok) = self.steps(f, p, ctx, line)?;
        if !ok {
            self.fault(ctx, f, FaultKind::IndexOutOfRange, line);
            return Ok(());
        }
        let root = self.root_value(f, &p.root)?;
        let mut tmp = std::mem::replace(root, Value::Bool(false));
        let done = self.write_at(&mut tmp, &steps, v);
        *self.root_value(f, &p.root)? = tmp;
        if done {
            Ok(())
        } else {
            Err(format!("internal: cannot write {p:?}"))
        }
    }
}

pub(crate) fn self_root<'a>(f: &'a mut Frame, r: &Root) -> Result<&'a mut Value, String> {
    match r {
        Root::Ret => Ok(&mut f.ret),
        Root::Var(i) => f
            .vars
            .get_mut(*i)
            .ok_or_else(|| "internal: bad variable".into()),
        Root::Addr(_) => Err("internal: process image is not an instance".into()),
    }
}

fn raw_bits(v: &Value) -> u64 {
    match v {
        Value::Int(x, _) => *x as u64,
        Value::Bool(b) => u64::from(*b),
        other => other.as_i64() as u64,
    }
}

/// Part `index` of `w` (a partial access, `v.3` / `v.%B1`).
fn part_read(w: &Value, part: Elem, index: u32) -> Value {
    let (mask, shift) = PathElem::part_mask(part, index);
    let x = (raw_bits(w) >> shift) & mask;
    if part == Elem::BOOL {
        Value::Bool(x != 0)
    } else {
        Value::Int(x as i128, part)
    }
}

/// `w` (of type `whole`) with part `index` replaced by `v`.
fn part_write(w: &Value, v: &Value, whole: Elem, part: Elem, index: u32) -> Value {
    let (mask, shift) = PathElem::part_mask(part, index);
    let x = (raw_bits(w) & !(mask << shift)) | ((raw_bits(v) & mask) << shift);
    Value::Int(crate::values::wrap(x as i128, whole), whole)
}
