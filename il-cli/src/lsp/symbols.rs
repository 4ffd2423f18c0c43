//! Document symbols (POUs, their sections and variables, labels; types and
//! configurations) and workspace symbols.

use lsp_types::{DocumentSymbol, SymbolInformation, SymbolKind, Uri};

use super::index::{Kind, Outline, pou_symbol_kind};
use super::workspace::Workspace;

pub fn document(ws: &Workspace, uri: &Uri) -> Vec<DocumentSymbol> {
    let Some(k) = ws.doc(uri) else {
        return Vec::new();
    };
    let Some(file) = ws.analysis.index(k).and_then(|ix| ix.file(k)) else {
        return Vec::new();
    };
    file.outline.iter().map(|o| convert(ws, k, o)).collect()
}

#[allow(deprecated)] // `deprecated` is a required field of the type
fn convert(ws: &Workspace, k: usize, o: &Outline) -> DocumentSymbol {
    DocumentSymbol {
        name: o.name.clone(),
        detail: o.detail.clone(),
        kind: o.kind,
        tags: None,
        deprecated: None,
        range: ws.range(k, o.span),
        selection_range: ws.range(k, o.sel),
        children: (!o.children.is_empty())
            .then(|| o.children.iter().map(|c| convert(ws, k, c)).collect()),
    }
}

/// Most workspace symbols answered for one query.
const MAX_RESULTS: usize = 1000;

#[allow(deprecated)]
pub fn workspace(ws: &Workspace, query: &str) -> Vec<SymbolInformation> {
    let q = query.to_ascii_lowercase();
    let all = ws
        .analysis
        .indexes
        .iter()
        .flat_map(|ix| ix.symbols.iter().map(move |s| (ix, s)));
    all.filter(|(_, s)| s.name.to_ascii_lowercase().contains(&q))
        .filter_map(|(ix, s)| {
            Some(SymbolInformation {
                name: s.name.clone(),
                kind: match s.kind {
                    Kind::Pou(k) => pou_symbol_kind(k),
                    Kind::Var(_) => SymbolKind::VARIABLE,
                    Kind::Label => SymbolKind::KEY,
                    Kind::Type => SymbolKind::STRUCT,
                    Kind::Field => SymbolKind::FIELD,
                    Kind::Config => SymbolKind::PACKAGE,
                },
                tags: None,
                deprecated: None,
                location: ws.location(s.file, s.span)?,
                container_name: s.container.map(|c| ix.symbols[c].name.clone()),
            })
        })
        .take(MAX_RESULTS)
        .collect()
}
