//! Fixed-capacity IEC strings: `STRING[n]` (bytes) and `WSTRING[n]` (UTF-16 code units).
//!
//! No allocation: the characters live in an array of the declared capacity inside the value,
//! so strings are `Copy`. Operations that would exceed the capacity truncate and report it.

use core::cmp::Ordering;
use core::fmt;
use core::hash::{Hash, Hasher};

/// The implementation-defined default length of IEC `STRING` and `WSTRING` when no length is
/// declared (`VAR s : STRING; END_VAR` is `STRING[80]`): 80 characters.
pub const DEFAULT_STRING_LEN: usize = 80;

/// Operations shared by [`STRING`] and [`WSTRING`], used by the string functions of
/// [`func`](crate::func).
#[cfg(feature = "runtime")]
pub trait AnyString: Copy + Default + PartialEq + PartialOrd {
    /// One character: `u8` for `STRING`, `u16` for `WSTRING`.
    type Unit: Copy + PartialEq + 'static;
    /// The capacity in characters.
    const CAPACITY: usize;
    /// The characters.
    fn units(&self) -> &[Self::Unit];
    /// A string holding as many of `u` as fit; `true` if some were cut off.
    fn from_units_truncating(u: &[Self::Unit]) -> (Self, bool);
    /// Appends as many of `u` as fit; `true` if some were cut off.
    fn push_units(&mut self, u: &[Self::Unit]) -> bool;
}

macro_rules! iec_string {
    ($name:ident, $unit:ty, $iec:literal, $units_fn:ident, $doc:literal) => {
        #[doc = $doc]
        ///
        #[doc = concat!("`", stringify!($name), "<N>` is IEC `", $iec, "[N]`; a plain `",
            stringify!($name), "` is `", $iec, "` with the default length [`DEFAULT_STRING_LEN`] (80).")]
        /// The default value is the empty string. Equality and ordering compare the contents
        /// (lexicographically by character code), whatever the capacity.
        #[derive(Clone, Copy)]
        pub struct $name<const N: usize = DEFAULT_STRING_LEN> {
            buf: [$unit; N],
            len: usize,
        }

        impl<const N: usize> $name<N> {
            /// The capacity in characters (`N`).
            pub const CAPACITY: usize = N;

            /// The empty string.
            pub const fn new() -> Self {
                Self { buf: [0; N], len: 0 }
            }

            /// A string holding as many characters of `u` as fit; the flag is `true` if some
            /// were cut off. Usable in `const` items.
            pub const fn from_units_truncating(u: &[$unit]) -> (Self, bool) {
                let mut s = Self::new();
                let n = if u.len() < N { u.len() } else { N };
                let mut i = 0;
                while i < n {
                    s.buf[i] = u[i];
                    i += 1;
                }
                s.len = n;
                (s, u.len() > N)
            }

            /// The characters.
            pub fn $units_fn(&self) -> &[$unit] {
                self.buf.get(..self.len).unwrap_or(&[])
            }

            /// The length in characters (IEC `LEN`).
            pub const fn len(&self) -> usize {
                self.len
            }

            /// `true` if the string is empty.
            pub const fn is_empty(&self) -> bool {
                self.len == 0
            }

            /// The capacity in characters (`N`).
            pub const fn capacity(&self) -> usize {
                N
            }

            /// Appends as many characters of `u` as fit; `true` if some were cut off.
            pub fn push_units(&mut self, u: &[$unit]) -> bool {
                let room = N.saturating_sub(self.len);
                let n = u.len().min(room);
                if let (Some(dst), Some(src)) = (self.buf.get_mut(self.len..self.len + n), u.get(..n)) {
                    dst.copy_from_slice(src);
                    self.len += n;
                }
                n < u.len()
            }

            /// The same contents with capacity `M`; `true` if some characters were cut off.
            pub fn resize<const M: usize>(&self) -> ($name<M>, bool) {
                $name::<M>::from_units_truncating(self.$units_fn())
            }
        }

        impl<const N: usize> Default for $name<N> {
            fn default() -> Self {
                Self::new()
            }
        }

        #[cfg(feature = "runtime")]
        impl<const N: usize> AnyString for $name<N> {
            type Unit = $unit;
            const CAPACITY: usize = N;
            fn units(&self) -> &[$unit] {
                self.$units_fn()
            }
            fn from_units_truncating(u: &[$unit]) -> (Self, bool) {
                Self::from_units_truncating(u)
            }
            fn push_units(&mut self, u: &[$unit]) -> bool {
                $name::push_units(self, u)
            }
        }

        impl<const N: usize, const M: usize> PartialEq<$name<M>> for $name<N> {
            fn eq(&self, other: &$name<M>) -> bool {
                self.$units_fn() == other.$units_fn()
            }
        }
        impl<const N: usize> Eq for $name<N> {}
        impl<const N: usize, const M: usize> PartialOrd<$name<M>> for $name<N> {
            fn partial_cmp(&self, other: &$name<M>) -> Option<Ordering> {
                Some(self.$units_fn().cmp(other.$units_fn()))
            }
        }
        impl<const N: usize> Ord for $name<N> {
            fn cmp(&self, other: &Self) -> Ordering {
                self.$units_fn().cmp(other.$units_fn())
            }
        }
        impl<const N: usize> Hash for $name<N> {
            fn hash<H: Hasher>(&self, state: &mut H) {
                self.$units_fn().hash(state)
            }
        }
        impl<const N: usize> fmt::Debug for $name<N> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(concat!(stringify!($name), "("))?;
                fmt::Write::write_char(f, '"')?;
                for c in self.chars() {
                    for e in c.escape_debug() {
                        fmt::Write::write_char(f, e)?;
                    }
                }
                f.write_str("\")")
            }
        }
        impl<const N: usize> fmt::Display for $name<N> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                for c in self.chars() {
                    fmt::Write::write_char(f, c)?;
                }
                Ok(())
            }
        }
        impl<const N: usize> fmt::Write for $name<N> {
            /// Appends `s`; on overflow appends what fits and returns `Err`.
            fn write_str(&mut self, s: &str) -> fmt::Result {
                let (t, truncated) = Self::from_str_truncating(s);
                if self.push_units(t.$units_fn()) || truncated {
                    Err(fmt::Error)
                } else {
                    Ok(())
                }
            }
        }
    };
}

