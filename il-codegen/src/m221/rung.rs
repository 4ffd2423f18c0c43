//! One rung's instruction lines as IEC IL: the bit instructions, edges, the
//! stack, parentheses, jumps and the end of the scan; `blocks` has the
//! function blocks, `brackets` the operation and comparison blocks.
//!
//! M221 instructions that IEC IL has as such are written as they are
//! (`LD`, `ANDN`, `ST`, `S`, `AND(` ... `)`). The others become small IEC
//! sequences, with the POU's own variables:
//! - an edge (`LDR x`, `ANDF x` ...) compares `x` with its value at the
//!   instruction's previous execution, kept in `_eK` (one per edge
//!   instruction): `LD x / ST _tK / ANDN _eK` (inside `AND(` ... `)` for
//!   `ANDR`); `_eK := _tK` is written at the end of the rung, and before a
//!   jump, so that the edge sees the value `x` had at the instruction;
//! - `MPS`/`MRD`/`MPP` store and load `_s1` .. `_s8`;
//! - `END` sets the global `SCAN_END` and returns; each POU after the first
//!   returns at once while it is set, and the first clears it.

use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;

use super::codes::{BAD_LINE, UNCONFIGURED, UNSUPPORTED};
use super::objects::{Block, NotObject, Objects, Ty};
use super::read::{Line, Project, span};
use crate::diag::Diagnostic;
use crate::plcopen::map::Writer;

/// The global that `END`, `ENDC` and `ENDCN` set: the POUs after the one
/// that ended the scan do not run in it.
pub(super) const SCAN_END: &str = "SCAN_END";

/// The POU's own variables the translation needs.
#[derive(Default)]
pub(super) struct Locals {
    /// Edge instructions: `_eK` (memory) and `_tK` (sample), K from 1.
    pub edges: u32,
    /// `_s1` .. `_sN` of `MPS`.
    pub stack: u32,
    /// `_cr`.
    pub cr: bool,
    /// Temporaries of expressions, by name.
    pub temps: BTreeMap<String, &'static str>,
    /// Labels of operation blocks (`_opK`).
    pub ops: u32,
    /// The globals the POU uses.
    pub used: BTreeSet<String>,
    /// The subroutines it calls (`CAL SR3` → 3).
    pub calls: BTreeSet<u32>,
}

/// The translation of one POU.
pub(super) struct Pou<'a> {
    pub p: &'a Project,
    pub objs: &'a mut Objects,
    pub w: &'a mut Writer,
    pub diags: &'a mut Vec<Diagnostic>,
    pub locals: Locals,
    /// Whether the POU is a subroutine (`SRn:` ... `RET`).
    pub sr: bool,
    /// Whether the program can end the scan (`END`, `ENDC`, `ENDCN`).
    pub ends: bool,
}

/// The state of one rung.
#[derive(Default)]
pub(super) struct Rung {
    /// Operators of the open `AND(`s.
    pub parens: Vec<String>,
    /// `MPS` depth.
    pub stack: u32,
    /// Edge instructions whose memory is updated at the end of the rung.
    pub pending: Vec<u32>,
    /// The open `BLK`, and whether `OUT_BLK` was seen.
    pub blk: Option<(Block, bool)>,
    /// Whether the CR holds a value (a load was run in this rung).
    pub cr: bool,
}

/// A line's error: the diagnostic, the rung is left out.
pub(super) type Fail = Box<Diagnostic>;

pub(super) fn bad(line: &Line, r: Range<usize>, what: impl Into<String>) -> Fail {
    Box::new(
        Diagnostic::error(BAD_LINE, span(&line.xml(r)), what.into())
            .with_label("not an M221 instruction the import reads"),
    )
}

/// `word` split off `text` at `from`: the word and its byte range.
pub(super) fn words(text: &str) -> Vec<(&str, Range<usize>)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.char_indices().chain([(text.len(), ' ')]) {
        match (c.is_whitespace(), start) {
            (false, None) => start = Some(i),
            (true, Some(s)) => {
                out.push((&text[s..i], s..i));
                start = None;
            }
            _ => {}
        }
    }
    out
}

