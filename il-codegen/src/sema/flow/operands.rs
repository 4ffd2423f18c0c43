//! Operands: variables, literals and direct addresses as values of the CR.

use super::*;

impl Walk<'_, '_> {
    pub(super) fn operand(&mut self, o: &Operand) -> Option<Arg> {
        // Enumeration values: `Color#Red`, or a bare `Red` that names no variable.
        match o {
            Operand::Lit(ast::Literal {
                kind: ast::LitKind::Enum(e),
                span,
                ..
            }) => {
                let (ty, value) = (&e.ty, &e.value);
                let env = self.env;
                let Some((name, vals)) = env.types.enums.get(&ty.key()) else {
                    self.err(
                        UNKNOWN_TYPE,
                        ty.span,
                        format!("`{ty}` is not an enumeration type"),
                    );
                    return None;
                };
                let Some(v) = vals.iter().find(|v| value.is(v)) else {
                    let hint = suggest(&value.name, vals.iter().map(String::as_str))
                        .map(|s| format!("did you mean `{s}`?"));
                    if let Some(d) = self.err(
                        UNKNOWN_NAME,
                        *span,
                        format!("`{value}` is not a value of {name}"),
                    ) {
                        d.help = hint;
                    }
                    return None;
                };
                let k = ty.key();
                self.note(ty.span, |_| Some(names::Key::Type(k.clone())));
                let i = vals.iter().position(|x| x == v).unwrap_or(0);
                self.note(value.span, |_| Some(names::Key::EnumValue(k, i)));
                let c = Const::enum_value(name.clone(), v.clone());
                return Some(Arg::Typed(Value::Const(c.clone()), c.ty()));
            }
            Operand::Var(v)
                if v.path.is_empty()
                    && self.sig.var(&v.base.name).is_none()
                    && !(self.sig.kind == PouKind::Function && v.base.is(&self.sig.name)) =>
            {
                if let Some((ty, value)) = self.env.types.enum_of_value(&v.base.name) {
                    self.note(v.base.span, |w| {
                        let k = ty.to_ascii_uppercase();
                        let (_, vals) = w.env.types.enums.get(&k)?;
                        let i = vals.iter().position(|x| *x == value)?;
                        Some(names::Key::EnumValue(k, i))
                    });
                    let c = Const::enum_value(ty, value);
                    return Some(Arg::Typed(Value::Const(c.clone()), c.ty()));
                }
            }
            _ => {}
        }
        match o {
            Operand::Lit(l) => match lit_class(l) {
                LitClass::Typed(c) => Some(Arg::Typed(Value::Const(c.clone()), c.ty())),
                LitClass::Unsupported(m) => {
                    self.err(UNSUPPORTED, l.span, m);
                    None
                }
                LitClass::Invalid(m) => {
                    self.err(LITERAL_RANGE, l.span, m);
                    None
                }
                other => Some(Arg::Lit(other, l.span)),
            },
            Operand::Var(v) => {
                let p = self.place(v, false)?;
                let ty = p.ty.clone();
                Some(Arg::Typed(Value::Read(self.place_id(p)), ty))
            }
            Operand::Addr(a) => {
                let p = self.addr_place(a, false)?;
                let ty = p.ty.clone();
                Some(Arg::Typed(Value::Read(self.place_id(p)), ty))
            }
        }
    }
}
