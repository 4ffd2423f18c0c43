//! `textDocument/formatting` and `rangeFormatting`: `il_codegen::format`
//! (what `ilc fmt` writes) as one edit per changed line. The formatter keeps
//! every line break, so old and new lines pair one to one; a range is
//! formatted with the whole file around it (alignment spans blocks), and
//! only its lines are edited.

use il_codegen::SourceFile;
use il_codegen::ast::Span;
use il_codegen::format::{FormatOptions, format};
use lsp_types::{Range, TextEdit, Uri};

use super::workspace::Workspace;

/// The edits that format the document (the lines of `only`, all when
/// `None`), or
/// `None` when it is not formatted (XML, syntax errors: the diagnostics
/// say why).
pub fn edits(ws: &Workspace, uri: &Uri, only: Option<Range>) -> Option<Vec<TextEdit>> {
    let k = ws.doc(uri)?;
    let doc = &ws.docs[k];
    if il_codegen::pipeline::is_xml(&doc.name, &doc.text) {
        return None;
    }
    let file = SourceFile::new(doc.name.clone(), doc.text.clone());
    let new = format(&file, &FormatOptions::default()).ok()?;
    let lines = only.map(|r| (r.start.line as usize, r.end.line as usize));
    let old_lines: Vec<(usize, &str)> = line_spans(&doc.text);
    let new_lines: Vec<(usize, &str)> = line_spans(&new);
    if old_lines.len() != new_lines.len() {
        // Never happens (line breaks are kept); replace everything if it did.
        let all = ws.range(k, Span::new(0, doc.text.len()));
        return Some(vec![TextEdit::new(all, new)]);
    }
    let mut out = Vec::new();
    for (n, ((lo, was), (_, now))) in old_lines.iter().zip(&new_lines).enumerate() {
        if was == now || lines.is_some_and(|(a, b)| n < a || n > b) {
            continue;
        }
        let range = ws.range(k, Span::new(*lo, lo + was.len()));
        out.push(TextEdit::new(range, now.to_string()));
    }
    Some(out)
}

/// Each line's start and text, without its line break (`\r\n` or `\n`).
fn line_spans(text: &str) -> Vec<(usize, &str)> {
    let mut at = 0;
    text.split('\n')
        .map(|l| {
            let start = at;
            at += l.len() + 1;
            (start, l.strip_suffix('\r').unwrap_or(l))
        })
        .collect()
}
