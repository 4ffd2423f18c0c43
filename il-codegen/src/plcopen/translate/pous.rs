//! POUs: the header, the interface and the IL body.

use super::*;

impl Tr<'_, '_> {
    pub(super) fn pou(&mut self, p: Node) {
        // A POU without a valid name is left out, whatever its language:
        // the name is written into the IL text and quoted in messages.
        let Some(name) = self.checked(p, "name", Kind::Name) else {
            return;
        };
        let name = name.value().to_string();
        let name_span = self.attr_span(p, "name");
        let keyword = match p.attribute("pouType") {
            Some("program") => "PROGRAM",
            Some("functionBlock") => "FUNCTION_BLOCK",
            Some("function") => "FUNCTION",
            other => {
                let what = other.map_or("no `pouType`".to_string(), |o| {
                    format!("`pouType=\"{}\"`", shown(o))
                });
                self.diags.push(
                    Diagnostic::error(
                        BAD_PROJECT,
                        self.attr_span(p, "pouType"),
                        format!(
                            "POU `{name}` has {what}: expected program, functionBlock or function"
                        ),
                    )
                    .with_label("unknown POU type"),
                );
                return;
            }
        };
        let body = kid(p, "body");
        let lang = body.and_then(|b| {
            b.children()
                .find(|c| c.is_element() && BODY_LANGUAGES.contains(&c.tag_name().name()))
        });
        let Some(lang) = lang else {
            self.diags.push(
                Diagnostic::error(
                    BAD_PROJECT,
                    name_span,
                    format!("POU `{name}` has no body in IL, ST, FBD, LD or SFC"),
                )
                .with_label("no `<body>`"),
            );
            return;
        };
        let language = lang.tag_name().name().to_string();
        if language != "IL" {
            self.diags.push(
                Diagnostic::warning(
                    NOT_IL,
                    name_span,
                    format!(
                        "POU `{name}` is not translated: its body is {} ({language}); only IL bodies are",
                        language_name(&language)
                    ),
                )
                .with_label(format!("{language} body"))
                .with_secondary(self.tag(lang), format!("the {language} body")),
            );
            self.left_out.note(&name, self.pous.len());
            self.pous.push(PouInfo {
                name,
                kind: keyword,
                language,
                translated: false,
            });
            return;
        }
        for extra in ["actions", "transitions"] {
            if let Some(a) = kid(p, extra).filter(|a| a.children().any(|c| c.is_element())) {
                let at = self.tag(a);
                self.diags.push(
                    Diagnostic::warning(
                        NOT_TRANSLATED,
                        at,
                        format!("the {extra} of POU `{name}` are not translated"),
                    )
                    .with_label("skipped"),
                );
            }
        }
        let pou_start = self.w.mark();
        self.put(keyword, p);
        self.put(" ", p);
        self.attr(p, "name", Kind::Name);
        let iface = kid(p, "interface");
        if keyword == "FUNCTION" {
            match iface.and_then(|i| kid(i, "returnType")) {
                Some(r) => {
                    let start = self.w.mark();
                    self.put(" : ", r);
                    if !self.ty(r, 0) {
                        // Reported; no half-written type.
                        self.w.rollback(start);
                    }
                }
                None => {
                    self.diags.push(
                        Diagnostic::error(
                            BAD_PROJECT,
                            name_span,
                            format!("FUNCTION `{name}` has no `<returnType>`"),
                        )
                        .with_label("no result type"),
                    );
                }
            }
        }
        self.put("\n", p);
        if let Some(i) = iface {
            for b in i.children().filter(|c| c.is_element()) {
                self.block(b);
            }
        }
        // The body starts on a line of its own, so its lines stay whole.
        self.put("\n", lang);
        decode_content(&mut self.w, self.xml, content_range(self.xml, lang.range()));
        let end = lang.range().end;
        let end_tag = self
            .xml
            .get(..end)
            .and_then(|s| s.rfind("</"))
            .unwrap_or(lang.range().start);
        self.w.gen_at(&format!("\nEND_{keyword}\n\n"), end_tag..end);
        if !self.stays_in_its_pou(pou_start, &name, lang) {
            self.w.rollback(pou_start);
            return;
        }
        self.pous.push(PouInfo {
            name,
            kind: keyword,
            language,
            translated: true,
        });
    }

    /// Whether the POU written since `start` lexes as one POU: its body
    /// (which is copied as it is) must not end it early (`END_PROGRAM`
    /// then another POU) or swallow what follows (an unclosed `(*`). When
    /// it does, report it at the place in the body.
    fn stays_in_its_pou(&mut self, start: (usize, usize), name: &str, lang: Node) -> bool {
        let Err(at) = escape(&self.w, start.0) else {
            return true;
        };
        let at = at.unwrap_or_else(|| self.tag(lang));
        self.diags.push(
            Diagnostic::error(
                BODY_ESCAPES,
                at,
                format!(
                    "the IL body of POU `{name}` reaches outside its POU: it ends the POU early or opens a comment it does not close"
                ),
            )
            .with_label("the POU would end here")
            .with_note(format!("POU `{name}` is left out")),
        );
        false
    }
}

/// Whether the POU written into `w` since byte `start` lexes as one POU:
/// its body (copied as it is) must not end it early (`END_PROGRAM` then
/// another POU) or swallow what follows (an unclosed `(*`). `Err` holds
/// the XML span of the first token that does not belong, when there is
/// one. The LogicLab import checks its bodies with it too.
pub(crate) fn escape(w: &Writer, start: usize) -> Result<(), Option<Span>> {
    let text = &w.text[start..];
    let (toks, _) = lexer::lex(text);
    let structural = |t: &Tok| {
        matches!(
            t,
            Tok::Pou(_)
                | Tok::EndPou(_)
                | Tok::Type
                | Tok::EndType
                | Tok::Configuration
                | Tok::EndConfiguration
                | Tok::Orphan
        )
    };
    let mut it = toks.iter().filter(|(_, t, _)| structural(t));
    let first_ok = matches!(it.next(), Some((0, Tok::Pou(_), _)));
    let end = it.next();
    let extra = it.next();
    let end_is_last = matches!(end, Some((_, Tok::EndPou(_), _)))
        && toks.last().map(|(lo, _, _)| *lo) == end.map(|(lo, _, _)| *lo);
    if first_ok && end_is_last && extra.is_none() {
        return Ok(());
    }
    // The first token that does not belong.
    Err(match (end_is_last, end, extra) {
        (true, _, Some((lo, _, hi))) | (false, Some((lo, _, hi)), _) => {
            let lo = w.xml_at(start + lo);
            let hi = w.xml_at(start + hi).max(lo);
            Some(Span::new(lo, hi))
        }
        _ => None,
    })
}
