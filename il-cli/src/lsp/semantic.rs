//! `textDocument/semanticTokens/full`: every name coloured by what the
//! checker resolved it to (its resolution table), not by the TextMate
//! grammar's guess: labels and jump targets, FB instances, user and
//! standard functions and blocks, types, enumeration values, parameters.
//! Keywords, literals and comments are left to the grammar.

use lsp_types::{
    SemanticToken, SemanticTokenModifier as M, SemanticTokenType as T, SemanticTokens,
    SemanticTokensLegend, Uri,
};

use il_codegen::ast::{PouKind, VarKind};
use il_codegen::ir::SymbolKind;

use super::index::Index;
use super::workspace::Workspace;

/// The token types, in the legend's order (`instance`: a variable holding a
/// FUNCTION_BLOCK instance; `label`: a label or jump target; the VS Code
/// extension declares both in its package.json, as kinds of `variable` and
/// `macro`).
const TYPES: [&str; 10] = [
    "function",
    "class",
    "variable",
    "parameter",
    "property",
    "type",
    "enumMember",
    "namespace",
    "label",
    "instance",
];
const MODIFIERS: [&str; 3] = ["declaration", "defaultLibrary", "static"];

const DECLARATION: u32 = 1;
const DEFAULT_LIBRARY: u32 = 2;
const STATIC: u32 = 4;

pub fn legend() -> SemanticTokensLegend {
    SemanticTokensLegend {
        token_types: TYPES.iter().map(|t| T::new(t)).collect(),
        token_modifiers: MODIFIERS.iter().map(|m| M::new(m)).collect(),
    }
}

fn ty(name: &str) -> u32 {
    TYPES.iter().position(|t| *t == name).unwrap_or(2) as u32
}

/// The tokens of one document, or `None` when it is not known.
pub fn full(ws: &Workspace, uri: &Uri) -> Option<SemanticTokens> {
    let k = ws.doc(uri)?;
    let ix = ws.analysis.index(k)?;
    let file = ix.docs.binary_search(&k).ok()?;
    let text = &ws.docs[k].text;
    let lines = ws.analysis.lines.get(k)?;
    let mut data = Vec::new();
    let (mut line, mut col, mut end) = (0u32, 0u32, 0u32);
    for &(span, sym) in ix.table.uses.get(file)? {
        // Sorted, one per span; a name inside another (never, today) is
        // skipped rather than sent out of order.
        if span.lo < end || span.hi <= span.lo {
            continue;
        }
        let Some((token_type, mut mods)) = classify(ix, sym) else {
            continue;
        };
        if ix.table.symbols[sym]
            .decl
            .is_some_and(|d| d.file == k && d.span == span)
        {
            mods |= DECLARATION;
        }
        let Some(name) = text.get(span.lo as usize..span.hi as usize) else {
            continue;
        };
        let at = lines.position(text, span.lo as usize);
        let delta_line = at.line - line;
        let delta_start = if delta_line == 0 {
            at.character - col
        } else {
            at.character
        };
        data.push(SemanticToken {
            delta_line,
            delta_start,
            length: name.encode_utf16().count() as u32,
            token_type,
            token_modifiers_bitset: mods,
        });
        (line, col, end) = (at.line, at.character, span.hi);
    }
    Some(SemanticTokens {
        result_id: None,
        data,
    })
}

/// The token type and modifiers of symbol `sym`.
fn classify(ix: &Index, sym: usize) -> Option<(u32, u32)> {
    let s = ix.table.symbols.get(sym)?;
    Some(match s.kind {
        SymbolKind::Pou(PouKind::Function) => (ty("function"), 0),
        SymbolKind::Pou(_) => (ty("class"), 0),
        SymbolKind::Var { kind, .. } => {
            if holds_instance(ix, sym) {
                (ty("instance"), 0)
            } else if matches!(kind, VarKind::Input | VarKind::Output | VarKind::InOut) {
                (ty("parameter"), 0)
            } else {
                (ty("variable"), 0)
            }
        }
        SymbolKind::Global { .. } => {
            let t = if holds_instance(ix, sym) {
                "instance"
            } else {
                "variable"
            };
            (ty(t), STATIC)
        }
        SymbolKind::Label { .. } => (ty("label"), 0),
        SymbolKind::Type => (ty("type"), 0),
        SymbolKind::Field { .. } => (ty("property"), 0),
        SymbolKind::EnumValue { .. } => (ty("enumMember"), 0),
        SymbolKind::Config | SymbolKind::Resource { .. } | SymbolKind::ProgramInstance { .. } => {
            (ty("namespace"), 0)
        }
        SymbolKind::StdFunction => (ty("function"), DEFAULT_LIBRARY),
        SymbolKind::StdBlock => (ty("class"), DEFAULT_LIBRARY),
        SymbolKind::StdMember { .. } => (ty("property"), DEFAULT_LIBRARY),
    })
}

/// Whether the variable holds a FUNCTION_BLOCK instance (or an array of
/// them): its declared type is a user or standard block.
fn holds_instance(ix: &Index, sym: usize) -> bool {
    let Some(decl) = ix.declared(sym) else {
        return false;
    };
    ix.symbols[decl].ty.as_deref().is_some_and(|t| {
        il_interp::il_std::signature::lookup_fb(t).is_some()
            || ix.pou_by_name.get(t).is_some_and(|&p| {
                matches!(
                    ix.symbols[p].kind,
                    super::index::Kind::Pou(PouKind::FunctionBlock)
                )
            })
    })
}
