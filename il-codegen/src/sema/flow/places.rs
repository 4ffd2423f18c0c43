//! Places: what an operand names in storage (a variable, a member, an
//! array element, a direct address), for reading and writing.

use super::*;

impl Walk<'_, '_> {
    pub(super) fn addr_place(&mut self, a: &ast::DirectAddress, write: bool) -> Option<Place> {
        if !self.final_pass {
            // Resolution reports errors; report them once, on the final pass.
            let saved = std::mem::take(&mut self.cx.diags);
            let l = super::super::resolve::resolve_addr(self.cx, a, None);
            self.cx.diags = saved;
            return l.map(|l| Place {
                range: None,
                ty: Ty::Elem(l.elem),
                root: Root::Addr(Box::new(l)),
                path: Vec::new(),
            });
        }
        let l = super::super::resolve::resolve_addr(self.cx, a, None)?;
        if write && l.area == ast::Area::Input {
            self.err(
                NOT_WRITABLE,
                a.span,
                format!(
                    "`{}` is an input: the host writes it before each scan",
                    l.text
                ),
            );
            return None;
        }
        if !self.addresses.contains(&l) {
            self.addresses.push(l.clone());
        }
        Some(Place {
            range: None,
            ty: Ty::Elem(l.elem),
            root: Root::Addr(Box::new(l)),
            path: Vec::new(),
        })
    }

    pub(super) fn place_of(&mut self, o: &Operand, write: bool) -> Option<Place> {
        match o {
            Operand::Var(v) => self.place(v, write),
            Operand::Lit(l) => {
                self.err(NOT_WRITABLE, l.span, "expected a variable, found a literal");
                None
            }
            Operand::Addr(a) => self.addr_place(a, write),
        }
    }

