//! The one pipeline every front end runs (`il!`, the build-script
//! [`Builder`](crate::Builder), `ilc`, the interpreter, the fuzz targets):
//! sources in ([`Program`]) → a checked program ([`Checked`]) → emitted Rust
//! ([`Emitted`]: Rust text, which `il!` parses into tokens once and build.rs
//! and `ilc emit` write as files). The rules are decided here once: every file is parsed; the files
//! without syntax errors are checked together (a FUNCTION_BLOCK of one is
//! usable in another); diagnostics are moved into the file the user wrote
//! (an XML project's lines), sorted by position and limited per file; code
//! is emitted only when no input has an error. A [`Session`] runs the same
//! pipeline again after each edit, parsing and checking only what the edit
//! touched.

#[cfg(feature = "build")]
pub(crate) mod file;
mod input;
mod session;
pub mod snippet;

pub use input::{Input, is_xml};
pub use session::{Moved, Session};

/// What parsing one IL text gives: the tree, the syntax diagnostics, and
/// the comments that hold a `(*` (for naming the checker's errors after them).
type Parsed = (
    crate::ast::CompilationUnit,
    Vec<Diagnostic>,
    Vec<syntax::lexer::comments::InnerOpen>,
);

#[cfg(feature = "build")]
use crate::diag::render;
use crate::diag::{Diagnostic, SourceFile, has_errors};
use crate::{emit, sema, syntax};

/// The sources of one program: IL files and PLCopen XML projects.
#[derive(Clone, Debug, Default)]
pub struct Program {
    inputs: Vec<Input>,
    standard: crate::dialect::Standard,
    cr_steps: bool,
    resolutions: bool,
}

impl Program {
    /// A program without sources.
    pub fn new() -> Self {
        Program::default()
    }

    /// With an IL source.
    pub fn il(self, file: SourceFile) -> Self {
        self.input(Input::il(file))
    }

    /// With a PLCopen TC6 XML project (translated to IL now).
    pub fn plcopen(self, file: SourceFile) -> Self {
        self.input(Input::plcopen(file))
    }

    /// With a source that is PLCopen XML when it is XML (its text starts
    /// with `<`, or its name ends in `.xml`: [`is_xml`]), IL otherwise.
    pub fn source(self, file: SourceFile) -> Self {
        self.input(Input::by_content(file))
    }

    /// With a bare instruction list, the body of a PROGRAM named after the
    /// file ([`Input::snippet`]).
    pub fn snippet(self, file: SourceFile) -> Self {
        self.input(Input::snippet(file))
    }

    /// With an input.
    pub fn input(mut self, input: Input) -> Self {
        self.inputs.push(input);
        self
    }

    /// The inputs, in the order they were added.
    pub fn inputs(&self) -> &[Input] {
        &self.inputs
    }

    /// Check against this standard (default [`Standard::Iec2013`]:
    /// 3rd-edition and vendor forms are accepted; [`Standard::Iec2003`]
    /// refuses each of them).
    ///
    /// [`Standard::Iec2013`]: crate::Standard::Iec2013
    /// [`Standard::Iec2003`]: crate::Standard::Iec2003
    pub fn standard(mut self, standard: crate::dialect::Standard) -> Self {
        self.standard = standard;
        self
    }

    /// Also record the CR the checker proved at every instruction and label
    /// ([`CheckedPou::cr_steps`], for tools such as the language server's
    /// hover); off by default: the compiler does not read them.
    ///
    /// [`CheckedPou::cr_steps`]: crate::ir::CheckedPou::cr_steps
    pub fn cr_steps(mut self, record: bool) -> Self {
        self.cr_steps = record;
        self
    }

    /// Also record what every name of the program names, as the checker
    /// resolves it ([`Checked::resolutions`], for tools such as the language
    /// server's definition and references); off by default: the compiler
    /// does not read it.
    pub fn resolutions(mut self, record: bool) -> Self {
        self.resolutions = record;
        self
    }

