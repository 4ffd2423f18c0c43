//! String functions: LEN LEFT RIGHT MID CONCAT INSERT DELETE REPLACE FIND.
//!
//! They work on [`STRING`](crate::STRING) and [`WSTRING`](crate::WSTRING) alike (any capacity).
//! Positions are 1-based as in IEC. A result has the capacity of the first string argument:
//! if it does not fit, it is truncated (the `*_checked` variants also return `true` then, so the
//! caller can record [`FaultKind::StringOverflow`](crate::FaultKind::StringOverflow)). Lengths
//! and positions out of range are clamped, never a panic: a negative length counts as 0, a
//! position below 1 as 1, one beyond the end as the end.

use crate::num::{AnyInt, AnyString};

/// A non-negative count from an IEC integer, clamped to `0..=usize::MAX`.
fn clamp_len<I: AnyInt>(v: I) -> usize {
    let v = v.to_i128();
    if v <= 0 {
        0
    } else {
        usize::try_from(v).unwrap_or(usize::MAX)
    }
}

/// 0-based index of the 1-based position `p`, clamped to `0..=len`.
fn clamp_pos<I: AnyInt>(p: I, len: usize) -> usize {
    clamp_len(p).saturating_sub(1).min(len)
}

fn build<S: AnyString>(parts: &[&[S::Unit]]) -> (S, bool) {
    let mut s = S::default();
    let mut truncated = false;
    for p in parts {
        truncated |= s.push_units(p);
    }
    (s, truncated)
}

fn split<U>(u: &[U], at: usize) -> (&[U], &[U]) {
    u.split_at(at.min(u.len()))
}

/// `LEN`: the length of `IN` in characters.
pub fn LEN<S: AnyString>(IN: S) -> i16 {
    i16::try_from(IN.units().len()).unwrap_or(i16::MAX)
}

/// `LEFT`: the leftmost `L` characters of `IN` (all of it if `L ≥ LEN(IN)`).
pub fn LEFT<S: AnyString, I: AnyInt>(IN: S, L: I) -> S {
    let (l, _) = split(IN.units(), clamp_len(L));
    build::<S>(&[l]).0
}

/// `RIGHT`: the rightmost `L` characters of `IN` (all of it if `L ≥ LEN(IN)`).
pub fn RIGHT<S: AnyString, I: AnyInt>(IN: S, L: I) -> S {
    let u = IN.units();
    let (_, r) = split(u, u.len().saturating_sub(clamp_len(L)));
    build::<S>(&[r]).0
}

/// `MID`: `L` characters of `IN` starting at position `P` (1-based); fewer if the string ends
/// first, empty if `P > LEN(IN)`.
pub fn MID<S: AnyString, I: AnyInt, J: AnyInt>(IN: S, L: I, P: J) -> S {
    let u = IN.units();
    let (_, rest) = split(u, clamp_pos(P, u.len()));
    let (m, _) = split(rest, clamp_len(L));
    build::<S>(&[m]).0
}

/// `CONCAT`: `IN1` followed by `IN2` (extensible: fold), with `IN1`'s capacity (truncated if
/// longer).
pub fn CONCAT<S: AnyString, S2: AnyString<Unit = S::Unit>>(IN1: S, IN2: S2) -> S {
    concat_checked(IN1, IN2).0
}

/// [`CONCAT`] plus `true` if the result was truncated.
pub fn concat_checked<S: AnyString, S2: AnyString<Unit = S::Unit>>(IN1: S, IN2: S2) -> (S, bool) {
    build::<S>(&[IN1.units(), IN2.units()])
}

/// `INSERT`: `IN2` inserted into `IN1` after the `P`-th character (`P = 0` inserts at the
/// start), with `IN1`'s capacity (truncated if longer).
pub fn INSERT<S: AnyString, S2: AnyString<Unit = S::Unit>, I: AnyInt>(IN1: S, IN2: S2, P: I) -> S {
    insert_checked(IN1, IN2, P).0
}

/// [`INSERT`] plus `true` if the result was truncated.
pub fn insert_checked<S: AnyString, S2: AnyString<Unit = S::Unit>, I: AnyInt>(
    IN1: S,
    IN2: S2,
    P: I,
) -> (S, bool) {
    let (a, b) = split(IN1.units(), clamp_len(P));
    build::<S>(&[a, IN2.units(), b])
}

/// `DELETE`: `IN` without the `L` characters starting at position `P` (1-based).
pub fn DELETE<S: AnyString, I: AnyInt, J: AnyInt>(IN: S, L: I, P: J) -> S {
    let u = IN.units();
    let (a, rest) = split(u, clamp_pos(P, u.len()));
    let (_, b) = split(rest, clamp_len(L));
    build::<S>(&[a, b]).0
}

/// `REPLACE`: `IN1` with the `L` characters starting at position `P` (1-based) replaced by
/// `IN2`, with `IN1`'s capacity (truncated if longer).
pub fn REPLACE<S: AnyString, S2: AnyString<Unit = S::Unit>, I: AnyInt, J: AnyInt>(
    IN1: S,
    IN2: S2,
    L: I,
    P: J,
) -> S {
    replace_checked(IN1, IN2, L, P).0
}

/// [`REPLACE`] plus `true` if the result was truncated.
pub fn replace_checked<S: AnyString, S2: AnyString<Unit = S::Unit>, I: AnyInt, J: AnyInt>(
    IN1: S,
    IN2: S2,
    L: I,
    P: J,
) -> (S, bool) {
    let u = IN1.units();
    let (a, rest) = split(u, clamp_pos(P, u.len()));
    let (_, b) = split(rest, clamp_len(L));
    build::<S>(&[a, IN2.units(), b])
}

