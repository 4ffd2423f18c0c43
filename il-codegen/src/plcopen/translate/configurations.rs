//! Configurations, resources, tasks and program instances.

use super::*;

impl Tr<'_, '_> {
    pub(super) fn configuration(&mut self, c: Node) {
        // Without a valid name the configuration is left out: the name is
        // written into the IL text and quoted in messages.
        let Some(name) = self.checked(c, "name", Kind::Name) else {
            return;
        };
        let name = name.value().to_string();
        let resources: Vec<Node> = kids(c, "resource").collect();
        // Program instances of POUs that were not translated: the
        // configuration cannot be compiled, say so once.
        for r in &resources {
            let instances = kids(*r, "pouInstance")
                .chain(kids(*r, "task").flat_map(|t| kids(t, "pouInstance")));
            for i in instances {
                let ty = i.attribute("typeName").unwrap_or("");
                if let Some(p) = self.left_out.get(ty).map(|k| &self.pous[k]) {
                    let msg = format!(
                        "CONFIGURATION `{name}` is not translated: its instance `{}` runs POU `{}`, whose body is {} ({})",
                        shown(i.attribute("name").unwrap_or("")),
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
        self.attr(c, "name", Kind::Name);
        self.put("\n", c);
        for b in kids(c, "globalVars") {
            self.block(b);
        }
        for r in resources {
            self.resource(r);
        }
        self.put("END_CONFIGURATION\n\n", c);
    }

    /// A resource, left out whole when its name is invalid.
    fn resource(&mut self, r: Node) {
        let start = self.w.mark();
        self.put("RESOURCE ", r);
        if !self.attr(r, "name", Kind::Name) {
            self.w.rollback(start);
            return;
        }
        self.put(" ON PLC\n", r);
        for b in kids(r, "globalVars") {
            self.block(b);
        }
        let tasks: Vec<Node> = kids(r, "task").filter(|t| self.task(*t)).collect();
        for t in &tasks {
            for i in kids(*t, "pouInstance") {
                self.program_instance(i, Some(*t));
            }
        }
        // The instances of a task that was left out are left out with it
        // (the task's error says why).
        for i in kids(r, "pouInstance") {
            self.program_instance(i, None);
        }
        self.put("END_RESOURCE\n", r);
    }

    /// `TASK name (SINGLE := s, INTERVAL := t, PRIORITY := p);`, or nothing
    /// (false) when an attribute is invalid.
    fn task(&mut self, t: Node) -> bool {
        let start = self.w.mark();
        self.put("    TASK ", t);
        let mut ok = self.attr(t, "name", Kind::Name);
        self.put(" (", t);
        let mut first = true;
        for (attr, param, kind) in [
            ("single", "SINGLE", Kind::Trigger),
            ("interval", "INTERVAL", Kind::Duration),
            ("priority", "PRIORITY", Kind::Count),
        ] {
            if t.attribute(attr).is_some() {
                if !first {
                    self.put(", ", t);
                }
                first = false;
                self.put(&format!("{param} := "), t);
                ok &= self.attr(t, attr, kind);
            }
        }
        if first {
            // TC6 requires a priority; IL needs at least one parameter.
            self.put("PRIORITY := 0", t);
        }
        self.put(");\n", t);
        if !ok {
            self.w.rollback(start);
        }
        ok
    }

    /// `PROGRAM name WITH task : type;`, left out when invalid.
    fn program_instance(&mut self, i: Node, task: Option<Node>) {
        let start = self.w.mark();
        self.put("    PROGRAM ", i);
        let mut ok = self.attr(i, "name", Kind::Name);
        if let Some(t) = task {
            self.put(" WITH ", i);
            // Checked with the task; valid here.
            ok &= self.attr(t, "name", Kind::Name);
        }
        self.put(" : ", i);
        ok &= self.attr(i, "typeName", Kind::Name);
        self.put(";\n", i);
        if !ok {
            self.w.rollback(start);
        }
    }
}
