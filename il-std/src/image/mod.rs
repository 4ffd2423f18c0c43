//! The process image: the PLC's inputs (`%I`), outputs (`%Q`) and memory
//! (`%M`) as byte areas that the host fills before a scan and reads after it.
//!
//! Addressing follows the common byte-oriented convention (CODESYS): `%IX3.2`
//! is bit 2 of input byte 3, `%IB3` is byte 3, `%IW3` is the 16-bit word at
//! byte 6 (word 3), `%ID3` the 32-bit double word at byte 12, `%IL3` the
//! 64-bit word at byte 24. Multi-byte values are little-endian, so `%MW0`
//! and `%MX0.3` overlap as on a PLC: bit 3 of `%MW0` is `%MX0.3`. A bit
//! address with one number, `%IX17`, is bit 17 counted from bit 0 of byte 0
//! (byte 2, bit 1).
//!
//! Accessors never panic: an access outside an area reads 0 and writes
//! nothing (the compiler refuses addresses outside the areas anyway).
//! Hosts use the typed addresses of [`address`] (`ctx.io.set(iw(1), 500)`)
//! rather than byte offsets.

pub mod address;

use crate::area::{INPUT_BYTES, MEMORY_BYTES, OUTPUT_BYTES};

pub use crate::area::Area;

/// A located variable or direct address used by generated code, for hosts
/// that bind fieldbus data (see each generated POU's `ADDRESSES`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Located {
    /// The variable's name, or the address itself for a direct address in code.
    pub name: &'static str,
    /// As written, e.g. `%QX0.1`.
    pub address: &'static str,
    /// Its area.
    pub area: Area,
    /// Byte offset in the area.
    pub byte: usize,
    /// Bit number for bit addresses.
    pub bit: Option<u8>,
    /// IEC type name (`BOOL`, `INT`, ...).
    pub ty: &'static str,
    /// `false` for a partly specified address (`AT %I*`, `%Q*`, `%M*`) that
    /// no VAR_CONFIG completed: `byte` and `bit` mean nothing, and the host
    /// binds the variable by reading or writing its field (`name`).
    pub bound: bool,
    /// Declared RETAIN: a host that keeps RETAIN variables over a restart
    /// saves these bytes of the process image too (located variables live
    /// there, not in the generated RETAIN snapshots).
    pub retain: bool,
}

/// The three byte areas.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProcessImage {
    /// `%I` bytes.
    pub inputs: [u8; INPUT_BYTES],
    /// `%Q` bytes.
    pub outputs: [u8; OUTPUT_BYTES],
    /// `%M` bytes.
    pub memory: [u8; MEMORY_BYTES],
}

impl Default for ProcessImage {
    fn default() -> Self {
        ProcessImage {
            inputs: [0; INPUT_BYTES],
            outputs: [0; OUTPUT_BYTES],
            memory: [0; MEMORY_BYTES],
        }
    }
}

impl ProcessImage {
    fn area(&self, a: Area) -> &[u8] {
        match a {
            Area::Input => &self.inputs,
            Area::Output => &self.outputs,
            Area::Memory => &self.memory,
        }
    }
    fn area_mut(&mut self, a: Area) -> &mut [u8] {
        match a {
            Area::Input => &mut self.inputs,
            Area::Output => &mut self.outputs,
            Area::Memory => &mut self.memory,
        }
    }
    /// Bit `bit` (0..7) of byte `byte`.
    pub fn bit(&self, a: Area, byte: usize, bit: u8) -> bool {
        self.area(a)
            .get(byte)
            .is_some_and(|b| b >> (bit & 7) & 1 == 1)
    }
    /// Set or clear bit `bit` of byte `byte`.
    pub fn set_bit(&mut self, a: Area, byte: usize, bit: u8, v: bool) {
        if let Some(b) = self.area_mut(a).get_mut(byte) {
            let m = 1u8 << (bit & 7);
            if v { *b |= m } else { *b &= !m }
        }
    }
    pub(crate) fn read<const N: usize>(&self, a: Area, byte: usize) -> [u8; N] {
        let mut out = [0u8; N];
        if let Some(s) = self.area(a).get(byte..byte.saturating_add(N)) {
            out.copy_from_slice(s);
        }
        out
    }
    pub(crate) fn write<const N: usize>(&mut self, a: Area, byte: usize, v: [u8; N]) {
        if let Some(s) = self.area_mut(a).get_mut(byte..byte.saturating_add(N)) {
            s.copy_from_slice(&v);
        }
    }
    /// The byte at `byte`.
    pub fn byte(&self, a: Area, byte: usize) -> u8 {
        self.area(a).get(byte).copied().unwrap_or(0)
    }
    /// Store a byte.
    pub fn set_byte(&mut self, a: Area, byte: usize, v: u8) {
        self.write(a, byte, [v]);
    }
    /// The little-endian 16-bit value at byte offset `byte`.
    pub fn word(&self, a: Area, byte: usize) -> u16 {
        u16::from_le_bytes(self.read(a, byte))
    }
    /// Store a 16-bit value.
    pub fn set_word(&mut self, a: Area, byte: usize, v: u16) {
        self.write(a, byte, v.to_le_bytes());
    }
    /// The little-endian 32-bit value at byte offset `byte`.
    pub fn dword(&self, a: Area, byte: usize) -> u32 {
        u32::from_le_bytes(self.read(a, byte))
    }
    /// Store a 32-bit value.
    pub fn set_dword(&mut self, a: Area, byte: usize, v: u32) {
        self.write(a, byte, v.to_le_bytes());
    }
    /// The little-endian 64-bit value at byte offset `byte`.
    pub fn lword(&self, a: Area, byte: usize) -> u64 {
        u64::from_le_bytes(self.read(a, byte))
    }
    /// Store a 64-bit value.
    pub fn set_lword(&mut self, a: Area, byte: usize, v: u64) {
        self.write(a, byte, v.to_le_bytes());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn word_and_bits_overlap_little_endian() {
        let mut p = ProcessImage::default();
        p.set_word(Area::Memory, 0, 0b1000);
        assert!(p.bit(Area::Memory, 0, 3));
        p.set_bit(Area::Memory, 1, 0, true);
        assert_eq!(p.word(Area::Memory, 0), 0x0108);
        assert_eq!(p.byte(Area::Memory, 1), 1);
    }

    #[test]
    fn out_of_range_reads_zero_and_never_panics() {
        let mut p = ProcessImage::default();
        p.set_dword(Area::Input, INPUT_BYTES - 2, u32::MAX);
        assert_eq!(p.dword(Area::Input, INPUT_BYTES - 2), 0);
        assert_eq!(p.lword(Area::Output, usize::MAX), 0);
        assert!(!p.bit(Area::Output, usize::MAX, 9));
        p.set_lword(Area::Memory, MEMORY_BYTES - 8, 7);
        assert_eq!(p.lword(Area::Memory, MEMORY_BYTES - 8), 7);
    }
}
