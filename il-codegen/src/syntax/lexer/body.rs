//! Body mode: the operator field, operands and punctuation of instruction
//! lines.

use super::*;

impl<'a> Lexer<'a> {
    /// A token in the operator field of a body line.
    pub(super) fn body_token(&mut self) {
        if !self.op_field {
            return self.operand_token();
        }
        let start = self.pos;
        if self.excess > 0 {
            return self.skip_excess_line();
        }
        match self.peek(0) {
            b')' => {
                self.pos += 1;
                self.op_field = false;
                if self.excess > 0 {
                    self.excess -= 1;
                    self.push(start, Tok::Error, start + 1);
                } else if self.defer_stack.pop().is_some() {
                    self.push(start, Tok::RParen, start + 1);
                } else {
                    self.diag(
                        code::PAREN,
                        start,
                        start + 1,
                        "this `)` has no matching `(`",
                        "unmatched",
                    );
                    self.push(start, Tok::Error, start + 1);
                }
            }
            b'&' => {
                self.pos += 1;
                let negate = matches!(self.peek(0), b'N' | b'n') && !is_ident(self.peek(1));
                if negate {
                    self.pos += 1;
                }
                self.op_field = false;
                self.push(
                    start,
                    Tok::Expr(ExprTok {
                        op: ExprOp::And,
                        negate,
                    }),
                    self.pos,
                );
            }
            c if is_ident_start(c) => self.op_word(),
            _ => {
                self.op_field = false;
                self.operand_token();
            }
        }
    }

    /// Inside parentheses nested too deep (already reported): skip whole
    /// lines, only counting the parentheses they open and close, so that the
    /// parser sees neither them nor a cascade of errors.
    pub(super) fn skip_excess_line(&mut self) {
        let start = self.pos;
        let end = self.src[start..]
            .find('\n')
            .map_or(self.b.len(), |i| start + i);
        let line = &self.src[start..end];
        let word_len = line
            .bytes()
            .take_while(|&c| is_ident(c) || c == b'&')
            .count();
        let word = line[..word_len].to_ascii_uppercase();
        let opens = (word.starts_with('&') || matches!(operator(&word), Some(Tok::Expr(_))))
            && line[word_len..].trim_start().starts_with('(')
            && !line[word_len..].trim_start().starts_with("(*");
        if line.starts_with(')') {
            self.excess -= 1;
        } else if opens {
            self.excess += 1;
        } else if end_pou_kind(&word).is_some() {
            // The body ends: close_deferred will report and repair.
            self.excess = 0;
            return self.op_word();
        }
        self.pos = end;
    }

    pub(super) fn op_word(&mut self) {
        let (start, end) = self.read_word();
        if self.peek(0) == b'#' {
            self.pos = start;
            self.op_field = false;
            return self.operand_token();
        }
        let word = &self.src[start..end];
        let up = word.to_ascii_uppercase();
        // A label?
        let mut j = end;
        while matches!(self.b.get(j), Some(b' ' | b'\t')) {
            j += 1;
        }
        if self.b.get(j) == Some(&b':') && self.b.get(j + 1) != Some(&b'=') {
            self.pos = j + 1;
            self.push(start, Tok::Label(word.to_string()), end);
            return;
        }
        if let Some(t) = operator(&up) {
            self.op_field = false;
            self.push(start, t, end);
            return;
        }
        if let Some(k) = end_pou_kind(&up) {
            self.close_deferred(start);
            if self.orphan {
                self.put((start, Tok::EndOrphan, start));
                self.orphan = false;
            }
            self.push(start, Tok::EndPou(k), end);
            self.mode = Mode::Top;
            return;
        }
        if let Some(k) = var_kind(&up) {
            self.push(start, Tok::Var(k), end);
            self.mode = Mode::Var;
            self.var_ret = Mode::Body;
            return;
        }
        if pou_kind(&up).is_some() || up == "TYPE" || up == "CONFIGURATION" {
            // A new item while a body is open: its END_ keyword is missing.
            self.close_deferred(start);
            if self.orphan {
                self.put((start, Tok::EndOrphan, start));
                self.orphan = false;
            }
            self.pos = start;
            self.mode = Mode::Top;
            self.line_start = true;
            return;
        }
        if ST_KEYWORDS.contains(&up.as_str())
            || self.assignment_follows(end)
            || self.st_call_follows(end)
        {
            let line_end = self.src[start..]
                .find('\n')
                .map_or(self.b.len(), |e| start + e);
            let shown = self.src[start..line_end].trim_end();
            let shown = if shown.len() > 40 {
                format!("{}...", &shown[..floor_char(shown, 37)])
            } else {
                shown.to_string()
            };
            self.diag(
                code::ST_CODE,
                start,
                line_end,
                format!("this is a Structured Text statement (`{shown}`); only Instruction List is supported"),
                "Structured Text",
            )
            .notes
            .push("the rest of this POU is skipped".into());
            self.mode = Mode::Skip;
            return;
        }
        if SFC_KEYWORDS.contains(&up.as_str()) {
            self.diag(
                code::SFC_CODE,
                start,
                end,
                "SFC (STEP/TRANSITION/ACTION) is not supported",
                "SFC element",
            )
            .notes
            .push("the rest of this POU is skipped".into());
            self.mode = Mode::Skip;
            return;
        }
        // Any other word is a function used as an operator.
        self.op_field = false;
        self.push(start, Tok::Ident(word.to_string()), end);
    }

