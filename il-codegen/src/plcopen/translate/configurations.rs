//! Configurations, resources, tasks and program instances.

use super::*;
impl Tr<'_, '_> {
    pub(super) fn configuration(&mut self, c: Node) {
        let name = c.attribute("name").unwrap_or("").to_string();
        let resources: Vec<Node> = kids(c, "resource").collect();
        // Program instances of POUs that were not translated: the
        // configuration cannot be compiled, say so once.
        for r in &resources {
            let instances = kids(*r, "pouInstance")
                .chain(kids(*r, "task").flat_map(|t| kids(t, "pouInstance")));
            for i in instances {
                let ty = i.attribute("typeName").unwrap_or("");
                if let Some(p) = self
                    .pous
                    .iter()
                    .find(|p| !p.translated && p.name.eq_ignore_ascii_case(ty))
                {
                    let msg = format!(
                        "CONFIGURATION `{name}` is not translated: its instance `{}` runs POU `{}`, whose body is {} ({})",
                        i.attribute("name").unwrap_or(""),
                        p.name,
                        language_name(&p.language),
                        p.language
                    );
                    let at = self.attr_span(i, "typeName");
                    let cfg = self.attr_span(c, "name");
                    self.diags.push(
                        Diagnostic::warning(NOT_TRANSLATED, cfg, msg)
                            .with_label("skipped")
                            .with_secondary(at, "this POU is not translated"),
                    );
                    return;
                }
            }
        }
        for extra in kids(c, "accessVars").chain(kids(c, "configVars")) {
            let at = self.tag(extra);
            self.diags.push(
                Diagnostic::warning(
                    NOT_TRANSLATED,
                    at,
                    format!(
                        "`<{}>` of CONFIGURATION `{name}` is not translated",
                        extra.tag_name().name()
                    ),
                )
                .with_label("skipped"),
            );
        }
        self.put("CONFIGURATION ", c);
        self.attr(c, "name");
        self.put("\n", c);
        for b in kids(c, "globalVars") {
            self.block(b);
        }
        for r in resources {
            self.put("RESOURCE ", r);
            self.attr(r, "name");
            self.put(" ON PLC\n", r);
            for b in kids(r, "globalVars") {
                self.block(b);
            }
            let tasks: Vec<Node> = kids(r, "task").collect();
            for t in &tasks {
                self.put("    TASK ", *t);
                self.attr(*t, "name");
                self.put(" (", *t);
                let mut first = true;
                for (attr, param) in [
                    ("single", "SINGLE"),
                    ("interval", "INTERVAL"),
                    ("priority", "PRIORITY"),
                ] {
                    if t.attribute(attr).is_some() {
                        if !first {
                            self.put(", ", *t);
                        }
                        first = false;
                        self.put(&format!("{param} := "), *t);
                        self.attr(*t, attr);
                    }
                }
                if first {
                    // TC6 requires a priority; IL needs at least one parameter.
                    self.put("PRIORITY := 0", *t);
                }
                self.put(");\n", *t);
            }
            for t in &tasks {
                for i in kids(*t, "pouInstance") {
                    self.program_instance(i, Some(*t));
                }
            }
            for i in kids(r, "pouInstance") {
                self.program_instance(i, None);
            }
            self.put("END_RESOURCE\n", r);
        }
        self.put("END_CONFIGURATION\n\n", c);
    }

    pub(super) fn program_instance(&mut self, i: Node, task: Option<Node>) {
        self.put("    PROGRAM ", i);
        self.attr(i, "name");
        if let Some(t) = task {
            self.put(" WITH ", i);
            self.attr(t, "name");
        }
        self.put(" : ", i);
        self.attr(i, "typeName");
        self.put(";\n", i);
    }
}
