//! Literals and direct addresses: numbers, strings, typed literals
//! (`T#5s`, `INT#3`) and `%IX0.1`.

use super::*;

impl<'a> Lexer<'a> {
    /// A number at `start` (optionally signed): integer, based integer or real.
    /// `prefix`: the type prefix of a typed literal (its span starts earlier).
    pub(super) fn number(&mut self, start: usize, prefix: Option<(Ident, usize)>) {
        let b = self.b;
        let mut i = start;
        if matches!(b.get(i), Some(b'-' | b'+')) {
            i += 1;
        }
        while b.get(i).is_some_and(|c| c.is_ascii_digit() || *c == b'_') {
            i += 1;
        }
        let mut real = false;
        let mut no_dot_exp = false;
        if b.get(i) == Some(&b'#') {
            i += 1;
            while b.get(i).is_some_and(|&c| is_ident(c)) {
                i += 1;
            }
        } else {
            if b.get(i) == Some(&b'.') && b.get(i + 1).is_some_and(u8::is_ascii_digit) {
                real = true;
                i += 1;
                while b.get(i).is_some_and(|c| c.is_ascii_digit() || *c == b'_') {
                    i += 1;
                }
            }
            if matches!(b.get(i), Some(b'e' | b'E')) {
                let mut j = i + 1;
                if matches!(b.get(j), Some(b'+' | b'-')) {
                    j += 1;
                }
                if b.get(j).is_some_and(u8::is_ascii_digit) {
                    while b.get(j).is_some_and(u8::is_ascii_digit) {
                        j += 1;
                    }
                    no_dot_exp = !real;
                    real = true;
                    i = j;
                }
            }
        }
        // Letters glued to a number (`25x`) make it malformed.
        let mut bad = false;
        while b.get(i).is_some_and(|&c| is_ident(c)) {
            i += 1;
            bad = true;
        }
        self.pos = i;
        let text = &self.src[start..i];
        let lo = prefix.as_ref().map_or(start, |p| p.1);
        let kind = if bad {
            // `5s`, `100ms`: a duration without its `T#`.
            let duration = prefix.is_none()
                && !text.starts_with(['-', '+'])
                && literal::parse_duration(text).is_ok();
            let d = self.diag(
                code::BAD_NUMBER,
                start,
                i,
                format!("`{text}` is not a number"),
                "malformed number",
            );
            if duration {
                d.help = Some(format!("a duration is written `T#{text}`"));
                d.fixes.push(crate::diag::Fix {
                    title: format!("Write `T#{text}`"),
                    edits: vec![(span(start, start), "T#".into())],
                });
            }
            LitKind::Int(IntValue::new(0))
        } else if real {
            if no_dot_exp {
                let (mant, exp) = text.split_at(text.find(['e', 'E']).unwrap_or(text.len()));
                self.diag(
                    code::BAD_NUMBER,
                    start,
                    i,
                    format!("`{text}` is not an IEC real literal: a REAL needs a decimal point"),
                    "exponent without `.`",
                )
                .help = Some(format!("write {mant}.0{exp}"));
            }
            match literal::parse_real(text) {
                Ok(value) => LitKind::Real {
                    value,
                    text: text.into(),
                },
                Err(e) => {
                    let m = literal_message(e, text);
                    self.diag(code::BAD_NUMBER, start, i, m, "malformed number");
                    LitKind::Int(IntValue::new(0))
                }
            }
        } else {
            match literal::parse_int(text) {
                Ok(v) => LitKind::Int(v.into()),
                Err(e) => {
                    let m = literal_message(e, text);
                    self.diag(code::BAD_NUMBER, start, i, m, "malformed number");
                    LitKind::Int(IntValue::new(0))
                }
            }
        };
        let (kind, type_prefix) = match prefix {
            Some((p, _)) if p.is("BOOL") => match kind {
                LitKind::Int(n) if n.get() == 0 => (LitKind::Bool(false), Some(p)),
                LitKind::Int(n) if n.get() == 1 => (LitKind::Bool(true), Some(p)),
                k => {
                    self.diag(
                        code::BAD_NUMBER,
                        lo,
                        i,
                        "a BOOL literal is 0, 1, TRUE or FALSE",
                        "not a BOOL",
                    );
                    (k, Some(p))
                }
            },
            Some((p, _)) => (kind, Some(p)),
            None => (kind, None),
        };
        let lit = Literal {
            kind,
            type_prefix: type_prefix.map(Box::new),
            span: span(lo, i),
        };
        self.push(lo, Tok::Lit(Box::new(lit)), i);
    }

