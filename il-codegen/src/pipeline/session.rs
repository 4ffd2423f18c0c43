//! A program checked again after every edit (an editor's): [`Session`].

use std::collections::HashMap;
use std::ops::Range;

use super::{Checked, Input, Parsed, Program};
use crate::ast::CompilationUnit;
use crate::diag::SourceFile;
use crate::sema;
use crate::syntax::{self, lexer::comments::InnerOpen};

/// Checks a program again and again as its texts change, and keeps the
/// last [`Checked`]: an IL file is then parsed again only in the top-level
/// items (POUs, TYPE blocks, CONFIGURATIONs) that an edit touches, the
/// other items' trees are kept with their positions moved; and when the
/// edit changed one POU's body alone (its declarations and its use of
/// `ENO` kept), only that POU is checked again: the others' checked IR,
/// diagnostics and resolved names are the last check's, their bytes and
/// lines moved (a POU whose messages name a line in their text is checked
/// again when the lines after the edit moved). The declarations and the
/// program-wide rules are checked every time.
///
/// The result is the one [`Program::check`] gives for the same sources,
/// diagnostics and spans included; where that is not sure the longer way
/// is taken: a file whose last parse had diagnostics, an edit that crosses
/// an item's line or leaves an error in the part parsed again, is parsed
/// whole; any other edit, or a change of the inputs or of the options,
/// checks the whole program.
///
/// Files are matched with the last check's by their name ([`SourceFile::name`]).
///
/// ```
/// use il_codegen::{pipeline::Session, Program, SourceFile};
/// let a = "FUNCTION_BLOCK A\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_FUNCTION_BLOCK\n";
/// let b = "FUNCTION_BLOCK B\nVAR y : INT; END_VAR\n    LD y\n    ST y\nEND_FUNCTION_BLOCK\n";
/// let mut session = Session::new();
/// let text = format!("{a}{b}");
/// session.check(Program::new().il(SourceFile::new("m.il", text.clone())));
/// // An edit in B: A's tree is kept, B is parsed again.
/// let edited = text.replace("    LD y", "    LD nosuch");
/// let checked = session.check(Program::new().il(SourceFile::new("m.il", edited)));
/// assert_eq!(checked.diagnostics()[0].len(), 1);
/// assert_eq!(session.reparsed()[0], Some(a.len()..a.len() + b.len() + 5));
/// ```
#[derive(Debug, Default)]
pub struct Session {
    last: Option<Checked>,
    /// Per input of `last`: its comments that hold a `(*` when its parse
    /// gave no diagnostic (then its tree can be kept), `None` otherwise.
    clean: Vec<Option<Vec<InnerOpen>>>,
    reparsed: Vec<Option<Range<usize>>>,
    /// What a check left of the one before (its IR, diagnostics,
    /// resolutions), until [`Session::release`].
    spent: Option<Checked>,
    parse_time: std::time::Duration,
    /// Each POU's results of the last check (see `sema/reuse.rs`).
    cache: sema::reuse::Cache,
    /// What the last check was asked: the cache serves only the same.
    settings: Option<Settings>,
    generation: u64,
}

#[derive(Debug, PartialEq)]
struct Settings {
    standard: crate::dialect::Standard,
    cr_steps: bool,
    resolutions: bool,
    names: Vec<String>,
}

/// How a check moved the results of the one before ([`Session::moved`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Moved {
    /// The input that changed (no other did).
    pub input: usize,
    /// The POU checked again, by its number among the input's POUs
    /// (`None`: no text changed, every result was taken as it was).
    pub pou: Option<usize>,
    /// The bytes of the input's old text that the edit replaced, all
    /// inside that POU: a position before `change.start` stays, one at
    /// or after `change.end` moves by `delta` bytes.
    pub change: Range<usize>,
    /// How many bytes longer the new text is.
    pub delta: i64,
}

/// What parsing an input again found (see `syntax::reparse::Reparsed`).
struct Edit {
    parsed: Range<usize>,
    items: Range<usize>,
    replaced: Vec<crate::ast::Item>,
    change: (usize, usize),
    delta: i64,
    lines: i64,
}

/// What the check of the new texts may reuse of the last one's: every
/// POU's results but the edited one's, when every file was parsed again in part,
/// and one POU alone changed, inside, keeping its declarations (see
/// `sema/reuse.rs`).
fn reuse(edits: &[Option<Edit>], parsed: &[Parsed]) -> Option<sema::reuse::Reuse> {
    use crate::ast::Item;
    let mut changed = edits
        .iter()
        .enumerate()
        .filter(|(_, e)| e.as_ref().is_none_or(|e| !e.parsed.is_empty()));
    let Some((file, edit)) = changed.next() else {
        // Nothing changed: everything is reused.
        return Some(sema::reuse::Reuse {
            file: 0,
            pou: usize::MAX,
            change: (u32::MAX, u32::MAX),
            delta: 0,
            lines: 0,
        });
    };
    let e = edit.as_ref()?;
    if changed.next().is_some() || e.items.len() != 1 {
        return None;
    }
    let items = &parsed[file].0.items;
    let (Some(Item::Pou(new)), [Item::Pou(old)]) = (items.get(e.items.start), &e.replaced[..])
    else {
        return None;
    };
    let inside = (old.span.lo as usize) < e.change.0 && e.change.1 < old.span.hi as usize;
    if !inside || !sema::reuse::same_interface(old, new) {
        return None;
    }
    let pou = items[..e.items.start]
        .iter()
        .filter(|i| matches!(i, Item::Pou(_)))
        .count();
    Some(sema::reuse::Reuse {
        file,
        pou,
        change: (e.change.0 as u32, e.change.1 as u32),
        delta: e.delta,
        lines: e.lines,
    })
}

