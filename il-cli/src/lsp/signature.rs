//! `textDocument/signatureHelp` for the calls of IL: a function as an
//! operator (`LIMIT 0, 100`: the current result is its first input), a
//! formal function call (`LIMIT(MN := 0, IN := x, MX := 100)`) and an FB
//! call (`CAL t1(IN := go, PT := T#5s)`), user or standard: the parameters
//! in order and the one being written.

use lsp_types::{
    Documentation, ParameterInformation, ParameterLabel, Position, SignatureHelp,
    SignatureInformation, Uri,
};

use il_codegen::ast::{PouKind, VarKind};
use il_interp::il_std::signature as sig;

use super::index::{Index, Kind};
use super::workspace::Workspace;

/// A callee's parameters: (name, type) in order, and what it is.
struct Callee {
    label: String,
    params: Vec<(String, String)>,
    /// A function called as an operator takes the CR as its first input.
    operator: bool,
    doc: String,
}

pub fn help(ws: &Workspace, uri: &Uri, pos: Position) -> Option<SignatureHelp> {
    let (k, off) = ws.locate(uri, pos)?;
    let ix = ws.analysis.index(k)?;
    let text = &ws.docs[k].text;
    let line_start = text[..off].rfind('\n').map_or(0, |i| i + 1);
    if let Some(h) = help_from(ix, k, text, line_start, off) {
        return Some(h);
    }
    // An argument list over lines: the nearest earlier line whose `(` is
    // still open at the cursor (a few lines back at most).
    let mut s = line_start;
    for _ in 0..32 {
        if s == 0 {
            break;
        }
        s = text[..s - 1].rfind('\n').map_or(0, |i| i + 1);
        let seg = &text[s..off];
        if seg.matches('(').count() > seg.matches(')').count() {
            return help_from(ix, k, text, s, off);
        }
    }
    None
}

/// The signature help of the call written from `start` to the cursor.
fn help_from(ix: &Index, k: usize, text: &str, start: usize, off: usize) -> Option<SignatureHelp> {
    let (callee, args) = split_call(&text[start..off])?;
    let callee = match callee {
        CalleeRef::Function(name) => fn_callee(ix, name, args.formal)?,
        CalleeRef::Instance { name, at } => fb_callee(ix, k, start + at, name)?,
    };
    // Which parameter: a formal one by its name, else by its position
    // (after the CR for an operator).
    let active = match args.current_name {
        Some(n) => callee
            .params
            .iter()
            .position(|(p, _)| p.eq_ignore_ascii_case(n))
            .unwrap_or(args.commas),
        None => args.commas + usize::from(callee.operator && !args.formal),
    };
    let params: Vec<ParameterInformation> = callee
        .params
        .iter()
        .map(|(n, t)| ParameterInformation {
            label: ParameterLabel::Simple(format!("{n} : {t}")),
            documentation: None,
        })
        .collect();
    let label = format!(
        "{}({})",
        callee.label,
        callee
            .params
            .iter()
            .map(|(n, t)| format!("{n} : {t}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let mut doc = callee.doc;
    if callee.operator
        && !args.formal
        && let Some((first, _)) = callee.params.first()
    {
        doc.push_str(&format!(
            "\n\nAs an operator, the current result is its first input `{first}`."
        ));
    }
    Some(SignatureHelp {
        signatures: vec![SignatureInformation {
            label,
            documentation: Some(Documentation::String(doc)),
            parameters: Some(params),
            active_parameter: Some(active as u32),
        }],
        active_signature: Some(0),
        active_parameter: Some(active as u32),
    })
}

/// What is called.
enum CalleeRef<'a> {
    /// A function, by name (an operator or a formal call).
    Function(&'a str),
    /// An FB instance after `CAL`, named at byte `at` of the text.
    Instance { name: &'a str, at: usize },
}

/// The arguments written so far.
struct Args<'a> {
    formal: bool,
    commas: usize,
    /// `NAME :=` (or `NAME =>`) of the argument being written.
    current_name: Option<&'a str>,
}

/// The callee and the arguments of the instruction text before the
/// cursor; `None` when it is no call (`LD x`, `AND(`: IL's own operators).
fn split_call(before: &str) -> Option<(CalleeRef<'_>, Args<'_>)> {
    let mut rest = before.trim_start();
    // A label.
    if let Some(i) = rest.find(':')
        && !rest[i..].starts_with(":=")
        && !rest[..i].trim().is_empty()
        && rest[..i]
            .trim()
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_')
    {
        rest = rest[i + 1..].trim_start();
    }
    let at = before.len() - rest.len();
    let word_end = rest
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    let op = &rest[..word_end];
    if op.is_empty() || word_end == rest.len() {
        return None;
    }
    let after = &rest[word_end..];
    if ["CAL", "CALC", "CALCN", "CALNC"]
        .iter()
        .any(|c| op.eq_ignore_ascii_case(c))
    {
        let a = after.trim_start();
        let name_at = at + word_end + (after.len() - a.len());
        let end = a
            .find(|c: char| !(c.is_ascii_alphanumeric() || "_.[]".contains(c)))
            .unwrap_or(a.len());
        let args = a[end..].trim_start().strip_prefix('(')?;
        let name = &before[name_at..name_at + end];
        return Some((
            CalleeRef::Instance { name, at: name_at },
            parse_args(args, true),
        ));
    }
    // IL's own operators (`ADD(` opens a deferred operation, not a call).
    if super::completion::OPERATORS
        .iter()
        .any(|(o, _)| o.eq_ignore_ascii_case(op))
    {
        return None;
    }
    let (formal, args) = match after.strip_prefix('(') {
        Some(args) => (true, args),
        None => (false, after.trim_start()),
    };
    Some((CalleeRef::Function(op), parse_args(args, formal)))
}

fn parse_args(args: &str, formal: bool) -> Args<'_> {
    // Commas at the top level of the list (a subscript's do not count).
    let (mut depth, mut commas, mut seg_start) = (0i32, 0, 0);
    for (i, c) in args.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' if depth == 0 => {
                commas += 1;
                seg_start = i + 1;
            }
            _ => {}
        }
    }
    let seg = &args[seg_start..];
    let current_name = formal
        .then(|| seg.find(":=").or_else(|| seg.find("=>")))
        .flatten()
        .map(|i| seg[..i].trim().trim_start_matches("NOT ").trim())
        .filter(|n| !n.is_empty());
    Args {
        formal,
        commas,
        current_name,
    }
}

