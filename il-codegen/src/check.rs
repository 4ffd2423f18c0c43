//! The whole front-to-back check of one source file, for `ilc check`, build
//! scripts and editors: every stage that runs without emitting code.

use crate::diag::{Diagnostic, SourceFile, has_errors};

/// Every diagnostic of several files checked as one program (a
/// FUNCTION_BLOCK of one may be used in another), one list per file.
pub fn check_sources(files: &[SourceFile]) -> Vec<Vec<Diagnostic>> {
    let parsed: Vec<_> = files.iter().map(crate::syntax::parse).collect();
    let mut all: Vec<Vec<Diagnostic>> = parsed.iter().map(|(_, d)| d.clone()).collect();
    // Files with syntax errors stay out of the semantic check (it would
    // mostly repeat them); the others are checked together.
    let clean: Vec<usize> = (0..files.len()).filter(|&i| !has_errors(&all[i])).collect();
    let pairs: Vec<_> = clean.iter().map(|&i| (&files[i], &parsed[i].0)).collect();
    for (&i, more) in clean.iter().zip(crate::sema::check_all(&pairs).1) {
        all[i].extend(more);
    }
    for d in &mut all {
        d.sort_by_key(|d| (d.span.lo, d.span.hi));
        crate::diag::limit(d);
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
    crate::diag::limit(&mut diags);
    diags
}