iec_string!(
    STRING,
    u8,
    "STRING",
    as_bytes,
    "IEC `STRING`: a single-byte character string of fixed capacity `N` (no allocation).\n\n\
     The bytes are not interpreted (Latin-1 or UTF-8 alike); `Display` shows valid UTF-8 as \
     such and other bytes as Latin-1 characters."
);
iec_string!(
    WSTRING,
    u16,
    "WSTRING",
    as_units,
    "IEC `WSTRING`: a double-byte (UTF-16 code unit) string of fixed capacity `N` (no allocation)."
);

impl<const N: usize> STRING<N> {
    /// The UTF-8 bytes of `s`, truncated to the capacity at a character boundary; the flag is
    /// `true` if something was cut off.
    pub fn from_str_truncating(s: &str) -> (Self, bool) {
        let mut end = s.len().min(N);
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        let (v, _) = Self::from_units_truncating(s.as_bytes().get(..end).unwrap_or(&[]));
        (v, end < s.len())
    }
    /// Same as [`STRING::from_units_truncating`].
    pub const fn from_bytes_truncating(b: &[u8]) -> (Self, bool) {
        Self::from_units_truncating(b)
    }
    /// The contents as `&str` if they are valid UTF-8.
    pub fn as_str(&self) -> Option<&str> {
        core::str::from_utf8(self.as_bytes()).ok()
    }
    /// The characters for display: UTF-8 if the whole string is valid UTF-8, else Latin-1.
    pub fn chars(&self) -> impl Iterator<Item = char> + '_ {
        let utf8 = self.as_str();
        let latin1 = if utf8.is_some() {
            &[][..]
        } else {
            self.as_bytes()
        };
        utf8.unwrap_or("")
            .chars()
            .chain(latin1.iter().map(|&b| char::from(b)))
    }
}

