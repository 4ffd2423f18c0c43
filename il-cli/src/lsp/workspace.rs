//! The documents the server knows (open in the editor, or `.il` files of
//! the workspace folders) and the result of checking them together.
//!
//! The documents of one folder are one program, as with `ilc check
//! plc/a.il plc/b.il` (see [`programs`]): an edit re-checks them all (full
//! sync), which costs what the front end costs; the index of each program's
//! check then answers the requests on its documents.

use std::collections::HashMap;
use std::path::Path;
use std::time::{Duration, Instant};

use il_codegen::{Program, Session, SourceFile};
use lsp_types::Uri;

use super::convert::{LineIndex, path_to_uri, uri_to_name};
use super::diagnostics;
use super::index::{Index, Step};

/// One document.
#[derive(Debug)]
pub struct Doc {
    pub uri: Uri,
    /// The name in messages and the one deciding IL or PLCopen XML.
    pub name: String,
    pub text: String,
    /// The line table of `text`, when kept from the last check or moved
    /// through the editor's edits (`None`: the next check builds it).
    pub lines: Option<LineIndex>,
    /// Open in the editor (its text is the editor's, not the disk's).
    pub open: bool,
    /// Found in a workspace folder (kept when the editor closes it).
    pub on_disk: bool,
    /// What reading the text from disk reported (an encoding guessed, bad
    /// bytes); none for the editor's text, which comes as UTF-8.
    pub read_diagnostics: Vec<il_codegen::diag::Diagnostic>,
}

/// A fix the checker offers for one diagnostic, in the document's terms.
#[derive(Debug, Clone)]
pub struct QuickFix {
    pub range: lsp_types::Range,
    pub title: String,
    pub edits: Vec<lsp_types::TextEdit>,
}

/// The result of one check of every document.
#[derive(Debug, Default)]
pub struct Analysis {
    /// The line table of each document's text (the user's file).
    pub lines: Vec<LineIndex>,
    /// Each document's diagnostics, converted.
    pub diagnostics: Vec<Vec<lsp_types::Diagnostic>>,
    /// Each document's quick fixes: the range of the diagnostic they fix,
    /// and the fix's title and edits (the checker's `Diagnostic::fixes`).
    pub fixes: Vec<Vec<QuickFix>>,
    /// One index per program (see [`programs`]).
    pub indexes: Vec<Index>,
    /// Each document's program: an index into `indexes`.
    pub program_of: Vec<usize>,
    /// Each program's folder (its session's key) and the session's
    /// generation its index was built from.
    pub checks: Vec<(String, u64)>,
}

impl Analysis {
    /// The index of the program that holds document `k`.
    pub fn index(&self, k: usize) -> Option<&Index> {
        self.indexes.get(*self.program_of.get(k)?)
    }
}

/// The documents checked together: those of one folder, as a crate's
/// `il!(files = [...])` or build.rs builder takes its `plc/` folder. A
/// workspace often holds several such programs (examples, tests, two
/// crates), each with its own `PROGRAM Main`; checking every file as one
/// program made those duplicates of each other. The folder and its group
/// of document numbers, ascending, in the order of their first document.
fn programs(docs: &[Doc]) -> Vec<(String, Vec<usize>)> {
    let mut groups: Vec<(String, Vec<usize>)> = Vec::new();
    let mut by_dir: HashMap<String, usize> = HashMap::new();
    for (k, d) in docs.iter().enumerate() {
        let dir = Path::new(&d.name)
            .parent()
            .map(|p| p.to_string_lossy().into_owned())
            .unwrap_or_default();
        let g = *by_dir.entry(dir.clone()).or_insert_with(|| {
            groups.push((dir, Vec::new()));
            groups.len() - 1
        });
        groups[g].1.push(k);
    }
    groups
}

/// Client settings.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Inlay hints with the CR type at the end of each instruction line.
    pub cr_type_hints: bool,
    /// The client re-asks for inlay hints when told (`workspace/inlayHint/refresh`).
    pub hint_refresh: bool,
    /// How the files read from disk that are not UTF-8 are decoded
    /// (`ilc --encoding`, or the option `{"encoding": "windows-1251"}`).
    pub encoding: il_codegen::read::Encoding,
    /// The Instruction List of the text documents (`{"dialect": "m221"}`:
    /// Modicon M221 / TwidoSuite listings, as `ilc --dialect m221`).
    pub dialect: il_codegen::Dialect,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            cr_type_hints: true,
            hint_refresh: false,
            encoding: Default::default(),
            dialect: Default::default(),
        }
    }
}

