//! Data types: `<dataTypes>` and the type of a variable.

use super::*;
impl Tr<'_, '_> {
    /// Write the type held by `holder` (`<type>`, `<baseType>`, `<returnType>`).
    pub(super) fn ty(&mut self, holder: Node) -> bool {
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
                    self.attr(t, "length");
                    self.put("]", t);
                }
                true
            }
            "derived" => self.attr(t, "name"),
            "array" => {
                self.put("ARRAY [", t);
                let mut ok = true;
                for (k, d) in kids(t, "dimension").enumerate() {
                    if k > 0 {
                        self.put(", ", d);
                    }
                    ok &= self.attr(d, "lower");
                    self.put("..", d);
                    ok &= self.attr(d, "upper");
                }
                self.put("] OF ", t);
                match kid(t, "baseType") {
                    Some(b) => ok && self.ty(b),
                    None => self.missing(t, "baseType"),
                }
            }
            "subrangeSigned" | "subrangeUnsigned" => {
                let ok = match kid(t, "baseType") {
                    Some(b) => self.ty(b),
                    None => self.missing(t, "baseType"),
                };
                let Some(r) = kid(t, "range") else {
                    return self.missing(t, "range");
                };
                self.put(" (", r);
                let lo = self.attr(r, "lower");
                self.put("..", r);
                let hi = self.attr(r, "upper");
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
                    ok &= self.attr(*v, "name");
                    if v.attribute("value").is_some() {
                        self.put(" := ", *v);
                        self.attr(*v, "value");
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
                    ok &= self.var_decl(v, None);
                }
                self.put("    END_STRUCT", t);
                ok
            }
            "pointer" => self.untranslatable(
                t,
                "pointer types cannot be translated: IEC 61131-3 IL has no pointers",
            ),
            other => {
                let msg = format!("the type `<{other}>` cannot be translated");
                self.untranslatable(t, &msg)
            }
        }
    }

    pub(super) fn data_types(&mut self, dts: Node) {
        let types: Vec<Node> = kids(dts, "dataType").collect();
        if types.is_empty() {
            return;
        }
        self.put("TYPE\n", dts);
        for d in types {
            self.put("  ", d);
            self.attr(d, "name");
            self.put(" : ", d);
            match kid(d, "baseType") {
                Some(b) => {
                    self.ty(b);
                }
                None => {
                    self.missing(d, "baseType");
                }
            }
            if let Some(iv) = kid(d, "initialValue") {
                self.put(" := ", iv);
                self.value(iv);
            }
            self.put(";\n", d);
        }
        self.put("END_TYPE\n\n", dts);
    }
}