    /// After a word at the start of a line: `:=` (possibly after `.a` / `[i]`)?
    /// `fb(10, 20);` or `F(x);`: a Structured Text call statement, which IL
    /// writes without the `;` (a `(`, then the line ends in `);`). Without
    /// this, the `;` reads as a comment and each argument as an error.
    pub(super) fn st_call_follows(&self, j: usize) -> bool {
        let rest = &self.src[j..];
        let line = &rest[..rest.find('\n').unwrap_or(rest.len())];
        // A trailing IEC comment does not count.
        let code = line.find("(*").map_or(line, |c| &line[..c]).trim_end();
        line.trim_start().starts_with('(') && code.ends_with(");")
    }

    pub(super) fn assignment_follows(&self, mut j: usize) -> bool {
        let b = self.b;
        loop {
            while matches!(b.get(j), Some(b' ' | b'\t')) {
                j += 1;
            }
            match b.get(j) {
                Some(b'.') => {
                    j += 1;
                    while b.get(j).is_some_and(|&c| is_ident(c)) {
                        j += 1;
                    }
                }
                Some(b'[') => {
                    while b.get(j).is_some_and(|&c| c != b']' && c != b'\n') {
                        j += 1;
                    }
                    j += 1;
                }
                Some(b':') => return b.get(j + 1) == Some(&b'='),
                _ => return false,
            }
        }
    }

    /// Skip a body in ST or SFC up to the END_ keyword of its POU.
    pub(super) fn skip_step(&mut self) {
        let c = self.peek(0);
        if is_ident_start(c) {
            let line_start = self.line_start;
            let (start, end) = self.read_word();
            let up = self.src[start..end].to_ascii_uppercase();
            let new_item = line_start
                && self.orphan
                && (pou_kind(&up).is_some() || up == "TYPE" || up == "CONFIGURATION");
            if end_pou_kind(&up).is_some() || new_item {
                self.pos = start;
                self.mode = Mode::Body;
                self.op_field = true;
                self.dirty = false;
            }
            self.line_start = false;
        } else if c == b'\'' || c == b'"' {
            let (end, _) = self.string_end(self.pos);
            self.pos = end.max(self.pos + 1);
        } else {
            self.pos += self.char_len();
            self.line_start = false;
        }
    }