impl Session {
    /// A session that has checked nothing yet.
    pub fn new() -> Self {
        Session::default()
    }

    /// Check `program` as [`Program::check`] does, reusing the trees of
    /// the last check's files where their text is unchanged but for the
    /// edit, and the other POUs' results when the edit changed one POU's
    /// body only; the result stays in the session until the next check.
    pub fn check(&mut self, mut program: Program) -> &Checked {
        let start = std::time::Instant::now();
        let settings = Settings {
            standard: program.standard,
            cr_steps: program.cr_steps,
            resolutions: program.resolutions,
            names: program
                .inputs
                .iter()
                .map(|i| i.il_text().name.clone())
                .collect(),
        };
        let same = self.settings.as_ref() == Some(&settings);
        let mut trees = self.take_trees(&program, same);
        let mut clean = Vec::new();
        let mut edits = Vec::new();
        let parsed = program.parse_with(|input, file, standard| {
            let kept = match input {
                Input::Il(_) => trees.remove(&file.name),
                _ => None,
            };
            let again = kept.and_then(|(old, unit, opens)| {
                syntax::reparse::reparse(&old.text, unit, opens, file, standard)
            });
            let parsed: Parsed = match again {
                Some(r) => {
                    let p = (r.unit, Vec::new(), r.inner_opens);
                    edits.push(Some(Edit {
                        parsed: r.parsed,
                        items: r.items,
                        replaced: r.replaced,
                        change: r.change,
                        delta: r.delta,
                        lines: r.lines,
                    }));
                    p
                }
                None => {
                    edits.push(None);
                    syntax::parse_noted(file, standard)
                }
            };
            let keep = matches!(input, Input::Il(_)) && parsed.1.is_empty();
            clean.push(keep.then(|| parsed.2.clone()));
            parsed
        });
        self.parse_time = start.elapsed();
        self.cache.reuse = if same { reuse(&edits, &parsed) } else { None };
        if self.cache.reuse.is_none() {
            self.cache.old_ir.clear();
        }
        let checked = program.check_parsed(parsed, Some(&mut self.cache));
        self.settings = Some(settings);
        self.generation += 1;
        self.clean = clean;
        self.reparsed = edits.into_iter().map(|e| e.map(|e| e.parsed)).collect();
        self.last.insert(checked)
    }

    /// How many checks the session has run: tells the last check's
    /// results from an earlier one's (for a tool that keeps positions in
    /// them, such as an editor's index).
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// How many POUs the last check checked: the others' results were
    /// those of the check before (see [`Session`]).
    pub fn pous_checked(&self) -> usize {
        self.cache.checked
    }

    /// How the last check's positions relate to the one before's, when it
    /// checked again only the POU an edit changed, inside its body, and
    /// took the others' results, moved (`None`: it checked the whole
    /// program). A tool that keeps what it built from the check before (an
    /// editor's index) may move it likewise: every other POU's syntax,
    /// declarations and checked IR are the same, moved.
    pub fn moved(&self) -> Option<Moved> {
        let r = self.cache.applied?;
        Some(Moved {
            input: r.file,
            pou: (r.pou != usize::MAX).then_some(r.pou),
            change: r.change.0 as usize..r.change.1 as usize,
            delta: r.delta,
        })
    }

    /// The last check's result.
    pub fn last(&self) -> Option<&Checked> {
        self.last.as_ref()
    }

    /// For each input of the last check, the byte range of its IL text
    /// that was parsed (`Some(0..0)`: the text was unchanged; `None`: it
    /// was parsed whole).
    pub fn reparsed(&self) -> &[Option<Range<usize>>] {
        &self.reparsed
    }

    /// The last check's IL texts that parsed without a diagnostic, with
    /// their trees, by name (when `program` is checked under the same
    /// standard); the rest of the last check is dropped.
    fn take_trees(
        &mut self,
        program: &Program,
        same: bool,
    ) -> HashMap<String, (SourceFile, CompilationUnit, Vec<InnerOpen>)> {
        let mut trees = HashMap::new();
        let Some(mut last) = self.last.take() else {
            return trees;
        };
        if last.standard != program.standard {
            return trees;
        }
        if same {
            // The IR of the POUs the next check may reuse.
            self.cache.old_ir = std::mem::take(&mut last.ir)
                .into_iter()
                .map(|p| p.pous.into_iter().map(Some).collect())
                .collect();
        }
        let units = std::mem::take(&mut last.units);
        let inputs = std::mem::take(&mut last.inputs);
        for ((input, unit), clean) in inputs.into_iter().zip(units).zip(self.clean.drain(..)) {
            if let (Input::Il(f), Some(opens)) = (input, clean) {
                trees.insert(f.name.clone(), (f, unit, opens));
            }
        }
        self.spent = Some(last);
        trees
    }

    /// Drop what the last check kept of the one before it (without this,
    /// the next check does it). For a caller that has time after a check,
    /// as a language server once it has published the diagnostics.
    pub fn release(&mut self) {
        self.spent = None;
    }

    /// How long the last check spent parsing (the rest of
    /// [`Session::check`] is the semantic check).
    pub fn parse_time(&self) -> std::time::Duration {
        self.parse_time
    }
}
