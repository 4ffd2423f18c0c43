//! What an XML attribute may hold before it is written into the IL text.
//!
//! Attribute values are copied into the IL text, so an unchecked one could
//! end a section and start another (`name="x; END_VAR VAR evil"`). Each
//! attribute that reaches the IL text is checked against the one token (or
//! the few fixed shapes) it stands for; anything else is refused with the
//! reason, and the import leaves its element out.

use crate::ast::LitKind;
use crate::syntax::lexer::{self, Tok};

/// What an attribute stands for in the IL text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// A name being declared or referred to: POU, variable, type, member,
    /// enumeration value, configuration, resource, task, instance.
    Name,
    /// One literal or one name (an enumeration value, a constant): a
    /// `<simpleValue value>`.
    Value,
    /// An integer literal (an enumeration's value).
    Integer,
    /// An integer literal or a constant's name (array and subrange bounds).
    Bound,
    /// A decimal count (a string length, a repetition, a priority).
    Count,
    /// A direct address: `%IX0.1`, `%QW4`, `%MD10.2`.
    Address,
    /// A duration literal: `T#10ms`, `TIME#1s`.
    Duration,
    /// A task's `single` input: a name or a direct address.
    Trigger,
}

impl Kind {
    /// What the attribute should be, for messages.
    pub(crate) fn what(self) -> &'static str {
        match self {
            Kind::Name => "an IEC identifier",
            Kind::Value => "a literal, a name or a `[...]` / `(...)` value of them",
            Kind::Integer => "an integer literal",
            Kind::Bound => "an integer literal or a constant's name",
            Kind::Count => "a decimal number",
            Kind::Address => "a direct address such as `%IX0.1`",
            Kind::Duration => "a duration literal such as `T#10ms`",
            Kind::Trigger => "a variable name or a direct address",
        }
    }
}

pub(crate) use super::MAX_NAME;
/// Longest literal accepted (a long STRING initial value is the largest).
const MAX_VALUE: usize = 64 * 1024;

/// Check `s` against `kind`: `Err` holds why it is refused.
pub(crate) fn check(kind: Kind, s: &str) -> Result<(), String> {
    if s.is_empty() {
        return Err("it is empty".into());
    }
    if let Some(c) = s.chars().find(|&c| forbidden_char(c)) {
        return Err(format!(
            "it holds the control character U+{:04X}",
            u32::from(c)
        ));
    }
    match kind {
        Kind::Name => identifier(s),
        Kind::Value => value(s).map(|_| ()),
        Kind::Integer => integer(s),
        Kind::Bound => integer(s)
            .or_else(|_| identifier(s))
            .map_err(|_| "it is neither an integer literal nor an identifier".to_string()),
        Kind::Count => count(s),
        Kind::Address => address(s),
        Kind::Duration => match value(s)? {
            Some(LitKind::Time { .. }) => Ok(()),
            _ => Err("it is not a duration literal".into()),
        },
        Kind::Trigger => identifier(s).or_else(|_| address(s)),
    }
}

/// Characters no attribute may hold, even inside a string literal: C0 and
/// C1 controls, line and paragraph separators, bidirectional controls.
pub(crate) fn forbidden_char(c: char) -> bool {
    crate::diag::text::unsafe_char(c)
}

