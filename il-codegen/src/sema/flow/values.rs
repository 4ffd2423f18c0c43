//! Values of the CR: using it, fitting it to a type, and settling untyped
//! literals (pending folds) into typed values.

use super::*;

impl Walk<'_, '_> {
    /// The fix that converts the CR before the instruction being walked:
    /// the conversion as an instruction of its own, after the line's label
    /// (a jump to the label converts too), the instruction moved to the next
    /// line at its column.
    fn insert_conversion(&self, from: &Ty, to: &Ty) -> Option<crate::diag::Fix> {
        let name = super::operators::conversion_name(from, to)?;
        let text = &self.cx.file.text;
        let lo = (self.instr_lo as usize).min(text.len());
        let start = text[..lo].rfind('\n').map_or(0, |i| i + 1);
        let indent: String = text[start..lo]
            .chars()
            .map(|c| if c.is_whitespace() { c } else { ' ' })
            .collect();
        let nl = if text[lo..].split('\n').next()?.ends_with('\r') {
            "\r\n"
        } else {
            "\n"
        };
        Some(crate::diag::Fix {
            title: format!("Convert the current result with `{name}`"),
            edits: vec![(Span::new(lo, lo), format!("{name}{nl}{indent}"))],
        })
    }

    /// The CR as an argument, or a diagnostic saying why there is none.
    pub(super) fn use_cr(&mut self, cr: &Cr, span: Span) -> Option<Arg> {
        match cr {
            Cr::Dead => None,
            Cr::Undef(Why::Error) => None,
            Cr::Undef(Why::Start) => {
                if let Some(d) = self.err(CR_UNDEFINED, span, "there is no current result here") {
                    d.label = "this uses the current result".into();
                    d.help = Some("load a value first, e.g. `LD x`".into());
                }
                None
            }
            Cr::Undef(Why::AfterCal(line)) => {
                let line = *line;
                if let Some(d) = self.err(
                    CR_UNDEFINED,
                    span,
                    format!("the current result is undefined after the CAL on line {line}"),
                ) {
                    d.help =
                        Some("load a value first, e.g. an output of the block: `LD inst.Q`".into());
                }
                None
            }
            Cr::Undef(Why::Mixed(text)) => {
                // "label\0paths" (the label's name is added where it is known).
                let (label, paths) = text.split_once('\u{0}').unwrap_or(("above", text));
                let label = if label == "above" {
                    "the label above".to_string()
                } else {
                    format!("`{label}`")
                };
                let paths = paths.to_string();
                // Every path (or the only one) leaves no value: say that, not
                // that the paths disagree.
                let none = paths.split(", ").all(|p| p.starts_with("undefined"));
                let msg = if none {
                    format!(
                        "the current result is undefined at {label}: no path into it leaves a value"
                    )
                } else {
                    format!("the current result has different types on the paths into {label}")
                };
                if let Some(d) = self.err(CR_DISAGREES, span, msg) {
                    d.notes.push(format!("the paths bring: {paths}"));
                    d.help =
                        Some("load a value after the label before using the current result".into());
                }
                None
            }
            Cr::Lit(l, s) => Some(Arg::Lit(l.clone(), *s)),
            Cr::Val(t) => Some(Arg::Typed(Value::Cr(self.cr_index(t)), t.clone())),
        }
    }

    /// The CR as a BOOL condition (JMPC, CALC, RETC, S, R).
    pub(super) fn cond_value(&mut self, cr: &Cr, span: Span) -> Option<Value> {
        match self.use_cr(cr, span)? {
            Arg::Typed(v, t) if t.is_bool() => Some(v),
            Arg::Typed(_, t) => {
                if let Some(d) = self.err(
                    COND_NOT_BOOL,
                    span,
                    format!(
                        "this instruction tests the current result, which must be BOOL; it is {t}"
                    ),
                ) {
                    d.help = Some("compare first, e.g. `GT 0` or `EQ x`".into());
                }
                None
            }
            Arg::Lit(LitClass::Pending(p), _) => {
                self.materialize(&p, Some(&Ty::BOOL)).map(|(v, _)| v)
            }
            Arg::Lit(l, s) => match coerce(&l, &Ty::BOOL) {
                Ok(c) => {
                    // The CR is BOOL from here on, so it must live in its local.
                    let cr = self.cr_index(&Ty::BOOL);
                    self.push(Op::SetCr {
                        cr,
                        expr: Expr::Value(Value::Const(c)),
                    });
                    Some(Value::Cr(cr))
                }
                Err(m) => {
                    self.err(COND_NOT_BOOL, s, m);
                    None
                }
            },
        }
    }

    /// Make an argument a value of type `ty` for `dest` ("`x`", "input `PT` of t"):
    /// like [`Self::fit`], with a message that names both sides.
    pub(super) fn fit_to(
        &mut self,
        arg: Arg,
        ty: &Ty,
        span: Span,
        dest: impl FnOnce() -> String,
    ) -> Option<Value> {
        if let Arg::Typed(v, t) = &arg
            && t != ty
            && !t.resizes_to(ty)
        {
            if let Some(w) = self.widen(v.clone(), t, ty, span) {
                return Some(w);
            }
            let src = if matches!(v, Value::Cr(_) | Value::Saved(..)) {
                "the current result"
            } else {
                "the value"
            };
            let msg = format!("{} is {ty}, but {src} is {t}{}", dest(), narrowing(t, ty));
            let fix = matches!(v, Value::Cr(_))
                .then(|| self.insert_conversion(t, ty))
                .flatten();
            if let Some(d) = self.err(TYPE_MISMATCH, span, msg) {
                d.help = conversion_hint(t, ty);
                d.fixes.extend(fix);
            }
            return None;
        }
        self.fit(arg, ty, span)
    }