    /// Parse and check every input.
    pub fn check(mut self) -> Checked {
        let parsed = self.parse_with(|_, f, standard| syntax::parse_noted(f, standard));
        self.check_parsed(parsed, None)
    }

    /// Parse each input's IL text with `parse` (a [`Session`] parses again
    /// only what changed), which must give what `syntax::parse_noted` gives.
    fn parse_with(
        &mut self,
        mut parse: impl FnMut(&Input, &SourceFile, crate::dialect::Standard) -> Parsed,
    ) -> Vec<Parsed> {
        one_guess_per_program(&mut self.inputs);
        // The CODESYS exports of the program are one project: their
        // global lists and task configuration are read together.
        let mut exps: Vec<&mut crate::exp::Import> = self
            .inputs
            .iter_mut()
            .filter_map(|i| match i {
                Input::Exp(e) => Some(&mut **e),
                _ => None,
            })
            .collect();
        if exps.len() > 1 {
            crate::exp::assemble(&mut exps);
        }
        let standard = self.standard;
        self.inputs
            .iter()
            .map(|input| parse(input, input.il_text(), standard))
            .collect()
    }

    /// Check the inputs parsed by [`Program::parse_with`]; with a `cache`,
    /// each POU's results are kept in it, and the POUs its `reuse` allows
    /// are not checked again (see `sema/reuse.rs`).
    fn check_parsed(self, parsed: Vec<Parsed>, cache: Option<&mut sema::reuse::Cache>) -> Checked {
        let files: Vec<&SourceFile> = self.inputs.iter().map(Input::il_text).collect();
        let mut units = Vec::new();
        let mut diags: Vec<Vec<Diagnostic>> = Vec::new();
        let mut inner_opens = Vec::new();
        for (u, d, n) in parsed {
            units.push(u);
            diags.push(d);
            inner_opens.push(n);
        }
        // Files with syntax errors stay out of the semantic check (it would
        // mostly repeat them); the others are checked together. A pragma
        // refused by the strict standard is no damage to the syntax tree, so
        // such a file is still checked (and gets its other refusals too).
        // A CODESYS export holds many objects: one whose IL has a syntax
        // error is left out of the check, and the export's other objects
        // are checked (`pruned`).
        let pruned: Vec<Option<crate::ast::CompilationUnit>> = (0..files.len())
            .map(|i| match &self.inputs[i] {
                Input::Exp(_) => without_broken_items(&units[i], &diags[i]),
                _ => None,
            })
            .collect();
        let clean: Vec<usize> = (0..files.len())
            .filter(|&i| {
                pruned[i].is_some()
                    || !diags[i]
                        .iter()
                        .any(|d| d.is_error() && d.code != crate::dialect::codes::PRAGMA)
            })
            .collect();
        let pairs: Vec<_> = clean
            .iter()
            .map(|&i| (files[i], pruned[i].as_ref().unwrap_or(&units[i])))
            .collect();
        let broken = clean.len() < files.len();
        // The POUs' results are kept only when every file is checked (the
        // cache numbers them by file); pruned files are not.
        let cache = cache.and_then(|c| {
            if broken || pruned.iter().any(Option::is_some) {
                *c = Default::default();
                None
            } else {
                Some(c)
            }
        });
        let (programs, more, table) = sema::check_recorded(
            &pairs,
            self.standard,
            self.cr_steps,
            self.resolutions && !broken,
            cache,
        );
        let mut ir: Vec<sema::ir::Program> = files.iter().map(|_| Default::default()).collect();
        for ((&i, p), mut m) in clean.iter().zip(programs).zip(more) {
            ir[i] = p;
            syntax::lexer::comments::name_nested(&files[i].text, &inner_opens[i], &mut m);
            diags[i].extend(m);
        }
        let diagnostics: Vec<Vec<Diagnostic>> = self
            .inputs
            .iter()
            .zip(diags)
            .map(|(input, d)| input.finish(d))
            .collect();
        let ok = !diagnostics.iter().any(|d| has_errors(d));
        let resolutions = if self.resolutions && broken {
            // A file with syntax errors stays out of the check, but its
            // names are still the editor's: the table then comes from a
            // check of every file (partial trees are checked safely: `il!`
            // does it for its stubs), whose diagnostics and IR go unused.
            let every: Vec<usize> = (0..files.len()).collect();
            let all: Vec<_> = every.iter().map(|&i| (files[i], &units[i])).collect();
            let (_, _, t) = sema::check_recorded(&all, self.standard, false, true, None);
            t.map(|t| to_inputs(t, &every, &self.inputs))
        } else {
            table.map(|t| to_inputs(t, &clean, &self.inputs))
        };
        Checked {
            standard: self.standard,
            inputs: self.inputs,
            diagnostics,
            ir,
            units,
            ok,
            resolutions,
        }
    }
}

