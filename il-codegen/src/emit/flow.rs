//! Control flow: IL labels and jumps as structured Rust where possible.
//!
//! - No labels: straight-line code.
//! - Jumps that nest (see `structure`): a label reached by backward jumps
//!   opens a labelled `loop` that ends after the last of them (`JMP L` is
//!   `continue 'L`); a label reached by forward jumps closes a labelled block
//!   that starts at the first jump to it, or further up where it would
//!   otherwise cross a loop or another block (`JMP L` is `break 'L`).
//! - Any other pattern (a jump into a loop, overlapping loops): a dispatcher
//!   loop over the code between labels, `__pc` holding the next block.

use super::PouEmitter;
use super::text::{Out, join, tail};
use super::writeback::WriteBacks;
use crate::ast::PouKind;
use crate::ir::types::Ty;
use crate::ir::{Expr, Op, PathElem, Root, Stmt, Value};

/// Deeper nesting than this falls back to the dispatcher (rustc recurses
/// on nested blocks, and each level indents every line inside it).
const MAX_NESTED_LABELS: usize = 128;

enum Mode {
    Straight,
    /// Labelled blocks and loops (see [`structure`]); `label_pos` is the
    /// position of each label in the body.
    Structured {
        label_pos: Vec<Option<usize>>,
    },
    Dispatch {
        block_of_label: Vec<usize>,
    },
}

/// A region of the body `[lo, hi)` that becomes a labelled block (forward
/// jumps to the label at `hi` break out of it) or a labelled loop (backward
/// jumps to the label at `lo` continue it).
#[derive(Clone, Copy, Debug)]
struct Region {
    lo: usize,
    hi: usize,
    label: usize,
    is_loop: bool,
}

/// The regions of a body, if jumps allow structured code: every loop runs
/// from its label to the last backward jump to it; every forward jump's
/// block starts at the first jump to its label (or earlier, so that it
/// nests with the other regions); all regions must nest. `None`: the
/// dispatcher is needed (a jump into a loop, overlapping loops, too deep).
fn structure(stmts: &[Stmt], label_pos: &[Option<usize>]) -> Option<Vec<Region>> {
    let n_labels = label_pos.len();
    let mut loop_end: Vec<Option<usize>> = vec![None; n_labels];
    let mut fwd: Vec<Vec<usize>> = vec![Vec::new(); n_labels];
    for (j, s) in stmts.iter().enumerate() {
        if let Op::Jump { label, .. } = s.op {
            let p = label_pos.get(label).copied().flatten()?;
            if p < j {
                loop_end[label] = Some(j + 1);
            } else {
                fwd[label].push(j);
            }
        }
    }
    let mut regions: Vec<Region> = Vec::new();
    for (l, end) in loop_end.iter().enumerate() {
        if let (Some(hi), Some(lo)) = (end, label_pos[l]) {
            regions.push(Region {
                lo,
                hi: *hi,
                label: l,
                is_loop: true,
            });
        }
    }
    for (l, js) in fwd.iter().enumerate() {
        let (Some(&first), Some(hi)) = (js.iter().min(), label_pos[l]) else {
            continue;
        };
        // With the statements of the jump's IL line before it (its comment).
        let mut lo = first;
        while lo > 0 && stmts[lo - 1].line == stmts[first].line {
            lo -= 1;
        }
        regions.push(Region {
            lo,
            hi,
            label: l,
            is_loop: false,
        });
    }
    // A block starts at its first jump, moved up to the start of any region
    // it would otherwise start inside of and end at or after (a loop holding
    // a jump but not the label: a label right after the loop's last jump is
    // outside it; another block), until all nest. Starting at
    // the top of the body instead nested every label's block around all
    // the code before it: 40 labels were 40 levels of indentation, 79% of
    // the bytes of the 10k-line benchmark's output.
    if !widen_blocks(&mut regions, stmts.len() + 1) {
        return None;
    }
    nest(regions)
}

