//! Hover: the CR before and after an instruction (and the paths into a
//! label where they disagree), a variable's declaration, a standard
//! function's or block's signature. What a name names is the checker's
//! resolution table's answer; its declaration's text is the index's.

use lsp_types::{Hover, HoverContents, MarkupContent, MarkupKind, Position, Uri};

use super::index::{Index, Kind, fb_signature};
use super::workspace::Workspace;
use il_codegen::ast::{self, PouKind};
use il_codegen::ir::{CrState, CrStep, SymbolId, SymbolKind};
use il_interp::il_std::signature::{self as sig, Class, Ext, ParamTy, Signature};

pub fn hover(ws: &Workspace, uri: &Uri, pos: Position) -> Option<Hover> {
    let (k, off) = ws.locate(uri, pos)?;
    let ix = ws.analysis.index(k)?;
    let named = ix.name_at(k, off).and_then(|(span, s)| {
        let mut text = symbol_text(ws, ix, s)?;
        // A user FUNCTION called as an operator: the CR it takes and gives.
        if matches!(ix.table.symbols[s].kind, SymbolKind::Pou(PouKind::Function))
            && ix.table.symbols[s].decl.is_none_or(|d| d.span != span)
            && let Some(step) = ix.step_at(k, off).filter(|st| !st.label)
            && let Some(step) = ws.cr_step(k, step)
        {
            text.push_str(&format!(
                "\n\n---\n\nCalled here with the current result as its first input: CR before: {}, CR after (its result): {}",
                cr(&step.before),
                cr(&step.after)
            ));
        }
        Some((span, text))
    });
    let (span, text) = match named {
        Some(n) => n,
        None => {
            let s = ix.step_at(k, off)?;
            (s.span, step_text(ws.cr_step(k, s)?))
        }
    };
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: text,
        }),
        range: Some(ws.range(k, span)),
    })
}

/// What symbol `s` of the table is: its declaration as written, or a
/// standard function's or block's signature.
fn symbol_text(ws: &Workspace, ix: &Index, s: SymbolId) -> Option<String> {
    let t = &ix.table.symbols[s];
    Some(match t.kind {
        SymbolKind::StdFunction => fn_signature(sig::lookup(&t.name)?),
        SymbolKind::StdBlock => fb_signature(sig::lookup_fb(&t.name)?),
        SymbolKind::StdMember { block, input } => {
            let fb = sig::lookup_fb(&ix.table.symbols[block].name)?;
            let list = if input { fb.inputs } else { fb.outputs };
            let p = list.iter().find(|p| p.name == t.name)?;
            format!(
                "```il\n{} : {}\n```\n\n{} of the standard function block `{}`",
                p.name,
                p.ty.name(),
                if input { "input" } else { "output" },
                fb.name
            )
        }
        SymbolKind::Pou(PouKind::Function) => match ix.declared(s) {
            Some(d) => function_text(ix, d),
            None => other_text(ix, s),
        },
        _ => match ix.declared(s) {
            Some(d) => declaration_text(ws, ix, d),
            None => other_text(ix, s),
        },
    })
}

/// A name the index keeps no declaration text for (an enumeration value,
/// a resource, a program instance): what it is.
fn other_text(ix: &Index, s: SymbolId) -> String {
    let t = &ix.table.symbols;
    let sym = &t[s];
    let what = match sym.kind {
        SymbolKind::EnumValue { ty } => format!("value of the enumeration `{}`", t[ty].name),
        SymbolKind::Resource { config } => {
            format!("RESOURCE of CONFIGURATION `{}`", t[config].name)
        }
        SymbolKind::ProgramInstance { config } => {
            format!("program instance of CONFIGURATION `{}`", t[config].name)
        }
        k => format!("{k:?}"),
    };
    format!("```il\n{}\n```\n\n{what}", sym.name)
}