impl Pou<'_> {
    /// Append one IL line standing for the XML range `at`.
    pub fn put(&mut self, il: &str, at: Range<usize>) {
        self.w.gen_at(&format!("    {il}\n"), at);
    }

    /// Append `op name` for the instruction at `at`, the name standing for
    /// the operand at `name_at` alone: a diagnostic about the name, and the
    /// language server's references and hover, point at the operand.
    pub fn put_operand(&mut self, op: &str, name: &str, at: Range<usize>, name_at: Range<usize>) {
        self.w.gen_at(&format!("    {op} "), at.clone());
        self.w.gen_at(name, name_at);
        self.w.gen_at("\n", at);
    }

    /// Before `END`/`RET` and their conditional forms (`conditional`: they
    /// read the CR): not inside `(` or a `BLK`, and the rung's pending edge
    /// memories written first, as at the rung's end.
    fn leave(
        &mut self,
        rung: &mut Rung,
        line: &Line,
        (first, fr, conditional): (&str, Range<usize>, bool),
        all: Range<usize>,
    ) -> Result<(), Fail> {
        if conditional {
            self.need_cr(rung, line, fr.clone(), first)?;
        }
        if !rung.parens.is_empty() || rung.blk.is_some() {
            return Err(bad(line, fr, format!("`{first}` inside `(` or a `BLK`")));
        }
        self.flush(rung, true, all);
        Ok(())
    }

    /// The IL name of an operand, or the line's error.
    pub fn operand(&mut self, line: &Line, s: &str, r: Range<usize>) -> Result<(String, Ty), Fail> {
        let at = line.xml(r.clone());
        match self.objs.operand(self.p, s, &at) {
            Ok(o) => Ok((o.il, o.ty)),
            Err(e) => Err(self.not_object(line, s, r, e)),
        }
    }

    pub fn not_object(&self, line: &Line, s: &str, r: Range<usize>, e: NotObject) -> Fail {
        let at = span(&line.xml(r));
        match e {
            NotObject::Unknown => Box::new(
                Diagnostic::error(
                    BAD_LINE,
                    at,
                    format!("`{s}` is not an M221 object (`%I0.1`, `%Q0.2`, `%M3`, `%MW4`, `%TM0.Q` ...)"),
                )
                .with_label("not an object"),
            ),
            NotObject::Unsupported(why) => Box::new(
                Diagnostic::error(UNSUPPORTED, at, why).with_label("not compiled"),
            ),
            NotObject::Unconfigured(why) => Box::new(
                Diagnostic::error(UNCONFIGURED, at, why).with_label("not configured"),
            ),
        }
    }

    /// Write the pending edge memories (`_eK := _tK`); keep the CR when
    /// the rung goes on after them.
    pub fn flush(&mut self, rung: &mut Rung, keep_cr: bool, at: Range<usize>) {
        if rung.pending.is_empty() {
            return;
        }
        if keep_cr && rung.cr {
            self.locals.cr = true;
            self.put("ST _cr", at.clone());
        }
        for k in std::mem::take(&mut rung.pending) {
            self.put(&format!("LD _t{k}"), at.clone());
            self.put(&format!("ST _e{k}"), at.clone());
        }
        if keep_cr && rung.cr {
            self.put("LD _cr", at);
        }
    }

    /// Translate one line.
    pub fn line(&mut self, rung: &mut Rung, line: &Line) -> Result<(), Fail> {
        let text = line.text.as_str();
        let all = line.xml(0..text.len());
        if let Some(open) = text.find('[') {
            return self.bracket(rung, line, open);
        }
        let ws = words(text);
        let Some(&(first, ref fr)) = ws.first() else {
            return Ok(());
        };
        let op = first.to_ascii_uppercase();
        let arg = ws.get(1).cloned();
        if ws.len() > 2 {
            return Err(bad(line, ws[2].1.clone(), "one operand at most"));
        }
        // A block's pins and outputs.
        if self.block_line(rung, line, &op, arg.as_ref(), fr.clone())? {
            return Ok(());
        }
        let need = |a: &Option<(&str, Range<usize>)>| -> Result<(String, Range<usize>), Fail> {
            match a {
                Some((s, r)) => Ok((s.to_string(), r.clone())),
                None => Err(bad(line, fr.clone(), format!("`{first}` needs an operand"))),
            }
        };
        match op.as_str() {
            "LD" | "LDN" | "AND" | "ANDN" | "OR" | "ORN" | "XOR" | "XORN" => {
                let (s, r) = need(&arg)?;
                let (il, ty) = self.operand(line, &s, r.clone())?;
                let il = bit_literal(&il, ty);
                if op.starts_with("LD") {
                    if rung.parens.is_empty() {
                        rung.cr = true;
                    }
                } else {
                    self.need_cr(rung, line, fr.clone(), first)?;
                }
                self.put_operand(&op, &il, all, line.xml(r));
            }
            "ST" | "STN" | "S" | "R" => {
                let (s, r) = need(&arg)?;
                self.need_cr(rung, line, fr.clone(), first)?;
                let (il, ty) = self.operand(line, &s, r.clone())?;
                if ty != Ty::Bool || block_output(&il) {
                    return Err(bad(
                        line,
                        r,
                        format!("`{first}` writes a bit object, not `{s}`"),
                    ));
                }
                self.put_operand(&op, &il, all, line.xml(r));
            }
            "LDR" | "LDF" | "ANDR" | "ANDF" | "ORR" | "ORF" | "XORR" | "XORF" => {
                let (s, r) = need(&arg)?;
                let (il, ty) = self.operand(line, &s, r.clone())?;
                if ty != Ty::Bool {
                    return Err(bad(line, r, format!("`{first}` takes a bit, not `{s}`")));
                }
                let (base, rising) = op.split_at(op.len() - 1);
                if base != "LD" {
                    self.need_cr(rung, line, fr.clone(), first)?;
                    self.put(&format!("{base}("), all.clone());
                } else if rung.parens.is_empty() {
                    rung.cr = true;
                }
                self.edge(rung, &il, rising == "R", all.clone());
                if base != "LD" {
                    self.put(")", all);
                }
            }
            _ if edge_block(&op) && arg.is_none() => {
                // `RISINGn`/`FALLINGn`: an edge of the rung's condition so
                // far (the ladder's edge block n), with its own memory.
                self.need_cr(rung, line, fr.clone(), first)?;
                self.locals.edges += 1;
                let k = self.locals.edges;
                if op.starts_with("RISING") {
                    self.put(&format!("ST _t{k}"), all.clone());
                    self.put(&format!("ANDN _e{k}"), all);
                } else {
                    self.put("NOT", all.clone());
                    self.put(&format!("STN _t{k}"), all.clone());
                    self.put(&format!("AND _e{k}"), all);
                }
                rung.pending.push(k);
            }
            "N" | "NOT" => {
                self.need_cr(rung, line, fr.clone(), first)?;
                self.put("NOT", all);
            }
            ")" => {
                if rung.parens.pop().is_none() {
                    return Err(bad(line, fr.clone(), "`)` without its `AND(` or `OR(`"));
                }
                self.put(")", all);
            }
            "MPS" | "MRD" | "MPP" => self.stack(rung, line, &op, fr.clone())?,
            "JMP" | "JMPC" | "JMPCN" => {
                let (s, r) = need(&arg)?;
                let label = label_name(&s).ok_or_else(|| {
                    bad(line, r, format!("`{s}` is not a label (`%L1` ... `%L63`)"))
                })?;
                if op != "JMP" {
                    self.need_cr(rung, line, fr.clone(), first)?;
                }
                self.flush(rung, true, all.clone());
                self.put(&format!("{op} {label}"), all);
            }
            _ if op.contains('(') => self.open(rung, line, &op, arg, fr.clone())?,
            _ if op.ends_with(':') => {
                let label = label_name(&op[..op.len() - 1]).ok_or_else(|| {
                    bad(line, fr.clone(), format!("`{first}` is not a label `%Ln:`"))
                })?;
                self.w.gen_at(&format!("{label}:\n"), all);
            }
            "END" | "ENDC" | "ENDCN" => {
                self.leave(rung, line, (first, fr.clone(), op != "END"), all.clone())?;
                self.locals.used.insert(SCAN_END.to_string());
                match op.as_str() {
                    "END" => {
                        self.put("LD TRUE", all.clone());
                        self.put(&format!("ST {SCAN_END}"), all.clone());
                        self.put("RET", all);
                    }
                    "ENDC" => {
                        self.put(&format!("S {SCAN_END}"), all.clone());
                        self.put("RETC", all);
                    }
                    _ => {
                        self.put("NOT", all.clone());
                        self.put(&format!("S {SCAN_END}"), all.clone());
                        self.put("RETC", all.clone());
                        self.put("NOT", all);
                    }
                }
            }
            "CAL" if arg.as_ref().is_some_and(|(s, _)| sr_number(s).is_some()) => {
                let (s, r) = need(&arg)?;
                self.call(rung, line, &s, r, all)?;
            }
            _ if arg.is_none() && sr_number(first).is_some() => {
                // TwidoSuite's call: `SR3` alone.
                self.call(rung, line, first, fr.clone(), all)?;
            }
            "RET" | "RETC" | "RETCN" => {
                if !self.sr {
                    return Err(bad(
                        line,
                        fr.clone(),
                        format!("`{first}` outside a subroutine (`SRn:` ... `RET`)"),
                    ));
                }
                self.leave(rung, line, (first, fr.clone(), op != "RET"), all.clone())?;
                self.put(&op, all);
            }
            "CAL" | "MULTIFB" => {
                return Err(Box::new(
                    Diagnostic::error(
                        UNSUPPORTED,
                        span(&line.xml(fr.clone())),
                        format!("`{first}` is not compiled yet (only `CAL SRn` calls)"),
                    )
                    .with_label("not compiled"),
                ));
            }
            _ => {
                return Err(bad(
                    line,
                    fr.clone(),
                    format!("`{first}` is not an M221 instruction"),
                ));
            }
        }
        Ok(())
    }

    /// `CAL SRn` (or `SRn`): the subroutine, when the rung's condition is
    /// 1 (always at the start of a rung); then, when a POU can end the
    /// scan, a return if the subroutine ended it.
    fn call(
        &mut self,
        rung: &mut Rung,
        line: &Line,
        s: &str,
        r: Range<usize>,
        all: Range<usize>,
    ) -> Result<(), Fail> {
        let n = sr_number(s).unwrap_or(0);
        if !self.p.pous.iter().any(|x| x.sr == Some(n)) {
            return Err(bad(
                line,
                r,
                format!("`{s}` calls no subroutine of this program (no `SR{n}:`)"),
            ));
        }
        if !rung.parens.is_empty() || rung.blk.is_some() {
            return Err(bad(line, r, format!("`{s}` called inside `(` or a `BLK`")));
        }
        let name = self.objs.subroutine(n, &line.xml(r));
        self.locals.used.insert(name.clone());
        self.locals.calls.insert(n);
        self.flush(rung, true, all.clone());
        let cal = if rung.cr { "CALC" } else { "CAL" };
        self.put(&format!("{cal} {name}"), all.clone());
        if self.ends {
            self.locals.used.insert(SCAN_END.to_string());
            self.put(&format!("LD {SCAN_END}"), all.clone());
            self.put("RETC", all);
        }
        // What the subroutine left in the CR is no condition of this rung.
        rung.cr = false;
        Ok(())
    }

    pub(super) fn need_cr(
        &self,
        rung: &Rung,
        line: &Line,
        r: Range<usize>,
        what: &str,
    ) -> Result<(), Fail> {
        if rung.cr || !rung.parens.is_empty() {
            Ok(())
        } else {
            Err(bad(
                line,
                r,
                format!("`{what}` before the rung's first load (`LD`)"),
            ))
        }
    }

    /// An edge load: `x` compared with its value at this instruction's
    /// previous execution.
    fn edge(&mut self, rung: &mut Rung, x: &str, rising: bool, at: Range<usize>) {
        self.locals.edges += 1;
        let k = self.locals.edges;
        if rising {
            self.put(&format!("LD {x}"), at.clone());
            self.put(&format!("ST _t{k}"), at.clone());
            self.put(&format!("ANDN _e{k}"), at);
        } else {
            self.put(&format!("LDN {x}"), at.clone());
            self.put(&format!("STN _t{k}"), at.clone());
            self.put(&format!("AND _e{k}"), at);
        }
        rung.pending.push(k);
    }

    /// `AND(`, `OR(N %I0.1`, `AND(R %I0.2` ...
    fn open(
        &mut self,
        rung: &mut Rung,
        line: &Line,
        op: &str,
        arg: Option<(&str, Range<usize>)>,
        fr: Range<usize>,
    ) -> Result<(), Fail> {
        let all = line.xml(0..line.text.len());
        let (base, modifier) = op.split_once('(').unwrap_or((op, ""));
        let base = match base {
            "AND" | "ANDN" | "OR" | "ORN" | "XOR" | "XORN" => base,
            _ => return Err(bad(line, fr, format!("`{op}` is not an M221 instruction"))),
        };
        self.need_cr(rung, line, fr.clone(), op)?;
        rung.parens.push(base.to_string());
        self.put(&format!("{base}("), all.clone());
        let Some((s, r)) = arg else {
            if !modifier.is_empty() {
                return Err(bad(line, fr, format!("`{op}` needs an operand")));
            }
            return Ok(());
        };
        let (il, ty) = self.operand(line, s, r.clone())?;
        match modifier {
            "" => self.put(&format!("LD {}", bit_literal(&il, ty)), all),
            "N" => self.put(&format!("LDN {il}"), all),
            "R" | "F" if ty == Ty::Bool => self.edge(rung, &il, modifier == "R", all),
            _ => return Err(bad(line, fr, format!("`{op}` is not an M221 instruction"))),
        }
        Ok(())
    }

    fn stack(
        &mut self,
        rung: &mut Rung,
        line: &Line,
        op: &str,
        fr: Range<usize>,
    ) -> Result<(), Fail> {
        let all = line.xml(0..line.text.len());
        match op {
            "MPS" => {
                self.need_cr(rung, line, fr.clone(), op)?;
                if rung.stack >= 8 {
                    return Err(bad(line, fr, "`MPS` deeper than the M221's 8 levels"));
                }
                rung.stack += 1;
                self.locals.stack = self.locals.stack.max(rung.stack);
                self.put(&format!("ST _s{}", rung.stack), all);
            }
            _ => {
                if rung.stack == 0 {
                    return Err(bad(line, fr, format!("`{op}` without an `MPS`")));
                }
                self.put(&format!("LD _s{}", rung.stack), all);
                if op == "MPP" {
                    rung.stack -= 1;
                }
            }
        }
        Ok(())
    }
}