/// A program of many files that are not UTF-8 (a CODESYS project exported
/// one object per file) gets one IL0039 warning, not one per file: the
/// first file's, with a note naming the others. The guess and the switch
/// are the same for all of them.
fn one_guess_per_program(inputs: &mut [Input]) {
    let guessed = |i: &Input| {
        i.source()
            .read_diagnostics
            .iter()
            .any(|d| d.code == crate::read::GUESSED_ENCODING)
    };
    let all: Vec<usize> = (0..inputs.len()).filter(|&k| guessed(&inputs[k])).collect();
    let [first, rest @ ..] = &all[..] else { return };
    if rest.is_empty() {
        return;
    }
    let names: Vec<String> = rest
        .iter()
        .take(8)
        .map(|&k| format!("`{}`", inputs[k].source().name))
        .collect();
    let more = match rest.len() {
        n if n > 8 => format!(" and {} more", n - 8),
        _ => String::new(),
    };
    for &k in rest {
        inputs[k]
            .source_mut()
            .read_diagnostics
            .retain(|d| d.code != crate::read::GUESSED_ENCODING);
    }
    let note = format!(
        "{} other file(s) of this program are not UTF-8 either and were read as Windows-1252: {}{more}",
        rest.len(),
        names.join(", ")
    );
    if let Some(d) = inputs[*first]
        .source_mut()
        .read_diagnostics
        .iter_mut()
        .find(|d| d.code == crate::read::GUESSED_ENCODING)
    {
        d.notes.push(note);
    }
}

/// `unit` without the items that hold a syntax error, when it has some and
/// every one of them is inside an item (`None` otherwise: then the file is
/// checked whole, or not at all).
fn without_broken_items(
    unit: &crate::ast::CompilationUnit,
    diags: &[Diagnostic],
) -> Option<crate::ast::CompilationUnit> {
    use crate::ast::Item;
    let errors: Vec<crate::ast::Span> = diags
        .iter()
        .filter(|d| d.is_error() && d.code != crate::dialect::codes::PRAGMA)
        .map(|d| d.span)
        .collect();
    if errors.is_empty() {
        return None;
    }
    let span = |it: &Item| match it {
        Item::Pou(p) => Some(p.span),
        Item::Configuration(c) => Some(c.span),
        Item::Types(t) => Some(t.first()?.span.to(t.last()?.span)),
    };
    // An error starting in the item (or at its end: a missing END_).
    let inside = |e: &crate::ast::Span, s: Option<crate::ast::Span>| {
        s.is_some_and(|s| s.lo <= e.lo && e.lo <= s.hi)
    };
    if !errors
        .iter()
        .all(|e| unit.items.iter().any(|it| inside(e, span(it))))
    {
        return None;
    }
    let items = unit
        .items
        .iter()
        .filter(|it| !errors.iter().any(|e| inside(e, span(it))))
        .cloned()
        .collect();
    Some(crate::ast::CompilationUnit { items })
}