    /// End (exclusive) of the string literal starting with a quote at
    /// `start`, and whether it is closed on its line.
    pub(super) fn string_end(&self, start: usize) -> (usize, bool) {
        let q = self.b[start];
        let mut i = start + 1;
        while i < self.b.len() {
            match self.b[i] {
                b'$' if self.b.get(i + 1).is_some_and(|&c| c != b'\n') => i += 2,
                b'\n' => return (i, false),
                c if c == q => return (i + 1, true),
                _ => i += 1,
            }
        }
        (self.b.len(), false)
    }

    pub(super) fn string(&mut self, start: usize) -> Option<(LitKind, usize)> {
        let q = self.b[start];
        let wide = q == b'"';
        let (end, closed) = self.string_end(start);
        self.pos = end;
        if !closed {
            self.diag(
                code::BAD_STRING,
                start,
                end,
                "this string is not closed on its line",
                "unterminated string",
            )
            .help = Some(format!("end it with {}", q as char));
            self.push(start, Tok::Error, end);
            return None;
        }
        let body = &self.src[start + 1..end - 1];
        // `$hh`/`$hhhh` codes become the character of that code point
        // (U+FFFD for a lone surrogate), as the emitter expects.
        let mut value = String::with_capacity(body.len());
        let r = literal::unescape_string(body, wide, &mut |p| match p {
            literal::StrPiece::Char(c) => value.push(c),
            literal::StrPiece::Code(v) => {
                value.push(char::from_u32(u32::from(v)).unwrap_or('\u{FFFD}'));
            }
        });
        match r {
            Ok(()) => Some((
                LitKind::String {
                    value: value.into(),
                    wide,
                },
                end,
            )),
            Err(e) => {
                let m = literal_message(e, body);
                self.diag(code::BAD_STRING, start, end, m, "in this string");
                Some((
                    LitKind::String {
                        value: body.into(),
                        wide,
                    },
                    end,
                ))
            }
        }
    }