pub(super) fn self_temp(l: &mut Locals, t: Ty) -> String {
    let name = format!("_x{}", l.temps.len() + 1);
    l.temps.insert(name.clone(), t.name());
    name
}

/// Whether an operand is an output of a block (`TM0.Q`, `C1.D`), which the
/// program reads only.
fn block_output(il: &str) -> bool {
    let (obj, member) = il.split_once('.').unwrap_or((il, ""));
    let kind = obj.trim_end_matches(|c: char| c.is_ascii_digit());
    match kind {
        "TM" | "C" => member != "P",
        "DR" => member == "F",
        "R" => matches!(member, "E" | "F"),
        _ => false,
    }
}

/// `1`/`0` as a bit operand (`LD 1`) are TRUE and FALSE.
fn bit_literal(il: &str, ty: Ty) -> String {
    match (ty, il) {
        (Ty::IntLit, "1") => "TRUE".into(),
        (Ty::IntLit, "0") => "FALSE".into(),
        _ => il.to_string(),
    }
}

/// `RISING0`, `FALLING3`: the ladder's edge blocks.
fn edge_block(op: &str) -> bool {
    let n = op
        .strip_prefix("RISING")
        .or_else(|| op.strip_prefix("FALLING"))
        .unwrap_or("");
    !n.is_empty() && n.len() < 6 && n.bytes().all(|b| b.is_ascii_digit())
}

/// `SR3`, `%SR3` → 3 (subroutines 0 to 255).
pub(super) fn sr_number(s: &str) -> Option<u32> {
    let s = s.strip_prefix('%').unwrap_or(s);
    let n = s.strip_prefix("SR").or_else(|| s.strip_prefix("sr"))?;
    let ok = !n.is_empty() && n.len() < 4 && n.bytes().all(|b| b.is_ascii_digit());
    n.parse().ok().filter(|v| ok && *v < 256)
}

/// `%L5` → `L5`.
pub(super) fn label_name(s: &str) -> Option<String> {
    let n = s.strip_prefix('%')?.strip_prefix(['L', 'l'])?;
    (!n.is_empty() && n.len() < 6 && n.bytes().all(|b| b.is_ascii_digit())).then(|| format!("L{n}"))
}
