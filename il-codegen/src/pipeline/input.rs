//! The sources a build reads: IL files and PLCopen XML files, checked and
//! compiled together as one program, with every diagnostic pointing into
//! the file the user wrote.

use super::snippet::Snippet;
use crate::diag::{Diagnostic, SourceFile};
use crate::plcopen::Import;

/// One source file of a program.
#[derive(Clone, Debug)]
pub enum Input {
    /// IL text.
    Il(SourceFile),
    /// A PLCopen TC6 XML project, translated to IL.
    PlcOpen(Box<Import>),
    /// A bare instruction list, compiled as the body of a PROGRAM.
    Snippet(Box<Snippet>),
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

    /// A bare instruction list (no POU around it), compiled as the body of
    /// a PROGRAM named after the file (`ilc check --snippet`).
    pub fn snippet(file: SourceFile) -> Input {
        Input::Snippet(Box::new(Snippet::new(file)))
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
            Input::Snippet(s) => &s.file,
        }
    }

    /// The IL text that is compiled.
    pub fn il_text(&self) -> &SourceFile {
        match self {
            Input::Il(f) => f,
            Input::PlcOpen(i) => &i.il,
            Input::Snippet(s) => &s.il,
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
            Input::Snippet(s) => s.finish(diags),
        };
        out.sort_by_key(|d| (d.span.lo, d.span.hi));
        crate::diag::limit(&mut out);
        out
    }
}

/// Whether a file name ends in `.xml` (any case).
pub fn is_xml_name(name: &str) -> bool {
    std::path::Path::new(name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}
