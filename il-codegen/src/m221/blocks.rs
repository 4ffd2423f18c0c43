//! Function blocks in a rung: `BLK %TM0` opens the block, the lines up to
//! `OUT_BLK` compute its inputs (a pin name alone, `IN`, `CU`, `R` ...,
//! stores the CR into that input), `OUT_BLK` runs it, and the lines up to
//! `END_BLK` read its outputs by their bare names (`LD Q`, `AND D`). A block
//! without `OUT_BLK` runs at `END_BLK`.

use std::ops::Range;

use super::read::Line;
use super::rung::{Fail, Pou, Rung, bad};

impl Pou<'_> {
    /// A line that belongs to the block syntax; `false` when it is none.
    pub fn block_line(
        &mut self,
        rung: &mut Rung,
        line: &Line,
        op: &str,
        arg: Option<&(&str, Range<usize>)>,
        fr: Range<usize>,
    ) -> Result<bool, Fail> {
        let all = line.xml(0..line.text.len());
        match (op, arg) {
            ("BLK", Some((s, r))) => {
                if rung.blk.is_some() {
                    return Err(bad(line, fr, "`BLK` inside another `BLK` ... `END_BLK`"));
                }
                let at = line.xml(r.clone());
                let b = match self.objs.block(self.p, s, &at) {
                    Ok(b) => b,
                    Err(e) => return Err(self.not_object(line, s, r.clone(), e)),
                };
                rung.blk = Some((b, false));
                Ok(true)
            }
            ("OUT_BLK", None) => {
                let Some((b, false)) = rung.blk else {
                    return Err(bad(
                        line,
                        fr,
                        "`OUT_BLK` outside `BLK` ... `END_BLK`, or twice",
                    ));
                };
                self.put(&format!("CAL {}", b.name()), all);
                rung.blk = Some((b, true));
                // The outputs are read with loads; the CR is undefined.
                rung.cr = false;
                Ok(true)
            }
            ("END_BLK", None) => {
                let Some((b, out)) = rung.blk.take() else {
                    return Err(bad(line, fr, "`END_BLK` without its `BLK`"));
                };
                if !out {
                    self.put(&format!("CAL {}", b.name()), all);
                }
                Ok(true)
            }
            (_, None) => {
                // A pin of the open block, before `OUT_BLK`.
                let Some((b, false)) = rung.blk else {
                    return Ok(false);
                };
                let (inputs, _) = b.pins();
                let Some(pin) = inputs.iter().find(|p| **p == op) else {
                    if ["IN", "CU", "CD", "R", "S", "U", "I", "O"].contains(&op) {
                        return Err(bad(line, fr, format!("`{}` has no input `{op}`", b.name())));
                    }
                    return Ok(false);
                };
                if !rung.cr {
                    return Err(bad(line, fr, format!("the input `{op}` before a load")));
                }
                self.put(&format!("ST {}.{pin}", b.name()), all);
                Ok(true)
            }
            (_, Some((s, _))) => {
                // An output of the block after `OUT_BLK`: `LD Q`.
                let Some((b, true)) = rung.blk else {
                    return Ok(false);
                };
                let (_, outputs) = b.pins();
                let up = s.to_ascii_uppercase();
                let Some(o) = outputs.iter().find(|o| **o == up) else {
                    return Ok(false);
                };
                if !["LD", "LDN", "AND", "ANDN", "OR", "ORN", "XOR", "XORN"].contains(&op) {
                    return Ok(false);
                }
                if op.starts_with("LD") {
                    rung.cr = true;
                } else if !rung.cr {
                    return Err(bad(line, fr, format!("`{op}` before a load")));
                }
                self.put(&format!("{op} {}.{o}", b.name()), all);
                Ok(true)
            }
        }
    }
}
