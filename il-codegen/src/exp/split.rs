//! An EXP file cut into its objects. CODESYS 2.3 writes each object as a
//! few header comments (`(* @NESTEDCOMMENTS := 'Yes' *)`, `(* @PATH :=
//! '\/K14' *)` ...) and then its text: a POU (declarations, `(*
//! @END_DECLARATION := '0' *)`, the body, `END_FUNCTION_BLOCK`, then its
//! `ACTION`s), a `TYPE`, a global variable list (`@GLOBAL_VARIABLE_LIST`,
//! `VAR_GLOBAL` blocks, `@OBJECT_END`), the task configuration
//! (`RESOURCE ... END_RESOURCE`), or an object that is no code (a library
//! reference `LIBRARY ... END_LIBRARY`, `PLC_CONFIGURATION ... PLC_END`,
//! `_WORKSPACE`, `_ALARMCONFIG`, a visualisation ...).
//!
//! Only the first token of a line (outside comments and strings) decides
//! where objects start and end, as CODESYS writes them.

use std::ops::Range;

use super::scan::{Scanner, Tok, line_start, next_line};
use super::{Language, Object, ObjectKind, codes};
use crate::ast::{PouKind, Span};
use crate::diag::Diagnostic;

/// The headers CODESYS 2.3 and the IDEs built on it write.
const KNOWN_HEADERS: &[&str] = &[
    "NESTEDCOMMENTS",
    "PATH",
    "OBJECTFLAGS",
    "SYMFILEFLAGS",
    "END_DECLARATION",
    "GLOBAL_VARIABLE_LIST",
    "OBJECT_END",
    "CONNECTIONS",
    "LIBRARYSYMFILEINFO",
];

/// Where an object is being read.
enum State {
    Outside,
    Pou {
        obj: Object,
    },
    Action {
        obj: Object,
        name: String,
        start: usize,
        body: usize,
    },
    /// TYPE, RESOURCE, LIBRARY or another object that ends at a keyword.
    Until {
        obj: Object,
        ends: Vec<String>,
    },
    Gvl {
        obj: Object,
    },
}

/// The objects of `text`, and the errors of its structure.
pub(super) fn split(text: &str) -> (Vec<Object>, Vec<Diagnostic>) {
    let mut s = Splitter {
        text,
        objects: Vec::new(),
        diags: Vec::new(),
        headers: Headers::default(),
    };
    s.run();
    (s.objects, s.diags)
}

/// The headers read since the last object.
#[derive(Default)]
struct Headers {
    start: Option<usize>,
    nested: Option<bool>,
    path: Option<String>,
    gvl: Option<String>,
}

struct Splitter<'a> {
    text: &'a str,
    objects: Vec<Object>,
    diags: Vec<Diagnostic>,
    headers: Headers,
}

fn kw(w: &str, k: &str) -> bool {
    w.eq_ignore_ascii_case(k)
}

