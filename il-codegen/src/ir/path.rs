//! Host paths: the text a user gives a tool to name one place of a running
//! program (`tank.level`, `valves[2].open`, `m[2 * 3 - 1, 0]`), as `ilc run
//! --set/--watch` and the interpreter's host access read it.
//!
//! A path names one place for the whole run, so its subscripts are
//! constants: integer literals (`16#FF`, `1_000`) joined by `+ - * / MOD`,
//! parentheses and unary minus, folded exactly as the checker folds a
//! constant subscript (division truncates toward zero, MOD takes the
//! dividend's sign).

use super::types::Ty;
use super::{BinOp, CheckedPou, Loc, Program, Storage, TypeDef, Var};

/// A parsed path: its first name and the steps after it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HostPath {
    /// The variable (or instance) the path starts at, as written.
    pub root: String,
    /// `.name` and `[i, j]` steps, in order.
    pub parts: Vec<PathPart>,
}

/// One step of a [`HostPath`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PathPart {
    /// `.name`: a member, as written.
    Field(String),
    /// `[i, j]`: the subscripts' values, one per dimension.
    Index(Vec<i64>),
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// `a op b` of a constant subscript (`+ - * / MOD`), exactly: division
/// truncates toward zero and MOD takes the dividend's sign. `None` on
/// overflow or a zero divisor. The one rule for the checker's folding of
/// literal subscripts, configuration paths and host paths alike.
pub fn fold(op: BinOp, a: i128, b: i128) -> Option<i128> {
    match op {
        BinOp::Add => a.checked_add(b),
        BinOp::Sub => a.checked_sub(b),
        BinOp::Mul => a.checked_mul(b),
        BinOp::Div => a.checked_div(b),
        BinOp::Mod => a.checked_rem(b),
        _ => None,
    }
}

/// Parse `a.b[1, 2 + k].c`-style text (no direct addresses: the caller
/// handles `%IX0.0`). The error names the path and what is wrong in it.
pub fn parse(text: &str) -> Result<HostPath, String> {
    let bad = || format!("`{text}` is not a variable path like `tank.level` or `valves[2].open`");
    let t = text.trim();
    let end = t.find(|c: char| !is_ident(c)).unwrap_or(t.len());
    let (root, mut rest) = t.split_at(end);
    if root.is_empty() || root.starts_with(|c: char| c.is_ascii_digit()) {
        return Err(bad());
    }
    let mut parts = Vec::new();
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('.') {
            let end = r.find(|c: char| !is_ident(c)).unwrap_or(r.len());
            if end == 0 || r.starts_with(|c: char| c.is_ascii_digit()) {
                return Err(bad());
            }
            parts.push(PathPart::Field(r[..end].to_string()));
            rest = &r[end..];
        } else if let Some(r) = rest.strip_prefix('[') {
            let close = r.find(']').ok_or_else(bad)?;
            let subs = r[..close]
                .split(',')
                .map(|s| {
                    constant(s).map_err(|e| format!("`{text}`: the subscript `{}` {e}", s.trim()))
                })
                .collect::<Result<_, _>>()?;
            parts.push(PathPart::Index(subs));
            rest = &r[close + 1..];
        } else {
            return Err(bad());
        }
    }
    Ok(HostPath {
        root: root.to_string(),
        parts,
    })
}

/// The value of a constant subscript expression (`7 MOD 3 - (2 / 2)`);
/// the error completes "the subscript `…` ".
pub fn constant(text: &str) -> Result<i64, String> {
    let mut p = Parser {
        toks: tokens(text)?,
        at: 0,
    };
    let v = p.sum()?;
    if p.at != p.toks.len() {
        return Err("is not an integer expression".into());
    }
    i64::try_from(v).map_err(|_| "overflows LINT".to_string())
}

/// One step of a resolved path: a member (its declared name and index), or
/// an element by its row-major index over all dimensions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Step {
    /// A member of a structure or an FB instance.
    Field(super::Member),
    /// The element at this flat index.
    Element(usize),
}

