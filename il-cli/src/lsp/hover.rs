//! Hover: the CR before and after an instruction (and the paths into a
//! label where they disagree), a variable's declaration, a standard
//! function's or block's signature.

use lsp_types::{Hover, HoverContents, MarkupContent, MarkupKind, Position, Uri};

use super::index::{Index, Kind, Step, Target, fb_signature};
use super::workspace::Workspace;
use il_codegen::ir::CrState;
use il_interp::il_std::signature::{Class, Ext, ParamTy, Signature};

pub fn hover(ws: &Workspace, uri: &Uri, pos: Position) -> Option<Hover> {
    let (k, off) = ws.locate(uri, pos)?;
    let ix = ws.analysis.index(k)?;
    let (span, text) = match ix.ref_at(k, off) {
        Some((span, t)) => (span, target_text(ix, t)),
        None => {
            let s = ix.step_at(k, off)?;
            (s.span, step_text(s))
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

fn target_text(ix: &Index, t: Target) -> String {
    match t {
        Target::Sym(s) => {
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
            {
                out.push_str("\n\n");
                out.push_str(&step_text(step));
            }
            out
        }
        Target::StdFn(f) => fn_signature(f),
        Target::StdFb(fb) => fb_signature(fb),
        Target::StdMember(fb, i) => {
            let (dir, p) = match fb.inputs.get(i) {
                Some(p) => ("input", p),
                None => ("output", &fb.outputs[i - fb.inputs.len()]),
            };
            format!(
                "```il\n{} : {}\n```\n\n{dir} of the standard function block `{}`",
                p.name,
                p.ty.name(),
                fb.name
            )
        }
    }
}

fn cr(s: &CrState) -> String {
    match s {
        CrState::Typed(t) => format!("`{t}`"),
        other => other.to_string(),
    }
}

fn step_text(s: &Step) -> String {
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

fn param_ty(t: ParamTy) -> String {
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
