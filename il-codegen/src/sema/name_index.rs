//! The variable table of a POU: upper-case name → index into its variables,
//! looked up with the name as written in the body (any case) once or twice
//! per operand. A `HashMap<String, _>` needs the upper-case key first (a copy
//! into a buffer, a UTF-8 check, then the hash); this table hashes and
//! compares the spelling as it is, folding ASCII case eight bytes at a time.
//! IEC names are case-insensitive in ASCII only, as `to_ascii_uppercase`.

const K: u64 = 0x51_7c_c1_b7_27_22_0a_95;
const LO7: u64 = 0x7f7f_7f7f_7f7f_7f7f;
const HI: u64 = 0x8080_8080_8080_8080;

/// The bytes of `w` with ASCII `a..=z` turned into `A..=Z`, others kept.
fn upper_word(w: u64) -> u64 {
    let low = w & LO7;
    // High bit of each byte: `>= 'a'` and not `>= '{'`, and ASCII.
    let ge_a = low.wrapping_add(0x1f1f_1f1f_1f1f_1f1f);
    let ge_brace = low.wrapping_add(0x0505_0505_0505_0505);
    let lower = ge_a & !ge_brace & !w & HI;
    w ^ (lower >> 2)
}

/// FxHash of the upper-case spelling of `name`, a word at a time.
fn fold_hash(name: &[u8]) -> u64 {
    let mut h = name.len() as u64;
    let mut chunks = name.chunks_exact(8);
    for c in &mut chunks {
        let mut w = [0u8; 8];
        w.copy_from_slice(c);
        h = (h.rotate_left(5) ^ upper_word(u64::from_le_bytes(w))).wrapping_mul(K);
    }
    let rest = chunks.remainder();
    if !rest.is_empty() {
        // Byte by byte: a copy of a variable length is a call to `memcpy`.
        let w = rest
            .iter()
            .rev()
            .fold(0u64, |w, &b| (w << 8) | u64::from(b));
        h = (h.rotate_left(5) ^ upper_word(w)).wrapping_mul(K);
    }
    h
}

/// Upper-case name → `usize`, open addressing with linear probing.
#[derive(Default, Clone, Debug)]
pub(crate) struct NameIndex {
    /// The keys (upper case) and values, in insertion order.
    entries: Vec<(String, usize)>,
    /// Entry number + 1, or 0 for an empty slot; a power of two long and at
    /// most half full.
    slots: Vec<u32>,
}

impl NameIndex {
    /// The slot of `name` (any case): where it is, or the empty slot where it
    /// would go.
    fn slot(&self, name: &str) -> usize {
        let mask = self.slots.len() - 1;
        // The high bits of the product mix every input bit.
        let mut i = (fold_hash(name.as_bytes()) >> 32) as usize & mask;
        loop {
            match self.slots[i] {
                0 => return i,
                e if self.entries[e as usize - 1].0.eq_ignore_ascii_case(name) => return i,
                _ => i = (i + 1) & mask,
            }
        }
    }

    /// The value of `name`, written in any case.
    pub fn get(&self, name: &str) -> Option<usize> {
        if self.slots.is_empty() {
            return None;
        }
        match self.slots[self.slot(name)] {
            0 => None,
            e => Some(self.entries[e as usize - 1].1),
        }
    }

    /// Sets the value of `name` (stored in upper case), replacing an old one.
    pub fn insert(&mut self, name: &str, value: usize) {
        if (self.entries.len() + 1) * 2 > self.slots.len() {
            self.grow();
        }
        let s = self.slot(name);
        match self.slots[s] {
            0 => {
                self.entries.push((name.to_ascii_uppercase(), value));
                self.slots[s] = self.entries.len() as u32;
            }
            e => self.entries[e as usize - 1].1 = value,
        }
    }

    fn grow(&mut self) {
        let len = (self.slots.len() * 2).max(16);
        self.slots = vec![0; len];
        for e in 0..self.entries.len() {
            let s = self.slot(&self.entries[e].0);
            self.slots[s] = e as u32 + 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folding_is_ascii_uppercase() {
        let samples = [
            "",
            "a",
            "Zz_09",
            "abcdefgh",
            "ABCDEFGHIJ",
            "`az{@AZ[",
            "ärger_x",
            "m\u{e9}lange_long_name_9",
        ];
        for s in samples {
            let up = s.to_ascii_uppercase();
            assert_eq!(fold_hash(s.as_bytes()), fold_hash(up.as_bytes()), "{s}");
        }
        // Every byte value, in each position of a word.
        for b in 0..=255u8 {
            for pos in 0..8 {
                let mut w = [b'x'; 8];
                w[pos] = b;
                let mut want = w;
                want.make_ascii_uppercase();
                assert_eq!(
                    upper_word(u64::from_le_bytes(w)),
                    u64::from_le_bytes(want),
                    "byte {b} at {pos}"
                );
            }
        }
    }

    #[test]
    fn names_are_found_in_any_case() {
        let mut ix = NameIndex::default();
        assert_eq!(ix.get("X"), None);
        for i in 0..1000 {
            ix.insert(&format!("Var_{i}"), i);
        }
        assert!((0..1000).all(|i| ix.get(&format!("VAR_{i}")) == Some(i)));
        assert!((0..1000).all(|i| ix.get(&format!("var_{i}")) == Some(i)));
        assert_eq!(ix.get("VAR_1000"), None);
        assert_eq!(ix.get("VAR_1"), Some(1));
        ix.insert("vAR_1", 7);
        assert_eq!(ix.get("Var_1"), Some(7));
        assert_eq!(ix.entries.len(), 1000);
        // Not ASCII: only ASCII letters fold (as `eq_ignore_ascii_case`).
        ix.insert("ä", 1);
        assert_eq!(ix.get("ä"), Some(1));
        assert_eq!(ix.get("Ä"), None);
    }
}