/// Where a path's parts lead from a place of some type.
#[derive(Clone, Debug, PartialEq)]
pub struct Resolved {
    /// The steps, in order.
    pub steps: Vec<Step>,
    /// The type of the place they end at.
    pub ty: Ty,
    /// Its subrange, if it has one.
    pub range: Option<(i128, i128)>,
}

/// The steps `parts` take from a place of type `ty` (subrange `range`) in
/// `prog`: members of structures, of user FB instances (their inputs,
/// outputs and variables held in the instance) and of standard blocks, and
/// array elements inside the bounds. `text` is the whole path, for the
/// messages, which name the closest member where one is close.
pub fn resolve(
    prog: &Program,
    (ty, range): (Ty, Option<(i128, i128)>),
    parts: &[PathPart],
    text: &str,
) -> Result<Resolved, String> {
    let (mut ty, mut range) = (ty, range);
    let mut steps = Vec::with_capacity(parts.len());
    for part in parts {
        match part {
            PathPart::Field(f) => {
                let (name, fty, frange) = member(prog, &ty, f, text)?;
                steps.push(Step::Field(name));
                ty = fty;
                range = frange;
            }
            PathPart::Index(subs) => {
                let Ty::Array(arr) = &ty else {
                    return Err(format!("`{text}`: {ty} is not an array"));
                };
                if subs.len() != arr.dims.len() {
                    return Err(format!(
                        "`{text}`: {} subscripts for an array of {} dimensions",
                        subs.len(),
                        arr.dims.len()
                    ));
                }
                let mut flat = 0usize;
                for (&k, &(lo, hi)) in subs.iter().zip(&arr.dims) {
                    if k < lo || k > hi {
                        return Err(format!(
                            "`{text}`: subscript {k} is outside the bounds {lo}..{hi}"
                        ));
                    }
                    flat = flat * (hi - lo + 1) as usize + (k - lo) as usize;
                }
                steps.push(Step::Element(flat));
                // An element of an array of a subrange keeps its bounds.
                range = arr.range;
                ty = arr.elem.clone();
            }
        }
    }
    Ok(Resolved { steps, ty, range })
}

/// What a path rooted at a variable of a POU names ([`resolve_var`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Rooted {
    /// A located variable (`AT %IW2 : INT`): its place in the process
    /// image, and the variable's declared type and subrange.
    Located(Loc, Ty, Option<(i128, i128)>),
    /// Variable `index` of the POU, and where the path's parts lead in it.
    Var(usize, Resolved),
}

/// Which variables of a POU a path may start at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// Those an instance holds between calls ([`held`]) and the located
    /// ones: a host or a tool between scans.
    Held,
    /// Every variable, temporaries included: a debugger stopped in a call.
    All,
}

/// Resolve `root` and `parts` (of the path `text`) against the variables of
/// `pou` in `prog`: the one resolution of a path's root for every tool (the
/// interpreter's host access, the configuration's program variables and
/// the debugger). `unknown` phrases the error for a root that is no variable
/// of the POU, given the hint (`; did you mean `x`?`, or empty).
pub fn resolve_var(
    prog: &Program,
    pou: &CheckedPou,
    (root, parts): (&str, &[PathPart]),
    text: &str,
    scope: Scope,
    unknown: impl FnOnce(&str) -> String,
) -> Result<Rooted, String> {
    let seen = |v: &Var| scope == Scope::All || held(v) || v.storage == Storage::Located;
    let found = (pou.vars.iter().position(|v| v.name == root))
        .or_else(|| (pou.vars.iter()).position(|v| v.name.eq_ignore_ascii_case(root)));
    let Some(i) = found else {
        let names = pou.vars.iter().filter(|v| seen(v)).map(|v| v.name.as_str());
        let hint = crate::diag::suggest(root, names)
            .map(|s| format!("; did you mean `{s}`?"))
            .unwrap_or_default();
        return Err(unknown(&hint));
    };
    let var = &pou.vars[i];
    // A debugger shows any variable with an address at its address.
    let located = scope == Scope::All || var.storage == Storage::Located;
    if let Some(l) = var.location.as_ref().filter(|_| located) {
        if !parts.is_empty() {
            return Err(format!(
                "`{root}` is located at {}: it has no members",
                l.text
            ));
        }
        return Ok(Rooted::Located(l.clone(), var.ty.clone(), var.range));
    }
    if !seen(var) {
        return Err(format!(
            "`{root}` lives only during a call of {} (a temporary); it cannot be set or watched",
            pou.name
        ));
    }
    let resolved = resolve(prog, (var.ty.clone(), var.range), parts, text)?;
    Ok(Rooted::Var(i, resolved))
}

