//! Integers (decimal and based) and reals.

use super::*;

pub(super) fn split_sign(text: &str) -> (bool, &str) {
    match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    }
}

/// Digits in `radix` with single `_` between digits (IEC `digit {[_] digit}`).
pub(super) fn digits(text: &str, radix: u32) -> Result<i128, LiteralError> {
    if text.is_empty() {
        return Err(LiteralError::EmptyNumber);
    }
    if text.starts_with('_') || text.ends_with('_') || text.contains("__") {
        return Err(LiteralError::BadUnderscore);
    }
    let mut v: i128 = 0;
    for c in text.chars().filter(|&c| c != '_') {
        let d = c
            .to_digit(radix)
            .ok_or(LiteralError::BadDigit { digit: c, radix })?;
        v = v
            .checked_mul(i128::from(radix))
            .and_then(|v| v.checked_add(i128::from(d)))
            .ok_or(LiteralError::IntTooLarge)?;
    }
    Ok(v)
}

/// Parses an IEC integer literal: decimal with an optional sign (`-12`, `+7`, `1_000`) or based
/// `2#1010_1010`, `8#777`, `16#FF` (no sign). `_` may separate digits. The magnitude is at most
/// ULINT's (`u64::MAX`), the largest of any IEC integer type; the caller range-checks against
/// the target type (e.g. with [`Elem::min_max_i128`](crate::signature::Elem::min_max_i128)).
pub fn parse_int(text: &str) -> Result<i128, LiteralError> {
    let (neg, body) = split_sign(text);
    let v = match body.split_once('#') {
        Some((base, rest)) => {
            let radix = match base {
                "2" => 2,
                "8" => 8,
                "16" => 16,
                _ => return Err(LiteralError::BadBase),
            };
            if body.len() != text.len() {
                return Err(LiteralError::SignedBasedInt);
            }
            digits(rest, radix)?
        }
        None => digits(body, 10)?,
    };
    if v > i128::from(u64::MAX) {
        return Err(LiteralError::IntTooLarge);
    }
    Ok(if neg { -v } else { v })
}

/// Parses an IEC real literal such as `1.5`, `-0.5`, `1.0E-3`, `1_000.25`, `3e5`
/// (`_` only between digits).
pub fn parse_real(text: &str) -> Result<f64, LiteralError> {
    let mut prev = 0u8;
    for &b in text.as_bytes() {
        let ok = if b == b'_' {
            prev.is_ascii_digit()
        } else if prev == b'_' {
            b.is_ascii_digit()
        } else {
            // Also keeps out `inf` and `NaN`, which Rust parses but IEC does not have.
            b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-')
        };
        if !ok {
            return Err(if b == b'_' || prev == b'_' {
                LiteralError::BadUnderscore
            } else {
                LiteralError::BadReal
            });
        }
        prev = b;
    }
    if prev == b'_' {
        return Err(LiteralError::BadUnderscore);
    }
    if !text.contains('_') {
        return text.parse::<f64>().map_err(|_| LiteralError::BadReal);
    }
    // Without `_` for `str::parse`; no allocation, so the copy is bounded (longer reals with
    // `_` are refused; IEC REALs have at most 17 significant digits).
    let mut buf = [0u8; 256];
    let mut n = 0;
    for &b in text.as_bytes().iter().filter(|&&b| b != b'_') {
        *buf.get_mut(n).ok_or(LiteralError::BadReal)? = b;
        n += 1;
    }
    core::str::from_utf8(&buf[..n])
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .ok_or(LiteralError::BadReal)
}
