//! The index of every diagnostic code: each stage keeps its own table next to
//! the code that reports it ([`crate::diag::codes`] has the macro); this
//! module joins them for `ilc explain` and `docs/diagnostics.md`.

pub use crate::diag::codes::CodeInfo;

/// Every code of every stage, in the order of the stages.
pub fn all() -> impl Iterator<Item = &'static CodeInfo> {
    // Reading's codes follow the syntax codes they are numbered after.
    crate::syntax::CODES
        .iter()
        .chain(crate::read::CODES)
        .chain(crate::diag::codes::CODES)
        .chain(crate::sema::CODES)
        .chain(crate::plcopen::CODES)
        .chain(crate::exp::CODES)
        .chain(crate::logiclab::CODES)
        .chain(crate::m221::CODES)
        .chain(crate::dialect::CODES)
}

/// Look a code up (`IL0003`, case-insensitive).
pub fn lookup(code: &str) -> Option<&'static CodeInfo> {
    all().find(|c| c.code.eq_ignore_ascii_case(code))
}