/// Whether an instance holds `v` between calls, so that a path can name
/// it: its memory ([`Storage::Instance`]) and its VAR_EXTERNALs
/// ([`Storage::External`]: an interpreter keeps them in the instance, as
/// generated code keeps a reference). A VAR_IN_OUT is the caller's.
pub fn held(v: &Var) -> bool {
    matches!(v.storage, Storage::Instance | Storage::External)
}

/// The member `f` of a value of type `ty`: the member, its type and subrange.
#[allow(clippy::type_complexity)]
fn member(
    prog: &Program,
    ty: &Ty,
    f: &str,
    text: &str,
) -> Result<(super::Member, Ty, Option<(i128, i128)>), String> {
    let at = |name: &str, index: usize| super::Member {
        name: name.into(),
        index: index as u32,
    };
    let none = |names: Vec<&str>, of: &str| {
        let hint = crate::diag::suggest(f, names.iter().copied())
            .map(|s| format!("; did you mean `{s}`?"))
            .unwrap_or_default();
        format!("`{text}`: {of} has no member `{f}`{hint}")
    };
    match ty {
        Ty::Struct(n) => {
            let def = prog.types.iter().find(|d| match d {
                TypeDef::Struct { name, .. } | TypeDef::Enum { name, .. } => {
                    name.eq_ignore_ascii_case(n)
                }
            });
            match def {
                Some(TypeDef::Struct { fields, .. }) => (fields.iter().enumerate())
                    .find(|(_, x)| x.name.eq_ignore_ascii_case(f))
                    .map(|(i, x)| (at(&x.name, i), x.ty.clone(), x.range))
                    .ok_or_else(|| none(fields.iter().map(|x| x.name.as_str()).collect(), n)),
                Some(TypeDef::Enum { .. }) => Err(format!("`{text}`: {n} has no members")),
                None => Err(format!(
                    "internal: no user type `{n}` in the checked program"
                )),
            }
        }
        Ty::Fb(n) => {
            if let Some(p) = prog.pous.iter().find(|p| p.name.eq_ignore_ascii_case(n)) {
                let mut names = Vec::new();
                for (i, v) in p.vars.iter().enumerate().filter(|(_, v)| held(v)) {
                    if v.name.eq_ignore_ascii_case(f) {
                        return Ok((at(&v.name, i), v.ty.clone(), v.range));
                    }
                    names.push(v.name.as_str());
                }
                return Err(none(names, n));
            }
            let s = il_std::signature::lookup_fb(n)
                .ok_or_else(|| format!("internal: no function block {n}"))?;
            let params = || s.inputs.iter().chain(s.outputs);
            let (i, p) = (params().enumerate())
                .find(|(_, p)| p.name.eq_ignore_ascii_case(f))
                .ok_or_else(|| none(params().map(|p| p.name).collect(), n))?;
            Ok((at(p.name, i), Ty::of_std(p.ty), None))
        }
        _ => Err(format!("`{text}`: {ty} has no members")),
    }
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(i128),
    Op(char),
    Mod,
}

