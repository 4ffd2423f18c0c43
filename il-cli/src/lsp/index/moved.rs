//! The index of the check before, moved instead of built again, when the
//! session checked again only the POU an edit changed inside its body
//! ([`Session::moved`]): every other POU's declarations, labels and steps
//! are the same, at moved positions, and the symbols keep their numbers.
//! Building the index of 100 000 lines costs about 7 ms (a symbol, its
//! declaration text and notes per variable, a step per instruction);
//! moving it, a pass over its spans and the edited POU's steps.
//!
//! [`Session::moved`]: il_codegen::Session::moved

use il_codegen::ast::{self, Span};
use il_codegen::pipeline::Moved;
use il_codegen::{Checked, Input};

use super::{Index, Outline, Step};

/// A span of the text before the edit in the text after it: a span after
/// the edit moves, one around it (the edited POU's) grows or shrinks.
fn mv(m: &Moved, s: Span) -> Span {
    let by = |x: u32| (i64::from(x) + m.delta) as u32;
    let (start, end) = (m.change.start as u32, m.change.end as u32);
    if s.lo >= end {
        Span {
            lo: by(s.lo),
            hi: by(s.hi),
        }
    } else if s.hi > end || (s.hi == end && start < end) {
        Span {
            lo: s.lo,
            hi: by(s.hi),
        }
    } else {
        s
    }
}

fn mv_outline(m: &Moved, o: &mut Outline) {
    o.span = mv(m, o.span);
    o.sel = mv(m, o.sel);
    for c in &mut o.children {
        mv_outline(m, c);
    }
}

impl Index {
    /// This index, of the check before, made the index of `checked` (whose
    /// program holds documents `docs`) as `moved` says; `None` where that
    /// is not sure (the edit in a file that is not IL text, a label added,
    /// removed or renamed): then build it.
    pub fn moved(mut self, checked: &Checked, moved: &Moved, docs: &[usize]) -> Option<Index> {
        if self.docs != docs || self.files.len() != checked.inputs().len() {
            return None;
        }
        self.table = checked.resolutions().cloned().unwrap_or_default();
        for d in self
            .table
            .symbols
            .iter_mut()
            .filter_map(|s| s.decl.as_mut())
        {
            d.file = *docs.get(d.file)?;
        }
        let Some(k) = moved.pou else {
            // No text changed.
            return Some(self);
        };
        let f = moved.input;
        // Positions in the user's file are those of the IL text.
        if !matches!(checked.inputs().get(f)?, Input::Il(_)) {
            return None;
        }
        let pou = checked
            .syntax()
            .get(f)?
            .items
            .iter()
            .filter_map(|i| match i {
                ast::Item::Pou(p) => Some(p),
                _ => None,
            })
            .nth(k)?;
        let (old, sym) = *self.files[f].pous.get(k)?;
        if !self.symbols[sym].name.eq_ignore_ascii_case(&pou.name.name) {
            return None;
        }
        // The labels keep their symbols if they are the same, in order.
        let mut labels: Vec<&ast::Ident> = Vec::new();
        for s in &pou.body {
            if let ast::Stmt::Label(l) = s
                && !labels.iter().any(|m| m.key() == l.key())
            {
                labels.push(l);
            }
        }
        let old_labels = self.pou_labels.get(&sym)?;
        if old_labels.len() != labels.len()
            || !(old_labels.iter().zip(&labels)).all(|(&id, l)| *self.symbols[id].name == *l.name)
        {
            return None;
        }
        let doc = docs[f];
        for s in self.symbols.iter_mut().filter(|s| s.file == doc) {
            s.span = mv(moved, s.span);
        }
        for (&id, l) in old_labels.iter().zip(&labels) {
            self.symbols[id].span = l.span;
        }
        let name_span = self.symbols[sym].span;
        let file = &mut self.files[f];
        for (s, _) in &mut file.pous {
            *s = mv(moved, *s);
        }
        for o in &mut file.outline {
            mv_outline(moved, o);
        }
        // The POU's outline: its sections, then its labels.
        let outline = file.outline.iter_mut().find(|o| o.sel == name_span)?;
        let shown = outline
            .children
            .iter_mut()
            .filter(|o| o.kind == lsp_types::SymbolKind::KEY);
        for (o, l) in shown.zip(&labels) {
            (o.span, o.sel) = (l.span, l.span);
        }
        // The edited POU's steps, from its checked IR (its number among the
        // checked POUs is the old steps').
        let lo = file.steps.partition_point(|s| s.span.lo < old.lo);
        let hi = file.steps.partition_point(|s| s.span.lo <= old.hi);
        let first = file.steps.get(lo).filter(|_| lo < hi)?;
        let (pf, at) = (first.file, first.pou);
        let ir = checked
            .partial_ir()
            .get(pf as usize)?
            .pous
            .get(at as usize)?;
        if !ir.name.eq_ignore_ascii_case(&pou.name.name) {
            return None;
        }
        let mut new: Vec<Step> = (ir.cr_steps.iter().enumerate())
            .map(|(i, s)| Step {
                span: s.span,
                label: s.label,
                file: pf,
                pou: at,
                at: i as u32,
            })
            .collect();
        new.sort_by_key(|s| (s.span.lo, std::cmp::Reverse(s.span.hi)));
        for s in &mut file.steps[hi..] {
            s.span = mv(moved, s.span);
        }
        file.steps.splice(lo..hi, new);
        self.index_decls();
        Some(self)
    }
}
