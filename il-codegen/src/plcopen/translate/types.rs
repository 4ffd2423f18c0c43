//! Data types: `<dataTypes>` and the type of a variable.

use super::*;

impl Tr<'_, '_> {
    /// Write the type held by `holder` (`<type>`, `<baseType>`, `<returnType>`),
    /// `depth` levels down in types; false when something was reported.
    pub(super) fn ty(&mut self, holder: Node, depth: usize) -> bool {
        // Checked before recursing: each level is a stack frame.
        if depth >= MAX_DEPTH {
            return self.too_deep(holder);
        }
        let Some(t) = first_element(holder) else {
            let at = self.tag(holder);
            self.diags.push(
                Diagnostic::error(
                    BAD_PROJECT,
                    at,
                    format!("`<{}>` names no type", holder.tag_name().name()),
                )
                .with_label("empty type"),
            );
            return false;
        };
        let name = t.tag_name().name();
        if let Some((_, il)) = ELEMENTARY.iter().find(|(x, _)| *x == name) {
            self.put(il, t);
            return true;
        }
        match name {
            "string" | "wstring" => {
                self.put(
                    if name == "string" {
                        "STRING"
                    } else {
                        "WSTRING"
                    },
                    t,
                );
                if t.attribute("length").is_some() {
                    self.put("[", t);
                    if !self.attr(t, "length", Kind::Count) {
                        return false;
                    }
                    self.put("]", t);
                }
                true
            }
            "derived" => self.attr(t, "name", Kind::Name),
            "array" => {
                self.put("ARRAY [", t);
                let mut ok = true;
                for (k, d) in kids(t, "dimension").enumerate() {
                    if k > 0 {
                        self.put(", ", d);
                    }
                    ok = ok && self.attr(d, "lower", Kind::Bound);
                    self.put("..", d);
                    ok = ok && self.attr(d, "upper", Kind::Bound);
                }
                self.put("] OF ", t);
                match kid(t, "baseType") {
                    Some(b) => ok && self.ty(b, depth + 1),
                    None => self.missing(t, "baseType"),
                }
            }
            "subrangeSigned" | "subrangeUnsigned" => {
                let ok = match kid(t, "baseType") {
                    Some(b) => self.ty(b, depth + 1),
                    None => self.missing(t, "baseType"),
                };
                let Some(r) = kid(t, "range") else {
                    return self.missing(t, "range");
                };
                self.put(" (", r);
                let lo = ok && self.attr(r, "lower", Kind::Bound);
                self.put("..", r);
                let hi = lo && self.attr(r, "upper", Kind::Bound);
                self.put(")", r);
                ok && lo && hi
            }
            "enum" => {
                self.put("(", t);
                let values: Vec<Node> = kids(t, "values").flat_map(|v| kids(v, "value")).collect();
                let mut ok = !values.is_empty();
                for (k, v) in values.iter().enumerate() {
                    if k > 0 {
                        self.put(", ", *v);
                    }
                    ok = ok && self.attr(*v, "name", Kind::Name);
                    if ok && v.attribute("value").is_some() {
                        self.put(" := ", *v);
                        ok = self.attr(*v, "value", Kind::Integer);
                    }
                }
                self.put(")", t);
                if values.is_empty() {
                    let at = self.tag(t);
                    self.diags.push(
                        Diagnostic::error(BAD_PROJECT, at, "an enumeration without values")
                            .with_label("no `<value>`"),
                    );
                }
                ok
            }
            "struct" => {
                self.put("\n    STRUCT\n", t);
                let mut ok = true;
                for v in kids(t, "variable") {
                    ok &= self.var_decl(v, None, depth + 1);
                }
                self.put("    END_STRUCT", t);
                ok
            }
            "pointer" => self.untranslatable(
                t,
                "pointer types cannot be translated: IEC 61131-3 IL has no pointers",
            ),
            other => {
                let msg = format!("the type `<{}>` cannot be translated", shown(other));
                self.untranslatable(t, &msg)
            }
        }
    }

    pub(super) fn data_types(&mut self, dts: Node) {
        let types: Vec<Node> = kids(dts, "dataType").collect();
        if types.is_empty() {
            return;
        }
        let block = self.w.mark();
        self.put("TYPE\n", dts);
        let mut any = false;
        for d in types {
            // A type with anything invalid is left out whole.
            let start = self.w.mark();
            self.put("  ", d);
            let mut ok = self.attr(d, "name", Kind::Name);
            self.put(" : ", d);
            ok = ok
                && match kid(d, "baseType") {
                    Some(b) => self.ty(b, 0),
                    None => self.missing(d, "baseType"),
                };
            if let Some(iv) = kid(d, "initialValue").filter(|_| ok) {
                self.put(" := ", iv);
                ok = self.value(iv, 0);
            }
            self.put(";\n", d);
            if ok {
                any = true;
            } else {
                self.w.rollback(start);
            }
        }
        if any {
            self.put("END_TYPE\n\n", dts);
        } else {
            self.w.rollback(block);
        }
    }
}