    /// Make an argument a value of type `ty` (widened implicitly when the
    /// 3rd edition's table allows it).
    pub(super) fn fit(&mut self, arg: Arg, ty: &Ty, span: Span) -> Option<Value> {
        match arg {
            Arg::Typed(v, t) if t == *ty => Some(v),
            // Another STRING length: cut at the target's (docs/semantics.md, "Types").
            Arg::Typed(v, t) if t.resizes_to(ty) => Some(Value::fit_string(v, &t, ty)),
            Arg::Typed(v, t) => {
                if let Some(w) = self.widen(v, &t, ty, span) {
                    return Some(w);
                }
                let msg = format!("expected {ty}, found {t}{}", narrowing(&t, ty));
                if let Some(d) = self.err(TYPE_MISMATCH, span, msg) {
                    d.help = conversion_hint(&t, ty);
                }
                None
            }
            Arg::Lit(l, s) => self.lit_value(&l, ty, s, LITERAL_RANGE),
        }
    }

    /// An output of type `ty` read with `=>` into `place`: `Ok(None)` when
    /// the types agree, `Ok(Some(w))` when it widens (3rd edition), `Err` (reported) otherwise.
    pub(super) fn output_fit(
        &mut self,
        name: &str,
        ty: &Ty,
        place: &Place,
        span: Span,
    ) -> Result<Option<ir::Widen>, ()> {
        // Another STRING length is cut by the store (the emitter's and the
        // interpreter's `fit_output`).
        if place.ty == *ty || ty.resizes_to(&place.ty) {
            return Ok(None);
        }
        if let Some(w) = super::super::widen::widening(ty, &place.ty) {
            self.feature(
                crate::dialect::Feature::Widening {
                    from: ty.to_string(),
                    to: place.ty.to_string(),
                },
                span,
            );
            return Ok(Some(w));
        }
        let msg = format!(
            "`{name}` is {ty}, the variable is {}{}",
            place.ty,
            narrowing(ty, &place.ty)
        );
        if let Some(d) = self.err(TYPE_MISMATCH, span, msg) {
            d.help = conversion_hint(ty, &place.ty);
        }
        Err(())
    }

    /// A pending call as an argument where no type is expected: emit it
    /// with the types its arguments default to.
    pub(super) fn settle(&mut self, a: Arg) -> Option<Arg> {
        match a {
            Arg::Lit(LitClass::Pending(p), _) => {
                let (v, t) = self.materialize(&p, None)?;
                Some(Arg::Typed(v, t))
            }
            a => Some(a),
        }
    }

    pub(super) fn settle_cr(&mut self, cr: Cr) -> Cr {
        match cr {
            Cr::Lit(LitClass::Pending(p), _) => match self.materialize(&p, None) {
                Some((_, t)) => Cr::Val(t),
                None => Cr::Undef(Why::Error),
            },
            cr => cr,
        }
    }

    /// Emit a pending call with result type `force` (or its default): the
    /// CR local of that type holds the result.
    pub(super) fn materialize(&mut self, p: &Pending, force: Option<&Ty>) -> Option<(Value, Ty)> {
        let shapes: Vec<stdfn::ArgShape> = p
            .args
            .iter()
            .map(|(a, _)| match a {
                PendArg::Typed(_, t) => stdfn::ArgShape::Ty(t.clone()),
                PendArg::Lit(l) => stdfn::ArgShape::Lit(l.clone()),
            })
            .collect();
        let res = match stdfn::resolve(&p.key, &shapes, force) {
            Ok(r) => r,
            Err(e) => {
                if let Some(d) = self.err(TYPE_MISMATCH, p.span, e.message) {
                    d.notes.push(format!("signature: {}", e.signature));
                }
                return None;
            }
        };
        if let Some(f) = force
            && res.ret != *f
        {
            self.err(
                TYPE_MISMATCH,
                p.span,
                format!(
                    "{} cannot give {f} here (its arguments make it {})",
                    p.key, res.ret
                ),
            );
            return None;
        }
        let mut values = Vec::new();
        for ((a, s), t) in p.args.iter().zip(&res.params) {
            let v = match a {
                PendArg::Typed(v, _) => v.clone(),
                PendArg::Lit(l) => self.lit_value(l, t, *s, LITERAL_RANGE)?,
            };
            values.push(v);
        }
        let ret = self.push_std_call(res, values, p.en.clone());
        Some((Value::Cr(self.cr_index(&ret)), ret))
    }

    /// A literal (or pending call) as a value of type `ty`.
    pub(super) fn lit_value(
        &mut self,
        l: &LitClass,
        ty: &Ty,
        span: Span,
        code: &'static str,
    ) -> Option<Value> {
        if let LitClass::Pending(p) = l {
            return self.materialize(p, Some(ty)).map(|(v, _)| v);
        }
        // A typed literal (`INT#5`) meeting a wider type is widened like a
        // typed value; the checker folds the conversion.
        if let LitClass::Typed(c) = l
            && c.ty() != *ty
            && let Some(v) = self.widen(Value::Const(c.clone()), &c.ty(), ty, span)
        {
            return Some(v);
        }
        match coerce(l, ty) {
            Ok(c) => Some(Value::Const(c)),
            Err(m) => {
                self.err(code, span, m);
                None
            }
        }
    }
}

/// "; narrowing is never implicit: use DINT_TO_INT" when `to` widens into
/// `from` (so the user meant a lossy conversion, which must be written).
pub(super) fn narrowing(from: &Ty, to: &Ty) -> String {
    match (from, to) {
        (Ty::Elem(f), Ty::Elem(t)) if super::super::widen::widens(*t, *f) => format!(
            "; narrowing is never implicit: convert with {}",
            super::super::widen::conversion_name(*f, *t)
        ),
        _ => String::new(),
    }
}
