//! Large arrays on the heap (feature `alloc`, on with `std`).
//!
//! A FUNCTION_BLOCK or PROGRAM variable that is an array of more than 64 KiB
//! becomes a `Box<[T]>` field (its first dimension on the heap), so that
//! creating the instance never builds the array on the stack: a
//! `ARRAY[0..1999999] OF LREAL` is 16 MB, more than a thread's stack. The
//! generated code indexes it with `get`, as any array; the host reads it as a
//! slice. Its length is the declared one (a deserialized snapshot of another
//! length is refused).

pub use alloc::boxed::Box;

/// `len` elements, element `i` being `f(i)`, built in place on the heap.
pub fn from_fn<T>(len: usize, f: impl FnMut(usize) -> T) -> Box<[T]> {
    (0..len).map(f).collect()
}

/// serde for a heap array of exactly `N` elements (features `alloc` and
/// `serde`); generated code puts `#[serde(serialize_with =
/// "::il_std::heap::serde_len::serialize", deserialize_with =
/// "::il_std::heap::serde_len::deserialize::<_, _, N>")]` on the field.
#[cfg(feature = "serde")]
pub mod serde_len {
    use super::Box;
    use core::fmt;
    use core::marker::PhantomData;
    use serde::de::{self, Deserialize, Deserializer, SeqAccess, Visitor};
    use serde::ser::{Serialize, SerializeSeq, Serializer};

    /// Serializes the elements as a sequence.
    pub fn serialize<S: Serializer, T: Serialize>(a: &[T], s: S) -> Result<S::Ok, S::Error> {
        let mut t = s.serialize_seq(Some(a.len()))?;
        for x in a {
            t.serialize_element(x)?;
        }
        t.end()
    }

    /// Deserializes a sequence of exactly `N` elements.
    pub fn deserialize<'de, D, T, const N: usize>(d: D) -> Result<Box<[T]>, D::Error>
    where
        D: Deserializer<'de>,
        T: Deserialize<'de>,
    {
        let len = N;
        struct V<T>(usize, PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for V<T> {
            type Value = Box<[T]>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "an array of {} elements", self.0)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Box<[T]>, A::Error> {
                let mut out = alloc::vec::Vec::with_capacity(self.0.min(1 << 16));
                while let Some(x) = seq.next_element()? {
                    if out.len() == self.0 {
                        return Err(de::Error::invalid_length(self.0 + 1, &self));
                    }
                    out.push(x);
                }
                if out.len() != self.0 {
                    return Err(de::Error::invalid_length(out.len(), &self));
                }
                Ok(out.into_boxed_slice())
            }
        }
        d.deserialize_seq(V::<T>(len, PhantomData))
    }
}
