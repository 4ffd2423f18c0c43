//! IEC names as Rust identifiers (text for [`super::text::Out`]): only
//! `[A-Za-z_][A-Za-z0-9_]*`, or `r#` and a keyword, ever comes out, so an
//! identifier can never carry other Rust text into the output.

/// Rust keywords that cannot be raw identifiers get a trailing `_` (which no
/// IEC identifier has); other keywords become raw identifiers (`r#loop`).
pub fn rust_ident(name: &str) -> String {
    // The parser only produces IEC identifiers, but error recovery may leave
    // placeholders (e.g. an empty name): never panic on them.
    if !is_ident(name) {
        return format!("__invalid_{}", name.len());
    }
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
        format!("{name}_")
    } else if KEYWORDS.contains(&name) {
        format!("r#{name}")
    } else {
        name.to_string()
    }
}

/// The struct of references to the globals a POU uses (`Motor__Ext`): IEC
/// names have no `__`, so it never collides with a user's item.
pub fn ext_ident(pou: &str) -> String {
    rust_ident(&format!("{pou}__Ext"))
}

/// The RETAIN snapshot of a POU or configuration (`Motor__Retain`).
pub fn retain_ident(pou: &str) -> String {
    rust_ident(&format!("{pou}__Retain"))
}

/// The Rust name of a local binding (a FUNCTION's parameters and locals, VAR_TEMP).
/// Locals are not part of the host's API, so they get a prefix that keeps
/// them apart from everything in the user's scope: a `let` cannot bind a name
/// that is a constant or unit struct there (`None`, a user `const SPEED`).
pub fn local_ident(name: &str) -> String {
    if !is_ident(name) {
        return rust_ident(name);
    }
    format!("__v_{name}")
}

/// The local that holds an FB/PROGRAM variable during a call.
pub fn cache_ident(name: &str) -> String {
    if !is_ident(name) {
        return rust_ident(name);
    }
    ["__s_", name].concat()
}

/// `[A-Za-z_][A-Za-z0-9_]*`, not `_` alone.
fn is_ident(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && name != "_"
}

/// The Rust name of a generated item (struct or fn). A POU named like a Rust
/// primitive type (`i16`, `bool` ...) would hide that type from the generated
/// code, so it gets a trailing `_` (which no IEC identifier has).
pub fn item_ident(name: &str) -> String {
    const PRIMITIVES: &[&str] = &[
        "bool", "char", "str", "i8", "i16", "i32", "i64", "i128", "isize", "u8", "u16", "u32",
        "u64", "u128", "usize", "f32", "f64",
    ];
    if PRIMITIVES.contains(&name) {
        format!("{name}_")
    } else {
        rust_ident(name)
    }
}

#[cfg(test)]
mod tests {
    use super::{item_ident, local_ident, rust_ident};

    #[test]
    fn never_panics_on_placeholders() {
        assert!(rust_ident("").starts_with("__invalid"));
        assert!(local_ident("a b").starts_with("__invalid"));
        assert!(item_ident("9x").starts_with("__invalid"));
    }

    #[test]
    fn keywords_and_plain_names() {
        assert_eq!(rust_ident("loop"), "r#loop");
        assert_eq!(rust_ident("self"), "self_");
        assert_eq!(rust_ident("Motor_On"), "Motor_On");
    }
}
