//! The index of diagnostic codes: each stage keeps its own list next to the
//! code that reports them; this module joins them for `ilc explain`.

/// A diagnostic code and its explanation.
#[derive(Clone, Copy, Debug)]
pub struct CodeInfo {
    /// The code as shown in messages: `IL` and four digits.
    pub code: &'static str,
    /// One line.
    pub title: &'static str,
    /// Paragraphs with an example of IL that triggers it and how to fix it.
    pub explanation: &'static str,
}

/// Every code of every stage.
pub fn all() -> impl Iterator<Item = &'static CodeInfo> {
    crate::syntax::CODES
        .iter()
        .chain(crate::sema::CODES)
        .chain(crate::plcopen::CODES)
}

/// Look a code up (`IL0003`, case-insensitive).
pub fn lookup(code: &str) -> Option<&'static CodeInfo> {
    all().find(|c| c.code.eq_ignore_ascii_case(code))
}
