//! A small, fast hasher for the checker's name tables (variables, labels,
//! POUs), looked up once per operand. The keys are short upper-case names
//! from the program being compiled, not attacker-chosen keys of a server,
//! so the standard library's SipHash (built against hash flooding) is more
//! than they need; this is the multiply-rotate hash rustc uses (FxHash).

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// `HashMap` with [`FxHasher`].
pub(crate) type FxMap<K, V> = HashMap<K, V, BuildHasherDefault<FxHasher>>;

/// Mixes each word into the state: `(state.rotl(5) ^ word) * K`.
#[derive(Default, Clone, Copy)]
pub(crate) struct FxHasher(u64);

const K: u64 = 0x51_7c_c1_b7_27_22_0a_95;

impl FxHasher {
    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(K);
    }
}

impl Hasher for FxHasher {
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for c in &mut chunks {
            let mut w = [0u8; 8];
            w.copy_from_slice(c);
            self.add(u64::from_le_bytes(w));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut w = [0u8; 8];
            w[..rest.len()].copy_from_slice(rest);
            self.add(u64::from_le_bytes(w));
        }
    }
    fn write_u8(&mut self, i: u8) {
        self.add(i as u64);
    }
    fn write_u32(&mut self, i: u32) {
        self.add(i as u64);
    }
    fn write_u64(&mut self, i: u64) {
        self.add(i);
    }
    fn write_usize(&mut self, i: usize) {
        self.add(i as u64);
    }
    fn finish(&self) -> u64 {
        self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_find_their_entries() {
        let mut m: FxMap<String, usize> = FxMap::default();
        for i in 0..1000 {
            m.insert(format!("VAR_{i}"), i);
        }
        assert!((0..1000).all(|i| m.get(format!("VAR_{i}").as_str()) == Some(&i)));
        assert_eq!(m.get("VAR_1000"), None);
    }
}
