//! The inputs every scan measurement gives the benchmark programs: the same
//! on the generated side, the hand-written side (`benches/scan.rs`, the
//! `scans` binary) and MATIEC's C (`benches/matiec/driver.c` computes the
//! same xorshift sequences).

use crate::generator::XorShift;
use il_std::TIME;

/// Time between two scans (`Cycle::advance` before each scan).
pub const TICK: TIME = TIME::from_ms(10);

/// `Interlock.x`.
pub fn interlock_x() -> [bool; 64] {
    let mut r = XorShift::new(5);
    core::array::from_fn(|_| r.below(3) != 0)
}

/// `ArrayProc.samples`.
pub fn samples() -> [i16; 256] {
    let mut r = XorShift::new(9);
    core::array::from_fn(|_| r.next_u64() as i16 >> 4)
}

/// `Blocks.go` and `BlocksLoop.go`.
pub fn go() -> [bool; 100] {
    let mut r = XorShift::new(3);
    core::array::from_fn(|_| r.below(4) != 0)
}

/// `Mixed.raw`.
pub fn raw() -> [i16; 32] {
    let mut r = XorShift::new(11);
    core::array::from_fn(|_| r.next_u64() as i16 >> 3)
}
