//! One instruction: loads, stores, S/R, jumps, RET, and deferred operators
//! (parentheses), each giving the CR after it.

use super::*;

impl Walk<'_, '_> {
    /// One instruction. Deferred parentheses recurse (one level per nesting
    /// level, up to the parser's limit of 256), so the recursion path is kept
    /// to two small frames: this dispatcher and [`Walk::deferred`]. Every
    /// other instruction is checked in [`Walk::simple_instr`], whose frame is
    /// large in debug builds (tens of KiB); with it on the recursion path,
    /// 256 levels overflowed a 2 MiB thread (a debug `cargo test` thread)
    /// and aborted the process.
    pub(super) fn instr(&mut self, i: &ast::Instr, cr: Cr, in_parens: bool) -> Cr {
        crate::step_counter::add(1);
        // Only the final pass records the CR for tools; the copy is kept
        // out of this frame's hot path (see above).
        let before = self.final_pass.then(|| Box::new(cr.clone()));
        let after = match &i.kind {
            InstrKind::Deferred {
                op,
                negate,
                first,
                body,
                close_span,
            } => self.deferred(i, cr, (*op, *negate), first.as_deref(), body, *close_span),
            _ => self.simple_instr(i, cr, in_parens),
        };
        if let Some(before) = before {
            self.step(i.span, false, &before, &after);
        }
        after
    }

    /// `OP( operand` / `OP(` ... `)`: see [`Walk::instr`].
    #[inline(never)]
    pub(super) fn deferred(
        &mut self,
        i: &ast::Instr,
        cr: Cr,
        (op, negate): (ExprOp, bool),
        first: Option<&Operand>,
        body: &[ast::Stmt],
        close_span: Span,
    ) -> Cr {
        let span = i.span;
        // A pending call is emitted before the inner instructions,
        // which reuse the CR locals its arguments may read.
        let Some(lhs) = self.use_cr(&cr, span).and_then(|a| self.settle(a)) else {
            return Cr::Undef(Why::Error);
        };
        let lhs = match lhs {
            Arg::Typed(v, t) => {
                let slot = self.save_slot(&t);
                self.push(Op::Save { slot, value: v });
                Arg::Typed(Value::Saved(slot), t)
            }
            lit => lit,
        };
        // Groups inside this one save into slots of the next depth: this
        // group's saved value is live until its `)`.
        self.save_depth += 1;
        let mut inner = match first {
            Some(o) => self.load(false, o, span),
            None => Cr::Undef(Why::Start),
        };
        // Each inner instruction's statements carry its own line (a fault
        // there names it, its comment is above them); the operator's own
        // statements, after the `)`, carry the operator's line again.
        let (line, col) = (self.line, self.col);
        for s in body {
            match s {
                ast::Stmt::Label(id) => {
                    self.err(
                        IN_PARENS,
                        id.span,
                        "a label is not allowed inside parentheses",
                    );
                }
                ast::Stmt::Instr(ii) => {
                    self.at(ii.span);
                    inner = self.instr(ii, inner, true);
                }
            }
        }
        (self.line, self.col) = (line, col);
        self.save_depth -= 1;
        let Some(rhs) = self.use_cr(&inner, close_span) else {
            return Cr::Undef(Why::Error);
        };
        self.binary(op, negate, lhs, rhs, i.op_span)
    }

    /// The save slot of a group at the current depth whose outer CR has type
    /// `t`. A group's saved value is read at its `)`, before the next group
    /// of the same depth starts (no label or jump inside parentheses), so
    /// groups of one depth and type share a slot: a POU has a `__save_N`
    /// per depth and type, not one per group (11,000 in the 100k-line
    /// benchmark POU before).
    fn save_slot(&mut self, t: &Ty) -> u32 {
        let d = self.save_depth;
        if self.save_slots.len() <= d {
            self.save_slots.resize_with(d + 1, Vec::new);
        }
        let types = &self.save_types;
        if let Some(&s) = self.save_slots[d]
            .iter()
            .find(|&&s| types[s as usize] == *t)
        {
            return s;
        }
        // Slots per depth and type: a handful.
        let slot = self.save_types.len() as u32;
        self.save_types.push(t.clone());
        self.save_slots[d].push(slot);
        slot
    }

