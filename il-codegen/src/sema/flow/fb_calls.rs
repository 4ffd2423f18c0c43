//! Function block calls: `CAL` with a formal list, the input operators
//! (S1, CLK, PT ...), in-outs and the externals an instance passes down.

use super::*;
use crate::sema::types::Name;

impl Walk<'_, '_> {
    /// If the operand is an FB instance (a variable, a member or an array
    /// element: `ctr`, `line.t1`, `cnt[i]`), its block type, and its place
    /// when that is a standard block with the input `input`: then
    /// `S`/`R`/`LD` are that block's input operators (Table 54), not the
    /// BOOL or load instructions.
    pub(super) fn fb_operand(&mut self, o: &Operand, input: &str) -> Option<(Name, Option<Place>)> {
        let Operand::Var(v) = o else { return None };
        let t = self.instance_type(v)?;
        let has = |s: &stdfb::StdFb| s.inputs.iter().any(|(n, _)| n.eq_ignore_ascii_case(input));
        if !stdfb::lookup(&t).is_some_and(has) {
            return Some((t, None));
        }
        let saved = self.final_pass;
        let p = self.place(v, false);
        self.final_pass = saved;
        Some((t, p))
    }

    /// The block type of the instance a variable reference names, from the
    /// declarations alone: no subscript is evaluated and nothing is
    /// reported (the caller resolves the place itself when it needs it).
    /// Every operand of `LD` comes here: a plain name or an element is
    /// looked at in place, and a member of a standard block (`t.Q`, never
    /// an instance) stops at once.
    fn instance_type(&self, v: &VarRef) -> Option<Name> {
        let (_, var) = self.sig.var(&v.base.name)?;
        let mut ty = std::borrow::Cow::Borrowed(&var.ty);
        for acc in &v.path {
            ty = match (acc, ty) {
                (Accessor::Index(..), std::borrow::Cow::Borrowed(Ty::Array(a))) => {
                    std::borrow::Cow::Borrowed(&a.elem)
                }
                (Accessor::Index(..), std::borrow::Cow::Owned(Ty::Array(a))) => {
                    std::borrow::Cow::Owned(a.elem)
                }
                (Accessor::Field(f), t) => match &*t {
                    Ty::Fb(b) if stdfb::lookup(b).is_some() => return None,
                    Ty::Fb(b) | Ty::Struct(b) => {
                        std::borrow::Cow::Owned(self.find_member(b, &f.name)?.1)
                    }
                    _ => return None,
                },
                _ => return None,
            };
        }
        match &*ty {
            Ty::Fb(t) => Some(t.clone()),
            _ => None,
        }
    }

    /// Table 54: set one input from the CR and call the instance.
    pub(super) fn fb_input(&mut self, inst: Place, input: &str, cr: Cr, span: Span) -> Cr {
        let Ty::Fb(fb) = inst.ty.clone() else {
            self.err(
                NOT_AN_FB,
                span,
                format!(
                    "`{input}` as an operator needs a function block instance; this is {}",
                    inst.ty
                ),
            );
            return cr;
        };
        // The input with its index (a list of every input, cloned, was
        // built for each input operator to find one).
        let found = match stdfb::lookup(&fb) {
            Some(s) => (s.inputs.iter().enumerate())
                .find(|(_, (n, _))| n.eq_ignore_ascii_case(input))
                .map(|(k, (n, e))| (n.to_string(), Ty::Elem(*e), k)),
            None => self.env.pou(&fb).and_then(|sig| {
                sig.inputs()
                    .find(|(_, v)| v.name.eq_ignore_ascii_case(input))
                    .map(|(k, v)| (v.name.clone(), v.ty.clone(), k))
            }),
        };
        let Some((name, ty, index)) = found else {
            self.err(
                BAD_INPUT_OP,
                span,
                format!("`{input}` is not an input of {fb}"),
            );
            return cr;
        };
        let Some(arg) = self.use_cr(&cr, span) else {
            return cr;
        };
        let Some(value) = self.fit_to(arg, &ty, span, || format!("input `{name}` of {fb}")) else {
            return cr;
        };
        let (inouts, externals) = self.fb_refs(&fb);
        if let Some((n, _, _)) = inouts.first() {
            self.err(
                BAD_IN_OUT,
                span,
                format!("{fb} has VAR_IN_OUT `{n}`, which every call binds: use `CAL inst({n} := variable, ...)`"),
            );
            return cr;
        }
        let input = ir::Member {
            name: name.into(),
            index: index as u32,
        };
        self.push(Op::CallFb(Box::new(crate::sema::ir::FbCall {
            inst,
            inputs: vec![(input, value)],
            outputs: Vec::new(),
            inouts: Vec::new(),
            inouts_in_instance: false,
            externals,
            cond: None,
        })));
        cr
    }