/// Sorts the regions outer first and checks that they nest; `None` if not
/// or too deep.
fn nest(mut regions: Vec<Region>) -> Option<Vec<Region>> {
    // Outer regions first; of two equal ranges, the block is outside.
    regions.sort_by_key(|r| (r.lo, std::cmp::Reverse(r.hi), r.is_loop));
    // Nesting: each region lies inside or after the ones opened before it.
    let mut open: Vec<usize> = Vec::new();
    for r in &regions {
        while open.last().is_some_and(|&hi| hi <= r.lo) {
            open.pop();
        }
        if open.last().is_some_and(|&hi| r.hi > hi) {
            return None;
        }
        open.push(r.hi);
        if open.len() > MAX_NESTED_LABELS {
            return None;
        }
    }
    Some(regions)
}

/// Moves each block's `lo` up as `structure` describes, in one sweep by
/// `hi` (loops before blocks of the same `hi`): a block moves only to the
/// `lo` of regions ending at or before it, which are then final. Of the
/// final regions holding a point strictly inside, one query gives the
/// least `lo`; were a second move possible, two final regions would cross
/// and `nest` would refuse them anyway: `false` then. A tree over the
/// positions `0..len` keeps, per node, the least `lo` of the regions
/// covering it: O(R log len) instead of the fixpoint's O(R^2) per pass.
fn widen_blocks(regions: &mut [Region], len: usize) -> bool {
    let mut order: Vec<usize> = (0..regions.len()).collect();
    order.sort_unstable_by_key(|&i| (regions[i].hi, !regions[i].is_loop, i));
    let size = len.next_power_of_two();
    let mut tree = vec![usize::MAX; 2 * size];
    // The least `lo` of the regions inserted so far with lo < x < hi.
    let query = |tree: &[usize], x: usize| {
        let (mut k, mut best, mut steps) = (x + size, usize::MAX, 0);
        while k > 0 {
            best = best.min(tree[k]);
            k /= 2;
            steps += 1;
        }
        crate::step_counter::add(steps);
        best
    };
    for i in order {
        let mut r = regions[i];
        if !r.is_loop && r.lo < len {
            let lo = query(&tree, r.lo);
            if lo < r.lo {
                r.lo = lo;
                if query(&tree, r.lo) < r.lo {
                    return false;
                }
                regions[i].lo = lo;
            }
        }
        // Cover the positions r.lo+1 ..= r.hi-1 with r.lo.
        let (mut a, mut b) = (r.lo + 1 + size, r.hi.min(len) + size);
        let mut steps = 1;
        while a < b {
            if a & 1 == 1 {
                tree[a] = tree[a].min(r.lo);
                a += 1;
            }
            if b & 1 == 1 {
                b -= 1;
                tree[b] = tree[b].min(r.lo);
            }
            a /= 2;
            b /= 2;
            steps += 1;
        }
        crate::step_counter::add(steps);
    }
    true
}

/// See [`PouEmitter::seq`].
const FENCED_RUNGS: usize = 8;

/// Rungs per fence in a fenced network: between two fences LLVM may keep
/// the loads of a few rungs in registers (`interlock`: 2,129 instructions
/// per scan with a fence before every rung, 2,125 every 4th, 2,122 every
/// 8th), but too many rungs between fences bring the spills back.
const RUNGS_PER_FENCE: usize = 4;

/// Positions in `stmts` where a rung starts (a `SetCr` whose previous
/// statement other than a `Nop` is a `Store`) by reading memory (not a
/// variable that `cached` says lives in a local), in runs of at least
/// [`FENCED_RUNGS`] such starts with no FB call between them; of those,
/// every [`RUNGS_PER_FENCE`]th.
fn fenced_rungs(
    pou: &crate::ir::CheckedPou,
    stmts: &[Stmt],
    cached: impl Fn(usize) -> bool,
) -> Vec<usize> {
    let (mut out, mut run) = (Vec::new(), Vec::new());
    let mut stored = false;
    for (k, s) in stmts.iter().enumerate() {
        match &s.op {
            Op::Nop => continue,
            Op::SetCr { expr, .. } if stored => {
                let local = matches!(expr, Expr::Value(Value::Read(p)) | Expr::Not(Value::Read(p))
                    if pou.place(*p).path.is_empty() && matches!(pou.place(*p).root, Root::Var(i) if cached(i)));
                if !local {
                    run.push(k);
                }
            }
            Op::CallFb(_) => {
                if run.len() >= FENCED_RUNGS {
                    out.extend(
                        run.iter()
                            .skip(RUNGS_PER_FENCE - 1)
                            .step_by(RUNGS_PER_FENCE),
                    );
                }
                run.clear();
            }
            _ => {}
        }
        stored = matches!(s.op, Op::Store { .. });
    }
    if run.len() >= FENCED_RUNGS {
        out.extend(
            run.iter()
                .skip(RUNGS_PER_FENCE - 1)
                .step_by(RUNGS_PER_FENCE),
        );
    }
    out
}