impl Splitter<'_> {
    fn new_object(&mut self, kind: ObjectKind, at: usize) -> Object {
        let h = std::mem::take(&mut self.headers);
        let start = h.start.unwrap_or(at).min(at);
        let name = self.name_after(at);
        Object {
            kind,
            name: h.gvl.clone().unwrap_or(name),
            path: h.path.unwrap_or_default(),
            nested: h.nested.unwrap_or(true),
            span: start..at,
            keyword: at..at,
            decl: at..at,
            body: None,
            language: Language::Il,
            end: None,
            actions: Vec::new(),
        }
    }

    /// The name after the keyword at `at` (`FUNCTION_BLOCK fb` → `fb`).
    fn name_after(&self, at: usize) -> String {
        let mut sc = Scanner::new(self.text, at..next_line(self.text, at), false);
        sc.next();
        match sc.next() {
            Some((Tok::Word, r)) => self.text[r].to_string(),
            _ => String::new(),
        }
    }

    fn err(&mut self, code: &'static str, span: Range<usize>, msg: String, label: &str) {
        self.diags
            .push(Diagnostic::error(code, Span::new(span.start, span.end), msg).with_label(label));
    }

    fn run(&mut self) {
        let text = self.text;
        let mut state = State::Outside;
        let mut sc = Scanner::new(text, 0..text.len(), true);
        // The end of the token before: a token is first on its line when a
        // line break lies between (see `scan::line_firsts`).
        let mut prev_end = 0usize;
        while let Some((tok, r)) = sc.next() {
            let first = if prev_end == 0 {
                text[..r.start].trim().is_empty() || text[..r.start].contains('\n')
            } else {
                text[prev_end.min(r.start)..r.start].contains('\n')
            };
            prev_end = r.end;
            if !first {
                continue;
            }
            let word = &text[r.clone()];
            // A header comment: `(* @KEY := 'value' *)`.
            // (Inside an object that is no code, such as the alarm
            // configuration, `(* @...` lines are its own settings.)
            let skipping = matches!(
                &state,
                State::Until { obj, .. } if matches!(obj.kind, ObjectKind::Skipped(_))
            );
            if let Tok::Comment { .. } = tok
                && !skipping
                && let Some(h) = header(word)
            {
                state = self.on_header(state, h, r.clone(), &mut sc);
                continue;
            }
            if !matches!(tok, Tok::Word) {
                if let (State::Outside, Tok::Literal | Tok::Str | Tok::Punct) = (&state, tok) {
                    self.stray(r.clone());
                    sc.pos = next_line(text, r.end);
                }
                continue;
            }
            state = self.on_word(state, word, r.clone(), &mut sc);
        }
        let end = text.len();
        self.close(state, end, true);
    }

    /// Text between objects that starts no object: an error, the line skipped.
    fn stray(&mut self, r: Range<usize>) {
        let line_end = self.text[r.start..]
            .find(['\r', '\n'])
            .map_or(self.text.len(), |k| r.start + k);
        let shown: String = self.text[r.start..line_end].chars().take(40).collect();
        self.err(
            codes::UNKNOWN_OBJECT,
            r.start..line_end,
            format!("`{shown}` starts no object of a CODESYS export"),
            "not a POU, TYPE, global variable list, task configuration or other object",
        );
    }

    fn on_header(
        &mut self,
        state: State,
        (key, value): (&str, &str),
        r: Range<usize>,
        sc: &mut Scanner,
    ) -> State {
        if !KNOWN_HEADERS.iter().any(|k| kw(k, key)) {
            self.err(
                codes::UNKNOWN_HEADER,
                r.clone(),
                format!("unknown header `@{key}` in a CODESYS export"),
                "unknown header",
            );
            return state;
        }
        let key = key.to_ascii_uppercase();
        match (key.as_str(), state) {
            ("END_DECLARATION", State::Pou { mut obj }) if obj.body.is_none() => {
                let body = next_line(self.text, r.end);
                obj.decl.end = line_start(self.text, r.start);
                obj.body = Some(body..body);
                State::Pou { obj }
            }
            (
                "END_DECLARATION",
                State::Action {
                    obj, name, start, ..
                },
            ) => State::Action {
                obj,
                name,
                start,
                body: next_line(self.text, r.end),
            },
            ("OBJECT_END", State::Gvl { mut obj }) => {
                obj.span.end = next_line(self.text, r.end);
                self.objects.push(obj);
                State::Outside
            }
            ("END_DECLARATION" | "CONNECTIONS" | "OBJECT_END", state) => state,
            (_, state @ (State::Outside | State::Gvl { .. })) => {
                // A header of the next object: a global list ends here.
                let state = self.close(state, line_start(self.text, r.start), false);
                let h = &mut self.headers;
                h.start.get_or_insert(line_start(self.text, r.start));
                match key.as_str() {
                    "NESTEDCOMMENTS" => {
                        let nested = !kw(value, "No");
                        h.nested = Some(nested);
                        sc.nested = nested;
                    }
                    "PATH" => h.path = Some(value.to_string()),
                    "GLOBAL_VARIABLE_LIST" => h.gvl = Some(value.to_string()),
                    _ => {}
                }
                state
            }
            (_, state) => state,
        }
    }

    fn on_word(&mut self, state: State, word: &str, r: Range<usize>, sc: &mut Scanner) -> State {
        let text = self.text;
        match state {
            State::Outside => self.start(word, r, sc),
            State::Pou { mut obj } => {
                let ObjectKind::Pou(kind) = obj.kind else {
                    return State::Pou { obj };
                };
                if let Some(other) = end_keyword(word) {
                    let mismatched = other != kind;
                    if mismatched {
                        self.err(
                            codes::MISMATCHED_END,
                            r.clone(),
                            format!(
                                "`{word}` ends {} `{}`, which is a {}",
                                kind.keyword(),
                                obj.name,
                                kind.keyword()
                            ),
                            &format!("expected `END_{}`", kind.keyword()),
                        );
                    }
                    // A POU ended by another END_ is left out of the IL
                    // text (its error is said here): the others are checked.
                    obj.end = (!mismatched).then(|| r.clone());
                    obj.span.end = next_line(text, r.end);
                    match &mut obj.body {
                        Some(b) => b.end = line_start(text, r.start).max(b.start),
                        None => obj.decl.end = line_start(text, r.start),
                    }
                    self.objects.push(obj);
                    return State::Outside;
                }
                // (An SFC body holds its step actions, `ACTION a: ...
                // END_ACTION`, before the END_: no new object there.)
                if starts_object(word) && !kw(word, "ACTION") {
                    // The next object begins before this one ended.
                    self.truncated(&obj, r.start);
                    return self.start(word, r, sc);
                }
                State::Pou { obj }
            }
            State::Action {
                mut obj,
                name,
                start,
                body,
            } => {
                if kw(word, "END_ACTION") {
                    obj.actions.push(super::Action {
                        name,
                        keyword: start..start + "ACTION".len(),
                        body: body..line_start(text, r.start),
                        end: r.clone(),
                        language: Language::Il,
                    });
                    obj.span.end = next_line(text, r.end);
                    self.objects.push(obj);
                    return State::Outside;
                }
                if starts_object(word) {
                    self.err(
                        codes::TRUNCATED,
                        start..start + "ACTION".len(),
                        format!("ACTION `{name}` of `{}` has no `END_ACTION`", obj.name),
                        "this ACTION is not ended",
                    );
                    self.objects.push(obj);
                    return self.start(word, r, sc);
                }
                State::Action {
                    obj,
                    name,
                    start,
                    body,
                }
            }
            State::Until { mut obj, ends } => {
                if ends.iter().any(|e| kw(e, word)) {
                    obj.end = Some(r.clone());
                    obj.span.end = next_line(text, r.end);
                    obj.decl.end = obj.span.end;
                    self.objects.push(obj);
                    return State::Outside;
                }
                // Code objects cannot hold another; skipped ones (a PLC
                // configuration's `_MODULE` lines) hold no such keyword.
                if starts_object(word) {
                    self.truncated(&obj, r.start);
                    return self.start(word, r, sc);
                }
                State::Until { obj, ends }
            }
            State::Gvl { mut obj } => {
                if starts_object(word) && !is_var_block(word) {
                    obj.span.end = line_start(text, r.start);
                    self.objects.push(obj);
                    return self.start(word, r, sc);
                }
                obj.decl.end = next_line(text, r.end);
                obj.span.end = obj.decl.end;
                State::Gvl { obj }
            }
        }
    }

    /// An object that the next one interrupts.
    fn truncated(&mut self, obj: &Object, at: usize) {
        let what = obj.kind.describe();
        let end = match &obj.kind {
            ObjectKind::Pou(k) => format!("END_{}", k.keyword()),
            _ => "its end".to_string(),
        };
        let mut d = Diagnostic::error(
            codes::TRUNCATED,
            Span::new(obj.keyword.start, obj.keyword.end),
            format!("{what} `{}` ends before {end}", obj.name),
        )
        .with_label("this object is cut short");
        if at < self.text.len() {
            d = d.with_secondary(Span::new(at, at), "the next object starts here");
        }
        self.diags.push(d);
    }

    /// At the end of the file (`eof`) or of a global list.
    fn close(&mut self, state: State, at: usize, eof: bool) -> State {
        match state {
            State::Outside => {}
            State::Gvl { obj } => self.objects.push(obj),
            State::Pou { obj } | State::Until { obj, .. } if eof => {
                self.truncated(&obj, at);
            }
            State::Action {
                obj, name, start, ..
            } if eof => {
                self.err(
                    codes::TRUNCATED,
                    start..start + "ACTION".len(),
                    format!("ACTION `{name}` of `{}` has no `END_ACTION`", obj.name),
                    "this ACTION is not ended",
                );
                self.objects.push(obj);
            }
            other => return other,
        }
        State::Outside
    }

    /// The object that `word` (first on its line, between objects) starts.
    fn start(&mut self, word: &str, r: Range<usize>, sc: &mut Scanner) -> State {
        let text = self.text;
        let up = word.to_ascii_uppercase();
        let pou = match up.as_str() {
            "PROGRAM" => Some(PouKind::Program),
            "FUNCTION" => Some(PouKind::Function),
            "FUNCTION_BLOCK" => Some(PouKind::FunctionBlock),
            _ => None,
        };
        if let Some(kind) = pou {
            let mut obj = self.new_object(ObjectKind::Pou(kind), r.start);
            obj.keyword = r.clone();
            obj.decl = r.start..r.start;
            return State::Pou { obj };
        }
        if up == "ACTION" {
            let name = self.name_after(r.start);
            // An ACTION follows the POU it belongs to (after its END_).
            if let Some(obj) = self
                .objects
                .pop_if(|o| matches!(o.kind, ObjectKind::Pou(_)) && o.end.is_some())
            {
                return State::Action {
                    obj,
                    name,
                    start: r.start,
                    body: next_line(text, r.end),
                };
            }
            self.err(
                codes::UNKNOWN_OBJECT,
                r.clone(),
                format!("ACTION `{name}` follows no POU"),
                "an ACTION comes right after the POU it belongs to",
            );
            let mut obj = self.new_object(ObjectKind::Skipped("an action without POU"), r.start);
            obj.keyword = r.clone();
            return State::Until {
                obj,
                ends: vec!["END_ACTION".into()],
            };
        }
        let (kind, ends): (ObjectKind, &[&str]) = match up.as_str() {
            "TYPE" => (ObjectKind::Types, &["END_TYPE"]),
            "RESOURCE" => (ObjectKind::Tasks, &["END_RESOURCE"]),
            "LIBRARY" => (ObjectKind::Skipped("a library reference"), &["END_LIBRARY"]),
            "PLC_CONFIGURATION" => (
                ObjectKind::Skipped("the PLC configuration"),
                &["PLC_END", "_END_PLC_CONFIGURATION"],
            ),
            w if is_var_block(w) => {
                let mut obj = self.new_object(ObjectKind::Globals, r.start);
                obj.keyword = r.clone();
                obj.decl = r.start..next_line(text, r.end);
                return State::Gvl { obj };
            }
            w if w.starts_with('_') || w.starts_with("VISUALI") || w.starts_with("TARGET") => {
                let base = w.trim_start_matches('_').to_string();
                let mut obj = self.new_object(ObjectKind::Skipped(skipped_name(&base)), r.start);
                obj.keyword = r.clone();
                // `VISUALISATION PLC_VISU ...` has a name; `_WORKSPACE` none.
                if obj.name.is_empty() {
                    obj.name = base.clone();
                }
                return State::Until {
                    obj,
                    ends: vec![format!("_END_{base}"), format!("END_{base}")],
                };
            }
            _ => {
                self.stray(r.clone());
                sc.pos = next_line(text, r.end);
                return State::Outside;
            }
        };
        let mut obj = self.new_object(kind, r.start);
        obj.keyword = r.clone();
        if obj.kind == ObjectKind::Skipped("a library reference") {
            // `LIBRARY` is followed by the library's file name on its line.
            let line = next_line(text, r.end);
            let nl = next_line(text, line);
            obj.name = text[line..nl].trim().to_string();
        } else if matches!(obj.kind, ObjectKind::Tasks) {
            obj.name = "Task configuration".to_string();
        } else if obj.name.is_empty() {
            obj.name = up.clone();
        }
        obj.decl = r.start..r.start;
        State::Until {
            obj,
            ends: ends.iter().map(|e| e.to_string()).collect(),
        }
    }
}