impl<const N: usize> WSTRING<N> {
    /// The UTF-16 encoding of `s`, truncated to the capacity (never splitting a surrogate
    /// pair); the flag is `true` if something was cut off.
    pub fn from_str_truncating(s: &str) -> (Self, bool) {
        let mut w = Self::new();
        for c in s.chars() {
            let mut b = [0u16; 2];
            let enc = c.encode_utf16(&mut b);
            if w.len + enc.len() > N {
                return (w, true);
            }
            w.push_units(enc);
        }
        (w, false)
    }
    /// The characters (unpaired surrogates show as U+FFFD).
    pub fn chars(&self) -> impl Iterator<Item = char> + '_ {
        char::decode_utf16(self.as_units().iter().copied()).map(|r| r.unwrap_or('\u{FFFD}'))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::format;

    #[test]
    fn basics() {
        let s: STRING = STRING::new();
        assert_eq!(s.capacity(), 80);
        assert!(s.is_empty());
        let (s, t) = STRING::<5>::from_str_truncating("Hello, world");
        assert!(t);
        assert_eq!(s.as_bytes(), b"Hello");
        assert_eq!(s.len(), 5);
        assert_eq!(format!("{s}"), "Hello");
        assert_eq!(format!("{s:?}"), "STRING(\"Hello\")");
        let (s, t) = STRING::<3>::from_str_truncating("aé"); // 'é' is 2 bytes: fits exactly
        assert!(!t);
        assert_eq!(s.as_str(), Some("aé"));
        let (s, t) = STRING::<2>::from_str_truncating("aé"); // would split 'é'
        assert!(t);
        assert_eq!(s.as_bytes(), b"a");
        let (s, _) = STRING::<4>::from_bytes_truncating(&[0x41, 0xFF]);
        assert_eq!(format!("{s}"), "Aÿ");
        const C: (STRING<4>, bool) = STRING::from_bytes_truncating(b"abc");
        assert_eq!(C.0.as_bytes(), b"abc");
        let (z, t) = STRING::<0>::from_str_truncating("x");
        assert!(t && z.is_empty());
    }

    #[test]
    fn compare_across_capacities() {
        let a = STRING::<5>::from_str_truncating("ab").0;
        let b = STRING::<80>::from_str_truncating("ab").0;
        let c = STRING::<80>::from_str_truncating("ab\0").0;
        assert!(a == b);
        assert!(b < c);
        assert!(STRING::<3>::from_str_truncating("b").0 > b);
        assert_eq!(STRING::<4>::default(), STRING::<4>::new());
    }

    #[test]
    fn push_and_write() {
        use core::fmt::Write;
        let mut s = STRING::<4>::new();
        assert!(!s.push_units(b"ab"));
        assert!(s.push_units(b"cde"));
        assert_eq!(s.as_bytes(), b"abcd");
        let mut s = STRING::<4>::new();
        assert!(write!(s, "{}", 12345).is_err());
        assert_eq!(s.as_bytes(), b"1234");
        let (r, t) = s.resize::<2>();
        assert!(t);
        assert_eq!(r.as_bytes(), b"12");
    }

    #[test]
    fn wstring() {
        let (w, t) = WSTRING::<3>::from_str_truncating("a😀b");
        assert!(t);
        assert_eq!(w.len(), 3);
        assert_eq!(format!("{w}"), "a😀");
        let (w, t) = WSTRING::<2>::from_str_truncating("a😀");
        assert!(t);
        assert_eq!(format!("{w:?}"), "WSTRING(\"a\")");
        let (w, _) = WSTRING::<2>::from_units_truncating(&[0xD800]);
        assert_eq!(format!("{w}"), "\u{FFFD}");
        let w: WSTRING = WSTRING::default();
        assert_eq!(w.capacity(), DEFAULT_STRING_LEN);
    }
}

/// Strings serialise as text; a longer text is truncated to the capacity.
#[cfg(feature = "serde")]
macro_rules! string_serde {
    ($name:ident) => {
        impl<const N: usize> serde::Serialize for $name<N> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.collect_str(self)
            }
        }

        impl<'de, const N: usize> serde::Deserialize<'de> for $name<N> {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                struct V<const N: usize>;
                impl<const N: usize> serde::de::Visitor<'_> for V<N> {
                    type Value = $name<N>;
                    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                        f.write_str("a string")
                    }
                    fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<$name<N>, E> {
                        Ok($name::<N>::from_str_truncating(v).0)
                    }
                }
                d.deserialize_str(V::<N>)
            }
        }
    };
}
#[cfg(feature = "serde")]
string_serde!(STRING);
#[cfg(feature = "serde")]
string_serde!(WSTRING);
