//! 3rd-edition forms in generated bodies (kept apart from `bodies.rs`):
//! implicit widening conversions and partial (bit) access. The widening
//! table here is written again from IL-SEMANTICS.md, not taken from the
//! compiler, so the differential test also checks the compiler's table.

use super::*;

/// Whether a `from` value becomes a `to` implicitly (lossless widening).
pub fn widens(from: T, to: T) -> bool {
    let bits = |t: T| match t {
        T::Bool => 1,
        T::Sint | T::Usint | T::Byte => 8,
        T::Int | T::Uint | T::Word => 16,
        T::Dint | T::Udint | T::Dword | T::Real => 32,
        _ => 64,
    };
    let unsigned = |t: T| matches!(t, T::Usint | T::Uint | T::Udint | T::Ulint);
    let (fb, tb) = (bits(from), bits(to));
    match to {
        _ if from == to => false,
        T::Int | T::Dint | T::Lint => (from.is_signed() || unsigned(from)) && fb < tb,
        T::Uint | T::Udint | T::Ulint => unsigned(from) && fb < tb,
        T::Byte | T::Word | T::Dword | T::Lword => (from == T::Bool || from.is_bits()) && fb < tb,
        T::Real => from.is_int() && fb <= 16,
        T::Lreal => from == T::Real || (from.is_int() && fb <= 32),
        _ => false,
    }
}

impl Pou<'_> {
    /// One 3rd-edition statement: a widening store or operator, or a bit,
    /// byte or word of a variable read or written.
    pub(super) fn dialect_block(&mut self, types: &[T]) {
        if self.rng.chance(50) && self.widening(types) {
            return;
        }
        self.partial_access(types);
    }

    /// `LD narrow / [op wide] / ST wide`. False when no pair of types widens.
    fn widening(&mut self, types: &[T]) -> bool {
        let pairs: Vec<(T, T)> = types
            .iter()
            .flat_map(|&a| types.iter().map(move |&b| (a, b)))
            .filter(|&(a, b)| widens(a, b))
            .filter(|&(_, b)| !self.writable(b).is_empty())
            .collect();
        if pairs.is_empty() {
            return false;
        }
        let (narrow, wide) = *self.rng.pick(&pairs);
        let n = self.rng.pick(&self.vars_of(narrow)).clone();
        let w_vars = self.vars_of(wide);
        let w = self.rng.pick(&w_vars).clone();
        let target = self.rng.pick(&self.writable(wide)).clone();
        match self.rng.below(4) {
            // The CR widens at the operator (CR narrow, operand wide).
            0 if wide.is_num() => {
                let op = *self.rng.pick(&["ADD", "SUB", "MUL"]);
                self.emit(format!("LD {n}"));
                self.emit(format!("{op} {w}"));
                self.emit(format!("ST {target}"));
            }
            // The operand widens (CR wide, operand narrow).
            1 if wide.is_bits() => {
                let op = *self.rng.pick(&["AND", "OR", "XOR"]);
                self.emit(format!("LD {w}"));
                self.emit(format!("{op} {n}"));
                self.emit(format!("ST {target}"));
            }
            2 => {
                let op = *self.rng.pick(&["GT", "GE", "EQ", "NE", "LE", "LT"]);
                self.emit(format!("LD {n}"));
                self.emit(format!("{op} {w}"));
                self.finish_expr(T::Bool);
            }
            _ => {
                self.emit(format!("LD {n}"));
                self.emit(format!("ST {target}"));
            }
        }
        true
    }

    /// `v.n`, `v.%Bn` ... as an operand or a target.
    fn partial_access(&mut self, types: &[T]) {
        let wholes: Vec<T> = types
            .iter()
            .copied()
            .filter(|t| t.is_int() || t.is_bits())
            .collect();
        if wholes.is_empty() {
            return;
        }
        let t = *self.rng.pick(&wholes);
        let width: u32 = match t.range().1 {
            255 => 8,
            65535 => 16,
            4294967295 => 32,
            127 => 8,
            32767 => 16,
            2147483647 => 32,
            _ => 64,
        };
        let (part, size, count) = match self.rng.below(4) {
            0 if width >= 16 => ("%B", T::Byte, width / 8),
            1 if width >= 32 => ("%W", T::Word, width / 16),
            _ => (*self.rng.pick(&["", "%X"]), T::Bool, width),
        };
        let k = self.rng.below(count as usize);
        let read = self.rng.chance(50);
        if read {
            // From a variable or an array element.
            let arrays: Vec<_> = self.arrays.iter().filter(|a| a.1 == t).cloned().collect();
            let whole = if !arrays.is_empty() && self.rng.chance(30) {
                let (a, _, lo, hi) = self.rng.pick(&arrays).clone();
                let idx = self.vars_of(T::Int);
                if !idx.is_empty() && self.rng.chance(50) {
                    format!("{a}[{}]", self.rng.pick(&idx))
                } else {
                    format!(
                        "{a}[{}]",
                        lo + self.rng.below((hi - lo + 1) as usize) as i64
                    )
                }
            } else {
                // Not a direct address: `%IW4.3` reads as a bit address.
                let wholes: Vec<String> = self
                    .vars_of(t)
                    .into_iter()
                    .filter(|n| !n.starts_with('%'))
                    .collect();
                if wholes.is_empty() {
                    return;
                }
                self.rng.pick(&wholes).clone()
            };
            self.emit(format!("LD {whole}.{part}{k}"));
            self.finish_expr(size);
        } else {
            // Parts of a subrange cannot be written (IL0135): user.rs names
            // its subrange variables `sub`, `rec.s` and `recs[..].s`.
            let targets: Vec<String> = self
                .writable(t)
                .into_iter()
                .filter(|n| !n.starts_with('%') && n != "sub" && !n.ends_with(".s"))
                .collect();
            if targets.is_empty() {
                return;
            }
            let whole = self.rng.pick(&targets).clone();
            if size == T::Bool {
                self.bool_cond();
                let op = *self.rng.pick(&["ST", "STN", "S", "R"]);
                self.emit(format!("{op} {whole}.{part}{k}"));
            } else {
                let o = self.operand(size, false);
                self.emit(format!("LD {o}"));
                self.emit(format!("ST {whole}.{part}{k}"));
            }
        }
    }
}
