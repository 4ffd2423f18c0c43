//! Go to definition, find references, rename (variables and labels).

use std::collections::HashMap;

use lsp_types::{Location, Position, PrepareRenameResponse, TextEdit, Uri, WorkspaceEdit};

use super::index::{Index, Kind, SymId, Target};
use super::workspace::Workspace;

/// The symbol named at a position, and the index of its program.
fn symbol_at<'w>(
    ws: &'w Workspace,
    uri: &Uri,
    pos: Position,
) -> Option<(usize, il_codegen::ast::Span, SymId, &'w Index)> {
    let (k, off) = ws.locate(uri, pos)?;
    let ix = ws.analysis.index(k)?;
    match ix.ref_at(k, off)? {
        (span, Target::Sym(s)) => Some((k, span, s, ix)),
        _ => None,
    }
}

pub fn definition(ws: &Workspace, uri: &Uri, pos: Position) -> Option<Location> {
    let (_, _, s, ix) = symbol_at(ws, uri, pos)?;
    let sym = &ix.symbols[s];
    ws.location(sym.file, sym.span)
}

pub fn references(ws: &Workspace, uri: &Uri, pos: Position, with_decl: bool) -> Vec<Location> {
    let Some((_, _, s, ix)) = symbol_at(ws, uri, pos) else {
        return Vec::new();
    };
    let sym = &ix.symbols[s];
    ix.uses[s]
        .iter()
        .filter(|(f, span)| with_decl || !(*f == sym.file && *span == sym.span))
        .filter_map(|(f, span)| ws.location(*f, *span))
        .collect()
}

fn renamable(kind: Kind) -> bool {
    matches!(kind, Kind::Var(_) | Kind::Label)
}

pub fn prepare_rename(ws: &Workspace, uri: &Uri, pos: Position) -> Option<PrepareRenameResponse> {
    let (k, span, s, ix) = symbol_at(ws, uri, pos)?;
    renamable(ix.symbols[s].kind).then(|| PrepareRenameResponse::Range(ws.range(k, span)))
}

/// An IEC identifier: a letter or `_`, then letters, digits and single `_`.
fn is_identifier(s: &str) -> bool {
    let b = s.as_bytes();
    !b.is_empty()
        && (b[0].is_ascii_alphabetic() || b[0] == b'_')
        && b.iter().all(|c| c.is_ascii_alphanumeric() || *c == b'_')
        && !s.contains("__")
}

pub fn rename(
    ws: &Workspace,
    uri: &Uri,
    pos: Position,
    new_name: &str,
) -> Result<Option<WorkspaceEdit>, String> {
    let Some((_, _, s, ix)) = symbol_at(ws, uri, pos) else {
        return Ok(None);
    };
    if !renamable(ix.symbols[s].kind) {
        return Err("only variables and labels can be renamed".into());
    }
    if !is_identifier(new_name) {
        return Err(format!("`{new_name}` is not an IEC 61131-3 identifier"));
    }
    // `WorkspaceEdit` is keyed by `Uri`, whose hash does not change.
    #[allow(clippy::mutable_key_type)]
    let mut changes: HashMap<Uri, Vec<TextEdit>> = HashMap::new();
    for (f, span) in &ix.uses[s] {
        if let Some(loc) = ws.location(*f, *span) {
            changes
                .entry(loc.uri)
                .or_default()
                .push(TextEdit::new(loc.range, new_name.to_string()));
        }
    }
    Ok(Some(WorkspaceEdit::new(changes)))
}
