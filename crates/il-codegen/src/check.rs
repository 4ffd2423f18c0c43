//! The whole front-to-back check of one source file, for `ilc check`, build
//! scripts and editors: every stage that runs without emitting code.

use crate::diag::{Diagnostic, SourceFile, has_errors};

/// Every diagnostic of several files checked as one program (a
/// FUNCTION_BLOCK of one may be used in another), one list per file.
pub fn check_sources(files: &[SourceFile]) -> Vec<Vec<Diagnostic>> {
    let parsed: Vec<_> = files.iter().map(crate::syntax::parse).collect();
    let mut all: Vec<Vec<Diagnostic>> = parsed.iter().map(|(_, d)| d.clone()).collect();
    if !all.iter().any(|d| has_errors(d)) {
        let pairs: Vec<_> = files.iter().zip(parsed.iter().map(|(u, _)| u)).collect();
        for (d, more) in all.iter_mut().zip(crate::sema::check_all(&pairs).1) {
            d.extend(more);
        }
    }
    for d in &mut all {
        d.sort_by_key(|d| (d.span.lo, d.span.hi));
    }
    all
}

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
