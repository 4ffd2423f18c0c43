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
//! documentation).
//!
//! An edit that adds or removes lines moves every line after it: the
//! reused POUs' results are moved in place (spans by the bytes, the IR's
//! lines by the lines), not kept relative to their POU and rebased on use,
//! because every consumer (the emitter's comments, the interpreter's
//! debugger, the language server) reads the IR's absolute lines, and the
//! move costs one addition per statement of the POUs after the edit (a
//! check costs hundreds of instructions per statement). The lines that
//! the checker wrote into text (`after the CAL on line 4` in a message,
//! `INT from line 3` at a label) are not moved: a POU whose results name a
//! line in their text is checked again instead ([`PouResult::lines_in_text`];
//! rare: a CR used undefined, a label whose paths disagree). Columns do not
//! change: the items after the edit start on lines of their own, which the
//! parse again keeps whole (`syntax/reparse.rs`).

use super::flow::Noted;
use crate::ast::{self, Span};
use crate::diag::Diagnostic;
use crate::ir::{CheckedPou, CrState};

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
    /// Its diagnostics or its IR's texts name a line (`on line 4`): they
    /// cannot be moved when lines are added or removed before it.
    pub lines_in_text: bool,
}

/// The edit that allows reuse: in file `file`, POU `pou` (its number among
/// the file's POUs) changed; the old bytes `change` became `delta` bytes
/// more (or fewer), and `lines` lines more (or fewer).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Reuse {
    pub file: usize,
    pub pou: usize,
    pub change: (u32, u32),
    pub delta: i64,
    pub lines: i64,
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
    /// What the last check reused (`None`: it checked every POU).
    pub applied: Option<Reuse>,
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
    /// Whether POU `k` of file `f` may be reused (its results then decide:
    /// [`Reuse::takes`]).
    pub fn reuses(&self, f: usize, k: usize) -> bool {
        f != self.file || k != self.pou
    }

    /// Whether the results `r` of a POU that [`Reuse::reuses`] can be
    /// taken: not when lines moved and their text names a line.
    pub fn takes(&self, r: &PouResult) -> bool {
        self.lines == 0 || !r.lines_in_text
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
    /// outside the edited POU: they only move, and so do its lines).
    pub fn move_pou(&self, r: &mut PouResult, ir: Option<&mut CheckedPou>) {
        for (s, _) in &mut r.noted {
            *s = self.moved(*s).unwrap_or(*s);
        }
        if let Some(p) = ir {
            let line = |l: &mut u32| *l = (i64::from(*l) + self.lines) as u32;
            for c in &mut p.cr_steps {
                c.span = self.moved(c.span).unwrap_or(c.span);
                for s in [&mut c.before, &mut c.after] {
                    if let CrState::AfterCal(l) = s {
                        line(l);
                    }
                }
            }
            if self.lines != 0 {
                for s in &mut p.body {
                    line(&mut s.line);
                }
            }
        }
        for d in &mut r.diags {
            self.move_diag(d);
        }
    }
}

/// Whether a POU's diagnostics or IR name a line in their text (see
/// [`PouResult::lines_in_text`]): any `line` followed by a number, in any
/// text the checker wrote, so that a message added later is covered too.
pub(crate) fn lines_in_text(diags: &[Diagnostic], ir: Option<&CheckedPou>) -> bool {
    let names = |s: &str| {
        s.match_indices("line ")
            .any(|(i, m)| s[i + m.len()..].starts_with(|c: char| c.is_ascii_digit()))
    };
    let diag = |d: &Diagnostic| {
        names(&d.message)
            || names(&d.label)
            || d.secondary.iter().any(|(_, l)| names(l))
            || d.notes.iter().any(|n| names(n))
            || d.help.as_deref().is_some_and(names)
            || d.fixes
                .iter()
                .any(|f| names(&f.title) || f.edits.iter().any(|(_, t)| names(t)))
    };
    let state = |s: &CrState| match s {
        CrState::Undefined(t) | CrState::Literal(t) => names(t),
        _ => false,
    };
    diags.iter().any(diag)
        || ir.is_some_and(|p| {
            p.cr_steps.iter().any(|c| {
                state(&c.before) || state(&c.after) || c.paths.as_deref().is_some_and(names)
            })
        })
}
