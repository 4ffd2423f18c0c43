//! The sources a build reads: IL files and PLCopen XML files, checked and
//! compiled together as one program, with every diagnostic pointing into
//! the file the user wrote.

use crate::compile::{compile_all_tokens, format_file, format_file_with};
use crate::diag::{Diagnostic, SourceFile};
use crate::plcopen::Import;

/// One source file of a program.
#[derive(Clone, Debug)]
pub enum Input {
    /// IL text.
    Il(SourceFile),
    /// A PLCopen TC6 XML project, translated to IL.
    PlcOpen(Box<Import>),
}

impl Input {
    /// An IL source.
    pub fn il(file: SourceFile) -> Input {
        Input::Il(file)
    }

    /// A PLCopen XML source (translated now; XML errors are kept as
    /// diagnostics of the input).
    pub fn plcopen(file: SourceFile) -> Input {
        Input::PlcOpen(Box::new(Import::new(file)))
    }

    /// PLCopen XML when the name ends in `.xml` (any case), IL otherwise.
    pub fn by_extension(file: SourceFile) -> Input {
        if is_xml_name(&file.name) {
            Input::plcopen(file)
        } else {
            Input::il(file)
        }
    }

    /// The file as the user wrote it: what diagnostics point into.
    pub fn source(&self) -> &SourceFile {
        match self {
            Input::Il(f) => f,
            Input::PlcOpen(i) => &i.xml,
        }
    }

    /// The IL text that is compiled.
    pub fn il_text(&self) -> &SourceFile {
        match self {
            Input::Il(f) => f,
            Input::PlcOpen(i) => &i.il,
        }
    }

    /// Diagnostics of the IL text moved into [`Input::source`], with the
    /// input's own (import) diagnostics, sorted by position.
    pub fn finish(&self, diags: Vec<Diagnostic>) -> Vec<Diagnostic> {
        let mut out = match self {
            Input::Il(_) => diags,
            Input::PlcOpen(i) => {
                let mut out = i.diagnostics.clone();
                out.extend(diags.into_iter().map(|d| i.to_xml(d)));
                out
            }
        };
        out.sort_by_key(|d| (d.span.lo, d.span.hi));
        crate::diag::limit(&mut out);
        out
    }

    fn has_import_errors(&self) -> bool {
        match self {
            Input::Il(_) => false,
            Input::PlcOpen(i) => crate::diag::has_errors(&i.diagnostics),
        }
    }
}

/// Whether a file name ends in `.xml` (any case).
pub fn is_xml_name(name: &str) -> bool {
    std::path::Path::new(name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}

/// Every diagnostic of several inputs checked as one program, one list per
/// input, each in its input's own positions ([`crate::check_sources`] for
/// mixed IL and PLCopen inputs).
pub fn check_inputs(inputs: &[Input]) -> Vec<Vec<Diagnostic>> {
    let files: Vec<SourceFile> = inputs.iter().map(|i| i.il_text().clone()).collect();
    crate::check_sources(&files)
        .into_iter()
        .zip(inputs)
        .map(|(d, i)| i.finish(d))
        .collect()
}

/// Compile several inputs as one program ([`crate::compile_all_to_files`]
/// for mixed IL and PLCopen inputs): one formatted `.rs` text and the
/// warnings per input, or the diagnostics of every input that has any
/// (index, diagnostics). The code generated from an XML file names its XML
/// lines in its line comments.
#[allow(clippy::type_complexity)]
pub fn compile_inputs(
    inputs: &[Input],
) -> Result<Vec<(String, Vec<Diagnostic>)>, Vec<(usize, Vec<Diagnostic>)>> {
    compile_inputs_with(inputs, crate::emit::Options::default())
}

/// [`compile_inputs`] with emitter options (e.g. `serde`; line markers are
/// always on for files).
#[allow(clippy::type_complexity)]
pub fn compile_inputs_with(
    inputs: &[Input],
    opts: crate::emit::Options,
) -> Result<Vec<(String, Vec<Diagnostic>)>, Vec<(usize, Vec<Diagnostic>)>> {
    let files: Vec<SourceFile> = inputs.iter().map(|i| i.il_text().clone()).collect();
    let compiled = compile_all_tokens(&files, opts);
    let import_errors = inputs.iter().any(Input::has_import_errors);
    match compiled {
        Ok(per_file) if !import_errors => Ok(per_file
            .into_iter()
            .zip(inputs)
            .map(|((tokens, warnings), input)| {
                let code = match input {
                    Input::Il(f) => format_file(f, &tokens),
                    Input::PlcOpen(i) => {
                        let lines = i.xml_lines();
                        format_file_with(&i.xml.name, &tokens, Some("XML"), |n| {
                            let shown = lines.get(n.wrapping_sub(1)).copied().unwrap_or(0);
                            (shown, i.il.line_text(n))
                        })
                    }
                };
                (code, input.finish(warnings))
            })
            .collect()),
        Ok(per_file) => Err(per_file
            .into_iter()
            .zip(inputs)
            .enumerate()
            .map(|(k, ((_, w), input))| (k, input.finish(w)))
            .filter(|(_, d)| !d.is_empty())
            .collect()),
        Err(per_file) => {
            let mut by_index: Vec<Vec<Diagnostic>> = vec![Vec::new(); inputs.len()];
            for (k, d) in per_file {
                if let Some(slot) = by_index.get_mut(k) {
                    *slot = d;
                }
            }
            Err(by_index
                .into_iter()
                .zip(inputs)
                .enumerate()
                .map(|(k, (d, input))| (k, input.finish(d)))
                .filter(|(_, d)| !d.is_empty())
                .collect())
        }
    }
}
