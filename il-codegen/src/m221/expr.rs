//! Operation blocks (`[ %MW1 := %MW2 + 1 ]`) and comparison blocks
//! (`LD [ %MF1 >= %MF2 ]`): the expression between the brackets parsed into
//! a tree, and the tree written as IEC IL that leaves its value in the CR
//! (deferred operators `ADD( ... )` for a right side that is no operand).

use std::ops::Range;

use super::codes::{BAD_LINE, UNCONFIGURED, UNSUPPORTED};
use super::objects::{NotObject, Objects, Ty};
use super::read::{DEFAULT_TIMER, Project};

/// A token of an expression and its byte range in the line.
#[derive(Clone, Debug)]
struct Tok {
    s: String,
    at: Range<usize>,
}

fn tokens(text: &str, base: usize) -> Vec<Tok> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let start = i;
        let two = text.get(i..i + 2).unwrap_or("");
        if matches!(two, ":=" | "<=" | ">=" | "<>") {
            i += 2;
        } else if b"+-*/(),=<>".contains(&c) {
            i += 1;
        } else {
            while i < b.len() {
                let c = b[i];
                let op = b"+-*/(),=<>".contains(&c) || c.is_ascii_whitespace();
                if op || (c == b':' && b.get(i + 1) == Some(&b'=')) {
                    break;
                }
                // A sign inside a real's exponent (`1.5E-3`).
                i += 1;
                if (c == b'E' || c == b'e')
                    && matches!(b.get(i), Some(b'-' | b'+'))
                    && b[start].is_ascii_digit()
                {
                    i += 1;
                }
            }
        }
        out.push(Tok {
            s: text[start..i].to_string(),
            at: base + start..base + i,
        });
    }
    out
}