impl Settings {
    /// Read `{"inlayHints": {"crType": false}, "encoding": "windows-1251",
    /// "dialect": "m221"}`, also under an `ilc` key (as VS Code sends its
    /// configuration section). An unknown encoding or dialect is kept out,
    /// with the reason (for the log).
    pub fn update(&mut self, v: &serde_json::Value) -> Result<(), String> {
        let v = v.get("ilc").unwrap_or(v);
        let mut bad = Ok(());
        // An empty name (an editor's unset setting) leaves the encoding as it is.
        if let Some(label) = v
            .get("encoding")
            .and_then(serde_json::Value::as_str)
            .filter(|l| !l.trim().is_empty())
        {
            match il_codegen::read::Encoding::from_label(label) {
                Ok(e) => self.encoding = e,
                Err(e) => bad = Err(e),
            }
        }
        if let Some(name) = v
            .get("dialect")
            .and_then(serde_json::Value::as_str)
            .filter(|l| !l.trim().is_empty())
        {
            match il_codegen::Dialect::from_name(name) {
                Some(d) => self.dialect = d,
                None => bad = Err(format!("unknown dialect `{name}`: use `iec` or `m221`")),
            }
        }
        if let Some(b) = v
            .pointer("/inlayHints/crType")
            .or_else(|| v.get("inlayHints.crType"))
            .and_then(serde_json::Value::as_bool)
        {
            self.cr_type_hints = b;
        }
        bad
    }
}

#[derive(Debug, Default)]
pub struct Workspace {
    pub docs: Vec<Doc>,
    /// By [`key`]: one file under two spellings of its URI (an editor's
    /// `file:///c%3A/x.il`, the scan's `file:///C:/x.il`) is one document.
    by_uri: HashMap<String, usize>,
    pub analysis: Analysis,
    pub settings: Settings,
    /// The diagnostics last published per document (republished only when
    /// they change).
    published: Vec<Option<Vec<lsp_types::Diagnostic>>>,
    /// Each program's checker, by folder (see [`programs`]): it keeps the
    /// last check, so that an edit parses only the items it touches.
    sessions: HashMap<String, Session>,
    /// The analysis an edit replaced, dropped once the new diagnostics are
    /// published ([`Workspace::release`]): freeing it took 5 ms of an edit
    /// of a 100 000-line file.
    spent: Option<Analysis>,
    /// Where the last check's time went.
    pub times: Times,
}

/// Where the time of one [`Workspace::check`] went.
#[derive(Debug, Default)]
pub struct Times {
    /// Parsing (the parts an edit touched, or whole files).
    pub parse: Duration,
    /// The semantic check (the rest of `Session::check`).
    pub check: Duration,
    /// The server's index of each program and the conversion of the
    /// diagnostics.
    pub index: Duration,
    /// The line tables of the documents.
    pub lines: Duration,
    /// The POUs checked (the others' results were reused).
    pub pous: usize,
    /// The programs whose index was moved, not built (`index/moved.rs`).
    pub moved: usize,
}

/// The name of a document's file with a Windows drive letter in upper case.
fn key(uri: &Uri) -> String {
    let mut name = uri_to_name(uri);
    if name.as_bytes().get(1) == Some(&b':') {
        name[..1].make_ascii_uppercase();
    }
    name
}

/// Most `.il` files read from the workspace folders, and how deep.
const MAX_FILES: usize = 2000;
const MAX_DEPTH: usize = 8;

impl Workspace {
    pub fn doc(&self, uri: &Uri) -> Option<usize> {
        self.by_uri.get(&key(uri)).copied()
    }

    /// The document and byte offset of a position (clamped to the text).
    pub fn locate(&self, uri: &Uri, pos: lsp_types::Position) -> Option<(usize, usize)> {
        let k = self.doc(uri)?;
        let lines = self.analysis.lines.get(k)?;
        Some((k, lines.offset(&self.docs[k].text, pos)))
    }

