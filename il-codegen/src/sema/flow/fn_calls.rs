//! Function calls: user FUNCTIONs and the standard functions, formal and
//! non-formal argument lists.

use super::*;

/// What one name of a formal list binds in the called function.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Slot {
    /// `EN := b`.
    En,
    /// `ENO => b` of a function that declares no ENO.
    Eno,
    /// The k-th input (a standard function: the k-th parameter).
    Input(usize),
    /// The k-th VAR_IN_OUT.
    InOut(usize),
    /// The k-th VAR_OUTPUT.
    Output(usize),
}

/// Why a name of a formal list binds nothing: code, place, message.
type Unbound = (&'static str, Span, String);

impl Walk<'_, '_> {
    /// Bind a formal list to the callee's parameters: the one loop for user
    /// and standard functions. `slot` says what each name binds, or why it
    /// binds nothing; a parameter given twice is an error for both. Every
    /// error is reported; the bool says whether there was none.
    pub(super) fn bind_formal<'l>(
        &mut self,
        list: &'l [ast::ParamAssign],
        mut slot: impl FnMut(&ast::ParamAssign) -> Result<Slot, Unbound>,
    ) -> (Vec<(Slot, &'l ast::ParamAssign)>, bool) {
        let mut seen = std::collections::HashSet::new();
        let mut bound = Vec::new();
        let mut ok = true;
        for p in list {
            match slot(p) {
                Ok(s) if !seen.insert(s) => {
                    self.err(
                        UNKNOWN_MEMBER,
                        p.name.span,
                        format!("parameter `{}` is given twice", p.name),
                    );
                    ok = false;
                }
                Ok(s) => bound.push((s, p)),
                Err((code, span, msg)) => {
                    self.err(code, span, msg);
                    ok = false;
                }
            }
        }
        (bound, ok)
    }

    pub(super) fn is_function(&self, name: &str) -> bool {
        self.env
            .pou(name)
            .is_some_and(|s| s.kind == PouKind::Function)
            || stdfn::is_std(&name.to_ascii_uppercase())
    }

    /// A function call; `formal_only` for `CAL F(...)` (the CR is not an argument).
    pub(super) fn fn_call(
        &mut self,
        name: &ast::Ident,
        args: &CallArgs,
        cr: Cr,
        span: Span,
        formal_only: bool,
    ) -> Cr {
        let bad = Cr::Undef(Why::Error);
        if let Some(sig) = self
            .env
            .pou(&name.name)
            .filter(|s| s.kind == PouKind::Function)
        {
            self.note(name.span, |_| Some(names::Key::Pou(name.key())));
            if let CallArgs::Formal(list) = args {
                for p in list {
                    if let Some((i, _)) = sig.var(&p.name.name) {
                        self.note(p.name.span, |_| Some(names::Key::Var(name.key(), i)));
                    }
                }
            }
            let inputs: Vec<(usize, String, Ty)> = sig
                .inputs()
                .map(|(i, v)| (i, v.name.clone(), v.ty.clone()))
                .collect();
            let inouts: Vec<(String, Ty)> = sig
                .vars
                .iter()
                .filter(|v| v.kind == ast::VarKind::InOut)
                .map(|v| (v.name.clone(), v.ty.clone()))
                .collect();
            // Positional order: inputs and in-outs as declared.
            let params: Vec<(bool, usize)> = {
                let (mut i, mut j) = (0, 0);
                sig.vars
                    .iter()
                    .filter_map(|v| match v.kind {
                        ast::VarKind::Input => {
                            i += 1;
                            Some((false, i - 1))
                        }
                        ast::VarKind::InOut => {
                            j += 1;
                            Some((true, j - 1))
                        }
                        _ => None,
                    })
                    .collect()
            };
            let mut inout_places: Vec<Option<Place>> = vec![None; inouts.len()];
            let ret = sig.ret.clone();
            let fname = sig.name.clone();
            let mut values: Vec<Option<Value>> = vec![None; inputs.len()];
            let mut outputs = Vec::new();
            let mut en: Option<Value> = None;
            // `ENO => x` on a function that never sets ENO: x gets EN (or TRUE).
            let mut eno_plain: Vec<(Place, bool)> = Vec::new();
            match args {
                CallArgs::NonFormal(list) if !formal_only => {
                    let total = list.len() + 1;
                    if total != params.len() {
                        if let Some(d) = self.err(ARG_COUNT, span, format!("{fname} takes {} input(s); this call gives {total} (the current result and {} operand(s))", params.len(), list.len())) {
                            d.notes.push(format!("inputs of {fname}: {}", inputs.iter().map(|(_, n, t)| format!("{n} : {t}")).chain(inouts.iter().map(|(n, t)| format!("{n} : {t} (VAR_IN_OUT)"))).collect::<Vec<_>>().join(", ")));
                        }
                        return bad;
                    }
                    if params[0].0 {
                        self.err(BAD_IN_OUT, span, format!("the first parameter of {fname}, `{}`, is a VAR_IN_OUT: the current result is a value, not a variable; use a formal call `{fname}({} := variable, ...)`", inouts[0].0, inouts[0].0));
                        return bad;
                    }
                    let Some(first) = self.use_cr(&cr, span) else {
                        return bad;
                    };
                    values[params[0].1] = self.fit(first, &inputs[params[0].1].2, span);
                    for (k, o) in list.iter().enumerate() {
                        match params[k + 1] {
                            (true, j) => {
                                let (n, t) = inouts[j].clone();
                                inout_places[j] = self.inout_place(o, &n, &t, &fname);
                                if inout_places[j].is_none() {
                                    return bad;
                                }
                            }
                            (false, j) => {
                                let Some(a) = self.operand(o) else { return bad };
                                values[j] = self.fit(a, &inputs[j].2, o.span());
                            }
                        }
                    }
                }
                CallArgs::NonFormal(_) => {
                    self.err(
                        ARG_COUNT,
                        span,
                        "CAL of a function needs a formal list: `CAL F(IN := x)`",
                    );
                    return bad;
                }
                CallArgs::Formal(list) => {
                    let outs: Vec<&ir::Var> = sig
                        .vars
                        .iter()
                        .filter(|o| o.kind == ast::VarKind::Output)
                        .collect();
                    let (bound, _) = self.bind_formal(list, |p| match &p.kind {
                        ParamKind::Input(_) if p.name.is("EN") => Ok(Slot::En),
                        ParamKind::Output { .. }
                            if p.name.is("ENO") && sig.var("ENO").is_none() =>
                        {
                            Ok(Slot::Eno)
                        }
                        ParamKind::Input(_) => inouts
                            .iter()
                            .position(|(n, _)| p.name.is(n))
                            .map(Slot::InOut)
                            .or_else(|| {
                                inputs
                                    .iter()
                                    .position(|(_, n, _)| p.name.is(n))
                                    .map(Slot::Input)
                            })
                            .ok_or_else(|| {
                                let m = format!("{fname} has no input `{}`", p.name);
                                (UNKNOWN_MEMBER, p.name.span, m)
                            }),
                        ParamKind::Output { .. } => outs
                            .iter()
                            .position(|o| p.name.is(&o.name))
                            .map(Slot::Output)
                            .ok_or_else(|| {
                                let m = format!("{fname} has no output `{}`", p.name);
                                (UNKNOWN_MEMBER, p.name.span, m)
                            }),
                    });
                    for (slot, p) in bound {
                        match (slot, &p.kind) {
                            (Slot::En, ParamKind::Input(o)) => {
                                let Some(a) = self.operand(o) else { continue };
                                en = self.fit(a, &Ty::BOOL, o.span());
                            }
                            (Slot::Eno, ParamKind::Output { negate, target }) => {
                                let Some(place) = self.place_of(target, true) else {
                                    continue;
                                };
                                if place.ty != Ty::BOOL {
                                    self.err(
                                        TYPE_MISMATCH,
                                        target.span(),
                                        format!("`ENO` is BOOL, the variable is {}", place.ty),
                                    );
                                    continue;
                                }
                                eno_plain.push((place, *negate));
                            }
                            (Slot::InOut(j), ParamKind::Input(o)) => {
                                let (n, t) = inouts[j].clone();
                                inout_places[j] = self.inout_place(o, &n, &t, &fname);
                                if inout_places[j].is_none() {
                                    return bad;
                                }
                            }
                            (Slot::Input(k), ParamKind::Input(o)) => {
                                let Some(a) = self.operand(o) else { continue };
                                values[k] = self.fit(a, &inputs[k].2, o.span());
                            }
                            (Slot::Output(k), ParamKind::Output { negate, target }) => {
                                let ty = outs[k].ty.clone();
                                let Some(place) = self.place_of(target, true) else {
                                    continue;
                                };
                                let Ok(w) =
                                    self.output_fit(&p.name.name, &ty, &place, target.span())
                                else {
                                    continue;
                                };
                                outputs.push((k, place, *negate, w));
                            }
                            _ => {}
                        }
                    }
                    // An input left out takes its declared initial value
                    // (Ed.2 2.5.1.1), else the type's default.
                    for (k, (i, _, t)) in inputs.iter().enumerate() {
                        if values[k].is_none() {
                            values[k] = Some(Value::Const(match &sig.vars[*i].init {
                                Some(ir::Init::Const(c)) => c.clone(),
                                _ => default_const(t),
                            }));
                        }
                    }
                }
            }
            let Some(ret) = ret else { return bad };
            if let Some(j) = inout_places.iter().position(Option::is_none) {
                self.err(
                    BAD_IN_OUT,
                    span,
                    format!(
                        "{fname} has VAR_IN_OUT `{}`: every call binds it (`{fname}({} := variable, ...)`)",
                        inouts[j].0, inouts[j].0
                    ),
                );
                return bad;
            }
            if values.iter().any(Option::is_none) {
                return bad;
            }
            let inouts = inout_places.into_iter().flatten().collect();
            let args = values.into_iter().flatten().collect();
            let out_types = sig
                .vars
                .iter()
                .filter(|o| o.kind == ast::VarKind::Output)
                .map(|o| o.ty.clone())
                .collect();
            let eno = sig
                .vars
                .iter()
                .filter(|o| o.kind == ast::VarKind::Output)
                .position(|o| o.name == "ENO");
            let cr = self.cr_index(&ret);
            self.push(Op::SetCr {
                cr,
                expr: Expr::CallUser(Box::new(crate::sema::ir::UserCall {
                    name: fname,
                    inouts,
                    args,
                    out_types,
                    outputs,
                    en: en.clone(),
                    eno,
                    ret: ret.clone(),
                })),
            });
            for (place, negate) in eno_plain {
                let value = en.clone().unwrap_or(Value::Const(Const::Bool(true)));
                let place = self.place_id(place);
                self.push(Op::Store {
                    place,
                    value,
                    negate,
                });
            }
            return Cr::Val(ret);
        }
        let key = name.key();
        if stdfn::is_std(&key) {
            self.note(name.span, |_| {
                il_std::signature::lookup(&key).map(|s| names::Key::StdFn(s.name))
            });
            let mut argv: Vec<(Arg, Span)> = Vec::new();
            match args {
                CallArgs::NonFormal(list) if !formal_only => {
                    let before = self.cx.diags.len();
                    let Some(first) = self.use_cr(&cr, span) else {
                        // `ABS y` with no current result: the operand is not
                        // the argument (the CR is), which is worth saying.
                        let one = il_std::signature::lookup(&key).is_some_and(|s| {
                            s.params.len() == 1 && matches!(s.ext, il_std::signature::Ext::Fixed)
                        });
                        if one && list.len() == 1 && self.cx.diags.len() > before {
                            let operand = self.cx.file.snippet(list[0].span()).to_string();
                            if let Some(d) = self.cx.diags.last_mut() {
                                d.help = Some(format!(
                                    "{name} takes one argument, the current result, not its operand: write `LD {operand}`, then `{name}` alone"
                                ));
                            }
                        }
                        return bad;
                    };
                    argv.push((first, span));
                    for o in list {
                        let Some(a) = self.operand(o) else { return bad };
                        argv.push((a, o.span()));
                    }
                }
                CallArgs::NonFormal(_) => {
                    self.err(
                        ARG_COUNT,
                        span,
                        "CAL of a function needs a formal list: `CAL F(IN := x)`",
                    );
                    return bad;
                }
                CallArgs::Formal(list) => {
                    // EN and ENO exist on every function, standard ones too.
                    let count = list
                        .iter()
                        .filter(|p| !p.name.is("EN") && !p.name.is("ENO"))
                        .count();
                    let (bound, ok) = self.bind_formal(list, |p| match &p.kind {
                        ParamKind::Input(_) if p.name.is("EN") => Ok(Slot::En),
                        ParamKind::Output { .. } if p.name.is("ENO") => Ok(Slot::Eno),
                        ParamKind::Input(_) => stdfn::formal_slot(&key, &p.name, count)
                            .map(Slot::Input)
                            .map_err(|m| (UNKNOWN_MEMBER, p.name.span, m)),
                        ParamKind::Output { .. } => Err((
                            UNSUPPORTED,
                            p.span,
                            "standard functions have no outputs to read with `=>` but ENO".into(),
                        )),
                    });
                    if !ok {
                        return bad;
                    }
                    let mut given = Vec::new();
                    let mut en = None;
                    let mut enos = Vec::new();
                    for (slot, p) in bound {
                        match (slot, &p.kind) {
                            (Slot::Input(pos), ParamKind::Input(o)) => {
                                let Some(a) = self.operand(o) else { return bad };
                                given.push((pos, a, o.span()));
                            }
                            (Slot::En, ParamKind::Input(o)) => {
                                let Some(a) = self.operand(o) else { return bad };
                                en = Some(self.fit(a, &Ty::BOOL, o.span()));
                            }
                            (Slot::Eno, ParamKind::Output { negate, target }) => {
                                let Some(place) = self.place_of(target, true) else {
                                    return bad;
                                };
                                if place.ty != Ty::BOOL {
                                    self.err(
                                        TYPE_MISMATCH,
                                        target.span(),
                                        format!("`ENO` is BOOL, the variable is {}", place.ty),
                                    );
                                    return bad;
                                }
                                enos.push((place, *negate));
                            }
                            _ => {}
                        }
                    }
                    match stdfn::order_slots(&key, given) {
                        Ok(v) => argv = v,
                        Err(m) => {
                            self.err(UNKNOWN_MEMBER, span, m);
                            return bad;
                        }
                    }
                    if en.is_some() || !enos.is_empty() {
                        let Some(en) = en.unwrap_or(Some(Value::Const(Const::Bool(true)))) else {
                            return bad;
                        };
                        return self.std_call_en(&key, argv, name.span, en, enos);
                    }
                }
            }
            return self.std_call(&key, argv, name.span, None);
        }
        let is_var = self.sig.var(&name.name).is_some();
        let mut cands: Vec<String> = self
            .env
            .pous
            .values()
            .filter(|s| s.kind == PouKind::Function)
            .map(|s| s.name.clone())
            .collect();
        // A hash map's order: sorted, so that the suggestion is the same on
        // every run.
        cands.sort();
        cands.extend(stdfn::names().map(String::from));
        // A mistyped IL operator (`LDD`) lands here too.
        cands.extend(
            [
                "LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN", "OR", "ORN", "XOR", "XORN",
                "NOT", "ADD", "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT",
                "JMP", "JMPC", "JMPCN", "CAL", "CALC", "CALCN", "RET", "RETC", "RETCN", "S1", "R1",
                "CLK", "CU", "CD", "PV", "IN", "PT",
            ]
            .map(String::from),
        );
        let near = suggest(&name.name, cands.iter().map(String::as_str)).map(str::to_string);
        if let Some(d) = self.err(
            UNKNOWN_FUNCTION,
            name.span,
            format!("unknown operator or function `{name}`"),
        ) {
            if is_var {
                d.help = Some(format!(
                    "`{name}` is a variable: write `LD {name}` or `ST {name}`"
                ));
            } else {
                if let Some(s) = &near {
                    d.did_you_mean(name.span, s);
                }
                d.notes.push("a word in the operator field that is not an IL operator must name a FUNCTION; vendor built-ins are not IEC 61131-3".into());
                d.notes.push(format!("if the runtime provides `{name}`, declare it as a host function, whose body is the crate's Rust code: `{{extern}} FUNCTION {name} : BOOL VAR_INPUT ... END_VAR END_FUNCTION`"));
            }
        }
        bad
    }

    /// `CR := F(values)` for a resolved standard function; the CR's type.
    pub(super) fn push_std_call(
        &mut self,
        res: stdfn::Resolved,
        values: Vec<Value>,
        en: Option<Value>,
    ) -> Ty {
        let ret = res.ret.clone();
        let cr = self.cr_index(&ret);
        self.push(Op::SetCr {
            cr,
            expr: Expr::CallStd(Box::new(crate::sema::ir::StdFnCall {
                sig: res.sig,
                en,
                call: res.call,
                args: values,
                arg_types: res.params,
                ret: res.ret,
                fault: res.fault,
            })),
        });
        ret
    }

    /// A standard function called with `EN :=` or `ENO =>`: the call runs
    /// only when EN is TRUE (the result is then the type's default), and
    /// each ENO target gets EN.
    fn std_call_en(
        &mut self,
        key: &str,
        argv: Vec<(Arg, Span)>,
        span: Span,
        en: Value,
        enos: Vec<(Place, bool)>,
    ) -> Cr {
        let cr = self.std_call(key, argv, span, Some(en.clone()));
        if matches!(cr, Cr::Val(_)) {
            for (place, negate) in enos {
                let place = self.place_id(place);
                self.push(Op::Store {
                    place,
                    value: en.clone(),
                    negate,
                });
            }
        }
        cr
    }

    /// `en`: `EN :=` of a formal call.
    pub(super) fn std_call(
        &mut self,
        key: &str,
        argv: Vec<(Arg, Span)>,
        span: Span,
        en: Option<Value>,
    ) -> Cr {
        let bad = Cr::Undef(Why::Error);
        let mut settled = Vec::new();
        for (a, s) in argv {
            let Some(a) = self.settle(a) else { return bad };
            settled.push((a, s));
        }
        let argv = settled;
        let shapes: Vec<stdfn::ArgShape> = argv
            .iter()
            .map(|(a, _)| match a {
                Arg::Typed(_, t) => stdfn::ArgShape::Ty(t.clone()),
                Arg::Lit(l, _) => stdfn::ArgShape::Lit(l.clone()),
            })
            .collect();
        if stdfn::needs_context(key, &shapes) {
            let args = argv
                .into_iter()
                .map(|(a, s)| match a {
                    Arg::Typed(v, t) => (PendArg::Typed(v, t), s),
                    Arg::Lit(l, _) => (PendArg::Lit(l), s),
                })
                .collect();
            let p = Pending {
                key: key.to_string(),
                args,
                span,
                en,
            };
            // A call with EN runs in a branch of its own: its type cannot
            // wait for its use, as an all-literal call's does.
            if p.en.is_some() {
                return match self.materialize(&p, None) {
                    Some((_, ty)) => Cr::Val(ty),
                    None => bad,
                };
            }
            return Cr::Lit(LitClass::Pending(Box::new(p)), span);
        }
        match stdfn::resolve(key, &shapes, None) {
            Ok(res) => {
                let mut values = Vec::new();
                for ((a, s), t) in argv.into_iter().zip(&res.params) {
                    let Some(v) = self.fit(a, t, s) else {
                        return bad;
                    };
                    values.push(v);
                }
                Cr::Val(self.push_std_call(res, values, en))
            }
            Err(e) => {
                let code = if e.count { ARG_COUNT } else { TYPE_MISMATCH };
                if let Some(d) = self.err(code, span, e.message) {
                    d.notes.push(format!("signature: {}", e.signature));
                    if e.count {
                        d.notes
                            .push("in IL the current result is the first argument".into());
                    }
                }
                bad
            }
        }
    }
}
