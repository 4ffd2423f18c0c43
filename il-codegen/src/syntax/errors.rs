//! Syntax error messages in a PLC engineer's words, and the index of the
//! front end's diagnostic codes.

use lalrpop_util::ParseError;

use super::lexer::{LexError, Spanned, Tok};
use crate::ast::Span;
use crate::diag::{Diagnostic, SourceFile};

use super::code;

/// Human name of an expected terminal (lalrpop's name for it).
fn friendly(t: &str) -> Option<String> {
    let t = t.trim_matches('"');
    Some(match t {
        "Nl" => "end of line".into(),
        "IdentTok" => "a name".into(),
        "LabelTok" => "a label".into(),
        "Lit" => "a literal".into(),
        "Addr" => "a direct address".into(),
        "Ld" => "LD".into(),
        "St" => "ST".into(),
        "ExprOpTok" => "an operator".into(),
        "Jmp" => "JMP".into(),
        "Cal" => "CAL".into(),
        "Ret" => "RET".into(),
        "FbIn" => "an FB input operator".into(),
        "VarKw" => "VAR".into(),
        "PouKw" => "PROGRAM".into(),
        "EndPou" => "an END_ keyword".into(),
        "Orphan" | "EndOrphan" | "MissingEndVar" | "ErrorTok" => return None,
        other => format!("`{other}`"),
    })
}

fn expected_list(expected: &[String]) -> String {
    let mut v: Vec<String> = expected.iter().filter_map(|e| friendly(e)).collect();
    v.dedup();
    if v.len() > 5 {
        v.truncate(5);
        v.push("...".into());
    }
    v.join(", ")
}

fn has(expected: &[String], t: &str) -> bool {
    expected.iter().any(|e| e.trim_matches('"') == t)
}

fn operand_start(t: &Tok) -> bool {
    matches!(t, Tok::Ident(_) | Tok::Lit(_) | Tok::Addr(_))
}

/// Index of the first token (labels excluded) of the line that holds `toks[idx]`.
fn line_first(file: &SourceFile, toks: &[Spanned], idx: usize) -> usize {
    let mut i = idx;
    while i > 0 {
        let (_, t, h) = &toks[i - 1];
        if matches!(t, Tok::Nl | Tok::Label(_)) {
            break;
        }
        let cur = toks[i].0;
        if file.text.get(*h..cur).is_none_or(|gap| gap.contains('\n')) {
            break;
        }
        i -= 1;
    }
    i
}

