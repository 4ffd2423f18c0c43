//! IEC names as Rust identifiers.

use proc_macro2::{Ident, Span};

/// Rust keywords that cannot be raw identifiers get a trailing `_` (which no
/// IEC identifier has); other keywords become raw identifiers (`r#loop`).
pub fn rust_ident(name: &str) -> Ident {
    const NOT_RAW: &[&str] = &["self", "Self", "super", "crate", "_"];
    const KEYWORDS: &[&str] = &[
        "as",
        "async",
        "await",
        "box",
        "break",
        "const",
        "continue",
        "dyn",
        "else",
        "enum",
        "extern",
        "false",
        "fn",
        "for",
        "gen",
        "if",
        "impl",
        "in",
        "let",
        "loop",
        "macro",
        "match",
        "mod",
        "move",
        "mut",
        "priv",
        "pub",
        "ref",
        "return",
        "static",
        "struct",
        "trait",
        "true",
        "try",
        "type",
        "typeof",
        "unsafe",
        "unsized",
        "use",
        "virtual",
        "where",
        "while",
        "yield",
        "abstract",
        "become",
        "do",
        "final",
        "override",
        "union",
        "macro_rules",
        "raw",
        "safe",
    ];
    if NOT_RAW.contains(&name) {
        Ident::new(&format!("{name}_"), Span::call_site())
    } else if KEYWORDS.contains(&name) {
        Ident::new_raw(name, Span::call_site())
    } else {
        Ident::new(name, Span::call_site())
    }
}

#[cfg(test)]
mod tests {
    use super::rust_ident;

    #[test]
    fn keywords_and_plain_names() {
        assert_eq!(rust_ident("loop").to_string(), "r#loop");
        assert_eq!(rust_ident("self").to_string(), "self_");
        assert_eq!(rust_ident("Motor_On").to_string(), "Motor_On");
    }
}