    /// A user FB's VAR_IN_OUTs (name, type) and the names of its VAR_EXTERNALs
    /// that the caller passes (the located ones need no passing), each with
    /// its index in the FB's variables.
    #[allow(clippy::type_complexity)]
    pub(super) fn fb_refs(&self, fb: &str) -> (Vec<(String, Ty, u32)>, Box<[ir::PassedExternal]>) {
        let Some(sig) = self
            .env
            .pou(fb)
            .filter(|s| s.kind == PouKind::FunctionBlock)
        else {
            return (Vec::new(), Box::default());
        };
        let inouts = (sig.vars.iter().enumerate())
            .filter(|(_, v)| v.kind == ast::VarKind::InOut)
            .map(|(i, v)| (v.name.clone(), v.ty.clone(), i as u32))
            .collect();
        // The caller's own external of that name (the checker reports a
        // caller without it; MAX then fails a consumer's look-up loudly).
        let externals = (sig.vars.iter().enumerate())
            .filter(|(_, v)| v.kind == ast::VarKind::External && v.location.is_none())
            .map(|(i, v)| ir::PassedExternal {
                name: v.name.clone(),
                constant: v.constant,
                caller: self.sig.var(&v.name).map_or(u32::MAX, |(k, _)| k as u32),
                callee: i as u32,
            })
            .collect();
        (inouts, externals)
    }

    /// The place bound to a VAR_IN_OUT `name : ty`: a writable variable of exactly that type.
    pub(super) fn inout_place(
        &mut self,
        o: &Operand,
        name: &str,
        ty: &Ty,
        callee: &str,
    ) -> Option<Place> {
        if let Operand::Lit(l) = o {
            self.err(
                BAD_IN_OUT,
                l.span,
                format!("`{name}` is a VAR_IN_OUT of {callee}: it needs a variable, not a literal"),
            );
            return None;
        }
        let place = self.place_of(o, true)?;
        if place.split_part().is_some() {
            self.err(
                BAD_IN_OUT,
                o.span(),
                format!("`{name}` is a VAR_IN_OUT of {callee}: a part of a variable (`x.3`) cannot be passed by reference"),
            );
            return None;
        }
        if &place.ty != ty {
            self.err(
                BAD_IN_OUT,
                o.span(),
                format!(
                    "`{name}` is a VAR_IN_OUT of {callee} of type {ty}; the variable is {} (a reference needs exactly the same type)",
                    place.ty
                ),
            );
            return None;
        }
        Some(place)
    }

