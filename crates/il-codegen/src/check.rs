//! The whole front-to-back check of one source file, for `ilc check`, build
//! scripts and editors: every stage that runs without emitting code.

use crate::diag::{Diagnostic, SourceFile, has_errors};

/// Every diagnostic of `file`, sorted by position (stable: equal positions keep
/// the order in which the stages reported them).
pub fn check_source(file: &SourceFile) -> Vec<Diagnostic> {
    let (unit, mut diags) = crate::syntax::parse(file);
    // Semantic checks on a tree with syntax errors would mostly repeat them.
    if !has_errors(&diags) {
        diags.extend(crate::sema::check(file, &unit).1);
    }
    diags.sort_by_key(|d| (d.span.lo, d.span.hi));
    diags
}