/// A function named `name`: the user's FUNCTION, else il-std's.
fn fn_callee(ix: &Index, name: &str, formal: bool) -> Option<Callee> {
    if let Some(&p) = ix.pou_by_name.get(&name.to_ascii_uppercase())
        && ix.symbols[p].kind == Kind::Pou(PouKind::Function)
    {
        return Some(Callee {
            label: ix.symbols[p].name.clone(),
            params: params_of(ix, p, &[VarKind::Input, VarKind::InOut]),
            operator: true,
            doc: ix.symbols[p].decl.clone(),
        });
    }
    let f = sig::lookup(name)?;
    let mut params: Vec<(String, String)> = f
        .params
        .iter()
        .map(|p| (p.name.to_string(), super::hover::param_ty(p.ty)))
        .collect();
    if !formal && matches!(f.ext, sig::Ext::Fold | sig::Ext::Chain | sig::Ext::Mux) {
        params.push(("...".into(), String::new()));
    }
    Some(Callee {
        label: f.name.to_string(),
        params,
        operator: true,
        doc: f.doc.to_string(),
    })
}

/// The FB type of instance `inst` (named at `at` of document `k`).
fn fb_callee(ix: &Index, k: usize, at: usize, inst: &str) -> Option<Callee> {
    let (_, s) = ix.name_at(k, at)?;
    let ty = match ix.declared(s) {
        Some(d) => ix.symbols[d].ty.clone()?,
        None => return None,
    };
    if let Some(&p) = ix.pou_by_name.get(&ty) {
        return Some(Callee {
            label: format!("{inst} : {}", ix.symbols[p].name),
            params: params_of(ix, p, &[VarKind::Input, VarKind::InOut]),
            operator: false,
            doc: ix.symbols[p].decl.clone(),
        });
    }
    let fb = sig::lookup_fb(&ty)?;
    Some(Callee {
        label: format!("{inst} : {}", fb.name),
        params: fb
            .inputs
            .iter()
            .map(|p| (p.name.to_string(), p.ty.name().to_string()))
            .collect(),
        operator: false,
        doc: format!("standard function block {}", fb.name),
    })
}

/// A POU's variables of the sections `kinds`, in order: (name, type).
fn params_of(ix: &Index, pou: usize, kinds: &[VarKind]) -> Vec<(String, String)> {
    ix.members
        .get(&pou)
        .map_or(&[][..], Vec::as_slice)
        .iter()
        .filter_map(|&v| {
            let s = &ix.symbols[v];
            let Kind::Var(k) = s.kind else { return None };
            if !kinds.contains(&k) {
                return None;
            }
            // `VAR_INPUT / x : INT := 1; / END_VAR`: the type is after `:`.
            let line = s.decl.lines().nth(1).unwrap_or("");
            let ty = line
                .split_once(':')
                .map(|(_, t)| t.split([';', ':']).next().unwrap_or("").trim())
                .unwrap_or("");
            Some((s.name.clone(), ty.to_string()))
        })
        .collect()
}

/// The VAR_INPUTs, in order, of the block of the instance named at byte
/// `at` of document `k`: what a non-formal `CAL inst(a, b)` binds.
pub(super) fn instance_inputs(ix: &Index, k: usize, at: usize) -> Option<Vec<String>> {
    let (_, s) = ix.name_at(k, at)?;
    let ty = ix.symbols[ix.declared(s)?].ty.clone()?;
    if let Some(&p) = ix.pou_by_name.get(&ty) {
        return Some(
            params_of(ix, p, &[VarKind::Input])
                .into_iter()
                .map(|(n, _)| n)
                .collect(),
        );
    }
    let fb = sig::lookup_fb(&ty)?;
    Some(fb.inputs.iter().map(|p| p.name.to_string()).collect())
}
