//! Host POUs: an `{extern}` pragma right before a FUNCTION (or a
//! FUNCTION_BLOCK or PROGRAM, whose body a CODESYS export holds in another
//! language) marks it as provided by the crate around the generated code
//! (a runtime's print, an I/O driver, a vendor library). The pragma is the one place where a pragma
//! has a meaning, so the lexer reports where each stands and this pass ties
//! it to the declaration that follows.

use super::code;
use crate::ast::{CompilationUnit, Item, Span};
use crate::diag::Diagnostic;

/// The span an item covers, for placing a pragma before or inside it.
fn item_span(item: &Item) -> Option<Span> {
    match item {
        Item::Pou(p) => Some(p.span),
        Item::Configuration(c) => Some(c.span),
        Item::Types(t) => Some(t.first()?.span.to(t.last()?.span)),
    }
}

/// Mark the POU after each `{extern}` pragma; a pragma anywhere else
/// is IL0037. `marks` are in source order, as the lexer found them.
pub(super) fn mark(unit: &mut CompilationUnit, marks: &[Span], diags: &mut Vec<Diagnostic>) {
    if marks.is_empty() {
        return;
    }
    let spans: Vec<Option<Span>> = unit.items.iter().map(item_span).collect();
    // Items are in source order: the first item ending after the pragma is
    // the one it stands in or before.
    let mut next = 0;
    for &m in marks {
        while next < spans.len() && spans[next].is_none_or(|s| s.hi <= m.lo) {
            next += 1;
        }
        let target = match (unit.items.get_mut(next), spans.get(next)) {
            (Some(Item::Pou(p)), Some(Some(s))) if s.lo >= m.hi => {
                p.host = Some(m);
                continue;
            }
            (Some(_), Some(Some(s))) if s.lo < m.hi => "inside a declaration".to_string(),
            (Some(Item::Types(_)), _) => "before a TYPE block".to_string(),
            (Some(_), _) => "before a CONFIGURATION".to_string(),
            (None, _) => "after the last declaration".to_string(),
        };
        diags.push(
            Diagnostic::error(
                code::HOST_MARK,
                m,
                format!("`{{extern}}` stands {target}: it marks a POU only"),
            )
            .with_label("not before a POU")
            .with_help(
                "put `{extern}` right before a FUNCTION, FUNCTION_BLOCK or PROGRAM that the crate provides in Rust, or remove it",
            ),
        );
    }
}
