//! Initial values, variable declarations and variable blocks.

use super::*;

impl Tr<'_, '_> {
    /// Write the value held by `holder` (`<initialValue>` or an array's or
    /// structure's `<value>`), `depth` levels down; false when something
    /// was reported.
    pub(super) fn value(&mut self, holder: Node, depth: usize) -> bool {
        // Checked before recursing: each level is a stack frame.
        if depth >= MAX_DEPTH {
            return self.too_deep(holder);
        }
        let Some(v) = first_element(holder) else {
            return self.missing(holder, "simpleValue");
        };
        match v.tag_name().name() {
            "simpleValue" => self.attr(v, "value", Kind::Value),
            "arrayValue" => {
                self.put("[", v);
                let mut ok = true;
                for (k, e) in kids(v, "value").enumerate() {
                    if !ok {
                        break;
                    }
                    if k > 0 {
                        self.put(", ", e);
                    }
                    if e.attribute("repetitionValue").is_some() {
                        ok = self.attr(e, "repetitionValue", Kind::Count);
                        self.put("(", e);
                        ok = ok && self.value(e, depth + 1);
                        self.put(")", e);
                    } else {
                        ok = self.value(e, depth + 1);
                    }
                }
                self.put("]", v);
                ok
            }
            "structValue" => {
                self.put("(", v);
                let mut ok = true;
                for (k, e) in kids(v, "value").enumerate() {
                    if !ok {
                        break;
                    }
                    if k > 0 {
                        self.put(", ", e);
                    }
                    ok = self.attr(e, "member", Kind::Name);
                    self.put(" := ", e);
                    ok = ok && self.value(e, depth + 1);
                }
                self.put(")", v);
                ok
            }
            other => {
                let msg = format!(
                    "the initial value `<{}>` cannot be translated",
                    shown(other)
                );
                self.untranslatable(v, &msg)
            }
        }
    }

    /// `name AT %IX0.0 : TYPE := value;` — `init` replaces the variable's
    /// own initial value (for a lowered external constant). A variable with
    /// anything invalid is left out whole (false).
    pub(super) fn var_decl(&mut self, v: Node, init: Option<Node>, depth: usize) -> bool {
        let start = self.w.mark();
        self.put("    ", v);
        let mut ok = self.attr(v, "name", Kind::Name);
        if v.attribute("address").is_some() {
            self.put(" AT ", v);
            ok &= self.attr(v, "address", Kind::Address);
        }
        self.put(" : ", v);
        ok &= match kid(v, "type") {
            Some(t) => self.ty(t, depth),
            None => self.missing(v, "type"),
        };
        if let Some(iv) = init.or_else(|| kid(v, "initialValue")) {
            self.put(" := ", iv);
            ok &= self.value(iv, depth);
        }
        self.put(";\n", v);
        if !ok {
            self.w.rollback(start);
        }
        ok
    }

    pub(super) fn var_block(
        &mut self,
        b: Node,
        keyword: &str,
        constant: bool,
        vars: &[(Node, Option<Node>)],
    ) -> bool {
        if vars.is_empty() {
            return false;
        }
        let start = self.w.mark();
        self.put(keyword, b);
        if constant {
            self.put(" CONSTANT", b);
        }
        if flag(b, "retain") {
            self.put(" RETAIN", b);
        }
        if flag(b, "nonretain") {
            self.put(" NON_RETAIN", b);
        }
        self.put("\n", b);
        let mut any = false;
        for (v, init) in vars {
            any |= self.var_decl(*v, *init, 0);
        }
        if !any {
            // Every variable was left out: no empty block either.
            self.w.rollback(start);
            return false;
        }
        self.put("END_VAR\n", b);
        true
    }

    /// A variable block of an interface or a configuration.
    pub(super) fn block(&mut self, b: Node) {
        let keyword = match b.tag_name().name() {
            "inputVars" => "VAR_INPUT",
            "outputVars" => "VAR_OUTPUT",
            "inOutVars" => "VAR_IN_OUT",
            "localVars" => "VAR",
            "tempVars" => "VAR_TEMP",
            "externalVars" => "VAR_EXTERNAL",
            "globalVars" => "VAR_GLOBAL",
            "returnType" | "documentation" | "addData" => return,
            other => {
                let at = self.tag(b);
                self.diags.push(
                    Diagnostic::warning(
                        NOT_TRANSLATED,
                        at,
                        format!("`<{}>` is not translated", shown(other)),
                    )
                    .with_label("skipped"),
                );
                return;
            }
        };
        let constant = flag(b, "constant");
        let vars: Vec<Node> = kids(b, "variable").collect();
        if keyword != "VAR_EXTERNAL" || !constant {
            let vars: Vec<_> = vars.into_iter().map(|v| (v, None)).collect();
            self.var_block(b, keyword, constant, &vars);
            return;
        }
        // VAR_EXTERNAL CONSTANT naming exactly one VAR_GLOBAL CONSTANT of the
        // project: a local constant with the global's value (the same thing,
        // since neither can change).
        let mut lowered = Vec::new();
        let mut kept = Vec::new();
        for v in vars {
            let key = v.attribute("name").unwrap_or("").to_ascii_lowercase();
            match self.globals.get(&key).map(Vec::as_slice) {
                Some([g]) if g.constant => {
                    lowered.push((v, kid(g.var, "initialValue"), g.configuration.clone()))
                }
                _ => kept.push((v, None)),
            }
        }
        if !lowered.is_empty() {
            let start = self.w.mark();
            let configs: Vec<&str> = lowered.iter().map(|(_, _, c)| c.as_str()).collect();
            let mut configs = configs;
            configs.dedup();
            self.put(
                &format!(
                    "(* VAR_EXTERNAL CONSTANT: the values of VAR_GLOBAL CONSTANT of CONFIGURATION {} *)\n",
                    configs.join(", ")
                ),
                b,
            );
            let vars: Vec<_> = lowered.iter().map(|(v, i, _)| (*v, *i)).collect();
            if !self.var_block(b, "VAR", true, &vars) {
                self.w.rollback(start);
            }
        }
        self.var_block(b, "VAR_EXTERNAL", true, &kept);
    }
}