/// Map one lalrpop error to a diagnostic (None when the lexer already
/// reported the cause).
pub fn parse_error(
    file: &SourceFile,
    toks: &[Spanned],
    err: &ParseError<usize, Tok, LexError>,
) -> Option<Diagnostic> {
    let snippet = |lo: usize, hi: usize| file.snippet(Span::new(lo, hi)).to_string();
    match err {
        ParseError::User { error } => match *error {},
        ParseError::InvalidToken { location } => Some(Diagnostic::error(
            code::BAD_CHAR,
            Span::new(*location, *location + 1),
            "this text has no meaning in Instruction List",
        )),
        ParseError::ExtraToken { token: (lo, _, hi) } => Some(
            Diagnostic::error(
                code::SYNTAX,
                Span::new(*lo, *hi),
                format!("unexpected `{}`", snippet(*lo, *hi)),
            )
            .with_label("not expected here"),
        ),
        ParseError::UnrecognizedEof { location, expected } => {
            let at = Span::new(*location, *location);
            for (kw, what) in [
                ("END_VAR", "missing END_VAR"),
                ("END_STRUCT", "missing END_STRUCT"),
                ("END_TYPE", "missing END_TYPE"),
                ("END_RESOURCE", "missing END_RESOURCE"),
                ("END_CONFIGURATION", "missing END_CONFIGURATION"),
            ] {
                if has(expected, kw) {
                    return Some(
                        Diagnostic::error(code::MISSING_END, at, what)
                            .with_label("the file ends here"),
                    );
                }
            }
            if has(expected, ")") {
                return Some(
                    Diagnostic::error(code::PAREN, at, "missing `)`")
                        .with_label("the file ends here"),
                );
            }
            Some(
                Diagnostic::error(
                    code::UNEXPECTED_EOF,
                    at,
                    "the file ends in the middle of a declaration",
                )
                .with_label(format!("expected {}", expected_list(expected))),
            )
        }
        ParseError::UnrecognizedToken {
            token: (lo, tok, hi),
            expected,
        } => {
            // Error tokens and zero-width repairs were reported by the lexer.
            if *tok == Tok::Error || (*lo == *hi && *tok != Tok::Nl) {
                return None;
            }
            let (lo, hi) = (*lo, *hi);
            let idx = toks.partition_point(|(l, _, _)| *l < lo);
            // The token of the error is at or after idx; the one before is the previous token.
            let idx = (idx..toks.len())
                .find(|&i| toks[i].0 == lo && toks[i].1 == *tok)
                .unwrap_or(idx);
            let prev = idx.checked_sub(1).map(|i| &toks[i]);
            let span = Span::new(lo, hi);
            let found = if *tok == Tok::Nl {
                "the end of the line".to_string()
            } else {
                format!("`{}`", snippet(lo, hi))
            };
            if *tok != Tok::Nl && has(expected, "Ld") && line_first(file, toks, idx) == idx {
                return Some(
                    Diagnostic::error(
                        code::EXPECTED_INSTRUCTION,
                        span,
                        format!("expected an instruction, found {found}"),
                    )
                    .with_label("not an IL operator"),
                );
            }
            if let Some((plo, ptok, phi)) = prev {
                let op = snippet(*plo, *phi);
                let pspan = Span::new(*plo, *phi);
                let at_op = line_first(file, toks, idx - 1) == idx - 1;
                match ptok {
                    Tok::Ld(_)
                    | Tok::St(_)
                    | Tok::Set
                    | Tok::Reset
                    | Tok::Expr(_)
                    | Tok::FbIn(_)
                        if !operand_start(tok) && at_op =>
                    {
                        let d = Diagnostic::error(
                            code::MISSING_OPERAND,
                            pspan,
                            format!("expected an operand after `{op}`"),
                        )
                        .with_label(if *tok == Tok::Nl {
                            "operand missing".to_string()
                        } else {
                            format!("found {found}")
                        });
                        return Some(d);
                    }
                    Tok::Jmp(_) if !matches!(tok, Tok::Ident(_)) => {
                        return Some(
                            Diagnostic::error(
                                code::MISSING_LABEL,
                                pspan,
                                format!("expected a label after `{op}`"),
                            )
                            .with_label(format!("found {found}")),
                        );
                    }
                    Tok::Cal(_) if !matches!(tok, Tok::Ident(_)) => {
                        return Some(
                            Diagnostic::error(
                                code::MISSING_CAL_TARGET,
                                pspan,
                                format!("expected a function block instance after `{op}`"),
                            )
                            .with_label(format!("found {found}")),
                        );
                    }
                    Tok::Ret(_) if *tok != Tok::Nl => {
                        return Some(
                            Diagnostic::error(
                                code::NO_OPERAND,
                                span,
                                format!("`{op}` takes no operand"),
                            )
                            .with_label("remove this")
                            .with_secondary(pspan, "returns from the POU"),
                        );
                    }
                    Tok::Not if at_op && operand_start(tok) => {
                        return Some(
                            Diagnostic::error(
                                code::NO_OPERAND,
                                span,
                                format!(
                                    "`{op}` takes no operand: it complements the current result"
                                ),
                            )
                            .with_label("remove this")
                            .with_help(format!(
                                "to load the complement of `{}` write `LDN {}`",
                                snippet(lo, hi),
                                snippet(lo, hi)
                            )),
                        );
                    }
                    _ => {}
                }
            }
            if has(expected, "Lit")
                && has(expected, "Addr")
                && has(expected, "IdentTok")
                && !operand_start(tok)
            {
                let after = prev.map_or(String::new(), |(l, _, h)| {
                    format!(" after `{}`", snippet(*l, *h))
                });
                return Some(
                    Diagnostic::error(
                        code::MISSING_OPERAND,
                        span,
                        format!("expected an operand{after}"),
                    )
                    .with_label(format!("found {found}"))
                    .with_help("an operand is a variable, a literal or a direct address"),
                );
            }
            if *tok == Tok::Nl && has(expected, ")") {
                return Some(
                    Diagnostic::error(code::PAREN, span, "missing `)` to close the argument list")
                        .with_label("the line ends here")
                        .with_help("an argument list may span lines but must end with `)`"),
                );
            }
            if *tok == Tok::Comma && has(expected, "Nl") {
                // `ADD cycle, 1`: an operator with an argument list (echidna dialect).
                let line_op = toks.get(line_first(file, toks, idx));
                if let Some((ol, ot, oh)) = line_op
                    && !matches!(ot, Tok::Ident(_))
                {
                    let op = snippet(*ol, *oh);
                    return Some(
                        Diagnostic::error(code::EXTRA_TOKENS, span, format!("`{op}` takes one operand, not a list"))
                            .with_label("second operand")
                            .with_secondary(Span::new(*ol, *oh), "an IL operator")
                            .with_note("the current result is the left-hand side: `LD a` then `ADD b` computes a + b")
                            .with_help("load the first value with `LD`, then apply the operator to the second"),
                    );
                }
            }
            if has(expected, "Nl") && *tok != Tok::Nl {
                return Some(
                    Diagnostic::error(
                        code::EXTRA_TOKENS,
                        span,
                        format!("unexpected {found} after the instruction"),
                    )
                    .with_label("one instruction per line")
                    .with_help("put each instruction on its own line"),
                );
            }
            if matches!(tok, Tok::Lit(_) | Tok::Addr(_))
                && prev.is_some_and(|p| matches!(p.1, Tok::Nl))
            {
                return Some(
                    Diagnostic::error(
                        code::EXPECTED_INSTRUCTION,
                        span,
                        format!("expected an instruction, found {found}"),
                    )
                    .with_label("not an IL operator"),
                );
            }
            if has(expected, "ARRAY") && has(expected, "STRUCT") {
                let after = prev.map_or(String::new(), |(l, _, h)| {
                    format!(" after `{}`", snippet(*l, *h))
                });
                return Some(
                    Diagnostic::error(code::DECL_SYNTAX, span, format!("expected a type{after}"))
                        .with_label(format!("found {found}"))
                        .with_help("write a type such as `INT`, `BOOL`, `ARRAY [0..9] OF INT` or a type name"),
                );
            }
            if has(expected, "AT") && has(expected, ":") {
                let after = prev.map_or(String::new(), |(l, _, h)| {
                    format!(" after `{}`", snippet(*l, *h))
                });
                return Some(
                    Diagnostic::error(
                        code::DECL_SYNTAX,
                        span,
                        format!("expected `:` and a type{after}"),
                    )
                    .with_label(format!("found {found}"))
                    .with_help("declarations have the form `name : TYPE;`"),
                );
            }
            if has(expected, ";") {
                // A declaration: name it.
                let start = toks[..idx]
                    .iter()
                    .rposition(|(_, t, _)| {
                        matches!(
                            t,
                            Tok::Semi
                                | Tok::Var(_)
                                | Tok::Constant
                                | Tok::Retain
                                | Tok::NonRetain
                                | Tok::Struct
                                | Tok::Type
                                | Tok::Pou(_)
                                | Tok::Task
                                | Tok::Configuration
                                | Tok::Resource
                                | Tok::EndVar
                                | Tok::EndResource
                        )
                    })
                    .map_or(0, |i| i + 1);
                let name = toks[start..idx]
                    .iter()
                    .find_map(|(l, t, h)| matches!(t, Tok::Ident(_)).then(|| snippet(*l, *h)));
                let at = prev.map_or(span, |(l, _, h)| Span::new(*h, (*h).max(*l)));
                let msg = match name {
                    Some(n) => format!("expected `;` after the declaration of `{n}`"),
                    None => "expected `;` at the end of the declaration".to_string(),
                };
                return Some(
                    Diagnostic::error(code::DECL_SYNTAX, at, msg)
                        .with_label("`;` missing here")
                        .with_secondary(span, format!("found {found}")),
                );
            }
            if has(expected, "END_VAR") && !has(expected, "IdentTok") {
                return Some(
                    Diagnostic::error(code::MISSING_END_VAR, span, "missing END_VAR")
                        .with_label(format!("found {found}")),
                );
            }
            let in_decl = has(expected, ":")
                || has(expected, ":=")
                || has(expected, "END_VAR")
                || has(expected, "OF")
                || has(expected, "..");
            let code_ = if in_decl {
                code::DECL_SYNTAX
            } else if has(expected, "END_CONFIGURATION")
                || has(expected, "END_RESOURCE")
                || has(expected, "TASK")
            {
                code::CONFIG_SYNTAX
            } else {
                code::SYNTAX
            };
            let mut wanted: Vec<String> = expected.iter().filter_map(|e| friendly(e)).collect();
            wanted.dedup();
            let after = prev.map_or(String::new(), |(l, _, h)| {
                format!(" after `{}`", snippet(*l, *h))
            });
            let msg = match wanted.len() {
                1 => format!("expected {}{after}, found {found}", wanted[0]),
                2..=4 => {
                    let last = wanted.pop().unwrap_or_default();
                    format!(
                        "expected {} or {last}{after}, found {found}",
                        wanted.join(", ")
                    )
                }
                _ if *tok == Tok::Nl => format!("the line ends too early{after}"),
                _ => format!("unexpected {found}"),
            };
            let mut d = Diagnostic::error(code_, span, msg)
                .with_label(format!("expected {}", expected_list(expected)));
            // A word shaped like a name where a name may stand, that the lexer
            // did not read as one: a reserved keyword (`VAR on : BOOL`).
            let word = snippet(span.lo as usize, span.hi as usize);
            if has(expected, "IdentTok")
                && word.bytes().next().is_some_and(|c| c.is_ascii_alphabetic())
                && word.bytes().all(|c| c.is_ascii_alphanumeric() || c == b'_')
            {
                d.add_note(format!(
                    "`{word}` is a reserved keyword of IEC 61131-3 and cannot be a name; rename it (e.g. `{word}_`)"
                ));
            }
            Some(d)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_unique_documented_and_in_range() {
        let mut seen = std::collections::HashSet::new();
        for c in code::CODES {
            assert!(seen.insert(c.code), "duplicate {}", c.code);
            let n: u32 = c
                .code
                .strip_prefix("IL")
                .and_then(|n| n.parse().ok())
                .expect(c.code);
            assert!((1..=99).contains(&n), "{}", c.code);
            assert_eq!(c.code.len(), 6);
            assert!(!c.title.is_empty() && !c.title.contains('\n'));
            assert!(c.explanation.len() > 40, "{}", c.code);
        }
        assert_eq!(code::CODES.len(), 38);
    }
}