/// A checked program: every diagnostic of every input, and the checked IR.
#[derive(Debug)]
pub struct Checked {
    standard: crate::dialect::Standard,
    inputs: Vec<Input>,
    diagnostics: Vec<Vec<Diagnostic>>,
    ir: Vec<sema::ir::Program>,
    units: Vec<crate::ast::CompilationUnit>,
    ok: bool,
    resolutions: Option<crate::ir::Resolutions>,
}

/// The table of the checked files (`clean`, numbered as checked, spans in
/// the IL text) numbered and placed as the inputs: the file the user wrote.
fn to_inputs(
    mut t: crate::ir::Resolutions,
    clean: &[usize],
    inputs: &[Input],
) -> crate::ir::Resolutions {
    let mut uses = vec![Vec::new(); inputs.len()];
    for (&i, mut u) in clean.iter().zip(std::mem::take(&mut t.uses)) {
        for (s, _) in &mut u {
            *s = inputs[i].to_source(*s);
        }
        // The XML map keeps the order of spans; re-sorted all the same.
        u.sort_by_key(|(s, _)| (s.lo, s.hi));
        uses[i] = u;
    }
    for sym in &mut t.symbols {
        if let Some(d) = &mut sym.decl {
            d.file = clean[d.file];
            d.span = inputs[d.file].to_source(d.span);
        }
    }
    t.uses = uses;
    t
}

impl Checked {
    /// Whether any input has an error (then nothing is emitted).
    pub fn has_errors(&self) -> bool {
        !self.ok
    }

    /// The diagnostics of each input (in the order of the inputs), in the
    /// positions of the file the user wrote, sorted by position.
    pub fn diagnostics(&self) -> &[Vec<Diagnostic>] {
        &self.diagnostics
    }

    /// [`Checked::diagnostics`], owned.
    pub fn into_diagnostics(self) -> Vec<Vec<Diagnostic>> {
        self.diagnostics
    }

    /// The inputs, in the order they were added.
    pub fn inputs(&self) -> &[Input] {
        &self.inputs
    }

    /// Each input with its diagnostics.
    pub fn reports(&self) -> impl Iterator<Item = (&Input, &[Diagnostic])> {
        self.inputs
            .iter()
            .zip(self.diagnostics.iter().map(Vec::as_slice))
    }

    #[cfg(feature = "build")]
    /// Every diagnostic rendered as rustc renders its own (`color` adds ANSI
    /// styles), input by input.
    pub fn render(&self, color: bool) -> String {
        self.reports()
            .filter(|(_, d)| !d.is_empty())
            .map(|(i, d)| render(i.source(), d, color))
            .collect()
    }

    /// The checked IR of each input (what the emitter and the interpreter
    /// run on), or `None` when the program has errors.
    pub fn ir(&self) -> Option<&[sema::ir::Program]> {
        self.ok.then_some(self.ir.as_slice())
    }

    /// The IR of each input, whatever could be checked, also when the
    /// program has errors (an input with syntax errors has an empty one).
    /// For tools that show what the checker knows (the language server's
    /// hover); never emit code from it: use [`Checked::ir`].
    pub fn partial_ir(&self) -> &[sema::ir::Program] {
        &self.ir
    }

    /// What every name of the program names ([`crate::ir::Resolutions`],
    /// in the positions of the files the user wrote), when asked for by
    /// [`Program::resolutions`]; an input with syntax errors has no names.
    pub fn resolutions(&self) -> Option<&crate::ir::Resolutions> {
        self.resolutions.as_ref()
    }

    /// The syntax tree of each input's IL text (partial where it has syntax
    /// errors), in the positions of [`Input::il_text`].
    pub fn syntax(&self) -> &[crate::ast::CompilationUnit] {
        &self.units
    }

    /// Free the syntax trees ([`Checked::syntax`] is empty after this): a
    /// front end that only emits code needs the IR alone, and the tree is
    /// about a quarter of the memory of a checked program.
    pub fn drop_syntax(&mut self) {
        self.units = Vec::new();
    }

