//! Inlay hints: the CR's type at the end of each instruction line (off with
//! the setting `inlayHints.crType: false`).

use std::collections::BTreeMap;

use lsp_types::{InlayHint, InlayHintKind, InlayHintLabel, Range, Uri};

use super::index::Step;
use super::workspace::Workspace;
use il_codegen::ir::{CrState, CrStep};

pub fn hints(ws: &Workspace, uri: &Uri, range: Range) -> Vec<InlayHint> {
    if !ws.settings.cr_type_hints {
        return Vec::new();
    }
    let Some(k) = ws.doc(uri) else {
        return Vec::new();
    };
    let (doc, lines) = (&ws.docs[k], &ws.analysis.lines[k]);
    let Some(steps) = ws
        .analysis
        .index(k)
        .and_then(|ix| ix.file(k))
        .map(|f| &f.steps)
    else {
        return Vec::new();
    };
    let lo = lines.offset(&doc.text, lsp_types::Position::new(range.start.line, 0)) as u32;
    let hi = lines.offset(&doc.text, range.end) as u32;
    // Per line, the outermost instruction ending there (a group's `)` line
    // shows the group's result, not its last inner instruction's).
    let mut by_line: BTreeMap<usize, (&Step, &CrStep)> = BTreeMap::new();
    let first = steps.partition_point(|s| s.span.lo < lo);
    for s in steps[first..].iter().take_while(|s| s.span.lo <= hi) {
        let Some(cr) = ws.cr_step(k, s) else {
            continue;
        };
        if s.label || cr.after == CrState::Dead {
            continue;
        }
        let line = lines.line_of(s.span.hi as usize);
        let e = by_line.entry(line).or_insert((s, cr));
        if s.span.hi - s.span.lo > e.0.span.hi - e.0.span.lo {
            *e = (s, cr);
        }
    }
    by_line
        .into_iter()
        .map(|(line, (_, s))| {
            let (_, end) = lines.line_range(&doc.text, line);
            let label = match &s.after {
                CrState::Typed(t) => t.to_string(),
                // The reason is in the hover; the line stays short.
                CrState::Undefined(_) | CrState::AfterCal(_) => "undefined".to_string(),
                other => other.to_string(),
            };
            InlayHint {
                position: lines.position(&doc.text, end),
                label: InlayHintLabel::String(format!("CR: {label}")),
                kind: Some(InlayHintKind::TYPE),
                text_edits: None,
                tooltip: None,
                padding_left: Some(true),
                padding_right: None,
                data: None,
            }
        })
        .collect()
}
