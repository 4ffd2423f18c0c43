//! Modbus TCP: the address table (OpenPLC's) and the server.
//!
//! | Modbus table (function codes)          | Addresses    | IEC addresses        | Notes |
//! |----------------------------------------|--------------|----------------------|-------|
//! | discrete inputs (2)                    | 0 – 2047     | `%IX0.0` – `%IX255.7`| read only; address = 8·byte + bit |
//! | coils (1, 5, 15)                       | 0 – 2047     | `%QX0.0` – `%QX255.7`| address = 8·byte + bit |
//! | input registers (4)                    | 0 – 127      | `%IW0` – `%IW127`    | read only |
//! | holding registers (3, 6, 16)           | 0 – 127      | `%QW0` – `%QW127`    | |
//! | holding registers                      | 1024 – 1535  | `%MW0` – `%MW511`    | |
//! | holding registers                      | 2048 – 2559  | `%MD0` – `%MD255`    | two registers each, high word first |
//! | holding registers                      | 4096 – 4607  | `%ML0` – `%ML127`    | four registers each, high word first |
//!
//! The starts are OpenPLC's; the ends are il-std's area sizes (256 input,
//! 256 output, 1024 memory bytes). As in il-std, `%MW`, `%MD` and `%ML` are
//! views of the same memory bytes (`%MD0` is `%MW0` and `%MW1`), so a write to
//! register 2048 changes registers 1024–1025 too. A request that touches any
//! address outside the table gets exception 2 (illegal data address); an
//! unknown function code gets exception 1 (illegal function); a write to
//! discrete inputs or input registers has no function code at all.

mod server;

pub use server::{Server, ServerOptions};

use il_std::{Area, INPUT_BYTES, MEMORY_BYTES, OUTPUT_BYTES};

/// First holding register of `%MW`.
pub const MW_START: u16 = 1024;
/// First holding register of `%MD`.
pub const MD_START: u16 = 2048;
/// First holding register of `%ML`.
pub const ML_START: u16 = 4096;

/// The four Modbus tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Table {
    /// Coils: `%QX`.
    Coils,
    /// Discrete inputs: `%IX`.
    DiscreteInputs,
    /// Input registers: `%IW`.
    InputRegisters,
    /// Holding registers: `%QW`, `%MW`, `%MD`, `%ML`.
    HoldingRegisters,
}

/// Where a bit of a bit table lives: area, byte, bit; `None` outside the table.
pub fn bit_place(table: Table, address: u16) -> Option<(Area, usize, u8)> {
    let (area, bytes) = match table {
        Table::Coils => (Area::Output, OUTPUT_BYTES),
        Table::DiscreteInputs => (Area::Input, INPUT_BYTES),
        _ => return None,
    };
    let n = usize::from(address);
    (n < bytes * 8).then_some((area, n / 8, (n % 8) as u8))
}

/// Where a register lives: the area and the byte of the 16-bit word (as
/// `ProcessImage::word` reads it); `None` outside the table.
pub fn register_place(table: Table, reg: u16) -> Option<(Area, usize)> {
    let r = usize::from(reg);
    match table {
        Table::InputRegisters => (r < INPUT_BYTES / 2).then_some((Area::Input, 2 * r)),
        Table::HoldingRegisters => {
            let (mw, md, ml) = (
                usize::from(MW_START),
                usize::from(MD_START),
                usize::from(ML_START),
            );
            // Each view covers the whole memory area: MEMORY_BYTES / 2 registers.
            let regs = MEMORY_BYTES / 2;
            if r < OUTPUT_BYTES / 2 {
                Some((Area::Output, 2 * r))
            } else if (mw..mw + regs).contains(&r) {
                Some((Area::Memory, 2 * (r - mw)))
            } else if (md..md + regs).contains(&r) {
                // %MDk is little-endian at byte 4k; its high word (sent first) at 4k + 2.
                let (k, low) = ((r - md) / 2, (r - md) % 2 == 1);
                Some((Area::Memory, 4 * k + if low { 0 } else { 2 }))
            } else if (ml..ml + regs).contains(&r) {
                // Register j of %MLk (j = 0 the most significant) is the word at 8k + 2(3 - j).
                let (k, j) = ((r - ml) / 4, (r - ml) % 4);
                Some((Area::Memory, 8 * k + 2 * (3 - j)))
            } else {
                None
            }
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use il_std::ProcessImage;
    use il_std::addr::{md, ml, mw, qw};

    fn reg(io: &ProcessImage, r: u16) -> u16 {
        let (a, b) = register_place(Table::HoldingRegisters, r).unwrap();
        io.word(a, b)
    }

    #[test]
    fn holding_registers_follow_openplc() {
        let mut io = ProcessImage::default();
        io.set(qw(3), 33);
        io.set(mw(5), 55);
        io.set(md(4), 0x1234_5678); // bytes 16..20: no overlap with %MW5
        io.set(ml(3), 0x1111_2222_3333_4444); // bytes 24..32
        assert_eq!(reg(&io, 3), 33);
        assert_eq!(reg(&io, 1029), 55);
        assert_eq!((reg(&io, 2056), reg(&io, 2057)), (0x1234, 0x5678));
        let l: Vec<u16> = (4108..4112).map(|r| reg(&io, r)).collect();
        assert_eq!(l, [0x1111, 0x2222, 0x3333, 0x4444]);
        for r in [128, 1023, 1536, 2047, 2560, 4095, 4608, u16::MAX] {
            assert_eq!(register_place(Table::HoldingRegisters, r), None, "{r}");
        }
        assert_eq!(register_place(Table::InputRegisters, 128), None);
        assert_eq!(bit_place(Table::Coils, 2047), Some((Area::Output, 255, 7)));
        assert_eq!(bit_place(Table::Coils, 2048), None);
    }
}
