//! The refactoring "Convert to the formal form": `CAL t1(go, T#5s)`
//! becomes `CAL t1(IN := go, PT := T#5s)`, the inputs named in the order
//! the checker binds them (the block's VAR_INPUTs).

use lsp_types::{CodeAction, CodeActionKind, Range, TextEdit, Uri, WorkspaceEdit};

use il_codegen::ast::Span;

use super::workspace::Workspace;

/// The action for the `CAL` on the line of `range`'s start, if its list is
/// positional and closes on that line.
pub fn formal_form(ws: &Workspace, uri: &Uri, range: Range) -> Option<CodeAction> {
    let k = ws.doc(uri)?;
    let ix = ws.analysis.index(k)?;
    let text = &ws.docs[k].text;
    let lines = ws.analysis.lines.get(k)?;
    let off = lines.offset(text, range.start);
    let start = text[..off].rfind('\n').map_or(0, |i| i + 1);
    let end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    let line = &text[start..end];
    let upper = line.to_ascii_uppercase();
    let cal = upper.find("CAL")?;
    // `CAL`, `CALC`, `CALCN`, `CALNC`, then the instance and `(`.
    let after_kw = cal + upper[cal..].find(|c: char| c.is_whitespace())?;
    let rest = &line[after_kw..];
    let name_off = after_kw + (rest.len() - rest.trim_start().len());
    let open = name_off + line[name_off..].find('(')?;
    let close = open + line[open..].rfind(')')?;
    let args = &line[open + 1..close];
    let values = split_top(args)?;
    if values.is_empty() || values.iter().any(|v| v.contains(":=") || v.contains("=>")) {
        return None;
    }
    let inputs = super::signature::instance_inputs(ix, k, start + name_off)?;
    if values.len() > inputs.len() {
        return None;
    }
    let formal: Vec<String> = inputs
        .iter()
        .zip(&values)
        .map(|(n, v)| format!("{n} := {}", v.trim()))
        .collect();
    let span = Span::new(start + open + 1, start + close);
    let edit = TextEdit::new(ws.range(k, span), formal.join(", "));
    // `WorkspaceEdit` is keyed by `Uri`, whose hash does not change.
    #[allow(clippy::mutable_key_type)]
    let changes = std::iter::once((uri.clone(), vec![edit])).collect();
    Some(CodeAction {
        title: "Convert to the formal form".into(),
        kind: Some(CodeActionKind::REFACTOR_REWRITE),
        edit: Some(WorkspaceEdit {
            changes: Some(changes),
            ..Default::default()
        }),
        ..Default::default()
    })
}

/// The comma-separated parts of a list at its top level (commas inside a
/// subscript or parentheses stay); `None` if the brackets do not balance or
/// a comment or string makes the text unsafe to split.
fn split_top(args: &str) -> Option<Vec<&str>> {
    if args.contains("(*") || args.contains('\'') || args.contains('"') {
        return None;
    }
    let (mut depth, mut from, mut out) = (0i32, 0, Vec::new());
    for (i, c) in args.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&args[from..i]);
                from = i + 1;
            }
            _ => {}
        }
        if depth < 0 {
            return None;
        }
    }
    if depth != 0 {
        return None;
    }
    if !args[from..].trim().is_empty() || !out.is_empty() {
        out.push(&args[from..]);
    }
    Some(out)
}