    /// Every instruction but deferred parentheses (see [`Walk::instr`]).
    #[inline(never)]
    pub(super) fn simple_instr(&mut self, i: &ast::Instr, cr: Cr, in_parens: bool) -> Cr {
        let span = i.span;
        match &i.kind {
            InstrKind::Load { negate, operand } => {
                if !negate && let Some((_, Some(inst))) = self.fb_operand(operand, "LD") {
                    return self.fb_input(inst, "LD", cr, span);
                }
                self.load(*negate, operand, span)
            }
            InstrKind::Store { negate, target } => {
                let Some(place) = self.place_of(target, true) else {
                    self.offer_declaration(target.span(), &cr);
                    return cr;
                };
                let Some(arg) = self.use_cr(&cr, span) else {
                    return cr;
                };
                // The target's text only for a message (not on every store).
                let file = self.cx.file;
                let dest = || format!("`{}`", file.snippet(target.span()));
                let Some(value) = self.fit_to(arg, &place.ty, span, dest) else {
                    return cr;
                };
                if *negate && !place.ty.is_logic() {
                    self.err(
                        BAD_OPERATOR_TYPE,
                        i.op_span,
                        format!("STN needs BOOL or a bit string, not {}", place.ty),
                    );
                    return cr;
                }
                if let (Some(&(lo, hi)), Value::Const(Const::Int(v, _))) =
                    (place.range.as_deref(), &value)
                    && let v = v.get()
                    && (v < lo || v > hi)
                {
                    self.err(
                        LITERAL_RANGE,
                        span,
                        format!(
                            "{v} is outside the subrange {lo}..{hi} of `{}`",
                            self.cx.file.snippet(target.span())
                        ),
                    );
                    return cr;
                }
                let place = self.place_id(place);
                self.push(Op::Store {
                    place,
                    value,
                    negate: *negate,
                });
                cr
            }
            InstrKind::Set { target } | InstrKind::Reset { target } => {
                let set = matches!(i.kind, InstrKind::Set { .. });
                let which = if set { "S" } else { "R" };
                match self.fb_operand(target, which) {
                    Some((_, Some(inst))) => return self.fb_input(inst, which, cr, span),
                    Some((fb, None)) => {
                        self.err(
                            BAD_INPUT_OP,
                            target.span(),
                            format!(
                                "`{which}` is not an input operator of {} (an instance of {fb})",
                                self.cx.file.snippet(target.span()),
                            ),
                        );
                        return cr;
                    }
                    None => {}
                }
                let Some(place) = self.place_of(target, true) else {
                    return cr;
                };
                if !place.ty.is_bool() {
                    self.err(
                        BAD_OPERATOR_TYPE,
                        target.span(),
                        format!("S and R set or reset a BOOL; this is {}", place.ty),
                    );
                    return cr;
                }
                let Some(cond) = self.cond_value(&cr, span) else {
                    return cr;
                };
                let place = self.place_id(place);
                self.push(Op::SetIf {
                    place,
                    value: set,
                    cond,
                });
                Cr::Val(Ty::BOOL)
            }
            InstrKind::Not => {
                let Some(arg) = self.use_cr(&cr, span).and_then(|a| self.settle(a)) else {
                    return cr;
                };
                match arg {
                    Arg::Typed(v, t) if t.is_logic() => {
                        let cr = self.cr_index(&t);
                        self.push(Op::SetCr {
                            cr,
                            expr: Expr::Not(v),
                        });
                        Cr::Val(t)
                    }
                    Arg::Typed(_, t) => {
                        self.err(
                            BAD_OPERATOR_TYPE,
                            i.op_span,
                            format!("NOT needs a BOOL or bit-string current result; it is {t}"),
                        );
                        Cr::Val(t)
                    }
                    Arg::Lit(l, _) => {
                        self.err(
                            BAD_OPERATOR_TYPE,
                            i.op_span,
                            format!(
                                "NOT of {}: give the literal a type (BOOL#1, WORD#16#FF)",
                                describe(&l)
                            ),
                        );
                        cr
                    }
                }
            }
            InstrKind::Expr {
                op,
                negate,
                operand,
            } => {
                let Some(lhs) = self.use_cr(&cr, span) else {
                    return Cr::Undef(Why::Error);
                };
                let Some(rhs) = self.operand(operand) else {
                    return Cr::Undef(Why::Error);
                };
                self.binary(*op, *negate, lhs, rhs, i.op_span)
            }
            // Handled by `instr`.
            InstrKind::Deferred { .. } => cr,
            InstrKind::Jump { cond, label } => {
                if in_parens {
                    self.err(IN_PARENS, span, "a jump is not allowed inside parentheses");
                    return cr;
                }
                let Some(&l) = self.labels.get(&label.key()) else {
                    // In label order: `suggest` keeps the first of equally
                    // close names (fuzzing found a hash map's order making
                    // `l0` suggest `L2` or `L3` from run to run).
                    let near = suggest(&label.name, self.label_names.iter().map(String::as_str))
                        .map(str::to_string);
                    if let Some(d) = self.err(
                        UNKNOWN_LABEL,
                        label.span,
                        format!("no label `{label}` in {}", self.sig.name),
                    ) && let Some(s) = near
                    {
                        d.did_you_mean(label.span, &s);
                    }
                    return if *cond == Cond::Always { Cr::Dead } else { cr };
                };
                self.jumped[l] = true;
                self.note(label.span, |w| Some(names::Key::Label(w.pou_key(), l)));
                match cond {
                    Cond::Always => {
                        let cr = self.settle_cr(cr);
                        self.edge(l, &cr, span);
                        self.push(Op::Jump {
                            label: l,
                            cond: None,
                        });
                        Cr::Dead
                    }
                    c => {
                        let Some(v) = self.cond_value(&cr, span) else {
                            return cr;
                        };
                        let after = Cr::Val(Ty::BOOL);
                        self.edge(l, &after, span);
                        self.push(Op::Jump {
                            label: l,
                            cond: Some((v, *c == Cond::IfTrue)),
                        });
                        after
                    }
                }
            }
            InstrKind::Return { cond } => {
                if in_parens {
                    self.err(IN_PARENS, span, "RET is not allowed inside parentheses");
                    return cr;
                }
                match cond {
                    Cond::Always => {
                        self.push(Op::Return { cond: None });
                        Cr::Dead
                    }
                    c => {
                        let Some(v) = self.cond_value(&cr, span) else {
                            return cr;
                        };
                        self.push(Op::Return {
                            cond: Some((v, *c == Cond::IfTrue)),
                        });
                        Cr::Val(Ty::BOOL)
                    }
                }
            }
            InstrKind::Call { cond, target, args } => {
                let args = args.as_deref();
                if in_parens {
                    self.err(IN_PARENS, span, "CAL is not allowed inside parentheses");
                    return cr;
                }
                // CAL of a FUNCTION with a formal list (3rd edition, STACK_INT).
                if let Operand::Var(v) = target
                    && v.path.is_empty()
                    && self.sig.var(&v.base.name).is_none()
                    && self.is_function(&v.base.name)
                {
                    if *cond != Cond::Always {
                        self.err(
                            UNSUPPORTED,
                            i.op_span,
                            "CALC/CALCN of a FUNCTION is not supported; use JMPCN around it",
                        );
                        return cr;
                    }
                    let args = args.cloned().unwrap_or(CallArgs::Formal(Vec::new()));
                    return self.fn_call(&v.base, &args, cr, span, true);
                }
                let Some(inst) = self.place_of(target, false) else {
                    return Cr::Undef(Why::AfterCal(self.line));
                };
                let Ty::Fb(fb) = inst.ty.clone() else {
                    self.err(
                        NOT_AN_FB,
                        target.span(),
                        format!(
                            "CAL needs a function block instance; `{}` is {}",
                            self.cx.file.snippet(target.span()),
                            inst.ty
                        ),
                    );
                    return Cr::Undef(Why::AfterCal(self.line));
                };
                let cond_v = match cond {
                    Cond::Always => None,
                    c => match self.cond_value(&cr, span) {
                        Some(v) => Some((v, *c == Cond::IfTrue)),
                        None => return Cr::Undef(Why::AfterCal(self.line)),
                    },
                };
                let (inouts_decl, externals) = self.fb_refs(&fb);
                let (inputs, outputs, inouts) = match args {
                    None => (Vec::new(), Vec::new(), Vec::new()),
                    Some(a) => self.fb_args(&fb, a, target.span()),
                };
                if inouts.len() != inouts_decl.len() {
                    if let Some(CallArgs::Formal(_)) | None = args {
                        // Only the names not written at all (a bad binding was reported).
                        let written = |n: &str| match args {
                            Some(CallArgs::Formal(list)) => list.iter().any(|p| p.name.is(n)),
                            _ => false,
                        };
                        let missing: Vec<&str> = inouts_decl
                            .iter()
                            .filter(|(n, _, _)| !written(n))
                            .map(|(n, _, _)| n.as_str())
                            .collect();
                        if !missing.is_empty() {
                            self.err(
                                BAD_IN_OUT,
                                span,
                                format!(
                                    "{fb} has VAR_IN_OUT {}: every call binds it (`CAL inst({} := variable)`)",
                                    missing.iter().map(|m| format!("`{m}`")).collect::<Vec<_>>().join(", "),
                                    missing[0]
                                ),
                            );
                        }
                    }
                    return Cr::Undef(Why::AfterCal(self.line));
                }
                // In declaration order, with the FB's variable of each.
                let inouts: Vec<(u32, Place)> = inouts_decl
                    .iter()
                    .filter_map(|(n, _, k)| {
                        inouts
                            .iter()
                            .find(|(m, _)| m.eq_ignore_ascii_case(n))
                            .map(|(_, p)| (*k, p.clone()))
                    })
                    .collect();
                let inouts_in_instance = inouts.iter().any(|(_, p)| p.root == inst.root);
                self.push(Op::CallFb(Box::new(crate::sema::ir::FbCall {
                    inouts_in_instance,
                    inst,
                    inputs,
                    outputs,
                    inouts,
                    externals,
                    cond: cond_v,
                })));
                Cr::Undef(Why::AfterCal(self.line))
            }
            InstrKind::FnCall { name, args } => self.fn_call(name, args, cr, span, false),
            InstrKind::FbInput { op, instance } => {
                let Some(inst) = self.place_of(instance, false) else {
                    return cr;
                };
                self.fb_input(inst, op.input_name(), cr, span)
            }
        }
    }