/// An expression tree; leaves are IL operands (names or literals).
#[derive(Debug)]
pub(super) enum Expr {
    Leaf {
        il: String,
        ty: Ty,
    },
    /// A value that takes IL lines to load (a timer's `%TMn.V`).
    Load {
        lines: Vec<String>,
        ty: Ty,
    },
    Bin(Box<Expr>, &'static str, Box<Expr>),
    Not(Box<Expr>),
    Call(&'static str, Vec<Expr>),
}

/// What went wrong, at which bytes of the line.
pub(super) struct Error {
    pub what: String,
    pub at: Range<usize>,
    /// The diagnostic's code (IL0430, or IL0431/IL0436 for an object the
    /// import knows of).
    pub code: &'static str,
}

fn err(what: impl Into<String>, at: Range<usize>) -> Error {
    Error {
        what: what.into(),
        at,
        code: BAD_LINE,
    }
}

/// The M221 functions an expression may call, as IEC functions, with their
/// result type (`None`: the argument's).
const FUNCTIONS: &[(&str, Option<Ty>)] = &[
    ("ABS", None),
    ("SQRT", None),
    ("LN", None),
    ("LOG", None),
    ("EXP", None),
    ("SIN", None),
    ("COS", None),
    ("TAN", None),
    ("ASIN", None),
    ("ACOS", None),
    ("ATAN", None),
    ("EXPT", None),
    ("INT_TO_REAL", Some(Ty::Real)),
    ("DINT_TO_REAL", Some(Ty::Real)),
    ("REAL_TO_INT", Some(Ty::Int)),
    ("REAL_TO_DINT", Some(Ty::Dint)),
    ("TRUNC", Some(Ty::Dint)),
    // On words as bit strings: the INT is converted to WORD and back.
    ("SHL", None),
    ("SHR", None),
    ("ROL", None),
    ("ROR", None),
    ("BTI", None),
    ("ITB", None),
];

/// The functions of [`FUNCTIONS`] that IEC defines on a bit string (WORD)
/// or a BCD word, with the IEC function: the M221 applies them to an INT.
const ON_WORDS: &[(&str, &str)] = &[
    ("SHL", "SHL"),
    ("SHR", "SHR"),
    ("ROL", "ROL"),
    ("ROR", "ROR"),
    ("BTI", "BCD_TO_INT"),
    ("ITB", "INT_TO_BCD"),
];

struct Parser<'a> {
    toks: Vec<Tok>,
    k: usize,
    p: &'a Project,
    objs: &'a mut Objects,
    /// Where the line lies in the XML, to note an object's first use.
    xml: &'a dyn Fn(Range<usize>) -> Range<usize>,
    end: Range<usize>,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&str> {
        self.toks.get(self.k).map(|t| t.s.as_str())
    }

    fn here(&self) -> Range<usize> {
        self.toks
            .get(self.k)
            .map_or(self.end.clone(), |t| t.at.clone())
    }

    fn eat(&mut self, s: &str) -> bool {
        if self.peek().is_some_and(|t| t.eq_ignore_ascii_case(s)) {
            self.k += 1;
            true
        } else {
            false
        }
    }

    fn sum(&mut self) -> Result<Expr, Error> {
        let mut l = self.term()?;
        loop {
            let op = match self.peek().map(str::to_ascii_uppercase).as_deref() {
                Some("+") => "ADD",
                Some("-") => "SUB",
                Some("OR") => "OR",
                Some("XOR") => "XOR",
                _ => return Ok(l),
            };
            self.k += 1;
            let r = self.term()?;
            l = Expr::Bin(Box::new(l), op, Box::new(r));
        }
    }

    fn term(&mut self) -> Result<Expr, Error> {
        let mut l = self.unary()?;
        loop {
            let op = match self.peek().map(str::to_ascii_uppercase).as_deref() {
                Some("*") => "MUL",
                Some("/") => "DIV",
                Some("REM") => "MOD",
                Some("AND") => "AND",
                _ => return Ok(l),
            };
            self.k += 1;
            let r = self.unary()?;
            l = Expr::Bin(Box::new(l), op, Box::new(r));
        }
    }

    fn unary(&mut self) -> Result<Expr, Error> {
        if self.eat("-") {
            let x = self.unary()?;
            return Ok(match x {
                Expr::Leaf { il, ty } if matches!(ty, Ty::IntLit | Ty::RealLit) => Expr::Leaf {
                    il: format!("-{il}"),
                    ty,
                },
                x => Expr::Bin(
                    Box::new(Expr::Leaf {
                        il: "0".into(),
                        ty: Ty::IntLit,
                    }),
                    "SUB",
                    Box::new(x),
                ),
            });
        }
        if self.eat("NOT") {
            return Ok(Expr::Not(Box::new(self.unary()?)));
        }
        self.primary()
    }

    fn primary(&mut self) -> Result<Expr, Error> {
        let at = self.here();
        let Some(t) = self.toks.get(self.k).cloned() else {
            return Err(err("the expression ends where an operand is expected", at));
        };
        self.k += 1;
        if t.s == "(" {
            let e = self.sum()?;
            if !self.eat(")") {
                return Err(err("`(` without its `)`", self.here()));
            }
            return Ok(e);
        }
        let up = t.s.to_ascii_uppercase();
        if self.peek() == Some("(") {
            let Some(&(name, _)) = FUNCTIONS.iter().find(|(n, _)| *n == up) else {
                let mut e = err(
                    format!("`{}` is not a function the import compiles", t.s),
                    t.at,
                );
                e.code = UNSUPPORTED;
                return Err(e);
            };
            self.k += 1;
            let mut args = vec![self.sum()?];
            while self.eat(",") {
                args.push(self.sum()?);
            }
            if !self.eat(")") {
                return Err(err("a function's arguments end with `)`", self.here()));
            }
            return Ok(Expr::Call(name, args));
        }
        if !t
            .s
            .starts_with(|c: char| c == '%' || c == '#' || c.is_ascii_digit())
        {
            return Err(err(format!("`{}` is not an operand", t.s), t.at));
        }
        let xml_at = (self.xml)(t.at.clone());
        if let Some((real, n)) = word_view(self.p, &up) {
            // `%MDn`/`%MFn` over `%MWn` (low word) and `%MWn+1`.
            for w in [n, n + 1] {
                let _ = self.objs.operand(self.p, &format!("%MW{w}"), &xml_at);
            }
            let mut lines = vec![
                format!("LD MW{}", n + 1),
                "INT_TO_WORD".into(),
                "WORD_TO_DWORD".into(),
                "SHL 16".into(),
                "OR(".into(),
                format!("LD MW{n}"),
                "INT_TO_WORD".into(),
                "WORD_TO_DWORD".into(),
                ")".into(),
            ];
            lines.push(
                if real {
                    "DWORD_AS_REAL"
                } else {
                    "DWORD_TO_DINT"
                }
                .into(),
            );
            let ty = if real { Ty::Real } else { Ty::Dint };
            return Ok(Expr::Load { lines, ty });
        }
        if let Some((n, member)) = timer_member(&up) {
            // `%TMn.V`, `%TMn.P`: ET and PT in units of the time base.
            match self.objs.block(self.p, &format!("%TM{n}"), &xml_at) {
                Ok(_) => {}
                Err(NotObject::Unconfigured(why)) => {
                    let mut e = err(why, t.at);
                    e.code = UNCONFIGURED;
                    return Err(e);
                }
                Err(_) => return Err(err(format!("`{}` is not a timer", t.s), t.at)),
            }
            let base = self
                .p
                .timers
                .get(&n)
                .copied()
                .unwrap_or(DEFAULT_TIMER)
                .base_ms;
            let field = if member == "V" { "ET" } else { "PT" };
            return Ok(Expr::Load {
                lines: vec![
                    format!("LD TM{n}.{field}"),
                    "TIME_TO_DINT".into(),
                    format!("DIV DINT#{base}"),
                    "DINT_TO_INT".into(),
                ],
                ty: Ty::Int,
            });
        }
        match self.objs.operand(self.p, &t.s, &xml_at) {
            Ok(o) => Ok(Expr::Leaf { il: o.il, ty: o.ty }),
            Err(NotObject::Unknown) => Err(err(
                format!("`{}` is not an M221 object or a number", t.s),
                t.at,
            )),
            Err(NotObject::Unsupported(why)) => {
                let mut e = err(why, t.at);
                e.code = UNSUPPORTED;
                Err(e)
            }
            Err(NotObject::Unconfigured(why)) => {
                let mut e = err(why, t.at);
                e.code = UNCONFIGURED;
                Err(e)
            }
        }
    }
}

/// In a project whose memory objects share words: `%MF4` → (true, 4),
/// `%MD2` → (false, 2); `None` otherwise.
pub(super) fn word_view(p: &Project, up: &str) -> Option<(bool, u32)> {
    if !p.shared_words {
        return None;
    }
    let (real, n) = match (up.strip_prefix("%MF"), up.strip_prefix("%MD")) {
        (Some(n), _) => (true, n),
        (_, Some(n)) => (false, n),
        _ => return None,
    };
    let ok = !n.is_empty() && n.len() < 6 && n.bytes().all(|b| b.is_ascii_digit());
    Some((real, n.parse().ok().filter(|_| ok)?))
}

/// `%TM3.V` → (3, "V"); also `.P`.
pub(super) fn timer_member(up: &str) -> Option<(u32, &str)> {
    let (obj, member) = up.strip_prefix("%TM")?.split_once('.')?;
    let n = obj
        .parse()
        .ok()
        .filter(|_| obj.len() < 6 && obj.bytes().all(|b| b.is_ascii_digit()))?;
    matches!(member, "V" | "P").then_some((n, member))
}

/// The type of an expression's value.
pub(super) fn ty(e: &Expr) -> Ty {
    match e {
        Expr::Leaf { ty, .. } | Expr::Load { ty, .. } => *ty,
        Expr::Bin(l, op, r) => {
            if matches!(*op, "EQ" | "NE" | "LT" | "LE" | "GT" | "GE") {
                Ty::Bool
            } else {
                Ty::join(ty(l), ty(r))
            }
        }
        Expr::Not(x) => ty(x),
        Expr::Call(f, args) => FUNCTIONS
            .iter()
            .find(|(n, _)| n == f)
            .and_then(|(_, t)| *t)
            .unwrap_or_else(|| args.first().map_or(Ty::Int, ty)),
    }
}

/// A parsed block: an assignment `dest := expr` or a comparison.
pub(super) enum Parsed {
    Assign {
        dest: Dest,
        dest_ty: Ty,
        value: Expr,
    },
    Compare(Expr),
}

/// Where an operation block stores.
pub(super) enum Dest {
    /// An object: `ST dest`.
    Plain(String),
    /// A timer's preset `%TMn.P`, in units of its base (ms): `PT`.
    Preset { timer: String, base_ms: u64 },
    /// `%MFn` (`real`) or `%MDn` over the words `%MWn` (low) and `%MWn+1`.
    Words { n: u32, real: bool },
}

/// Parse the text between `[` and `]` (starting at byte `base` of the line).
pub(super) fn parse(
    p: &Project,
    objs: &mut Objects,
    text: &str,
    base: usize,
    xml: &dyn Fn(Range<usize>) -> Range<usize>,
) -> Result<Parsed, Error> {
    let parsed = parse_block(p, objs, text, base, xml)?;
    if let Parsed::Assign { dest_ty, value, .. } = &parsed {
        // The M221 assigns within a type; IEC widens INT to DINT only.
        let v = ty(value);
        let real = |t: Ty| matches!(t, Ty::Real | Ty::RealLit);
        let int = |t: Ty| matches!(t, Ty::Int | Ty::Dint);
        let narrowing = *dest_ty == Ty::Int && v == Ty::Dint;
        if real(*dest_ty) && int(v) || int(*dest_ty) && real(v) || narrowing {
            let what = match (dest_ty, v) {
                (Ty::Real, Ty::Int) => "convert with INT_TO_REAL",
                (Ty::Real, _) => "convert with DINT_TO_REAL",
                (Ty::Int, Ty::Dint) => "a double word does not fit a word (DINT_TO_INT)",
                (Ty::Int, _) => "convert with REAL_TO_INT",
                _ => "convert with REAL_TO_DINT or TRUNC",
            };
            return Err(err(
                format!(
                    "the value is {}, the object assigned is {}: {what}",
                    v.name(),
                    dest_ty.name()
                ),
                base..base + text.len(),
            ));
        }
    }
    Ok(parsed)
}

/// [`parse`] before the check of an assignment's types.
fn parse_block(
    p: &Project,
    objs: &mut Objects,
    text: &str,
    base: usize,
    xml: &dyn Fn(Range<usize>) -> Range<usize>,
) -> Result<Parsed, Error> {
    let toks = tokens(text, base);
    let end = base + text.len()..base + text.len();
    let mut ps = Parser {
        toks,
        k: 0,
        p,
        objs,
        xml,
        end,
    };
    if ps.toks.get(1).is_some_and(|t| t.s == ":=") {
        let d = ps.primary()?;
        ps.k += 1;
        if let Some((real, n)) = word_view(p, &ps.toks[0].s.to_ascii_uppercase()) {
            let value = ps.sum()?;
            if ps.k < ps.toks.len() {
                return Err(err("unexpected text after the expression", ps.here()));
            }
            return Ok(Parsed::Assign {
                dest: Dest::Words { n, real },
                dest_ty: if real { Ty::Real } else { Ty::Dint },
                value,
            });
        }
        if let Some((n, m)) = timer_member(&ps.toks[0].s.to_ascii_uppercase()) {
            if m == "V" {
                return Err(err(
                    "a timer's current value `.V` is read only",
                    ps.toks[0].at.clone(),
                ));
            }
            let value = ps.sum()?;
            if ps.k < ps.toks.len() {
                return Err(err("unexpected text after the expression", ps.here()));
            }
            let base_ms = p.timers.get(&n).copied().unwrap_or(DEFAULT_TIMER).base_ms;
            return Ok(Parsed::Assign {
                dest: Dest::Preset {
                    timer: format!("TM{n}"),
                    base_ms,
                },
                dest_ty: Ty::Int,
                value,
            });
        }
        let Expr::Leaf { il, ty } = d else {
            return Err(err("the left of `:=` is an object", base..base + 1));
        };
        if matches!(ty, Ty::IntLit | Ty::RealLit) || il.starts_with("KW") {
            return Err(err(
                "the left of `:=` is a number or constant, which cannot be assigned",
                ps.toks[0].at.clone(),
            ));
        }
        let value = ps.sum()?;
        if ps.k < ps.toks.len() {
            return Err(err("unexpected text after the expression", ps.here()));
        }
        return Ok(Parsed::Assign {
            dest: Dest::Plain(il),
            dest_ty: ty,
            value,
        });
    }
    let l = ps.sum()?;
    let op = match ps.peek() {
        Some("=") => "EQ",
        Some("<>") => "NE",
        Some("<") => "LT",
        Some("<=") => "LE",
        Some(">") => "GT",
        Some(">=") => "GE",
        _ => {
            return Err(err(
                "a block holds an assignment `x := ...` or a comparison (`=`, `<>`, `<`, `<=`, `>`, `>=`)",
                ps.here(),
            ));
        }
    };
    ps.k += 1;
    let r = ps.sum()?;
    if ps.k < ps.toks.len() {
        return Err(err("unexpected text after the comparison", ps.here()));
    }
    Ok(Parsed::Compare(Expr::Bin(Box::new(l), op, Box::new(r))))
}

/// The conversions to and from the bit string of an integer type (`NOT`,
/// `AND` ... on a word).
fn bit_string(t: Ty) -> Option<(&'static str, &'static str)> {
    match t {
        Ty::Int | Ty::IntLit => Some(("INT_TO_WORD", "WORD_TO_INT")),
        Ty::Dint => Some(("DINT_TO_DWORD", "DWORD_TO_DINT")),
        _ => None,
    }
}

/// A literal written with the type of its context (`INT#1`, `REAL#2.0`).
fn typed(il: &str, ty: Ty, ctx: Ty) -> String {
    match (ty, ctx) {
        (Ty::IntLit, Ty::Real | Ty::RealLit) => format!("REAL#{il}.0"),
        (Ty::IntLit, Ty::Int | Ty::Dint) => format!("{}#{il}", ctx.name()),
        (Ty::RealLit, Ty::Real | Ty::RealLit) => format!("REAL#{il}"),
        _ => il.to_string(),
    }
}

/// The IL lines that leave `e`'s value in the CR; `ctx` is the type its
/// literals take. `temp` declares a temporary of a type and gives its name.
pub(super) fn emit(e: &Expr, ctx: Ty, out: &mut Vec<String>, temp: &mut dyn FnMut(Ty) -> String) {
    match e {
        Expr::Leaf { il, ty } => out.push(format!("LD {}", typed(il, *ty, ctx))),
        Expr::Load { lines, .. } => out.extend(lines.iter().cloned()),
        Expr::Bin(l, op, r) => {
            // A comparison's sides have their own type.
            let ctx = if matches!(*op, "EQ" | "NE" | "LT" | "LE" | "GT" | "GE") {
                Ty::join(ty(l), ty(r))
            } else {
                ctx
            };
            // AND/OR/XOR of words: IEC has them on bit strings only.
            if let (true, Some((to, back))) = (matches!(*op, "AND" | "OR" | "XOR"), bit_string(ctx))
            {
                emit(l, ctx, out, temp);
                out.push(to.into());
                out.push(format!("{op}("));
                emit(r, ctx, out, temp);
                out.push(to.into());
                out.push(")".into());
                out.push(back.into());
                return;
            }
            emit(l, ctx, out, temp);
            match &**r {
                Expr::Leaf { il, ty } => out.push(format!("{op} {}", typed(il, *ty, ctx))),
                r => {
                    out.push(format!("{op}("));
                    emit(r, ctx, out, temp);
                    out.push(")".into());
                }
            }
        }
        Expr::Not(x) => {
            emit(x, ctx, out, temp);
            match bit_string(ctx) {
                Some((to, back)) => out.extend([to.to_string(), "NOT".into(), back.into()]),
                None => out.push("NOT".into()),
            }
        }
        Expr::Call(f, args) => {
            let arg_ctx = args.first().map_or(ctx, |a| Ty::join(ty(a), ctx));
            let arg_ctx = if FUNCTIONS.iter().any(|(n, t)| n == f && t.is_some()) {
                args.first().map_or(ctx, ty)
            } else {
                arg_ctx
            };
            // The later arguments first, into temporaries: the first is the CR.
            let mut rest = Vec::new();
            for a in args.iter().skip(1) {
                match a {
                    Expr::Leaf { il, ty } => rest.push(typed(il, *ty, arg_ctx)),
                    a => {
                        let t = temp(Ty::join(ty(a), arg_ctx));
                        emit(a, arg_ctx, out, temp);
                        out.push(format!("ST {t}"));
                        rest.push(t);
                    }
                }
            }
            match args.first() {
                Some(a) => emit(a, arg_ctx, out, temp),
                None => out.push(format!("LD {}", typed("0", Ty::IntLit, arg_ctx))),
            }
            let word = ON_WORDS.iter().find(|(m, _)| m == f);
            let name = word.map_or(*f, |(_, iec)| iec);
            // BCD_TO_INT gives an INT itself; the others give a WORD.
            if word.is_some() && name != "INT_TO_BCD" {
                out.push("INT_TO_WORD".into());
            }
            if rest.is_empty() {
                out.push(name.to_string());
            } else {
                out.push(format!("{name} {}", rest.join(", ")));
            }
            if word.is_some() && name != "BCD_TO_INT" {
                out.push("WORD_TO_INT".into());
            }
        }
    }
}