fn tokens(text: &str) -> Result<Vec<Tok>, String> {
    let not_int = || "is not an integer expression".to_string();
    let mut out = Vec::new();
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let c = b[i] as char;
        if c.is_whitespace() {
            i += 1;
        } else if "+-*/()".contains(c) {
            out.push(Tok::Op(c));
            i += 1;
        } else if c.is_ascii_alphanumeric() {
            let end = text[i..]
                .find(|c: char| !(is_ident(c) || c == '#'))
                .map_or(text.len(), |e| i + e);
            let word = &text[i..end];
            if word.eq_ignore_ascii_case("MOD") {
                out.push(Tok::Mod);
            } else if c.is_ascii_digit() {
                let n = il_std::literal::parse_int(word).map_err(|_| not_int())?;
                out.push(Tok::Num(n));
            } else {
                return Err("is not a constant: a path names one place for the whole run".into());
            }
            i = end;
        } else {
            return Err(not_int());
        }
    }
    Ok(out)
}

/// Recursive descent over `+ -` / `* / MOD` / unary `-` / atoms, exact in i128.
struct Parser {
    toks: Vec<Tok>,
    at: usize,
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.at)
    }

    fn sum(&mut self) -> Result<i128, String> {
        let mut v = self.term()?;
        while let Some(Tok::Op(c @ ('+' | '-'))) = self.peek().cloned() {
            self.at += 1;
            let r = self.term()?;
            let op = if c == '+' { BinOp::Add } else { BinOp::Sub };
            v = fold(op, v, r).ok_or("overflows")?;
        }
        Ok(v)
    }

    fn term(&mut self) -> Result<i128, String> {
        let mut v = self.unary()?;
        loop {
            let op = match self.peek() {
                Some(Tok::Op('*')) => BinOp::Mul,
                Some(Tok::Op('/')) => BinOp::Div,
                Some(Tok::Mod) => BinOp::Mod,
                _ => return Ok(v),
            };
            self.at += 1;
            let r = self.unary()?;
            if r == 0 && op != BinOp::Mul {
                return Err("divides by zero".into());
            }
            v = fold(op, v, r).ok_or("overflows")?;
        }
    }

    fn unary(&mut self) -> Result<i128, String> {
        match self.peek().cloned() {
            Some(Tok::Op('-')) => {
                self.at += 1;
                Ok(-self.unary()?)
            }
            Some(Tok::Op('(')) => {
                self.at += 1;
                let v = self.sum()?;
                if self.peek() != Some(&Tok::Op(')')) {
                    return Err("has an unclosed `(`".into());
                }
                self.at += 1;
                Ok(v)
            }
            Some(Tok::Num(n)) => {
                self.at += 1;
                Ok(n)
            }
            _ => Err("is not an integer expression".into()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subscripts_are_constant_expressions() {
        assert_eq!(constant("3 MOD 2 + 7"), Ok(8));
        assert_eq!(constant("-(-4)"), Ok(4));
        assert_eq!(constant("7 mod 3 - (2 / 2)"), Ok(0));
        assert_eq!(constant("-7 / 2"), Ok(-3));
        assert_eq!(constant("-7 MOD 2"), Ok(-1));
        assert_eq!(constant("16#10 * 2"), Ok(32));
        assert_eq!(constant("1 / 0"), Err("divides by zero".into()));
        assert!(constant("i + 1").unwrap_err().contains("not a constant"));
        assert!(constant("(1 + 2").unwrap_err().contains("unclosed"));
        assert!(constant("1 +").is_err() && constant("").is_err() && constant("2 3").is_err());
        let p = parse("line.t[1 + 1, 0].Q").unwrap();
        assert_eq!(p.root, "line");
        assert_eq!(
            p.parts,
            vec![
                PathPart::Field("t".into()),
                PathPart::Index(vec![2, 0]),
                PathPart::Field("Q".into())
            ]
        );
        assert!(parse("a[1 / 0]").unwrap_err().contains("divides by zero"));
        assert!(parse("1a").is_err() && parse("a.").is_err() && parse("a[1").is_err());
    }
}