    /// The argument list of a CAL of an FB.
    #[allow(clippy::type_complexity)]
    pub(super) fn fb_args(
        &mut self,
        fb: &str,
        args: &CallArgs,
        span: Span,
    ) -> (
        Vec<(ir::Member, Value)>,
        Vec<(ir::Member, Place, bool, Option<ir::Widen>)>,
        Vec<(String, Place)>,
    ) {
        let mut ins = Vec::new();
        let mut outs = Vec::new();
        let mut inouts: Vec<(String, Place)> = Vec::new();
        let (inout_decl, _) = self.fb_refs(fb);
        match args {
            CallArgs::Formal(list) => {
                // As for functions (`bind_formal`): an input or in-out named
                // twice is an error at the second, not "the last one wins".
                // An output may be read into several variables (`Q => done,
                // NOT Q => waiting`): nothing is ambiguous there.
                let mut seen = std::collections::HashSet::new();
                for p in list {
                    self.note(p.name.span, |w| w.member_key(fb, &p.name.name));
                    if matches!(p.kind, ParamKind::Input(_)) && !seen.insert(p.name.key()) {
                        self.err(
                            UNKNOWN_MEMBER,
                            p.name.span,
                            format!("parameter `{}` is given twice", p.name),
                        );
                        continue;
                    }
                    if let Some((name, ty, _)) = inout_decl.iter().find(|(n, _, _)| p.name.is(n)) {
                        match &p.kind {
                            ParamKind::Input(o) => {
                                if let Some(pl) = self.inout_place(o, name, ty, fb) {
                                    inouts.push((name.clone(), pl));
                                }
                            }
                            ParamKind::Output { .. } => {
                                self.err(
                                    BAD_IN_OUT,
                                    p.span,
                                    format!("`{name}` is a VAR_IN_OUT of {fb}: bind it with `{name} := variable`"),
                                );
                            }
                        }
                        continue;
                    }
                    let Some((name, ty, is_input)) = self.member(fb, &p.name.name, p.name.span)
                    else {
                        continue;
                    };
                    match &p.kind {
                        ParamKind::Input(o) => {
                            if !is_input {
                                self.err(
                                    NOT_WRITABLE,
                                    p.name.span,
                                    format!(
                                        "`{name}` is an output of {fb}: use `{name} => variable`"
                                    ),
                                );
                                continue;
                            }
                            let Some(a) = self.operand(o) else { continue };
                            if let Some(v) =
                                self.fit_to(a, &ty, o.span(), || format!("input `{name}` of {fb}"))
                            {
                                ins.push((name, v));
                            }
                        }
                        ParamKind::Output { negate, target } => {
                            if is_input {
                                self.err(
                                    NOT_WRITABLE,
                                    p.name.span,
                                    format!("`{name}` is an input of {fb}: use `{name} := value`"),
                                );
                                continue;
                            }
                            let Some(place) = self.place_of(target, true) else {
                                continue;
                            };
                            let Ok(w) = self.output_fit(&name.name, &ty, &place, target.span())
                            else {
                                continue;
                            };
                            if *negate && !ty.is_logic() {
                                self.err(
                                    BAD_OPERATOR_TYPE,
                                    p.span,
                                    format!(
                                        "NOT needs a BOOL or bit-string output; `{name}` is {ty}"
                                    ),
                                );
                                continue;
                            }
                            outs.push((name, place, *negate, w));
                        }
                    }
                }
            }
            CallArgs::NonFormal(_) if !inout_decl.is_empty() => {
                self.err(
                    BAD_IN_OUT,
                    span,
                    format!(
                        "{fb} has VAR_IN_OUT `{}`: call it with a formal list (`CAL inst({} := variable, ...)`)",
                        inout_decl[0].0, inout_decl[0].0
                    ),
                );
            }
            CallArgs::NonFormal(list) => {
                let member = |name: &str, index: usize| ir::Member {
                    name: name.into(),
                    index: index as u32,
                };
                let inputs: Vec<(ir::Member, Ty)> = if let Some(s) = stdfb::lookup(fb) {
                    (s.inputs.iter().enumerate())
                        .map(|(i, (n, e))| (member(n, i), Ty::Elem(*e)))
                        .collect()
                } else if let Some(sig) = self.env.pou(fb) {
                    sig.inputs()
                        .map(|(i, v)| (member(&v.name, i), v.ty.clone()))
                        .collect()
                } else {
                    Vec::new()
                };
                if list.len() > inputs.len() {
                    self.err(
                        ARG_COUNT,
                        span,
                        format!(
                            "{fb} has {} inputs; {} values given",
                            inputs.len(),
                            list.len()
                        ),
                    );
                }
                for (o, (name, ty)) in list.iter().zip(inputs) {
                    let Some(a) = self.operand(o) else { continue };
                    if let Some(v) =
                        self.fit_to(a, &ty, o.span(), || format!("input `{name}` of {fb}"))
                    {
                        ins.push((name, v));
                    }
                }
            }
        }
        (ins, outs, inouts)
    }
}