    /// Resolve a variable reference; `write` checks that it may be stored to.
    pub(super) fn place(&mut self, v: &VarRef, write: bool) -> Option<Place> {
        self.note(v.base.span, |w| match w.sig.var(&v.base.name) {
            Some((i, _)) => Some(names::Key::Var(w.pou_key(), i)),
            None => (w.sig.kind == PouKind::Function && v.base.is(&w.sig.name))
                .then(|| names::Key::Pou(w.pou_key())),
        });
        // One lookup of the name (a place is in most instructions).
        let (root, mut ty, constant, var_range) = if let Some((i, var)) = self.sig.var(&v.base.name)
        {
            match &var.location {
                Some(l) if write && l.area == ast::Area::Input => {
                    self.err(
                        NOT_WRITABLE,
                        v.span(),
                        format!(
                            "`{}` is located at the input `{}`: the host writes it",
                            v.base, l.text
                        ),
                    );
                    return None;
                }
                Some(l) => (
                    Root::Addr(Box::new(l.clone())),
                    var.ty.clone(),
                    var.constant,
                    None,
                ),
                None if write && var.edge.is_some() => {
                    self.err(
                        NOT_WRITABLE,
                        v.span(),
                        format!(
                            "`{}` is an edge input (R_EDGE/F_EDGE): it is read-only in the body",
                            v.base
                        ),
                    );
                    return None;
                }
                None => (Root::Var(i), var.ty.clone(), var.constant, var.range),
            }
        } else if self.sig.kind == PouKind::Function && v.base.is(&self.sig.name) {
            (Root::Ret, self.sig.ret.clone()?, false, None)
        } else if self.sig.poisoned.contains(&v.base.key()) {
            return None; // its declaration was already reported
        } else {
            let names: Vec<&str> = self.sig.vars.iter().map(|v| v.name.as_str()).collect();
            let near = suggest(&v.base.name, names).map(str::to_string);
            let what = if self.is_function(&v.base.name) {
                format!("`{}` is a function, not a variable", v.base)
            } else {
                format!("unknown variable `{}`", v.base)
            };
            let pou_name = self.sig.name.clone();
            if let Some(d) = self.err(UNKNOWN_NAME, v.base.span, what) {
                d.label = format!("not declared in {pou_name}");
                if let Some(s) = near {
                    d.did_you_mean(v.base.span, &s);
                }
            }
            return None;
        };
        if write && constant {
            self.err(
                NOT_WRITABLE,
                v.span(),
                format!("`{}` is a CONSTANT", v.base),
            );
            return None;
        }
        let mut range = var_range;
        // One step per accessor: exactly sized (a push reserved four steps,
        // 192 bytes, for the usual one of `fb.Q`).
        let mut path = Vec::with_capacity(v.path.len());
        for acc in &v.path {
            match acc {
                Accessor::Field(f) => {
                    range = None;
                    let (Ty::Fb(fb) | Ty::Struct(fb)) = &ty else {
                        self.err(
                            UNKNOWN_MEMBER,
                            f.span,
                            format!("`{}` is {ty}, which has no members", v.base),
                        );
                        return None;
                    };
                    let fb = fb.clone();
                    // A structure's field, with its subrange, in one look-up
                    // (a type is never also an FB: IL0104); an FB's member,
                    // or an unknown name and its message, from `member`.
                    let env = self.env;
                    let field = matches!(ty, Ty::Struct(_))
                        .then(|| env.types.structs.get(&fb.to_ascii_uppercase()))
                        .flatten()
                        .and_then(|fs| fs.iter().enumerate().find(|(_, x)| f.is(&x.name)));
                    let (name, mty, is_input) = match field {
                        Some((i, field)) => {
                            range = field.range;
                            let m = ir::Member {
                                name: field.name.as_str().into(),
                                index: i as u32,
                            };
                            (m, field.ty.clone(), true)
                        }
                        None => self.member(&fb, &f.name, f.span)?,
                    };
                    self.note(f.span, |w| w.member_key(&fb, &f.name));
                    if write && !is_input {
                        self.err(
                            NOT_WRITABLE,
                            f.span,
                            format!(
                                "`{}` is an output of {fb}; only the block sets it",
                                name.name
                            ),
                        );
                        return None;
                    }
                    path.push(PathElem::Field(name));
                    ty = mty;
                }
                Accessor::Index(subs, span) => {
                    let Ty::Array(arr) = &ty else {
                        self.err(
                            BAD_INDEX,
                            *span,
                            format!("`{}` is {ty}, not an array", v.base),
                        );
                        return None;
                    };
                    let (dims, elem, elem_range) = (&arr.dims, &arr.elem, &arr.range);
                    if subs.len() != dims.len() {
                        self.err(
                            BAD_INDEX,
                            *span,
                            format!(
                                "{} subscripts for an array of {} dimensions",
                                subs.len(),
                                dims.len()
                            ),
                        );
                        return None;
                    }
                    // An element of an array of a subrange is range-checked.
                    range = *elem_range;
                    let (dims, elem) = (dims.clone(), elem.clone());
                    let mut vals = Vec::with_capacity(subs.len());
                    for (s, (lo, hi)) in subs.iter().zip(&dims) {
                        vals.push(self.subscript(s, *lo, *hi)?);
                    }
                    path.push(PathElem::Index { dims, subs: vals });
                    ty = elem;
                }
                Accessor::Part { size, index, span } => {
                    let (whole, part) = self.part_of(v, &ty, *size, *index, *span)?;
                    if write && range.is_some() {
                        // Writing a bit could leave the subrange.
                        self.err(
                            BAD_PART,
                            *span,
                            format!("`{}` is a subrange: its parts cannot be written", v.base),
                        );
                        return None;
                    }
                    range = None;
                    path.push(PathElem::Part {
                        whole,
                        part,
                        index: *index,
                    });
                    ty = Ty::Elem(part);
                }
            }
        }
        if write && matches!(ty, Ty::Fb(_)) {
            self.err(
                NOT_WRITABLE,
                v.span(),
                "cannot store to a function block instance",
            );
            return None;
        }
        // A whole array over 64 KiB would be copied through the stack.
        if super::super::heap_arrays::is_large(self.env, &ty) {
            let msg = format!(
                "`{}` is an array of more than 64 KiB: it cannot be loaded, stored or passed as a whole",
                v.base
            );
            if let Some(d) = self.err(TOO_LARGE, v.span(), msg) {
                d.help = Some("use its elements (`x[i]`), in a loop".into());
            }
            return None;
        }
        Some(Place {
            root,
            path,
            ty,
            range: range.map(Box::new),
        })
    }

