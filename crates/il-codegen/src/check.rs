//! The whole front-to-back check of one source file, for `ilc check`, build
//! scripts and editors: every stage that runs without emitting code.
//!
//! Today only the parser runs; the semantic checker joins here (one call, below)
//! so that every front end gets it at once.

use crate::diag::{Diagnostic, SourceFile};

/// Every diagnostic of `file`, sorted by position (stable: equal positions keep
/// the order in which the stages reported them).
pub fn check_source(file: &SourceFile) -> Vec<Diagnostic> {
    let (_unit, mut diags) = crate::syntax::parse(file);
    // The semantic checker goes here, e.g.:
    // if !crate::diag::has_errors(&diags) { diags.extend(crate::sema::check(&_unit, file)); }
    diags.sort_by_key(|d| (d.span.lo, d.span.hi));
    diags
}
