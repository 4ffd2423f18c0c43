//! Operation blocks (`[ %MW1 := %MW2 + 1 ]`, `OPER [ ... ]`) and comparison
//! blocks (`LD [ %MF1 >= 2.0 ]`, `AND [ ... ]`, `AND( [ ... ]`) in a rung:
//! the expression (parsed and written by `expr`) placed where the M221 runs
//! it. An operation block after a condition runs when the CR is 1 (a jump
//! around it, the CR kept in `_cr`); inside `(`, where IEC IL has no jump,
//! its value is stored through `SEL`.

use std::ops::Range;

use super::codes::{BAD_LINE, UNCONFIGURED, UNSUPPORTED};
use super::expr::{self, Dest, Parsed};
use super::objects::Ty;
use super::read::{Line, span};
use super::rung::{Fail, Pou, Rung, bad, self_temp};
use crate::diag::Diagnostic;

impl Pou<'_> {
    /// `[ d := e ]`, `OPER [ ... ]`, `LD [ a > b ]`, `AND [ ... ]` ...
    pub(super) fn bracket(
        &mut self,
        rung: &mut Rung,
        line: &Line,
        open: usize,
    ) -> Result<(), Fail> {
        let text = line.text.as_str();
        let all = line.xml(0..text.len());
        let head = text[..open].trim().to_ascii_uppercase();
        let close = match text.rfind(']') {
            Some(c) if c > open && text[c + 1..].trim().is_empty() => c,
            _ => {
                return Err(bad(
                    line,
                    open..text.len(),
                    "`[` without its `]` at the end of the line",
                ));
            }
        };
        let inner = &text[open + 1..close];
        let xml = |r: Range<usize>| line.xml(r);
        let parsed = expr::parse(self.p, self.objs, inner, open + 1, &xml);
        let parsed = match parsed {
            Ok(p) => p,
            Err(e) => {
                let at = span(&line.xml(e.at.clone()));
                let d = if e.code == UNSUPPORTED {
                    Diagnostic::error(UNSUPPORTED, at, e.what).with_label("not compiled")
                } else if e.code == UNCONFIGURED {
                    Diagnostic::error(UNCONFIGURED, at, e.what).with_label("not configured")
                } else {
                    Diagnostic::error(BAD_LINE, at, e.what)
                        .with_label("not an M221 expression the import reads")
                };
                return Err(Box::new(d));
            }
        };
        let mut lines = Vec::new();
        match (parsed, head.as_str()) {
            (
                Parsed::Assign {
                    dest,
                    dest_ty,
                    value,
                },
                "" | "OPER",
            ) => {
                let ctx = Ty::join(dest_ty, expr::ty(&value));
                let conditional = rung.cr;
                let mut temp = |t: Ty| self_temp(&mut self.locals, t);
                expr::emit(&value, ctx, &mut lines, &mut temp);
                if !rung.parens.is_empty() {
                    // Inside `(`, where IEC IL has no jump: the value is
                    // computed, and stored when the CR is 1 (SEL).
                    let Dest::Plain(dest) = dest else {
                        return Err(bad(
                            line,
                            open..text.len(),
                            "a timer's preset set inside `(` ... `)`",
                        ));
                    };
                    let x = self_temp(&mut self.locals, dest_ty);
                    self.locals.cr = true;
                    self.put("ST _cr", all.clone());
                    for il in &lines {
                        self.put(il, all.clone());
                    }
                    self.put(&format!("ST {x}"), all.clone());
                    self.put("LD _cr", all.clone());
                    self.put(&format!("SEL {dest}, {x}"), all.clone());
                    self.put(&format!("ST {dest}"), all.clone());
                    self.put("LD _cr", all);
                    return Ok(());
                }
                match dest {
                    Dest::Plain(d) => lines.push(format!("ST {d}")),
                    Dest::Preset { timer, base_ms } => {
                        let x = self_temp(&mut self.locals, Ty::Int);
                        lines.push(format!("ST {x}"));
                        lines.push(format!("LD T#{base_ms}ms"));
                        lines.push(format!("MUL {x}"));
                        lines.push(format!("ST {timer}.PT"));
                    }
                    Dest::Words { n, real } => {
                        // The value's bits into the two words, low first.
                        let x = self_temp(&mut self.locals, dest_ty);
                        let d = self_temp(&mut self.locals, Ty::Dword);
                        lines.push(format!("ST {x}"));
                        lines.push(format!("LD {x}"));
                        lines.push(
                            if real {
                                "REAL_AS_DWORD"
                            } else {
                                "DINT_TO_DWORD"
                            }
                            .into(),
                        );
                        lines.push(format!("ST {d}"));
                        lines.extend([
                            "DWORD_TO_WORD".into(),
                            "WORD_TO_INT".into(),
                            format!("ST MW{n}"),
                            format!("LD {d}"),
                            "SHR 16".into(),
                            "DWORD_TO_WORD".into(),
                            "WORD_TO_INT".into(),
                            format!("ST MW{}", n + 1),
                        ]);
                        for w in [n, n + 1] {
                            let _ = self.objs.operand(self.p, &format!("%MW{w}"), &all);
                        }
                    }
                }
                if conditional {
                    self.locals.cr = true;
                    self.locals.ops += 1;
                    let l = format!("_op{}", self.locals.ops);
                    self.put("ST _cr", all.clone());
                    self.put(&format!("JMPCN {l}"), all.clone());
                    for il in &lines {
                        self.put(il, all.clone());
                    }
                    self.w.gen_at(&format!("{l}:\n"), all.clone());
                    self.put("LD _cr", all);
                } else {
                    for il in &lines {
                        self.put(il, all.clone());
                    }
                }
            }
            (Parsed::Compare(e), h) => {
                let mut temp = |t: Ty| self_temp(&mut self.locals, t);
                expr::emit(&e, Ty::Bool, &mut lines, &mut temp);
                let (op, neg) = match h {
                    "LD" | "LDN" => {
                        if rung.parens.is_empty() {
                            rung.cr = true;
                        }
                        (None, h == "LDN")
                    }
                    "AND" | "ANDN" | "OR" | "ORN" | "XOR" | "XORN" => {
                        self.need_cr(rung, line, 0..open, h)?;
                        (Some(h), false)
                    }
                    "AND(" | "ANDN(" | "OR(" | "ORN(" | "XOR(" | "XORN(" => {
                        // A parenthesis whose first term is the comparison:
                        // left open for the lines up to its `)`.
                        self.need_cr(rung, line, 0..open, h)?;
                        let base = &h[..h.len() - 1];
                        rung.parens.push(base.to_string());
                        self.put(&format!("{base}("), all.clone());
                        for il in &lines {
                            self.put(il, all.clone());
                        }
                        return Ok(());
                    }
                    _ => {
                        return Err(bad(
                            line,
                            0..open.max(1),
                            "a comparison block follows `LD`, `AND`, `OR` or `XOR`",
                        ));
                    }
                };
                if let Some(op) = op {
                    self.put(&format!("{op}("), all.clone());
                }
                for il in &lines {
                    self.put(il, all.clone());
                }
                if neg {
                    self.put("NOT", all.clone());
                }
                if op.is_some() {
                    self.put(")", all);
                }
            }
            (Parsed::Assign { .. }, _) => {
                return Err(bad(
                    line,
                    0..open.max(1),
                    "an operation block `[ x := ... ]` stands alone or after `OPER`",
                ));
            }
        }
        Ok(())
    }
}
