//! Checking again only the POU an edit touched (the pipeline's `Session`):
//! each POU's results of the last check (its checked IR, its diagnostics,
//! the names it resolved) are kept, and when an edit changed one POU's body
//! alone, the other POUs' results are taken again, their positions moved.
//!
//! A POU's check reads its own tree and the declarations of the program
//! (the environment, rebuilt every time from every file, as are the
//! program-wide passes: recursion, nesting, the resolution table), so the
//! others' results stand when the edited POU's declarations are unchanged,
//! text and positions alike: its name, kind, result type, VAR blocks, and
//! what its body adds to its interface (a FUNCTION's `ENO`). The edit must
//! lie inside the POU (the comment lines above a POU are its
//! documentation). A POU's messages and IR name its own lines only: those
//! before the edit keep theirs.

use super::flow::Noted;
use crate::ast::{self, Span};
use crate::diag::Diagnostic;
use crate::ir::CheckedPou;

/// What one POU's check gave.
#[derive(Debug, Default)]
pub(crate) struct PouResult {
    /// Its diagnostics, in the order pushed.
    pub diags: Vec<Diagnostic>,
    /// The names it resolved (when the table is asked for).
    pub noted: Noted,
    /// Its place among its file's checked POUs ([`ir::Program::pous`]),
    /// if it has one (a duplicate's is not kept).
    ///
    /// [`ir::Program::pous`]: crate::ir::Program::pous
    pub ir: Option<usize>,
}

/// The edit that allows reuse: in file `file`, POU `pou` (its number among
/// the file's POUs) changed; the old bytes `change` became `delta` bytes
/// more (or fewer).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Reuse {
    pub file: usize,
    pub pou: usize,
    pub change: (u32, u32),
    pub delta: i64,
    /// The edit kept the number of lines: the POUs after the edited one
    /// are reused too (else their lines, which their messages and IR name,
    /// moved: they are checked again).
    pub after_too: bool,
}

/// The per-POU results of the last check, and what the next may reuse.
#[derive(Debug, Default)]
pub(crate) struct Cache {
    /// Per file, per POU (in the order of the file's items).
    pub results: Vec<Vec<Option<PouResult>>>,
    /// The last check's IR of each file's checked POUs, handed back for
    /// the next check to take from ([`PouResult::ir`] numbers them).
    pub old_ir: Vec<Vec<Option<CheckedPou>>>,
    /// Set for the next check: what it may reuse (`None`: nothing).
    pub reuse: Option<Reuse>,
    /// How many POUs the last check checked (the others were reused).
    pub checked: usize,
}

/// Whether an edit that turned POU `old` into `new` leaves every other
/// POU's check as it was (see the module's comment).
pub(crate) fn same_interface(old: &ast::Pou, new: &ast::Pou) -> bool {
    old.kind == new.kind
        && old.name == new.name
        && old.return_type == new.return_type
        && old.var_blocks == new.var_blocks
        && old.host == new.host
        && old.begin_il == new.begin_il
        && super::interface::mentions(&old.body, "ENO")
            == super::interface::mentions(&new.body, "ENO")
}

impl Reuse {
    /// Whether POU `k` of file `f` is reused.
    pub fn reuses(&self, f: usize, k: usize) -> bool {
        f != self.file || k < self.pou || (k > self.pou && self.after_too)
    }

    /// Span `s` of the old text in the new one; `None` when it overlaps
    /// the bytes the edit replaced (or is empty where text was inserted):
    /// then where it belongs is not known.
    pub fn moved(&self, s: Span) -> Option<Span> {
        let (lo, hi) = self.change;
        if s.lo < lo && s.hi <= lo {
            return Some(s);
        }
        if s.lo >= hi && !(s.lo == s.hi && lo == hi && s.lo == lo) {
            let mv = |x: u32| (i64::from(x) + self.delta) as u32;
            return Some(Span {
                lo: mv(s.lo),
                hi: mv(s.hi),
            });
        }
        None
    }

    /// Every span of a diagnostic, moved; `false` (and the diagnostic
    /// unchanged) when one cannot be.
    pub fn move_diag(&self, d: &mut Diagnostic) -> bool {
        let spans = std::iter::once(d.span)
            .chain(d.secondary.iter().map(|(s, _)| *s))
            .chain(d.fixes.iter().flat_map(|f| f.edits.iter().map(|(s, _)| *s)));
        let mut moved = Vec::new();
        for s in spans {
            match self.moved(s) {
                Some(m) => moved.push(m),
                None => return false,
            }
        }
        let mut it = moved.into_iter();
        let mut next = || it.next().unwrap_or_default();
        d.span = next();
        for (s, _) in &mut d.secondary {
            *s = next();
        }
        for f in &mut d.fixes {
            for (s, _) in &mut f.edits {
                *s = next();
            }
        }
        true
    }

    /// The diagnostics of a reused POU before the edit (they may point
    /// after it).
    pub fn move_pou_diags(&self, r: &mut PouResult) {
        for d in &mut r.diags {
            self.move_diag(d);
        }
    }

    /// A reused POU's results moved to the new text (its own spans lie
    /// outside the edited POU: they only move).
    pub fn move_pou(&self, r: &mut PouResult, ir: Option<&mut CheckedPou>) {
        for (s, _) in &mut r.noted {
            *s = self.moved(*s).unwrap_or(*s);
        }
        if let Some(p) = ir {
            for c in &mut p.cr_steps {
                c.span = self.moved(c.span).unwrap_or(c.span);
            }
        }
        for d in &mut r.diags {
            self.move_diag(d);
        }
    }
}
