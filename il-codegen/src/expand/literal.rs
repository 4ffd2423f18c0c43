//! The value of a Rust string literal, from its source text (`"a\n"`,
//! `r#"..."#`): what `syn::LitStr::value` gives, without syn, so that an
//! `il!` user compiles neither syn nor its parser.

/// The value of a string literal written as `src`, or why it is not one
/// (a byte string, a C string, a number ...).
pub(crate) fn string_value(src: &str) -> Result<String, &'static str> {
    if let Some(raw) = src.strip_prefix('r') {
        let hashes = raw.len() - raw.trim_start_matches('#').len();
        let body = &raw[hashes..];
        let close = format!("\"{}", "#".repeat(hashes));
        return body
            .strip_prefix('"')
            .and_then(|b| b.strip_suffix(close.as_str()))
            .map(str::to_string)
            .ok_or("not a string literal");
    }
    let body = src
        .strip_prefix('"')
        .and_then(|b| b.strip_suffix('"'))
        .ok_or("not a string literal")?;
    let mut out = String::with_capacity(body.len());
    let mut chars = body.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '\\' {
            // rustc gives "\r\n" in a literal as "\n" (a bare CR is refused).
            if c == '\r' && chars.peek() == Some(&'\n') {
                continue;
            }
            out.push(c);
            continue;
        }
        match chars.next().ok_or("a string literal ends in `\\`")? {
            'n' => out.push('\n'),
            'r' => out.push('\r'),
            't' => out.push('\t'),
            '\\' => out.push('\\'),
            '0' => out.push('\0'),
            '\'' => out.push('\''),
            '"' => out.push('"'),
            'x' => {
                let hex: String = chars.by_ref().take(2).collect();
                let n = u8::from_str_radix(&hex, 16).map_err(|_| "a bad `\\x` escape")?;
                if n > 0x7f {
                    return Err("a bad `\\x` escape");
                }
                out.push(n as char);
            }
            'u' => {
                if chars.next() != Some('{') {
                    return Err("a bad `\\u` escape");
                }
                let hex: String = chars.by_ref().take_while(|&c| c != '}').collect();
                let n = u32::from_str_radix(&hex.replace('_', ""), 16)
                    .map_err(|_| "a bad `\\u` escape")?;
                out.push(char::from_u32(n).ok_or("a bad `\\u` escape")?);
            }
            // A line continuation: the newline and the next line's leading
            // whitespace are not part of the value.
            '\n' | '\r' => {
                while chars.peek().is_some_and(|c| c.is_whitespace()) {
                    chars.next();
                }
            }
            _ => return Err("an unknown escape"),
        }
    }
    Ok(out)
}

/// The source text of a literal whose value is `value` (for callers that
/// build an `il!` input without a tokenizer: benches, fuzzers, tests).
pub(crate) fn string_source(value: &str) -> String {
    format!("{value:?}")
}

#[cfg(test)]
mod tests {
    use super::{string_source, string_value};

    #[test]
    fn values_of_plain_and_raw_literals() {
        assert_eq!(string_value(r#""a\nb\t\"c\"\\""#).unwrap(), "a\nb\t\"c\"\\");
        assert_eq!(string_value(r#""\x41\u{1F600}\u{e9}""#).unwrap(), "A😀é");
        assert_eq!(string_value("\"one \\\n    two\"").unwrap(), "one two");
        assert_eq!(string_value("\"a\r\nb\"").unwrap(), "a\nb");
        assert_eq!(string_value(r##"r#"LD "x" \n"#"##).unwrap(), r#"LD "x" \n"#);
        assert_eq!(string_value(r#"r"x""#).unwrap(), "x");
        for bad in [
            "b\"x\"",
            "c\"x\"",
            "1",
            "'x'",
            r#""\q""#,
            r#""\x80""#,
            "\"x",
        ] {
            assert!(string_value(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn source_round_trips() {
        for v in ["", "LD x\n\tST y", "\"quoted\" \\ (* c *)", "é😀\0\r"] {
            assert_eq!(string_value(&string_source(v)).unwrap(), v);
        }
    }
}
