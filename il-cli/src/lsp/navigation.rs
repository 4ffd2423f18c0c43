//! Go to definition, find references, document highlight, rename
//! (variables, globals and labels): all from the checker's resolution
//! table ([`il_codegen::ir::Resolutions`]).

use std::collections::HashMap;

use il_codegen::ir::{SymbolId, SymbolKind};
use lsp_types::{
    DocumentHighlight, Location, Position, PrepareRenameResponse, TextEdit, Uri, WorkspaceEdit,
};

use super::index::Index;
use super::workspace::Workspace;

/// The name at a position: its document, span and symbol, and the index of
/// its program.
fn symbol_at<'w>(
    ws: &'w Workspace,
    uri: &Uri,
    pos: Position,
) -> Option<(usize, il_codegen::ast::Span, SymbolId, &'w Index)> {
    let (k, off) = ws.locate(uri, pos)?;
    let ix = ws.analysis.index(k)?;
    let (span, s) = ix.name_at(k, off)?;
    Some((k, span, s, ix))
}

pub fn definition(ws: &Workspace, uri: &Uri, pos: Position) -> Option<Location> {
    let (_, _, s, ix) = symbol_at(ws, uri, pos)?;
    let sym = &ix.table.symbols[s];
    match sym.kind {
        SymbolKind::StdBlock => return std_block(&sym.name, None),
        SymbolKind::StdMember { block, .. } => {
            return std_block(&ix.table.symbols[block].name, Some(&sym.name));
        }
        _ => {}
    }
    let d = sym.decl?;
    ws.location(d.file, d.span)
}

/// A standard function block's declaration, rendered from il-std's table
/// into a read-only file of its own (written once per version, and again
/// only if it differs), at the line of `member` or of the block's name.
fn std_block(name: &str, member: Option<&str>) -> Option<Location> {
    let fb = il_interp::il_std::signature::lookup_fb(name)?;
    let mut text = format!(
        "(* il-std's standard function block {0}, as the compiler knows it: a rendering, not a source to edit. *)\nFUNCTION_BLOCK {0}\n",
        fb.name
    );
    let mut at = (1, "FUNCTION_BLOCK ".len());
    for (kw, params) in [("VAR_INPUT", fb.inputs), ("VAR_OUTPUT", fb.outputs)] {
        text.push_str(kw);
        text.push('\n');
        for p in params {
            if member.is_some_and(|m| m.eq_ignore_ascii_case(p.name)) {
                at = (text.lines().count(), 4);
            }
            text.push_str(&format!("    {} : {};\n", p.name, p.ty.name()));
        }
        text.push_str("END_VAR\n");
    }
    text.push_str("END_FUNCTION_BLOCK\n");
    let dir = std::env::temp_dir().join(format!("ilc-std-{}", env!("CARGO_PKG_VERSION")));
    let path = dir.join(format!("{}.il", fb.name));
    if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
        std::fs::create_dir_all(&dir).ok()?;
        // Beside it, then renamed: two servers never read half a file.
        let tmp = dir.join(format!(".{}.{}", fb.name, std::process::id()));
        std::fs::write(&tmp, &text).ok()?;
        std::fs::rename(&tmp, &path).ok()?;
    }
    let start = Position::new(at.0 as u32, at.1 as u32);
    let len = member.unwrap_or(fb.name).len() as u32;
    Some(Location {
        uri: super::convert::path_to_uri(&path)?,
        range: lsp_types::Range::new(start, Position::new(start.line, start.character + len)),
    })
}

pub fn references(ws: &Workspace, uri: &Uri, pos: Position, with_decl: bool) -> Vec<Location> {
    let Some((_, _, s, ix)) = symbol_at(ws, uri, pos) else {
        return Vec::new();
    };
    // A standard function or block is declared nowhere: it has uses only.
    let Some(d) = ix.table.symbols[s].decl else {
        return Vec::new();
    };
    // A translated source may declare a name where it is first used (an
    // M221 listing): that place once.
    let mut seen = std::collections::HashSet::new();
    ix.uses(s)
        .filter(|&(f, span)| with_decl || !(f == d.file && span == d.span))
        .filter(|&(f, span)| seen.insert((f, span.lo, span.hi)))
        .filter_map(|(f, span)| ws.location(f, span))
        .collect()
}

/// Every use of the name at a position in its own document.
pub fn highlight(ws: &Workspace, uri: &Uri, pos: Position) -> Vec<DocumentHighlight> {
    let Some((k, _, s, ix)) = symbol_at(ws, uri, pos) else {
        return Vec::new();
    };
    let mut seen = std::collections::HashSet::new();
    ix.uses(s)
        .filter(|&(f, span)| f == k && seen.insert((span.lo, span.hi)))
        .map(|(_, span)| DocumentHighlight {
            range: ws.range(k, span),
            kind: None,
        })
        .collect()
}

fn renamable(kind: SymbolKind) -> bool {
    matches!(
        kind,
        SymbolKind::Var { .. } | SymbolKind::Global { .. } | SymbolKind::Label { .. }
    )
}

pub fn prepare_rename(ws: &Workspace, uri: &Uri, pos: Position) -> Option<PrepareRenameResponse> {
    let (k, span, s, ix) = symbol_at(ws, uri, pos)?;
    renamable(ix.table.symbols[s].kind).then(|| PrepareRenameResponse::Range(ws.range(k, span)))
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
    let sym = &ix.table.symbols[s];
    if sym.decl.is_none() {
        return Ok(None); // a standard function or block
    }
    if !renamable(sym.kind) {
        return Err("only variables and labels can be renamed".into());
    }
    if !is_identifier(new_name) {
        return Err(format!("`{new_name}` is not an IEC 61131-3 identifier"));
    }
    // An import that writes a name another way (an M221 listing's `%M0` is
    // the IL's `M0`) has no text to rename: the name is the object's address.
    for (f, span) in ix.uses(s) {
        let text = ws
            .docs
            .get(f)
            .and_then(|d| d.text.get(span.lo as usize..span.hi as usize));
        if let Some(t) = text.filter(|t| !t.eq_ignore_ascii_case(&sym.name)) {
            return Err(format!(
                "`{t}` is how this file writes `{}`, which the compiler names so; rename it in the tool the project comes from",
                sym.name
            ));
        }
    }
    // `WorkspaceEdit` is keyed by `Uri`, whose hash does not change.
    #[allow(clippy::mutable_key_type)]
    let mut changes: HashMap<Uri, Vec<TextEdit>> = HashMap::new();
    let mut seen = std::collections::HashSet::new();
    for (f, span) in ix
        .uses(s)
        .filter(|&(f, span)| seen.insert((f, span.lo, span.hi)))
    {
        if let Some(loc) = ws.location(f, span) {
            changes
                .entry(loc.uri)
                .or_default()
                .push(TextEdit::new(loc.range, new_name.to_string()));
        }
    }
    Ok(Some(WorkspaceEdit::new(changes)))
}