    /// What the checker recorded at `step` of document `k`'s program (from
    /// the check its index was built from, kept by the program's session).
    pub fn cr_step(&self, k: usize, step: &Step) -> Option<&il_codegen::ir::CrStep> {
        let (dir, generation) = self
            .analysis
            .checks
            .get(*self.analysis.program_of.get(k)?)?;
        let session = self.sessions.get(dir)?;
        if session.generation() != *generation {
            return None;
        }
        let ir = session.last()?.partial_ir();
        let pou = ir.get(step.file as usize)?.pous.get(step.pou as usize)?;
        pou.cr_steps.get(step.at as usize)
    }

    /// The LSP range of a span of document `k`.
    pub fn range(&self, k: usize, span: il_codegen::ast::Span) -> lsp_types::Range {
        match (self.docs.get(k), self.analysis.lines.get(k)) {
            (Some(d), Some(l)) => l.range(&d.text, span),
            _ => lsp_types::Range::default(),
        }
    }

    /// The location of a span of document `k`.
    pub fn location(&self, k: usize, span: il_codegen::ast::Span) -> Option<lsp_types::Location> {
        Some(lsp_types::Location::new(
            self.docs.get(k)?.uri.clone(),
            self.range(k, span),
        ))
    }

    /// Add the `.il` and `.exp` (CODESYS export) files under a workspace folder (not its hidden folders,
    /// `target` or `node_modules`).
    pub fn scan(&mut self, root: &Path) {
        let mut stack = vec![(root.to_path_buf(), 0)];
        while let Some((dir, depth)) = stack.pop() {
            let Ok(entries) = std::fs::read_dir(&dir) else {
                continue;
            };
            let mut entries: Vec<_> = entries.flatten().map(|e| e.path()).collect();
            entries.sort();
            for p in entries {
                let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
                if p.is_dir() {
                    if depth < MAX_DEPTH
                        && !name.starts_with('.')
                        && name != "target"
                        && name != "node_modules"
                    {
                        stack.push((p, depth + 1));
                    }
                } else if p
                    .extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("il") || e.eq_ignore_ascii_case("exp"))
                    && self.docs.len() < MAX_FILES
                    && let Some(uri) = path_to_uri(&p)
                    && self.doc(&uri).is_none()
                    && let Ok(f) =
                        crate::input::read_source(&p.to_string_lossy(), self.settings.encoding)
                {
                    let k = self.insert(uri, f.text, false, true);
                    self.docs[k].read_diagnostics = f.read_diagnostics;
                }
            }
        }
    }

    fn insert(&mut self, uri: Uri, text: String, open: bool, on_disk: bool) -> usize {
        let name = uri_to_name(&uri);
        let k = self.docs.len();
        self.by_uri.insert(key(&uri), k);
        self.docs.push(Doc {
            uri,
            name,
            text,
            lines: None,
            open,
            on_disk,
            read_diagnostics: Vec::new(),
        });
        k
    }

    pub fn open(&mut self, uri: Uri, text: String) {
        match self.doc(&uri) {
            Some(k) => {
                // Published under the editor's spelling of the URI.
                if self.docs[k].uri != uri {
                    self.docs[k].uri = uri;
                    if let Some(p) = self.published.get_mut(k) {
                        *p = None;
                    }
                }
                self.docs[k].text = text;
                self.docs[k].lines = None;
                self.docs[k].open = true;
                self.docs[k].read_diagnostics.clear();
            }
            None => {
                self.insert(uri, text, true, false);
            }
        }
    }

    /// The editor's new text of a document, and its line table if the
    /// caller kept it through the edits.
    pub fn change(&mut self, uri: &Uri, text: String, lines: Option<LineIndex>) {
        match self.doc(uri) {
            Some(k) => {
                self.docs[k].text = text;
                self.docs[k].lines = lines;
                self.docs[k].read_diagnostics.clear();
            }
            None => {
                self.insert(uri.clone(), text, true, false);
            }
        }
    }

    /// Closed in the editor: a workspace file goes back to its text on
    /// disk; another document leaves the program. Returns the URI whose
    /// diagnostics must be cleared.
    pub fn close(&mut self, uri: &Uri) -> Option<Uri> {
        let k = self.doc(uri)?;
        if self.docs[k].on_disk {
            self.docs[k].open = false;
            if let Ok(f) = crate::input::read_source(&self.docs[k].name, self.settings.encoding) {
                self.docs[k].text = f.text;
                self.docs[k].lines = None;
                self.docs[k].read_diagnostics = f.read_diagnostics;
            }
            return None;
        }
        self.docs.remove(k);
        if k < self.published.len() {
            self.published.remove(k);
        }
        self.by_uri = self
            .docs
            .iter()
            .enumerate()
            .map(|(i, d)| (key(&d.uri), i))
            .collect();
        Some(uri.clone())
    }

    /// Check the documents of each folder as one program (see [`programs`])
    /// and index the results.
    pub fn check(&mut self) {
        let start = Instant::now();
        let mut times = Times::default();
        // Kept in the document for its next edit, copied for the analysis
        // (a copy is a tenth of a build).
        let lines: Vec<LineIndex> = (self.docs.iter_mut())
            .map(|d| {
                d.lines
                    .get_or_insert_with(|| LineIndex::new(&d.text))
                    .clone()
            })
            .collect();
        times.lines = start.elapsed();
        let mut diagnostics = vec![Vec::new(); self.docs.len()];
        let mut fixes = vec![Vec::new(); self.docs.len()];
        let mut indexes = Vec::new();
        let mut program_of = vec![0; self.docs.len()];
        let mut sessions = HashMap::new();
        let mut checks = Vec::new();
        for (dir, group) in programs(&self.docs) {
            let session: &mut Session = sessions
                .entry(dir.clone())
                .or_insert_with(|| self.sessions.remove(&dir).unwrap_or_default());
            let program =
                group
                    .iter()
                    .fold(Program::new().cr_steps(true).resolutions(true), |p, &k| {
                        let d = &self.docs[k];
                        let mut f = SourceFile::new(d.name.clone(), d.text.clone());
                        f.read_diagnostics.clone_from(&d.read_diagnostics);
                        p.input(self.settings.dialect.input(f))
                    });
            let checking = Instant::now();
            session.check(program);
            // What the check moved, before `checked` borrows the session.
            let moved = session.moved();
            let before = session.generation().checked_sub(1);
            let Some(checked) = session.last() else {
                continue;
            };
            let indexing = Instant::now();
            times.check += indexing - checking;
            for (&k, ds) in group.iter().zip(checked.diagnostics()) {
                let d = &self.docs[k];
                diagnostics[k] = diagnostics::convert(&d.uri, &d.text, &lines[k], ds);
                fixes[k] = ds
                    .iter()
                    .flat_map(|diag| diag.fixes.iter().map(move |f| (diag.span, f)))
                    .map(|(span, f)| QuickFix {
                        range: lines[k].range(&d.text, span),
                        title: f.title.clone(),
                        edits: f
                            .edits
                            .iter()
                            .map(|(s, t)| {
                                lsp_types::TextEdit::new(lines[k].range(&d.text, *s), t.clone())
                            })
                            .collect(),
                    })
                    .collect();
                program_of[k] = indexes.len();
            }
            // The index of the check before, moved, when the session moved
            // that check's results (see `index/moved.rs`); else built. The
            // old one is taken from the analysis this check replaces (were
            // the check to panic, that analysis would stay without it
            // until the next check).
            let old = (self.analysis.checks.iter())
                .position(|(d, g)| *d == dir && Some(*g) == before)
                .and_then(|i| self.analysis.indexes.get_mut(i))
                .map(std::mem::take);
            let index = moved
                .zip(old)
                .and_then(|(m, old)| old.moved(checked, &m, &group))
                .inspect(|_| times.moved += 1)
                .unwrap_or_else(|| {
                    let mut index = Index::build(checked);
                    index.relocate(group);
                    index
                });
            indexes.push(index);
            times.index += indexing.elapsed();
            times.parse += session.parse_time();
            times.pous += session.pous_checked();
            checks.push((dir, session.generation()));
        }
        times.check = times.check.saturating_sub(times.parse);
        self.times = times;
        // The sessions of folders without documents go.
        self.sessions = sessions;
        self.spent = Some(std::mem::replace(
            &mut self.analysis,
            Analysis {
                lines,
                diagnostics,
                fixes,
                indexes,
                program_of,
                checks,
            },
        ));
    }

    /// Drop what the last check replaced (call it once its diagnostics are
    /// published: an editor waits for those, not for this).
    pub fn release(&mut self) {
        self.spent = None;
        for s in self.sessions.values_mut() {
            s.release();
        }
    }

    /// The documents whose diagnostics changed since they were last
    /// published, with the new ones (empty: cleared).
    pub fn take_changed_diagnostics(&mut self) -> Vec<(Uri, Vec<lsp_types::Diagnostic>)> {
        self.published.resize(self.docs.len(), None);
        let mut out = Vec::new();
        for (k, d) in self.docs.iter().enumerate() {
            let now = self
                .analysis
                .diagnostics
                .get(k)
                .cloned()
                .unwrap_or_default();
            if self.published[k].as_ref() != Some(&now) {
                self.published[k] = Some(now.clone());
                out.push((d.uri.clone(), now));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_file_under_two_uris_is_one_document() {
        let mut ws = Workspace::default();
        ws.insert(
            "file:///C:/plc/m.il".parse().unwrap(),
            "a".into(),
            false,
            true,
        );
        let editor: Uri = "file:///c%3A/plc/m.il".parse().unwrap();
        assert_eq!(ws.doc(&editor), Some(0));
        ws.open(editor.clone(), "b".into());
        assert_eq!(ws.docs.len(), 1);
        assert_eq!(ws.docs[0].uri, editor);
        assert_eq!(ws.docs[0].text, "b");
    }

    /// The `.EXP` files of one folder are one CODESYS project: a global of
    /// one is known in another, and diagnostics are at the export's lines.
    #[test]
    fn exp_documents_of_a_folder_are_one_project() {
        let mut ws = Workspace::default();
        ws.open(
            "file:///plc/G.EXP".parse().unwrap(),
            "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @GLOBAL_VARIABLE_LIST := 'G' *)\nVAR_GLOBAL\n\tcount : INT;\nEND_VAR\n(* @OBJECT_END := 'G' *)\n".into(),
        );
        ws.open(
            "file:///plc/PLC_PRG.EXP".parse().unwrap(),
            "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @PATH := '\\/Main' *)\nPROGRAM PLC_PRG\nVAR x : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD count\nST x\nLD y\nEND_PROGRAM\n".into(),
        );
        ws.check();
        assert_eq!(ws.analysis.diagnostics[0], []);
        let d = &ws.analysis.diagnostics[1];
        assert_eq!(d.len(), 1, "{d:?}");
        assert_eq!(
            d[0].code,
            Some(lsp_types::NumberOrString::String("IL0101".into()))
        );
        assert_eq!((d[0].range.start.line, d[0].range.start.character), (7, 3));
        // The POU's symbol shows its project folder.
        let syms =
            super::super::symbols::document(&ws, &"file:///plc/PLC_PRG.EXP".parse().unwrap());
        assert_eq!(syms[0].name, "PLC_PRG");
        assert_eq!(syms[0].detail.as_deref(), Some("PROGRAM · /Main"));
    }

    /// The editor's name for a document does not decide its language: its
    /// text does, as for `ilc check`.
    #[test]
    fn a_document_is_xml_by_its_text_whatever_its_name() {
        let mut ws = Workspace::default();
        let xml = "\u{feff}<?xml version=\"1.0\"?>\n<ProjectDescriptor xmlns=\"urn:x\">\n</ProjectDescriptor>\n";
        ws.open("file:///plc/Counters1.smbp".parse().unwrap(), xml.into());
        ws.open(
            "file:///plc/main.il".parse().unwrap(),
            "PROGRAM Main\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_PROGRAM\n".into(),
        );
        ws.check();
        let d = &ws.analysis.diagnostics[0];
        assert_eq!(d.len(), 1, "{d:?}");
        assert_eq!(
            d[0].code,
            Some(lsp_types::NumberOrString::String("IL0202".into()))
        );
        assert!(d[0].message.contains("`<ProjectDescriptor>`"), "{d:?}");
        assert!(d[0].message.contains("`urn:x`"), "{d:?}");
        assert_eq!(d[0].range.start.line, 1);
        assert_eq!(ws.analysis.diagnostics[1], []);
    }
}
