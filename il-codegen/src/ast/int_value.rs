//! Integer values of literals and constants, held small.

/// The value of an integer literal or constant: sign and magnitude, each
/// magnitude up to `u64::MAX` (what the literal parser accepts: every IEC
/// integer, and the too-negative values the checker then refuses for their
/// type). Held so rather than as an `i128`, whose 16-byte alignment made
/// every literal, operand, instruction, constant, IR value and statement
/// larger. The magnitude is two 32-bit halves: aligned to 4, the value is
/// 12 bytes, so a constant with its type and tag fits in 16 (and an IR
/// value with it).
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct IntValue {
    low: u32,
    high: u32,
    negative: bool,
}

impl IntValue {
    /// `v`; a magnitude over `u64::MAX` (which no caller makes: the
    /// literal parser refuses it) is held as `u64::MAX`.
    pub fn new(v: i128) -> IntValue {
        let magnitude = u64::try_from(v.unsigned_abs()).unwrap_or(u64::MAX);
        IntValue {
            low: magnitude as u32,
            high: (magnitude >> 32) as u32,
            negative: v < 0,
        }
    }

    /// The value.
    pub fn get(self) -> i128 {
        let m = i128::from(u64::from(self.high) << 32 | u64::from(self.low));
        if self.negative { -m } else { m }
    }
}

impl From<i128> for IntValue {
    fn from(v: i128) -> IntValue {
        IntValue::new(v)
    }
}

impl std::fmt::Debug for IntValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
    }
}

impl std::fmt::Display for IntValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.get())
    }
}