    /// Operands, literals, punctuation (body operand field, argument lists and
    /// declarations).
    pub(super) fn operand_token(&mut self) {
        let start = self.pos;
        let c = self.peek(0);
        let body = self.mode == Mode::Body;
        match c {
            c if is_ident_start(c) => {
                let (s, e) = self.read_word();
                if self.peek(0) == b'#' {
                    return self.typed_literal(s, e);
                }
                let word = &self.src[s..e];
                let up = word.to_ascii_uppercase();
                if up == "TRUE" || up == "FALSE" {
                    let lit = Literal {
                        kind: LitKind::Bool(up == "TRUE"),
                        type_prefix: None,
                        span: span(s, e),
                    };
                    self.push(s, Tok::Lit(Box::new(lit)), e);
                } else if up == "MOD" && self.nest > 0 && self.after_subscript_operand() {
                    // `a[i MOD 4]`: MOD is a reserved word, never a name.
                    self.push(s, Tok::ModKw, e);
                } else if up == "NOT" && (self.arg_depth > 0 || !body) {
                    self.push(s, Tok::Not, e);
                } else if !body && let Some(kw) = decl_keyword(&up) {
                    self.push(s, kw, e);
                } else {
                    self.push(s, Tok::Ident(word.to_string()), e);
                }
            }
            b'0'..=b'9' => self.number(start, None),
            // Inside a subscript `+ - * /` are operators (`a[i + 1]`, `a[i-1]`);
            // a sign right after `[`, `,` or an operator belongs to a number.
            b'+' | b'-' | b'*' | b'/' if self.nest > 0 && self.subscript_operator(c) => {
                let t = match c {
                    b'+' => Tok::Plus,
                    b'-' => Tok::Minus,
                    b'/' => Tok::Slash,
                    _ => Tok::Star,
                };
                self.punct(start, 1, t);
            }
            b'-' | b'+' if self.peek(1).is_ascii_digit() => self.number(start, None),
            b'\'' | b'"' => {
                if let Some((kind, end)) = self.string(start) {
                    let lit = Literal {
                        kind,
                        type_prefix: None,
                        span: span(start, end),
                    };
                    self.push(start, Tok::Lit(Box::new(lit)), end);
                }
            }
            b'%' => self.address(start),
            b'(' => {
                self.pos += 1;
                let deferred =
                    body && self.arg_depth == 0 && matches!(self.last_tok(), Some(Tok::Expr(_)));
                if deferred {
                    if self.defer_stack.len() >= MAX_DEFER_DEPTH || self.excess > 0 {
                        if self.excess == 0 {
                            self.diag(
                                code::TOO_DEEP,
                                start,
                                start + 1,
                                format!("parentheses are nested more than {MAX_DEFER_DEPTH} deep"),
                                "too deep",
                            )
                            .help =
                                Some("store intermediate results in temporary variables".into());
                        }
                        self.excess += 1;
                        self.push(start, Tok::Error, start + 1);
                    } else {
                        self.defer_stack.push(start);
                        self.push(start, Tok::LParen, start + 1);
                    }
                } else if body {
                    self.arg_depth += 1;
                    self.push(start, Tok::LParen, start + 1);
                } else if self.nest_ok(start, start + 1) {
                    self.nest += 1;
                    self.push(start, Tok::LParen, start + 1);
                }
            }
            b')' => {
                self.pos += 1;
                if body && self.arg_depth > 0 {
                    self.arg_depth -= 1;
                } else if !body {
                    self.nest = self.nest.saturating_sub(1);
                }
                self.push(start, Tok::RParen, start + 1);
            }
            b'[' if !body => {
                if self.nest_ok(start, start + 1) {
                    self.nest += 1;
                    self.punct(start, 1, Tok::LBracket);
                }
            }
            b']' if !body => {
                self.nest = self.nest.saturating_sub(1);
                self.punct(start, 1, Tok::RBracket);
            }
            b';' if !body => {
                self.arrays = 0;
                self.punct(start, 1, Tok::Semi);
            }
            b'[' => {
                if self.nest_ok(start, start + 1) {
                    self.nest += 1;
                    self.punct(start, 1, Tok::LBracket);
                }
            }
            b']' => {
                self.nest = self.nest.saturating_sub(1);
                self.punct(start, 1, Tok::RBracket);
            }
            b',' => self.punct(start, 1, Tok::Comma),
            b';' => self.punct(start, 1, Tok::Semi),
            b':' if self.peek(1) == b'=' => self.punct(start, 2, Tok::Assign),
            b':' => self.punct(start, 1, Tok::Colon),
            b'=' if self.peek(1) == b'>' => self.punct(start, 2, Tok::Arrow),
            b'.' if self.peek(1) == b'.' => self.punct(start, 2, Tok::DotDot),
            b'.' => self.punct(start, 1, Tok::Dot),
            _ => {
                // One diagnostic for a run of stray characters.
                let n = self.char_len();
                let ch = self.src[start..start + n].to_string();
                self.pos += n;
                while self.src[self.pos..].starts_with(ch.as_str()) {
                    self.pos += n;
                }
                let shown = &self.src[start..self.pos];
                self.diag(
                    code::BAD_CHAR,
                    start,
                    self.pos,
                    format!("`{shown}` has no meaning in Instruction List"),
                    "unexpected character",
                );
                self.push(start, Tok::Error, self.pos);
            }
        }
    }

    /// Whether `c` (`+`, `-` or `*` inside brackets) is a subscript
    /// operator: `*` always, a sign only after an operand.
    fn subscript_operator(&self, c: u8) -> bool {
        c == b'*' || c == b'/' || !self.peek(1).is_ascii_digit() || self.after_subscript_operand()
    }

    /// Whether the last token ends an operand (so what follows is an operator).
    pub(super) fn after_subscript_operand(&self) -> bool {
        matches!(
            self.last_tok(),
            Some(Tok::Ident(_) | Tok::Lit(_) | Tok::Addr(_) | Tok::RBracket | Tok::RParen)
        )
    }

    pub(super) fn punct(&mut self, start: usize, n: usize, t: Tok) {
        self.pos = start + n;
        self.push(start, t, start + n);
    }
}
