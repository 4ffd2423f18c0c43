//! Breakpoint conditions (`count > 5`, `t1.Q`, `NOT run`, `state = Idle`)
//! and log messages (`count is {count}`), over the paths of the stopped
//! frame. A side of a comparison is a variable path or an IL literal of
//! the other side's type.

use std::cmp::Ordering;

use il_interp::{Here, Value};

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CmpOp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

/// A parsed condition.
#[derive(Debug, PartialEq)]
pub enum Cond<'a> {
    /// A BOOL path (`t1.Q`), or its complement (`NOT run`).
    Bool(&'a str, bool),
    Cmp(&'a str, CmpOp, &'a str),
}

/// The first comparison operator outside brackets and quotes.
fn split_op(s: &str) -> Option<(usize, usize, CmpOp)> {
    let b = s.as_bytes();
    let (mut depth, mut quote) = (0i32, false);
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        match c {
            b'\'' | b'"' => quote = !quote,
            b'[' | b'(' if !quote => depth += 1,
            b']' | b')' if !quote => depth -= 1,
            b'<' | b'>' | b'=' | b'!' if !quote && depth == 0 => {
                let two = b.get(i + 1).copied();
                let (len, op) = match (c, two) {
                    (b'<', Some(b'=')) => (2, CmpOp::Le),
                    (b'>', Some(b'=')) => (2, CmpOp::Ge),
                    (b'<', Some(b'>')) | (b'!', Some(b'=')) => (2, CmpOp::Ne),
                    (b'=', Some(b'=')) => (2, CmpOp::Eq),
                    (b'<', _) => (1, CmpOp::Lt),
                    (b'>', _) => (1, CmpOp::Gt),
                    (b'=', _) => (1, CmpOp::Eq),
                    _ => return None,
                };
                return Some((i, len, op));
            }
            _ => {}
        }
        i += 1;
    }
    None
}

pub fn parse(s: &str) -> Result<Cond<'_>, String> {
    let s = s.trim();
    if let Some((i, len, op)) = split_op(s) {
        let (l, r) = (s[..i].trim(), s[i + len..].trim());
        if l.is_empty() || r.is_empty() {
            return Err(format!("condition `{s}`: a comparison needs two sides"));
        }
        return Ok(Cond::Cmp(l, op, r));
    }
    if s.is_empty() {
        return Err("the condition is empty".into());
    }
    let up = s.to_ascii_uppercase();
    match up.strip_prefix("NOT ") {
        Some(_) => Ok(Cond::Bool(s[4..].trim(), false)),
        None => Ok(Cond::Bool(s, true)),
    }
}

/// Whether the condition holds in the innermost frame of `at`.
pub fn holds(at: &Here<'_>, text: &str) -> Result<bool, String> {
    match parse(text)? {
        Cond::Bool(p, want) => match at.eval(0, p)? {
            (Value::Bool(b), _) => Ok(b == want),
            (_, ty) => Err(format!("condition `{text}`: `{p}` is {ty}, not BOOL")),
        },
        Cond::Cmp(l, op, r) => {
            let (a, b) = match (at.eval(0, l), at.eval(0, r)) {
                (Ok((a, _)), Ok((b, _))) => (a, b),
                (Ok((a, ty)), Err(_)) => (a, literal(&ty, r, text)?),
                (Err(_), Ok((b, ty))) => (literal(&ty, l, text)?, b),
                (Err(e), Err(_)) => return Err(format!("condition `{text}`: {e}")),
            };
            let ord = compare(&a, &b).ok_or_else(|| {
                format!(
                    "condition `{text}`: {} and {} cannot be compared",
                    a.display(),
                    b.display()
                )
            })?;
            Ok(match op {
                CmpOp::Eq => ord == Ordering::Equal,
                CmpOp::Ne => ord != Ordering::Equal,
                CmpOp::Lt => ord == Ordering::Less,
                CmpOp::Le => ord != Ordering::Greater,
                CmpOp::Gt => ord == Ordering::Greater,
                CmpOp::Ge => ord != Ordering::Less,
            })
        }
    }
}

fn literal(ty: &il_codegen::ir::types::Ty, text: &str, whole: &str) -> Result<Value, String> {
    if let il_codegen::ir::types::Ty::Enum(n) = ty {
        let bare = text.rsplit('#').next().unwrap_or(text);
        return Ok(Value::Enum {
            ty: n.to_string(),
            value: bare.to_string(),
        });
    }
    il_interp::parse_literal(ty, text).ok_or_else(|| {
        format!("condition `{whole}`: `{text}` is no variable here and no {ty} literal")
    })
}

/// The order of two values of one kind (enumerations and strings: equal or not).
fn compare(a: &Value, b: &Value) -> Option<Ordering> {
    match (a, b) {
        (Value::Bool(x), Value::Bool(y)) => Some(x.cmp(y)),
        (Value::Int(x, _), Value::Int(y, _)) => Some(x.cmp(y)),
        (Value::Time(x, _), Value::Time(y, _)) => Some(x.cmp(y)),
        (
            Value::Real(_) | Value::LReal(_) | Value::Int(..),
            Value::Real(_) | Value::LReal(_) | Value::Int(..),
        ) => a.as_f64().partial_cmp(&b.as_f64()),
        (Value::Enum { value: x, .. }, Value::Enum { value: y, .. }) => {
            Some(if x.eq_ignore_ascii_case(y) {
                Ordering::Equal
            } else {
                Ordering::Less
            })
        }
        (Value::Str { units: x, .. }, Value::Str { units: y, .. }) => Some(x.cmp(y)),
        _ => None,
    }
}

/// A log message with each `{path}` replaced by the path's value (an
/// unknown path by its error, so that a log point never stops the run).
pub fn interpolate(at: &Here<'_>, msg: &str) -> String {
    let mut out = String::new();
    let mut rest = msg;
    while let Some(i) = rest.find('{') {
        out.push_str(&rest[..i]);
        match rest[i + 1..].find('}') {
            Some(j) => {
                let path = &rest[i + 1..i + 1 + j];
                match at.eval(0, path) {
                    Ok((v, _)) => out.push_str(&v.display()),
                    Err(e) => out.push_str(&format!("<{e}>")),
                }
                rest = &rest[i + 2 + j..];
            }
            None => {
                out.push_str(&rest[i..]);
                rest = "";
            }
        }
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conditions_parse() {
        assert_eq!(parse("count > 5"), Ok(Cond::Cmp("count", CmpOp::Gt, "5")));
        assert_eq!(
            parse("m[1, 2] >= 3"),
            Ok(Cond::Cmp("m[1, 2]", CmpOp::Ge, "3"))
        );
        assert_eq!(parse("a <> b"), Ok(Cond::Cmp("a", CmpOp::Ne, "b")));
        assert_eq!(parse("s = 'a<b'"), Ok(Cond::Cmp("s", CmpOp::Eq, "'a<b'")));
        assert_eq!(parse("t1.Q"), Ok(Cond::Bool("t1.Q", true)));
        assert_eq!(parse("not run"), Ok(Cond::Bool("run", false)));
        assert!(parse("> 5").is_err());
        assert!(parse("  ").is_err());
    }
}