/// A user FUNCTION: its header, its inputs, in-outs and outputs in order
/// (the first input is the CR when it is called as an operator).
fn function_text(ix: &Index, f: super::index::SymId) -> String {
    let sym = &ix.symbols[f];
    let mut sections: Vec<(ast::VarKind, Vec<String>)> = Vec::new();
    for &v in ix.members.get(&f).map_or(&[][..], Vec::as_slice) {
        let Kind::Var(kind) = ix.symbols[v].kind else {
            continue;
        };
        if !matches!(
            kind,
            ast::VarKind::Input | ast::VarKind::InOut | ast::VarKind::Output
        ) {
            continue;
        }
        // The declaration's own line: `VAR_INPUT / x : INT; / END_VAR`.
        let line = ix.symbols[v]
            .decl
            .lines()
            .nth(1)
            .unwrap_or("")
            .trim()
            .to_string();
        match sections.last_mut() {
            Some((k, lines)) if *k == kind => lines.push(line),
            _ => sections.push((kind, vec![line])),
        }
    }
    let mut out = format!("```il\n{}", sym.decl);
    for (kind, lines) in &sections {
        out.push_str(&format!("\n{}", kind.keyword()));
        for l in lines {
            out.push_str(&format!("\n    {l}"));
        }
        out.push_str("\nEND_VAR");
    }
    out.push_str("\n```");
    let first = sections
        .iter()
        .find(|(k, _)| *k == ast::VarKind::Input)
        .and_then(|(_, l)| l.first());
    if let Some(first) = first {
        let name = first.split([':', ',', ' ']).next().unwrap_or("");
        out.push_str(&format!(
            "\n\nAs an operator (`{} ...`), the current result is its first input `{name}` and its result becomes the current result.",
            ix.symbols[f].name
        ));
    }
    out
}

/// A declared name: its declaration as written, and for a label the CR
/// there.
fn declaration_text(ws: &Workspace, ix: &Index, s: super::index::SymId) -> String {
    let sym = &ix.symbols[s];
    let mut out = format!("```il\n{}\n```", sym.decl);
    if !sym.note.is_empty() {
        out.push_str("\n\n");
        out.push_str(&sym.note);
    }
    if sym.kind == Kind::Label
        && let Some(step) = ix
            .step_at(sym.file, sym.span.lo as usize)
            .filter(|s| s.label)
        && let Some(step) = ws.cr_step(sym.file, step)
    {
        out.push_str("\n\n");
        out.push_str(&step_text(step));
    }
    out
}

fn cr(s: &CrState) -> String {
    match s {
        CrState::Typed(t) => format!("`{t}`"),
        other => other.to_string(),
    }
}

fn step_text(s: &CrStep) -> String {
    if s.label {
        let mut out = format!("CR at this label: {}", cr(&s.after));
        if let Some(p) = &s.paths {
            out.push_str(&format!("\n\nthe paths into this label disagree: {p}"));
        } else if s.before != CrState::Dead && s.before != s.after {
            out.push_str(&format!("\n\nfalling through: {}", cr(&s.before)));
        }
        return out;
    }
    format!("CR before: {}\n\nCR after: {}", cr(&s.before), cr(&s.after))
}

fn class_name(c: Class) -> &'static str {
    match c {
        Class::AnyNum => "ANY_NUM",
        Class::AnyInt => "ANY_INT",
        Class::AnyReal => "ANY_REAL",
        Class::AnyBit => "ANY_BIT",
        Class::AnyBitString => "ANY_BIT",
        Class::AnyMagnitude => "ANY_MAGNITUDE",
        Class::AnyElementary => "ANY_ELEMENTARY",
        Class::AnyString => "ANY_STRING",
        Class::AnyDate => "ANY_DATE",
        Class::Any => "ANY",
        Class::Bool => "BOOL",
    }
}

/// A parameter's type as signatures show it (`T: ANY_NUM`).
pub(super) fn param_ty(t: ParamTy) -> String {
    match t {
        ParamTy::Concrete(e) => e.name().to_string(),
        ParamTy::T(c) => format!("T: {}", class_name(c)),
        ParamTy::Other(c) => class_name(c).to_string(),
    }
}

/// `LIMIT(MN : T: ANY_ELEMENTARY, ...) : T: ANY_ELEMENTARY` and what it does.
pub fn fn_signature(f: &Signature) -> String {
    let mut params: Vec<String> = f
        .params
        .iter()
        .map(|p| format!("{} : {}", p.name, param_ty(p.ty)))
        .collect();
    if matches!(f.ext, Ext::Fold | Ext::Chain | Ext::Mux) {
        params.push("...".into());
    }
    format!(
        "```il\nFUNCTION {}({}) : {}\n```\n\nstandard function: {}",
        f.name,
        params.join(", "),
        param_ty(f.ret),
        f.doc
    )
}