/// A string of another capacity (the caller's type decides which) with the characters of
/// `IN`, plus `true` if some were cut off: what an assignment, a parameter or an output of
/// another `STRING[n]` length does (not an IEC function; the generated code records
/// `StringOverflow` on `true`).
pub fn resize_checked<S: AnyString, T: AnyString<Unit = S::Unit>>(IN: S) -> (T, bool) {
    T::from_units_truncating(IN.units())
}

/// `FIND`: the 1-based position of the first occurrence of `IN2` in `IN1`, 0 if there is none
/// (or if `IN2` is empty).
pub fn FIND<S: AnyString, S2: AnyString<Unit = S::Unit>>(IN1: S, IN2: S2) -> i16 {
    let (h, n) = (IN1.units(), IN2.units());
    if n.is_empty() {
        return 0;
    }
    h.windows(n.len())
        .position(|w| w == n)
        .map_or(0, |i| i16::try_from(i + 1).unwrap_or(i16::MAX))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{STRING, WSTRING};

    fn s(v: &str) -> STRING<10> {
        STRING::from_str_truncating(v).0
    }
    fn t(v: STRING<10>) -> &'static str {
        std::boxed::Box::leak(std::format!("{v}").into_boxed_str())
    }

    #[test]
    fn len_left_right_mid() {
        assert_eq!(LEN(s("ASTRING")), 7);
        assert_eq!(LEN(s("")), 0);
        assert_eq!(t(LEFT(s("ASTR"), 3)), "AST");
        assert_eq!(t(LEFT(s("ASTR"), 10)), "ASTR");
        assert_eq!(t(LEFT(s("ASTR"), -1)), "");
        assert_eq!(t(RIGHT(s("ASTR"), 3)), "STR");
        assert_eq!(t(RIGHT(s("ASTR"), 99i64)), "ASTR");
        assert_eq!(t(RIGHT(s("ASTR"), -3)), "");
        assert_eq!(t(MID(s("ASTR"), 2, 2)), "ST");
        assert_eq!(t(MID(s("ASTR"), 10, 2)), "STR");
        assert_eq!(t(MID(s("ASTR"), 2, 0)), "AS");
        assert_eq!(t(MID(s("ASTR"), 2, 9)), "");
        assert_eq!(t(MID(s("ASTR"), i64::MAX, i64::MIN)), "ASTR");
    }

    #[test]
    fn concat_insert_delete_replace() {
        assert_eq!(t(CONCAT(s("AB"), s("CD"))), "ABCD");
        let (r, tr) = concat_checked(s("ABCDEFGH"), s("IJKL"));
        assert!(tr);
        assert_eq!(t(r), "ABCDEFGHIJ");
        assert!(!concat_checked(s("A"), s("B")).1);
        let big = STRING::<80>::from_str_truncating("xyz").0;
        assert_eq!(t(CONCAT(s("AB"), big)), "ABxyz");
        assert_eq!(t(INSERT(s("ABC"), s("XY"), 2)), "ABXYC");
        assert_eq!(t(INSERT(s("ABC"), s("XY"), 0)), "XYABC");
        assert_eq!(t(INSERT(s("ABC"), s("XY"), 99)), "ABCXY");
        assert_eq!(t(INSERT(s("ABC"), s("XY"), -4)), "XYABC");
        assert!(insert_checked(s("ABCDEFGHI"), s("XY"), 1).1);
        assert_eq!(t(DELETE(s("ABXYC"), 2, 3)), "ABC");
        assert_eq!(t(DELETE(s("ABC"), 5, 2)), "A");
        assert_eq!(t(DELETE(s("ABC"), 1, 9)), "ABC");
        assert_eq!(t(DELETE(s("ABC"), -1, 1)), "ABC");
        assert_eq!(t(REPLACE(s("ABCDE"), s("X"), 2, 3)), "ABXE");
        assert_eq!(t(REPLACE(s("ABCDE"), s("XYZ"), 0, 1)), "XYZABCDE");
        assert_eq!(t(REPLACE(s("ABC"), s("XY"), 9, 9)), "ABCXY");
        assert!(replace_checked(s("ABCDEFGHIJ"), s("XY"), 1, 1).1);
    }

    #[test]
    fn resize() {
        let (r, cut): (STRING<3>, bool) = resize_checked(s("ABCDE"));
        assert_eq!((r.as_str(), cut), (Some("ABC"), true));
        let (r, cut): (STRING<80>, bool) = resize_checked(s("ABCDE"));
        assert_eq!((r.as_str(), cut), (Some("ABCDE"), false));
        let (r, cut): (STRING<5>, bool) = resize_checked(s("ABCDE"));
        assert_eq!((r.as_str(), cut), (Some("ABCDE"), false));
    }

    #[test]
    fn find() {
        assert_eq!(FIND(s("ABCBC"), s("BC")), 2);
        assert_eq!(FIND(s("ABCBC"), s("X")), 0);
        assert_eq!(FIND(s("AB"), s("ABC")), 0);
        assert_eq!(FIND(s("AB"), s("")), 0);
        assert_eq!(FIND(s("AB"), s("AB")), 1);
    }

    #[test]
    fn wide() {
        let w = WSTRING::<8>::from_str_truncating("äöü€").0;
        assert_eq!(LEN(w), 4);
        let r = RIGHT(w, 1);
        assert_eq!(r.as_units(), [0x20AC]);
        assert_eq!(FIND(w, WSTRING::<2>::from_str_truncating("ü").0), 3);
    }
}
