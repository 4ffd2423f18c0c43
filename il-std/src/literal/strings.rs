//! String literals: `$` escapes, and the STRING/WSTRING values they give.

use super::*;

/// One element of an unescaped string literal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StrPiece {
    /// A character written as itself or with a named escape (`$N` gives `'\n'`).
    Char(char),
    /// A character code given in hex: `$hh` (STRING, 0..=255) or `$hhhh` (WSTRING).
    Code(u16),
}

/// Unescapes the body of a string literal (without its quotes), passing each character to
/// `out`. Escapes: `$$ $' $" $L $N $P $R $T` (any case; `$L` and `$N` are line feed, `$P` form
/// feed) and `$hh` (two hex digits) in a STRING, `$hhhh` (four) in a WSTRING (`wide`).
pub fn unescape_string(
    body: &str,
    wide: bool,
    out: &mut impl FnMut(StrPiece),
) -> Result<(), LiteralError> {
    let mut it = body.char_indices().peekable();
    while let Some((i, c)) = it.next() {
        if c != '$' {
            out(StrPiece::Char(c));
            continue;
        }
        let Some((_, e)) = it.next() else {
            return Err(LiteralError::EscapeAtEnd { at: i });
        };
        let piece = match e.to_ascii_uppercase() {
            '$' => StrPiece::Char('$'),
            '\'' => StrPiece::Char('\''),
            '"' => StrPiece::Char('"'),
            'L' | 'N' => StrPiece::Char('\n'),
            'P' => StrPiece::Char('\x0C'),
            'R' => StrPiece::Char('\r'),
            'T' => StrPiece::Char('\t'),
            h if h.is_ascii_hexdigit() => {
                let n = if wide { 4 } else { 2 };
                let mut v = h.to_digit(16).unwrap_or(0);
                for _ in 1..n {
                    match it.next() {
                        Some((_, d)) if d.is_ascii_hexdigit() => {
                            v = v * 16 + d.to_digit(16).unwrap_or(0);
                        }
                        _ => return Err(LiteralError::HexEscapeDigits { at: i, wide }),
                    }
                }
                StrPiece::Code(v as u16)
            }
            _ => return Err(LiteralError::BadEscape { at: i, escape: e }),
        };
        out(piece);
    }
    Ok(())
}

/// Unescapes a STRING literal body into a `STRING<N>`: characters as UTF-8 bytes, `$hh` as the
/// byte `hh`. The flag is `true` if the value was truncated to the capacity.
pub fn string_literal<const N: usize>(body: &str) -> Result<(STRING<N>, bool), LiteralError> {
    let mut s = STRING::<N>::new();
    let mut truncated = false;
    unescape_string(body, false, &mut |p| {
        let mut b = [0u8; 4];
        truncated |= match p {
            StrPiece::Char(c) => s.push_units(c.encode_utf8(&mut b).as_bytes()),
            StrPiece::Code(v) => s.push_units(&[v as u8]),
        };
    })?;
    Ok((s, truncated))
}

/// Unescapes a WSTRING literal body into a `WSTRING<N>`: characters as UTF-16, `$hhhh` as the
/// code unit `hhhh`. The flag is `true` if the value was truncated to the capacity.
pub fn wstring_literal<const N: usize>(body: &str) -> Result<(WSTRING<N>, bool), LiteralError> {
    let mut s = WSTRING::<N>::new();
    let mut truncated = false;
    unescape_string(body, true, &mut |p| {
        let mut b = [0u16; 2];
        truncated |= match p {
            StrPiece::Char(c) => {
                let enc = c.encode_utf16(&mut b);
                if s.len() + enc.len() > N {
                    true
                } else {
                    s.push_units(enc)
                }
            }
            StrPiece::Code(v) => s.push_units(&[v]),
        };
    })?;
    Ok((s, truncated))
}