/// `s` as a message may quote it: control characters escaped (the
/// renderer escapes them too) and cut after 60 characters.
pub(crate) fn shown(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars().take(60) {
        if forbidden_char(c) {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    if s.chars().nth(60).is_some() {
        out.push('…');
    }
    out
}

/// IEC 61131-3 identifier: a letter or `_`, then letters, digits and single
/// underscores, not ending in `_`, and not a keyword that could end or
/// start a section.
fn identifier(s: &str) -> Result<(), String> {
    if s.len() > MAX_NAME {
        return Err(format!("it is longer than {MAX_NAME} characters"));
    }
    let b = s.as_bytes();
    if !(b[0].is_ascii_alphabetic() || b[0] == b'_') {
        return Err("an identifier starts with a letter or `_`".into());
    }
    if let Some(c) = s
        .chars()
        .find(|c| !(c.is_ascii_alphanumeric() || *c == '_'))
    {
        return Err(format!(
            "`{}` is not allowed in an identifier (letters, digits and `_` only)",
            c.escape_default()
        ));
    }
    if s.contains("__") || s.ends_with('_') {
        return Err("`_` may not be doubled or end an identifier".into());
    }
    let up = s.to_ascii_uppercase();
    if lexer::is_decl_keyword(&up)
        || matches!(up.as_str(), "TRUE" | "FALSE" | "BEGIN_IL" | "END_IL")
    {
        return Err(format!("`{s}` is a keyword"));
    }
    Ok(())
}

/// One literal or one name, or the structured initial values built of
/// them (`[1, 2(0)]`, `(x := 1, y := [TRUE])`), as the project's own lexer
/// reads them in a declaration: every byte belongs to such a token or is a
/// space between two (no comment), brackets balance, and the value ends
/// where the `;` written after it starts. Returns the literal's kind when
/// the value is one literal.
fn value(s: &str) -> Result<Option<LitKind>, String> {
    const PRE: &str = "TYPE\n  T : INT := ";
    if s.len() > MAX_VALUE {
        return Err(format!("it is longer than {MAX_VALUE} bytes"));
    }
    let t = s.trim_matches(' ');
    if t.is_empty() {
        return Err("it is blank".into());
    }
    let src = format!("{PRE}{t};\nEND_TYPE\n");
    let (toks, diags) = lexer::lex(&src);
    if let Some(d) = diags.first() {
        return Err(d.message.clone());
    }
    let not =
        || Err("it is not a literal, a name, or a `[...]` or `(...)` value of them".to_string());
    let (lo, hi) = (PRE.len(), PRE.len() + t.len());
    let mut pos = lo;
    let mut open: Vec<&Tok> = Vec::new();
    let mut only: Option<&Tok> = None;
    // `count`: the tokens of the value before this one.
    for (count, (a, tok, b)) in toks.iter().filter(|(a, _, _)| *a >= lo).enumerate() {
        if *a >= hi {
            // Nothing of the value may run past the `;` written after it.
            if !(*a == hi && *tok == Tok::Semi && pos == hi && open.is_empty()) {
                return not();
            }
            return match (count, only) {
                (1, Some(Tok::Lit(l))) => Ok(Some(l.kind.clone())),
                _ => Ok(None),
            };
        }
        if *b > hi || !src[pos..*a].bytes().all(|c| c == b' ') {
            return not();
        }
        // One item at top level; inside brackets, items are separated by
        // `,` or `:=`, and only a count may precede `(` (a repetition).
        let ends = |t: &Tok| matches!(t, Tok::Lit(_) | Tok::Ident(_) | Tok::RBracket | Tok::RParen);
        let sep = |t: &Tok| matches!(t, Tok::Comma | Tok::Assign);
        let fits = match only {
            None => !sep(tok) && !matches!(tok, Tok::RBracket | Tok::RParen),
            _ if open.is_empty() => false,
            Some(p) if ends(p) => {
                sep(tok)
                    || matches!(tok, Tok::RBracket | Tok::RParen)
                    || (matches!(p, Tok::Lit(_)) && *tok == Tok::LParen)
            }
            // After `,`, `:=`, `[` or `(`: an item.
            Some(_) => !sep(tok) && !matches!(tok, Tok::RBracket | Tok::RParen),
        };
        if !fits {
            return not();
        }
        match tok {
            Tok::Lit(_) | Tok::Comma | Tok::Assign => {}
            Tok::Ident(name) => identifier(name)?,
            Tok::LBracket | Tok::LParen => {
                open.push(tok);
                if open.len() > MAX_NEST {
                    return Err(format!("it nests more than {MAX_NEST} brackets deep"));
                }
            }
            Tok::RBracket if open.pop() == Some(&Tok::LBracket) => {}
            Tok::RParen if open.pop() == Some(&Tok::LParen) => {}
            _ => return not(),
        }
        only = Some(tok);
        pos = *b;
    }
    not()
}

/// Brackets in one initial value, at most (as deep as the import nests
/// `<arrayValue>` and `<structValue>`).
const MAX_NEST: usize = 64;

/// `5`, `-3`, `16#FF`, `2#1010`.
fn integer(s: &str) -> Result<(), String> {
    if s.len() > 80
        || !s
            .bytes()
            .all(|c| c.is_ascii_alphanumeric() || b"#_+-".contains(&c))
    {
        return Err("it is not an integer literal".into());
    }
    il_std::literal::parse_int(s)
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// `0`, `16`, `250`: decimal digits only.
fn count(s: &str) -> Result<(), String> {
    if s.len() > 10 || !s.bytes().all(|c| c.is_ascii_digit()) {
        return Err("it is not a decimal number of at most 10 digits".into());
    }
    Ok(())
}

/// `%` then I, Q or M, an optional size X, B, W, D or L, and digits
/// separated by single dots.
fn address(s: &str) -> Result<(), String> {
    let bad = || Err("it is not a direct address such as `%IX0.1`".to_string());
    let Some(rest) = s.strip_prefix('%') else {
        return bad();
    };
    let mut it = rest.chars().peekable();
    if !matches!(it.next(), Some('I' | 'Q' | 'M' | 'i' | 'q' | 'm')) {
        return bad();
    }
    if it.peek().is_some_and(|c| "XBWDLxbwdl".contains(*c)) {
        it.next();
    }
    let digits: String = it.collect();
    if s.len() > 64
        || digits
            .split('.')
            .any(|p| p.is_empty() || !p.bytes().all(|c| c.is_ascii_digit()))
    {
        return bad();
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names() {
        for ok in ["x", "Main", "_a1", "a_b", "TON", "In", "PT"] {
            assert_eq!(check(Kind::Name, ok), Ok(()), "{ok}");
        }
        let long = "a".repeat(MAX_NAME + 1);
        for bad in [
            "",
            "1a",
            "a__b",
            "a_",
            "a b",
            "Main\nEND_PROGRAM\nPROGRAM Evil",
            "x; END_VAR",
            "END_VAR",
            "end_program",
            "VAR",
            "TRUE",
            "a(*",
            "ä",
            &long,
        ] {
            assert!(check(Kind::Name, bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn values() {
        for ok in [
            "5",
            "-3",
            "1.5",
            "16#FF",
            "T#10ms",
            "TIME#1h_2m",
            "INT#7",
            "TRUE",
            "Green",
            "'abc; END_VAR (* x *)'",
            "'it$'s'",
            "\"wide\"",
            "D#2024-01-01",
            "TOD#12:00:00",
            "DT#2024-01-01-12:00:00",
            " 5 ",
            "Colour#Green",
            "WORD#16#FF",
            "-1.5E-3",
            "[1, 2, 3]",
            "[2(0), 1]",
            "(x := 1, y := [TRUE, FALSE])",
            "(1)",
        ] {
            assert_eq!(check(Kind::Value, ok), Ok(()), "{ok}");
        }
        for bad in [
            "",
            "  ",
            "5; END_VAR VAR evil : INT",
            "5 (* c *)",
            "1, 2",
            "'unterminated",
            "'a' 'b'",
            "x.y",
            "END_VAR",
            "5\n",
            "'a\u{202e}b'",
            "T#END_VAR",
            "5 // c",
            "[1; END_VAR",
            "[1] (* c *)",
            "(x := 1))",
            "[1, 2",
            "[1, 2)",
            "(x := END_VAR)",
            "[x.y]",
            "1 2",
        ] {
            assert!(check(Kind::Value, bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn numbers_addresses_durations() {
        for (k, ok) in [
            (Kind::Integer, "-5"),
            (Kind::Integer, "16#FF"),
            (Kind::Bound, "MaxLen"),
            (Kind::Count, "16"),
            (Kind::Address, "%IX0.1"),
            (Kind::Address, "%QW4"),
            (Kind::Address, "%md10.2.3"),
            (Kind::Duration, "T#10ms"),
            (Kind::Duration, "t#200ms"),
            (Kind::Duration, "LTIME#1s"),
            (Kind::Value, "16#FF_FF"),
            (Kind::Trigger, "trig"),
            (Kind::Trigger, "%IX1.0"),
        ] {
            assert_eq!(check(k, ok), Ok(()), "{ok}");
        }
        for (k, bad) in [
            (Kind::Integer, "1.5"),
            (Kind::Integer, "5;"),
            (Kind::Bound, "1..2"),
            (Kind::Count, "-1"),
            (Kind::Count, "16#10"),
            (Kind::Address, "%IX0.1 : INT; END_VAR"),
            (Kind::Address, "%IX0..1"),
            (Kind::Address, "%Z0"),
            (Kind::Address, "IX0"),
            (Kind::Duration, "5"),
            (Kind::Duration, "T#1s); TASK x (PRIORITY := 1"),
            (Kind::Trigger, "a; b"),
        ] {
            assert!(check(k, bad).is_err(), "{k:?} {bad:?}");
        }
    }
}
