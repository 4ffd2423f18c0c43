//! Declaration modes: POU headers, VAR blocks, TYPE and CONFIGURATION text.

use super::*;

impl<'a> Lexer<'a> {
    /// A token in declaration modes.
    pub(super) fn decl_token(&mut self) {
        let start = self.pos;
        let c = self.peek(0);
        if self.mode == Mode::Top {
            if is_ident_start(c) {
                let (s, e) = self.read_word();
                let up = self.src[s..e].to_ascii_uppercase();
                self.pos = start;
                if up.starts_with("END_") && (decl_keyword(&up).is_some() || up == "END_IL") {
                    self.pos = e;
                    let opener = up.trim_start_matches("END_").to_string();
                    self.diag(
                        code::MISSING_END,
                        s,
                        e,
                        format!("`{}` without a matching `{opener}`", &self.src[s..e]),
                        "nothing to close",
                    );
                    return;
                }
                if pou_kind(&up).is_none() && up != "TYPE" && up != "CONFIGURATION" {
                    return self.start_orphan();
                }
            } else {
                return self.start_orphan();
            }
        }
        if !is_ident_start(c) {
            return self.operand_token();
        }
        let (s, e) = self.read_word();
        if self.peek(0) == b'#' {
            self.pos = s;
            return self.operand_token();
        }
        let word = &self.src[s..e];
        let up = word.to_ascii_uppercase();
        if self.mode == Mode::Var && self.line_start && self.var_ret == Mode::Body {
            let line_end = self.src[s..].find('\n').map_or(self.b.len(), |x| s + x);
            let looks_like_code = (CLEAR_OPERATORS.contains(&up.as_str())
                && !self.src[e..line_end].contains(':'))
                || end_pou_kind(&up).is_some();
            if looks_like_code {
                self.missing_end_var(s);
                self.pos = s;
                self.mode = Mode::Body;
                self.op_field = true;
                self.dirty = false;
                return;
            }
        }
        let Some(kw) = decl_keyword(&up) else {
            if self.mode == Mode::Header {
                self.header_toks += 1;
            }
            if up == "MOD" && self.nest > 0 && self.after_subscript_operand() {
                // A constant subscript of a configuration path (`R.P.a[7 MOD 3]`).
                self.push(s, Tok::ModKw, e);
            } else if up == "TRUE" || up == "FALSE" {
                let lit = Literal {
                    kind: LitKind::Bool(up == "TRUE"),
                    type_prefix: None,
                    span: span(s, e),
                };
                self.push(s, Tok::Lit(Box::new(lit)), e);
            } else {
                self.push(s, Tok::Ident(word.to_string()), e);
            }
            return;
        };
        match (self.mode, &kw) {
            (Mode::Top, Tok::Pou(_)) => {
                self.mode = Mode::Header;
                self.header_toks = 0;
            }
            (Mode::Top, Tok::Type) => self.mode = Mode::Type,
            (Mode::Top, Tok::Configuration) => {
                self.mode = Mode::Config;
                self.in_resource = false;
            }
            (Mode::Header, Tok::Var(_)) => {
                self.header_incomplete(s);
                self.mode = Mode::Var;
                self.var_ret = Mode::Body;
            }
            (Mode::Header, Tok::EndPou(_)) => self.mode = Mode::Top,
            (Mode::Header, _) => self.header_toks += 1,
            (Mode::Var, Tok::EndVar) => {
                self.mode = self.var_ret;
                if self.mode == Mode::Body {
                    self.push(s, kw, e);
                    self.op_field = true;
                    self.dirty = false;
                    return;
                }
            }
            (Mode::Var, Tok::EndPou(_) | Tok::Pou(_) | Tok::Type | Tok::Configuration)
                if self.var_ret != Mode::Config =>
            {
                self.missing_end_var(s);
                self.pos = s;
                self.mode = self.var_ret;
                if self.mode == Mode::Body {
                    self.op_field = true;
                    self.dirty = false;
                }
                return;
            }
            (Mode::Type, Tok::EndType) => self.mode = Mode::Top,
            (Mode::Type, Tok::Pou(_) | Tok::Configuration) => {
                self.diag(
                    code::MISSING_END,
                    s,
                    e,
                    "missing END_TYPE before this",
                    "a new declaration starts here",
                );
                self.put((s, Tok::EndType, s));
                self.pos = s;
                self.mode = Mode::Top;
                return;
            }
            (Mode::Config, Tok::EndConfiguration | Tok::Resource) if self.in_resource => {
                self.diag(
                    code::MISSING_END,
                    s,
                    e,
                    "missing END_RESOURCE before this",
                    "the resource should end before this",
                );
                self.put((s, Tok::EndResource, s));
                self.in_resource = kw == Tok::Resource;
                if kw == Tok::EndConfiguration {
                    self.mode = Mode::Top;
                }
            }
            (Mode::Config, Tok::EndConfiguration) => self.mode = Mode::Top,
            (Mode::Config, Tok::Resource) => self.in_resource = true,
            (Mode::Config, Tok::EndResource) => self.in_resource = false,
            (Mode::Config, Tok::Var(_) | Tok::VarConfig | Tok::VarAccess) => {
                self.mode = Mode::Var;
                self.var_ret = Mode::Config;
            }
            (Mode::Config, Tok::Pou(PouKind::Function | PouKind::FunctionBlock) | Tok::Type) => {
                self.diag(
                    code::MISSING_END,
                    s,
                    e,
                    "missing END_CONFIGURATION before this",
                    "a new declaration starts here",
                );
                if self.in_resource {
                    self.put((s, Tok::EndResource, s));
                }
                self.put((s, Tok::EndConfiguration, s));
                self.pos = s;
                self.mode = Mode::Top;
                return;
            }
            _ => {}
        }
        match kw {
            Tok::Struct | Tok::Array => {
                if !self.nest_ok(s, e) {
                    return;
                }
                if kw == Tok::Struct {
                    self.nest += 1;
                } else {
                    self.arrays += 1;
                }
            }
            Tok::EndStruct => self.nest = self.nest.saturating_sub(1),
            Tok::EndVar | Tok::EndType | Tok::EndConfiguration => {
                self.nest = 0;
                self.arrays = 0;
                self.nest_reported = false;
            }
            _ => {}
        }
        self.push(s, kw, e);
    }