    /// [`Checked::ir`], owned.
    pub fn into_ir(self) -> Result<Vec<sema::ir::Program>, Vec<Vec<Diagnostic>>> {
        if self.ok {
            Ok(self.ir)
        } else {
            Err(self.diagnostics)
        }
    }

    /// The Rust items of each input, or `None` when the program has errors.
    pub fn emit(&self, opts: crate::EmitOptions) -> Option<Vec<Emitted<'_>>> {
        let ir = self.ir()?;
        Some(
            self.inputs
                .iter()
                .zip(ir)
                .zip(&self.diagnostics)
                .map(|((input, p), d)| {
                    let (text, markers) = emit::program_marked(p, opts);
                    Emitted {
                        input,
                        markers: (text.len(), markers),
                        text,
                        warnings: d.clone(),
                        pous: p.pous.iter().map(|p| p.name.clone()).collect(),
                    }
                })
                .collect(),
        )
    }
}

#[cfg(feature = "build")]
impl Checked {
    /// The text of each input's `.rs` file, with its IL lines as comments
    /// (what build.rs writes and `ilc emit` prints), or `None` when the
    /// program has errors.
    pub fn files(&self, opts: crate::EmitOptions) -> Option<Vec<String>> {
        let opts = emit::Options {
            line_markers: true,
            ..opts
        };
        Some(self.emit(opts)?.iter().map(Emitted::file_text).collect())
    }
}

/// The Rust generated from one input.
#[derive(Debug)]
pub struct Emitted<'c> {
    input: &'c Input,
    /// The items (Rust text, laid out): user types, one struct and impl per
    /// POU, configurations. `il!` parses it into tokens once; build.rs and
    /// `ilc emit` write it as it is.
    pub text: String,
    /// The input's warnings (there are no errors when code is emitted).
    pub warnings: Vec<Diagnostic>,
    /// The names of the POUs, as declared.
    pub pous: Vec<String>,
    /// The length of `text` as emitted and where its line markers start: the
    /// file writer uses them when `text` still has that length and each
    /// offset still holds a marker (`text` is public), else it searches.
    /// Without the `build` feature there is no file writer (`il!` only).
    #[cfg_attr(not(feature = "build"), allow(dead_code))]
    markers: (usize, Vec<usize>),
}

impl Emitted<'_> {
    /// The markers' offsets, if `text` has the length it was emitted with.
    #[cfg(feature = "build")]
    fn markers(&self) -> Option<&[usize]> {
        (self.text.len() == self.markers.0).then_some(&self.markers.1[..])
    }

    /// The input this code was generated from.
    pub fn input(&self) -> &Input {
        self.input
    }
}

#[cfg(feature = "build")]
impl Emitted<'_> {
    /// The text of the `.rs` file: `@generated`, and, when the
    /// text was emitted with [`EmitOptions::line_markers`](crate::EmitOptions), each IL
    /// line's source as a comment above the code it became (for an XML
    /// project, numbered by its XML lines).
    pub fn file_text(&self) -> String {
        match self.input {
            Input::Il(f) => {
                file::format_file_with(&f.name, &self.text, self.markers(), None, |n| {
                    (n, f.line_text(n))
                })
            }
            Input::Snippet(s) => {
                file::format_file_with(&s.file.name, &self.text, self.markers(), None, |n| {
                    (s.line_of(n), s.il.line_text(n))
                })
            }
            Input::Exp(i) => {
                let lines = i.exp_lines();
                file::format_file_with(&i.exp.name, &self.text, None, Some("EXP"), |n| {
                    let shown = lines.get(n.wrapping_sub(1)).copied().unwrap_or(0);
                    (shown, i.il.line_text(n))
                })
            }
            Input::PlcOpen(i) => {
                let lines = i.xml_lines();
                file::format_file_with(&i.xml.name, &self.text, None, Some("XML"), |n| {
                    let shown = lines.get(n.wrapping_sub(1)).copied().unwrap_or(0);
                    (shown, i.il.line_text(n))
                })
            }
        }
    }
}