    /// The types of a partial access `.n` / `.%Xn` / `.%Bn` ... of a place
    /// of type `ty`: (whole, part), checked against the width.
    fn part_of(
        &mut self,
        v: &VarRef,
        ty: &Ty,
        size: ast::AddrSize,
        index: u32,
        span: Span,
    ) -> Option<(Elem, Elem)> {
        let text = self.cx.file.snippet(v.span()).to_string();
        self.feature(
            crate::dialect::Feature::PartialAccess(text.clone()),
            v.span(),
        );
        let part = match size {
            ast::AddrSize::Default | ast::AddrSize::X => Elem::BOOL,
            ast::AddrSize::B => Elem::BYTE,
            ast::AddrSize::W => Elem::WORD,
            ast::AddrSize::D | ast::AddrSize::L => Elem::DWORD,
        };
        let whole = match ty {
            Ty::Elem(e) if e.is_int() || e.is_bitstring() => *e,
            _ => {
                self.err(
                    BAD_PART,
                    span,
                    format!("`{text}`: partial access needs a bit string or an integer, not {ty}"),
                );
                return None;
            }
        };
        let width = PathElem::part_bits(whole);
        let bits = PathElem::part_bits(part);
        let count = width / bits;
        if index >= count {
            let what = match part {
                Elem::BOOL => "bit",
                Elem::BYTE => "byte",
                Elem::WORD => "word",
                _ => "double word",
            };
            let msg = if count == 0 {
                format!("`{text}`: {ty} has no {what}s ({width} bits)")
            } else {
                format!(
                    "`{text}`: {what} {index} is beyond {ty}, which has {what}s 0..{} ({width} bits)",
                    count - 1
                )
            };
            self.err(BAD_PART, span, msg);
            return None;
        }
        Some((whole, part))
    }

    /// A member of an FB type: (declared name, type, is it an input).
    pub(super) fn member(
        &mut self,
        fb: &str,
        name: &str,
        span: Span,
    ) -> Option<(ir::Member, Ty, bool)> {
        // Most FB accesses name a member that exists: found directly; the
        // list of all members is built only for the message.
        if let Some(m) = self.find_member(fb, name) {
            return Some(m);
        }
        let all = self.members(fb);
        let near = suggest(name, all.iter().map(|(n, _, _)| n.as_str())).map(str::to_string);
        let list: Vec<&str> = all.iter().map(|(n, _, _)| n.as_str()).collect();
        if let Some(d) = self.err(
            UNKNOWN_MEMBER,
            span,
            format!("{fb} has no input or output `{name}`"),
        ) {
            d.notes.push(format!("{fb} has: {}", list.join(", ")));
            if let Some(s) = near {
                d.did_you_mean(span, &s);
            }
        }
        None
    }

    /// The member `name` of FB type `fb`, as [`Walk::members`] lists them,
    /// with its index ([`ir::Member`]).
    pub(super) fn find_member(&self, fb: &str, name: &str) -> Option<(ir::Member, Ty, bool)> {
        let member = |name: &str, index: usize| ir::Member {
            name: name.into(),
            index: index as u32,
        };
        if let Some(s) = stdfb::lookup(fb) {
            let params = s.inputs.iter().chain(&s.outputs).enumerate();
            let (i, (n, e)) = params
                .into_iter()
                .find(|(_, (n, _))| n.eq_ignore_ascii_case(name))?;
            return Some((member(n, i), Ty::Elem(*e), i < s.inputs.len()));
        }
        if let Some(fields) = self.env.types.structs.get(&fb.to_ascii_uppercase()) {
            let (i, f) =
                (fields.iter().enumerate()).find(|(_, f)| f.name.eq_ignore_ascii_case(name))?;
            return Some((member(&f.name, i), f.ty.clone(), true));
        }
        let (i, v) = self.env.pou(fb)?.var(name)?;
        match v.kind {
            ast::VarKind::Input => Some((member(&v.name, i), v.ty.clone(), true)),
            ast::VarKind::Output => Some((member(&v.name, i), v.ty.clone(), false)),
            _ => None,
        }
    }

    /// Every member of FB type `fb`: (declared name, type, is it an input),
    /// inputs before outputs for a standard block, in declaration order
    /// otherwise.
    fn members(&self, fb: &str) -> Vec<(String, Ty, bool)> {
        let mut all: Vec<(String, Ty, bool)> = Vec::new();
        if let Some(s) = stdfb::lookup(fb) {
            all.extend(
                s.inputs
                    .iter()
                    .map(|(n, e)| (n.to_string(), Ty::Elem(*e), true)),
            );
            all.extend(
                s.outputs
                    .iter()
                    .map(|(n, e)| (n.to_string(), Ty::Elem(*e), false)),
            );
        } else if let Some(fields) = self.env.types.structs.get(&fb.to_ascii_uppercase()) {
            // Every field of a STRUCT can be read and written.
            all.extend(fields.iter().map(|f| (f.name.clone(), f.ty.clone(), true)));
        } else if let Some(sig) = self.env.pou(fb) {
            for v in &sig.vars {
                match v.kind {
                    ast::VarKind::Input => all.push((v.name.clone(), v.ty.clone(), true)),
                    ast::VarKind::Output => all.push((v.name.clone(), v.ty.clone(), false)),
                    _ => {}
                }
            }
        }
        all
    }
}