    /// `PREFIX#value` with the prefix word at `s..e` and `#` at `e`.
    pub(super) fn typed_literal(&mut self, s: usize, e: usize) {
        let word = &self.src[s..e];
        let up = word.to_ascii_uppercase();
        let vstart = e + 1;
        self.pos = vstart;
        let take = |this: &mut Self, ok: &dyn Fn(u8) -> bool| {
            let mut i = this.pos;
            while this.b.get(i).is_some_and(|&c| ok(c)) {
                i += 1;
            }
            this.pos = i;
            &this.src[vstart..i]
        };
        let done =
            |this: &mut Self, r: Result<LitKind, String>, code_: &'static str, what: &str| {
                let hi = this.pos;
                let kind = match r {
                    Ok(k) => k,
                    Err(m) => {
                        this.diag(code_, s, hi, m, what);
                        LitKind::Int(IntValue::new(0))
                    }
                };
                let lit = Literal {
                    kind,
                    type_prefix: None,
                    span: span(s, hi),
                };
                this.push(s, Tok::Lit(Box::new(lit)), hi);
            };
        match up.as_str() {
            "T" | "TIME" | "LT" | "LTIME" => {
                let long = up.starts_with('L');
                let text = take(self, &|c| {
                    is_ident(c) || c == b'.' || c == b'-' || c == b'+'
                });
                let r = literal::parse_duration(text)
                    .map(|nanos| LitKind::Time { nanos, long })
                    .map_err(|e| literal_message(e, text));
                done(self, r, code::BAD_DURATION, "invalid duration");
            }
            "D" | "DATE" | "LDATE" => {
                let text = take(self, &|c| {
                    c.is_ascii_alphanumeric() || c == b'-' || c == b'_'
                });
                let r = literal::parse_date(text)
                    .map(|d| LitKind::Date(d.0))
                    .map_err(|e| literal_message(e, text));
                done(self, r, code::BAD_DATE, "invalid date");
            }
            "TOD" | "TIME_OF_DAY" | "LTOD" | "LTIME_OF_DAY" => {
                let text = take(self, &|c| {
                    c.is_ascii_alphanumeric() || c == b':' || c == b'.'
                });
                let r = literal::parse_tod(text)
                    .map(|t| LitKind::Tod(t.0))
                    .map_err(|e| literal_message(e, text));
                done(self, r, code::BAD_DATE, "invalid time of day");
            }
            "DT" | "DATE_AND_TIME" | "LDT" | "LDATE_AND_TIME" => {
                let text = take(self, &|c| {
                    c.is_ascii_alphanumeric() || c == b':' || c == b'.' || c == b'-'
                });
                let r = literal::parse_dt(text)
                    .map(|t| LitKind::Dt(t.0))
                    .map_err(|e| literal_message(e, text));
                done(self, r, code::BAD_DATE, "invalid date and time");
            }
            _ => {
                let prefix = Ident::new(word, span(s, e));
                let c = self.peek(0);
                let elementary = ELEMENTARY.contains(&up.as_str());
                if matches!(up.as_str(), "STRING" | "WSTRING" | "CHAR" | "WCHAR")
                    && (c == b'\'' || c == b'"')
                {
                    if let Some((kind, end)) = self.string(vstart) {
                        let lit = Literal {
                            kind,
                            type_prefix: Some(Box::new(prefix)),
                            span: span(s, end),
                        };
                        self.push(s, Tok::Lit(Box::new(lit)), end);
                    }
                } else if c.is_ascii_digit()
                    || (matches!(c, b'-' | b'+') && self.peek(1).is_ascii_digit())
                {
                    if !elementary {
                        // `Color#1`? Not IEC, but give it to the checker as a typed number.
                        self.diag(code::BAD_NUMBER, s, e, format!("`{word}` is not an elementary type: only numeric, bit-string and BOOL types prefix a number"), "not a type for numbers");
                    }
                    self.number(vstart, Some((prefix, s)));
                } else if is_ident_start(c) {
                    let (vs, ve) = self.read_word();
                    let v = &self.src[vs..ve];
                    let vup = v.to_ascii_uppercase();
                    let kind = if elementary && (vup == "TRUE" || vup == "FALSE") {
                        if up != "BOOL" {
                            self.diag(
                                code::BAD_NUMBER,
                                s,
                                ve,
                                format!("`{word}#{v}`: TRUE and FALSE are BOOL values"),
                                "not a BOOL type",
                            );
                        }
                        LitKind::Bool(vup == "TRUE")
                    } else {
                        LitKind::Enum(Box::new(EnumLit {
                            ty: prefix.clone(),
                            value: Ident::new(v, span(vs, ve)),
                        }))
                    };
                    let type_prefix = if matches!(kind, LitKind::Enum(_)) {
                        None
                    } else {
                        Some(Box::new(prefix))
                    };
                    let lit = Literal {
                        kind,
                        type_prefix,
                        span: span(s, ve),
                    };
                    self.push(s, Tok::Lit(Box::new(lit)), ve);
                } else {
                    self.diag(
                        code::BAD_NUMBER,
                        s,
                        vstart,
                        format!("expected a value after `{word}#`"),
                        "value missing",
                    );
                    self.push(s, Tok::Error, vstart);
                }
            }
        }
    }

    /// `%IX1.0`, `%QW3`, `%MD10`, `%I*`.
    pub(super) fn address(&mut self, start: usize) {
        let b = self.b;
        let mut i = start + 1;
        if start > 0 && b[start - 1] == b'.' && matches!(self.last_tok(), Some(Tok::Dot)) {
            // `v.%X3`, `v.%B1`, `v.%W0`, `v.%D1`: a part of `v` (3rd edition).
            let size = match b.get(i).map(u8::to_ascii_uppercase) {
                Some(b'X') => Some(AddrSize::X),
                Some(b'B') => Some(AddrSize::B),
                Some(b'W') => Some(AddrSize::W),
                Some(b'D') => Some(AddrSize::D),
                _ => None,
            };
            let digits = b[(i + 1).min(b.len())..]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count();
            if let Some(size) = size
                && digits > 0
                && !b.get(i + 1 + digits).is_some_and(|&c| is_ident(c))
            {
                let end = i + 1 + digits;
                // 64 bits at most: anything longer is out of range anyway.
                let n = self.src[i + 1..end].parse::<u32>().unwrap_or(u32::MAX);
                self.pos = end;
                self.push(start, Tok::Part(size, n), end);
                return;
            }
        }
        let area = match b.get(i).map(u8::to_ascii_uppercase) {
            Some(b'I') => Some(Area::Input),
            Some(b'Q') => Some(Area::Output),
            Some(b'M') => Some(Area::Memory),
            _ => None,
        };
        let end_of = |mut j: usize| {
            while b
                .get(j)
                .is_some_and(|&c| is_ident(c) || c == b'.' || c == b'*')
            {
                j += 1;
            }
            j
        };
        let Some(area) = area else {
            let end = end_of(i);
            self.pos = end.max(start + 1);
            self.diag(
                code::BAD_ADDRESS,
                start,
                self.pos,
                format!(
                    "`{}` is not a direct address: the area must be I, Q or M",
                    &self.src[start..self.pos]
                ),
                "invalid address",
            );
            self.push(start, Tok::Error, self.pos);
            return;
        };
        i += 1;
        let mut size = AddrSize::Default;
        let mut error: Option<(String, Option<String>)> = None;
        match b.get(i).map(u8::to_ascii_uppercase) {
            Some(b'X') => size = AddrSize::X,
            Some(b'B') => size = AddrSize::B,
            Some(b'W') => size = AddrSize::W,
            Some(b'D') => size = AddrSize::D,
            Some(b'L') => size = AddrSize::L,
            Some(b'F') => {
                size = AddrSize::D;
                error = Some((
                    "`F` is not an IEC address size: %IF/%QF/%MF float addresses are a vendor extension".into(),
                    Some("use a double word (`%MD0`) and declare the variable as REAL".into()),
                ));
            }
            _ => i -= 1,
        }
        i += 1;
        let mut path = Vec::new();
        let mut partial = false;
        if b.get(i) == Some(&b'*') {
            partial = true;
            i += 1;
        } else {
            loop {
                let ds = i;
                while b.get(i).is_some_and(u8::is_ascii_digit) {
                    i += 1;
                }
                if ds == i {
                    error.get_or_insert((
                        "expected a number in this direct address, e.g. `%IX0.1`".into(),
                        None,
                    ));
                    break;
                }
                match self.src[ds..i].parse::<u32>() {
                    Ok(n) => path.push(n),
                    Err(_) => {
                        error.get_or_insert(("this address number is too large".into(), None));
                    }
                }
                if b.get(i) == Some(&b'.') && b.get(i + 1).is_some_and(u8::is_ascii_digit) {
                    i += 1;
                } else {
                    break;
                }
            }
        }
        if b.get(i).is_some_and(|&c| is_ident(c)) {
            i = end_of(i);
            error.get_or_insert((
                format!("`{}` is not a valid direct address", &self.src[start..i]),
                None,
            ));
        }
        self.pos = i;
        if partial && self.mode == Mode::Body {
            error.get_or_insert((
                "a partly specified address (`%I*`) may only appear in a declaration".into(),
                Some("give the full address, e.g. `%IX0.0`, or use the declared variable".into()),
            ));
        }
        if let Some((m, help)) = error {
            let d = self.diag(code::BAD_ADDRESS, start, i, m, "invalid address");
            d.help = help;
        }
        let addr = DirectAddress {
            area,
            size,
            path,
            partial,
            span: span(start, i),
        };
        self.push(start, Tok::Addr(Box::new(addr)), i);
    }
}
