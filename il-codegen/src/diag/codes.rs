//! Diagnostic codes: what a code is ([`CodeInfo`]), the one macro every
//! stage declares its table with, and the codes of the diagnostics layer
//! itself. The index of every code (for `ilc explain` and the docs) is
//! [`crate::codes`], outside the stages, so no stage imports another's.

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

/// A stage's table of codes: one `const` per code (documented with its
/// title) and `CODES`, the table with every explanation.
///
/// ```ignore
/// codes! {
///     UNKNOWN_NAME = "IL0101", "unknown variable", "The operand names ...";
/// }
/// ```
macro_rules! codes {
    ($($id:ident = $code:literal, $title:literal, $expl:literal;)*) => {
        $(#[doc = concat!("`", $code, "`: ", $title, ".")] pub const $id: &str = $code;)*
        /// Every code of this table with its explanation.
        pub static CODES: &[$crate::diag::codes::CodeInfo] = &[$(
            $crate::diag::codes::CodeInfo { code: $code, title: $title, explanation: $expl },
        )*];
    };
}
pub(crate) use codes;

codes! {
    TOO_MANY = "IL0032", "more diagnostics in one file than are shown",
        "A file with very many errors (often not IL at all, or IL damaged by a bad copy) gets its first 200 diagnostics, by position, and this one, which says how many more there are.\n\n    LD x # # # # # # # # ...   (* thousands of stray characters *)\n\nFix the first ones: many of the rest usually follow from them.";
}