    pub(super) fn load(&mut self, negate: bool, operand: &Operand, span: Span) -> Cr {
        let Some(arg) = self.operand(operand) else {
            return Cr::Undef(Why::Error);
        };
        match arg {
            Arg::Lit(l, s) if !negate => Cr::Lit(l, s),
            Arg::Lit(l, s) => {
                self.err(
                    BAD_OPERATOR_TYPE,
                    s,
                    format!(
                        "LDN of {}: give the literal a type (BOOL#1, WORD#16#FF)",
                        describe(&l)
                    ),
                );
                Cr::Undef(Why::Error)
            }
            Arg::Typed(_, Ty::Fb(f)) => {
                self.err(BAD_OPERATOR_TYPE, operand.span(), format!("cannot load a function block instance ({f}); load one of its outputs, e.g. `.Q`"));
                let _ = span;
                Cr::Undef(Why::Error)
            }
            Arg::Typed(v, t) => {
                if negate && !t.is_logic() {
                    self.err(
                        BAD_OPERATOR_TYPE,
                        operand.span(),
                        format!("LDN needs BOOL or a bit string; this is {t}"),
                    );
                    return Cr::Val(t);
                }
                let expr = if negate { Expr::Not(v) } else { Expr::Value(v) };
                let cr = self.cr_index(&t);
                self.push(Op::SetCr { cr, expr });
                Cr::Val(t)
            }
        }
    }
}