fn label_lifetime(l: usize) -> String {
    format!("'__l{l}")
}

fn loop_lifetime(l: usize) -> String {
    format!("'__c{l}")
}

impl PouEmitter<'_> {
    /// Whether the body has a network of rungs that `seq` fences.
    pub(crate) fn has_fenced_rungs(&self) -> bool {
        !fenced_rungs(self.pou, &self.pou.body, |i| self.cached(i)).is_empty()
    }

    /// The body; returns the cached variables to write back at its end (see
    /// `writeback.rs`: the others are written back where their last store
    /// leaves them final).
    pub(crate) fn body(&self, o: &mut Out) -> Vec<usize> {
        let mut stmts: &[Stmt] = &self.pou.body;
        // A RET at the very end is where the body ends anyway.
        if let Some(Stmt {
            op: Op::Return { cond: None },
            ..
        }) = stmts.last()
        {
            stmts = &stmts[..stmts.len() - 1];
        }
        let label_pos: Vec<Option<usize>> = {
            let mut v = vec![None; self.pou.label_count];
            for (i, s) in stmts.iter().enumerate() {
                if let Op::Label(l) = s.op {
                    v[l] = Some(i);
                }
            }
            v
        };
        let has_labels = label_pos.iter().any(Option::is_some);
        let regions = if has_labels {
            structure(stmts, &label_pos)
        } else {
            None
        };
        let mode = if !has_labels {
            Mode::Straight
        } else if regions.is_some() {
            Mode::Structured {
                label_pos: label_pos.clone(),
            }
        } else {
            let mut block_of_label = vec![0; self.pou.label_count];
            let mut b = 0;
            for s in stmts {
                if let Op::Label(l) = s.op {
                    b += 1;
                    block_of_label[l] = b;
                }
            }
            Mode::Dispatch { block_of_label }
        };
        let spans: Option<Vec<(usize, usize)>> = match (&mode, &regions) {
            (Mode::Straight, _) => Some(Vec::new()),
            (Mode::Structured { .. }, Some(rs)) => Some(rs.iter().map(|r| (r.lo, r.hi)).collect()),
            _ => None,
        };
        let wb = self.write_backs(stmts, spans.as_deref());
        let wb_top = spans.is_some().then_some(&wb);
        match (&mode, regions) {
            (Mode::Structured { .. }, Some(regions)) => {
                let mut next = 0;
                self.nested(
                    o,
                    stmts,
                    0,
                    stmts.len(),
                    &regions,
                    &mut next,
                    &mode,
                    false,
                    wb_top,
                )
            }
            (Mode::Dispatch { .. }, _) => {
                let segments: Vec<&[Stmt]> =
                    stmts.split(|s| matches!(s.op, Op::Label(_))).collect();
                let last = segments.len() - 1;
                let mut base = 0;
                o.code("let mut __pc: usize = 0; '__dispatch: loop { match __pc {");
                for (k, seg) in segments.iter().enumerate() {
                    o.code(&format!("{k} => {{"));
                    self.seq(o, seg, base, &mode, false, None);
                    base += seg.len() + 1;
                    let ends = matches!(
                        seg.last(),
                        Some(Stmt {
                            op: Op::Jump { cond: None, .. } | Op::Return { cond: None },
                            ..
                        })
                    );
                    let next = k + 1;
                    if ends {
                        o.code("}");
                    } else if k == last {
                        o.code("break '__dispatch; }");
                    } else {
                        o.code(&format!("__pc = {next}; }}"));
                    }
                }
                o.code("_ => break '__dispatch, } }");
            }
            _ => self.seq(o, stmts, 0, &mode, true, wb_top),
        }
        wb.before(stmts.len()).to_vec()
    }

    /// Statements `[lo, hi)` with the regions that start at or after
    /// `regions[*next]` and lie inside `[lo, hi)`, as nested blocks/loops.
    /// `wb`: at the top level, the write-backs (see `writeback.rs`), which
    /// fall between statements outside every region.
    #[allow(clippy::too_many_arguments)]
    fn nested(
        &self,
        o: &mut Out,
        stmts: &[Stmt],
        lo: usize,
        hi: usize,
        regions: &[Region],
        next: &mut usize,
        mode: &Mode,
        in_loop: bool,
        wb: Option<&WriteBacks>,
    ) {
        let mut at = lo;
        while let Some(r) = regions.get(*next).copied().filter(|r| r.lo < hi) {
            *next += 1;
            self.seq(o, &stmts[at..r.lo], at, mode, !in_loop, wb);
            if let Some(wb) = wb {
                self.write_back(o, wb.before(r.lo));
            }
            let inner_loop = in_loop || r.is_loop;
            if r.is_loop {
                let lt = loop_lifetime(r.label);
                o.code(&format!("{lt}: loop {{"));
                self.nested(o, stmts, r.lo, r.hi, regions, next, mode, inner_loop, None);
                // Falling off the end of the region leaves the loop.
                if !matches!(
                    stmts[r.hi - 1].op,
                    Op::Jump { cond: None, .. } | Op::Return { cond: None }
                ) {
                    o.code(&format!("break {lt};"));
                }
                o.code("}");
            } else {
                o.code(&format!("{}: {{", label_lifetime(r.label)));
                self.nested(o, stmts, r.lo, r.hi, regions, next, mode, inner_loop, None);
                o.code("}");
            }
            at = r.hi;
        }
        self.seq(o, &stmts[at..hi], at, mode, !in_loop, wb);
    }

    /// Straight-line statements; `base` is the position of the first in the body.
    ///
    /// `fences` (code outside loops): in a network of at least
    /// [`FENCED_RUNGS`] rungs without a function block call, every
    /// [`RUNGS_PER_FENCE`]th rung (a CR load right after a store) starts
    /// with a `compiler_fence` (no machine instruction). Without it LLVM keeps every value loaded from `self` in
    /// a register across all later rungs (`&mut self` tells it nothing else
    /// writes them), runs out of registers in a long network and spills to
    /// the stack: `interlock`'s 300 rungs did ~900 stack stores and reloads
    /// per scan. With it the rungs reload their operands from `self`, as C
    /// does. Not in loops, where keeping `self` fields in registers is what
    /// pays, nor around FB calls, whose outputs LLVM forwards to the next
    /// rung (`blocks` ran 3% more instructions with fences there).
    ///
    /// `wb`: the write-backs due before each statement (top level only).
    fn seq(
        &self,
        o: &mut Out,
        stmts: &[Stmt],
        base: usize,
        mode: &Mode,
        fences: bool,
        wb: Option<&WriteBacks>,
    ) {
        let fenced = if fences {
            fenced_rungs(self.pou, stmts, |i| self.cached(i))
        } else {
            Vec::new()
        };
        let mut last_line = 0;
        for (k, s) in stmts.iter().enumerate() {
            // A write-back belongs to the statements before this one.
            if let Some(wb) = wb {
                self.write_back(o, wb.before(base + k));
            }
            // The line's comment next: a rung's fence is part of its first line.
            if self.opts.line_markers && s.line != last_line && s.line != 0 {
                o.marker(s.line);
                last_line = s.line;
            }
            if fenced.binary_search(&k).is_ok() {
                o.code(
                    "::core::sync::atomic::compiler_fence(::core::sync::atomic::Ordering::SeqCst);",
                );
            }
            o.code(&self.stmt(s, base + k, mode));
        }
    }

    fn cond(&self, c: &Option<(crate::ir::Value, bool)>, line: u32, body: String) -> String {
        match c {
            None => body,
            Some((v, true)) => {
                let v = self.value(v, line);
                format!("if {v} {{ {body} }}")
            }
            Some((v, false)) => {
                let v = self.value(v, line);
                format!("if !{v} {{ {body} }}")
            }
        }
    }

    /// Whether evaluating `v` reads a place under `root`: the place read,
    /// or a subscript of it, or the value inside a widening, a resize or a
    /// subscript expression. A CAL sets its inputs in place only when none
    /// reads the instance: an input set first must not change what a later
    /// one reads (`CAL b(x := 1, y := b.x)` passes the old `b.x`).
    fn reads_root(&self, v: &Value, root: &Root) -> bool {
        match v {
            Value::Cr(_) | Value::Const(_) | Value::Saved(_) => false,
            Value::Widen(b) => self.reads_root(&b.0, root),
            Value::Resized(b) => self.reads_root(&b.0, root),
            Value::Arith(a) => self.reads_root(&a.lhs, root) || self.reads_root(&a.rhs, root),
            Value::Read(q) => {
                let q = self.pou.place(*q);
                q.root == *root
                    || q.path.iter().any(|e| match e {
                        PathElem::Index { subs, .. } => {
                            subs.iter().any(|s| self.reads_root(s, root))
                        }
                        PathElem::Field(_) | PathElem::Part { .. } => false,
                    })
            }
        }
    }

    fn stmt(&self, s: &Stmt, pos: usize, mode: &Mode) -> String {
        let line = s.line;
        match &s.op {
            Op::SetCr { cr, expr } => {
                let id = super::values::cr_ident(self.pou.cr_ty(*cr));
                let e = self.expr(expr, line);
                [id.as_ref(), " = ", e.as_str(), ";"].concat()
            }
            Op::Save { slot, value } => {
                let v = self.value(value, line);
                [
                    super::values::saved_ident(*slot).as_str(),
                    " = ",
                    v.as_str(),
                    ";",
                ]
                .concat()
            }
            Op::Store {
                place,
                value,
                negate,
            } => {
                // STN complements in the CR's type, before a widening.
                let v = match (negate, value) {
                    (true, Value::Widen(b)) => {
                        let v = self.value(&b.0, line);
                        super::values::widened(format!("!{v}"), &Some(b.1))
                    }
                    (true, v) => {
                        let v = self.value(v, line);
                        format!("!{v}")
                    }
                    (false, v) => self.value(v, line),
                };
                let place = self.pou.place(*place);
                match (place.range.as_deref(), place.ty.elem()) {
                    // A subrange store outside the bounds is skipped and recorded.
                    (Some((lo, hi)), Some(e)) => {
                        let ty = e.rust();
                        let (lo, hi) = (
                            crate::emit::values::constant(&crate::ir::Const::Int((*lo).into(), e)),
                            crate::emit::values::constant(&crate::ir::Const::Int((*hi).into(), e)),
                        );
                        let w = self.write(place, "__r".to_string(), line);
                        let fault = self.fault("SubrangeViolation", line);
                        format!(
                            "{{ let __r: {ty} = {v}; if __r >= {lo} && __r <= {hi} {{ {w} }} else {{ {fault}; }} }}"
                        )
                    }
                    _ => self.write(place, v, line),
                }
            }
            Op::SetIf { place, value, cond } => {
                let place = self.pou.place(*place);
                let c = self.value(cond, line);
                let w = self.write(place, value.to_string(), line);
                format!("if {c} {{ {w} }}")
            }
            Op::CallFb(c) => {
                // `inouts_in_instance` needs no code of its own: an in-out
                // under the instance is copied in after the inputs are set.
                let crate::ir::FbCall {
                    inst,
                    inputs,
                    outputs,
                    inouts,
                    inouts_in_instance: _,
                    externals,
                    cond,
                } = &**c;
                let (io_lets, io_args, io_back) = self.bind_inouts(
                    &inouts.iter().map(|(_, p)| p).collect::<Vec<_>>(),
                    Some(inst),
                    line,
                );
                let ext = (!externals.is_empty()).then(|| {
                    let Ty::Fb(fb) = &inst.ty else {
                        return String::new();
                    };
                    let st = super::names::ext_ident(fb);
                    let fields = externals.iter().map(|e| {
                        let id = super::rust_ident(&e.name);
                        if e.constant {
                            format!("{id}: &*__ext.{id}")
                        } else {
                            format!("{id}: &mut *__ext.{id}")
                        }
                    });
                    format!(", {st} {{ {} }}", join(fields, ", "))
                });
                let ext = ext.unwrap_or_default();
                let io_args = tail(io_args);
                // An instance that is a plain path, with inputs that do not
                // read it: set the inputs in place, call, copy the outputs.
                if !inst
                    .path
                    .iter()
                    .any(|e| matches!(e, PathElem::Index { .. }))
                    && !inputs.iter().any(|(_, v)| self.reads_root(v, &inst.root))
                {
                    let path = self.simple_path(inst);
                    let sets = inputs.iter().map(|(n, v)| {
                        let f = super::rust_ident(&n.name);
                        let v = self.value(v, line);
                        format!("{path}.{f} = {v};")
                    });
                    let sets: String = sets.collect();
                    let outs = outputs.iter().map(|(n, target, neg, w)| {
                        let f = super::rust_ident(&n.name);
                        let v = format!("{path}.{f}");
                        let v = super::values::widened(if *neg { format!("!{v}") } else { v }, w);
                        let v = self.fit_output(v, None, target, line);
                        self.write(target, v, line)
                    });
                    let outs: String = outs.collect();
                    return self.cond(
                        cond,
                        line,
                        format!(
                            "{{ {sets} {io_lets} {path}.call(__ctx{io_args}{ext}); {io_back} {outs} }}"
                        ),
                    );
                }
                // Inputs are evaluated before the instance is borrowed.
                let lets: String = inputs
                    .iter()
                    .enumerate()
                    .map(|(k, (_, v))| format!("let __in{k} = {};", self.value(v, line)))
                    .collect();
                let sets: String = inputs
                    .iter()
                    .enumerate()
                    .map(|(k, (n, _))| format!("__fb.{} = __in{k};", super::rust_ident(&n.name)))
                    .collect();
                let call = self.with_fb(
                    inst,
                    format!("{sets} __fb.call(__ctx{io_args}{ext});"),
                    line,
                );
                let outs: String = outputs
                    .iter()
                    .map(|(n, target, neg, w)| {
                        let mut src = inst.clone();
                        src.path.push(crate::ir::PathElem::Field(n.clone()));
                        let v = self.read(&src, line);
                        let v = super::values::widened(if *neg { format!("!{v}") } else { v }, w);
                        let v = self.fit_output(v, None, target, line);
                        self.write(target, v, line)
                    })
                    .collect();
                self.cond(
                    cond,
                    line,
                    format!("{{ {lets} {io_lets} {call} {io_back} {outs} }}"),
                )
            }
            Op::Label(_) | Op::Nop => String::new(),
            Op::Jump { label, cond } => {
                let go = match mode {
                    Mode::Dispatch { block_of_label } => {
                        let b = block_of_label[*label];
                        format!("__pc = {b}; continue '__dispatch;")
                    }
                    Mode::Structured { label_pos } => {
                        if label_pos[*label].is_some_and(|p| p < pos) {
                            format!("continue {};", loop_lifetime(*label))
                        } else {
                            format!("break {};", label_lifetime(*label))
                        }
                    }
                    Mode::Straight => String::new(),
                };
                self.cond(cond, line, go)
            }
            Op::Return { cond } => {
                let r = if self.pou.kind == PouKind::Function {
                    "return __ret;"
                } else if self.has_cached() {
                    "break '__body;"
                } else {
                    "return;"
                };
                self.cond(cond, line, r.to_string())
            }
        }
    }
}

#[cfg(test)]
#[path = "flow_tests.rs"]
mod tests;