fn skipped_name(base: &str) -> &'static str {
    match base {
        b if b.starts_with("VISUAL") => "a visualisation",
        b if b.starts_with("ALARM") => "the alarm configuration",
        b if b.starts_with("WORKSPACE") => "the workspace settings",
        b if b.starts_with("TARGET") => "the target settings",
        b if b.starts_with("TRACE") => "the trace configuration",
        b if b.starts_with("PARAM") => "the parameter manager",
        _ => "an object that is no code",
    }
}

/// `(* @KEY := 'value' *)` → (KEY, value); `None` for any other comment.
fn header(comment: &str) -> Option<(&str, &str)> {
    let inner = comment.strip_prefix("(*")?.trim_start();
    let rest = inner.strip_prefix('@')?;
    let key_len = rest
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    let (key, rest) = rest.split_at(key_len);
    if key.is_empty() {
        return None;
    }
    let rest = rest
        .trim_start()
        .strip_prefix(":=")
        .unwrap_or(rest)
        .trim_start();
    let value = match rest.strip_prefix('\'') {
        Some(v) => &v[..v.find('\'').unwrap_or(0)],
        None => "",
    };
    Some((key, value))
}

/// The POU an `END_...` keyword ends.
fn end_keyword(word: &str) -> Option<PouKind> {
    match word.to_ascii_uppercase().as_str() {
        "END_PROGRAM" => Some(PouKind::Program),
        "END_FUNCTION" => Some(PouKind::Function),
        "END_FUNCTION_BLOCK" => Some(PouKind::FunctionBlock),
        _ => None,
    }
}

/// A keyword that starts a code object (no POU body line starts with one).
fn starts_object(word: &str) -> bool {
    [
        "PROGRAM",
        "FUNCTION",
        "FUNCTION_BLOCK",
        "TYPE",
        "RESOURCE",
        "LIBRARY",
        "ACTION",
    ]
    .iter()
    .any(|k| kw(k, word))
}

fn is_var_block(word: &str) -> bool {
    ["VAR_GLOBAL", "VAR_CONFIG"].iter().any(|k| kw(k, word))
}
