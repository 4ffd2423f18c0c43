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

/// The Rust name of a local binding (a FUNCTION's parameters and locals, VAR_TEMP).
/// Locals are not part of the host's API, so they get a prefix that keeps
/// them apart from everything in the user's scope: a `let` cannot bind a name
/// that is a constant or unit struct there (`None`, a user `const SPEED`).
pub fn local_ident(name: &str) -> Ident {
    Ident::new(&format!("__v_{name}"), Span::call_site())
}

/// The Rust name of a generated item (struct or fn). A POU named like a Rust
/// primitive type (`i16`, `bool` ...) would hide that type from the generated
/// code, so it gets a trailing `_` (which no IEC identifier has).
pub fn item_ident(name: &str) -> Ident {
    const PRIMITIVES: &[&str] = &[
        "bool", "char", "str", "i8", "i16", "i32", "i64", "i128", "isize", "u8", "u16", "u32",
        "u64", "u128", "usize", "f32", "f64",
    ];
    if PRIMITIVES.contains(&name) {
        Ident::new(&format!("{name}_"), Span::call_site())
    } else {
        rust_ident(name)
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