    /// Declarations nest at most MAX_DEFER_DEPTH deep; beyond, the token is
    /// replaced by an error token (deep trees overflow the stack when dropped).
    pub(super) fn nest_ok(&mut self, lo: usize, hi: usize) -> bool {
        if self.nest + self.arrays < MAX_DEFER_DEPTH {
            return true;
        }
        if !self.nest_reported {
            self.nest_reported = true;
            self.diag(
                code::TOO_DEEP,
                lo,
                hi,
                format!("this declaration is nested more than {MAX_DEFER_DEPTH} deep"),
                "too deep",
            );
        }
        // Skip the rest of the declaration: one error token, so that the
        // parser's recovery does not walk a deep stack once per token.
        let stop = if self.mode == Mode::Body { '\n' } else { ';' };
        let end = self.src[hi..].find(stop).map_or(self.b.len(), |i| hi + i);
        self.pos = end;
        self.nest = 0;
        self.arrays = 0;
        self.push(lo, Tok::Error, end.max(hi));
        false
    }

    /// A POU header ends (line break or VAR): synthesize a missing name or
    /// result type so that the rest of the POU still parses.
    pub(super) fn header_incomplete(&mut self, at: usize) {
        match self.out.back() {
            Some((lo, Tok::Pou(k), hi)) => {
                let (lo, hi, k) = (*lo, *hi, *k);
                self.diag(
                    code::SYNTAX,
                    lo,
                    hi,
                    format!(
                        "expected the name of the {} after `{}`",
                        k.keyword(),
                        &self.src[lo..hi]
                    ),
                    "name missing",
                );
                self.put((at, Tok::Ident(String::new()), at));
            }
            Some((_, Tok::Colon, _)) => self.put((at, Tok::Ident(String::new()), at)),
            _ => {}
        }
        self.header_toks += 1;
    }

    pub(super) fn start_orphan(&mut self) {
        let p = self.pos;
        self.put((p, Tok::Orphan, p));
        self.mode = Mode::Body;
        self.orphan = true;
        self.op_field = true;
        self.dirty = false;
    }
}
