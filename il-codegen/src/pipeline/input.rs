//! The sources a build reads: IL files and PLCopen XML files, checked and
//! compiled together as one program, with every diagnostic pointing into
//! the file the user wrote.

use super::snippet::Snippet;
use crate::diag::{Diagnostic, SourceFile};
use crate::exp::Import as ExpImport;
use crate::plcopen::Import;

/// One source file of a program.
#[derive(Clone, Debug)]
pub enum Input {
    /// IL text.
    Il(SourceFile),
    /// An XML project translated to IL: PLCopen TC6, or a LogicLab /
    /// Arduino PLC IDE project (`<plcProject>`, [`crate::logiclab`]), or
    /// an M221 project (`.smbp`), by its root; or an M221 text listing
    /// ([`Input::m221`]), translated the same way.
    PlcOpen(Box<Import>),
    /// A bare instruction list, compiled as the body of a PROGRAM.
    Snippet(Box<Snippet>),
    /// A CODESYS V2.3 / TwinCAT 2 export (`.EXP`), translated to IL with
    /// the program's other exports.
    Exp(Box<ExpImport>),
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

    /// A Modicon M221 / TwidoSuite Instruction List listing, translated to
    /// IEC IL as an `.smbp` project is ([`Import::m221_listing`]).
    pub fn m221(file: SourceFile) -> Input {
        Input::PlcOpen(Box::new(Import::m221_listing(file)))
    }

    /// A bare instruction list (no POU around it), compiled as the body of
    /// a PROGRAM named after the file (`ilc check --snippet`).
    pub fn snippet(file: SourceFile) -> Input {
        Input::Snippet(Box::new(Snippet::new(file)))
    }

    /// A CODESYS export (`.EXP`), cut into its objects now; the program
    /// translates all its exports together when it is checked.
    pub fn exp(file: SourceFile) -> Input {
        Input::Exp(Box::new(ExpImport::new(file)))
    }

    /// PLCopen XML when the file is XML ([`is_xml`]: its text starts with
    /// `<`, or its name ends in `.xml`), a CODESYS export when it is one
    /// ([`crate::exp::is_exp`]: a `.exp` name or an object header first),
    /// IL otherwise.
    pub fn by_content(file: SourceFile) -> Input {
        if is_xml(&file.name, &file.text) {
            Input::plcopen(file)
        } else if crate::exp::is_exp(&file.name, &file.text) {
            Input::exp(file)
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
            Input::Exp(i) => &i.exp,
        }
    }

    /// [`Input::source`], to change what reading it reported.
    pub(crate) fn source_mut(&mut self) -> &mut SourceFile {
        match self {
            Input::Il(f) => f,
            Input::PlcOpen(i) => &mut i.xml,
            Input::Snippet(s) => &mut s.file,
            Input::Exp(i) => &mut i.exp,
        }
    }

    /// The IL text that is compiled.
    pub fn il_text(&self) -> &SourceFile {
        match self {
            Input::Il(f) => f,
            Input::PlcOpen(i) => &i.il,
            Input::Snippet(s) => &s.il,
            Input::Exp(i) => &i.il,
        }
    }

    /// A span of the IL text in [`Input::source`], the file the user wrote.
    pub fn to_source(&self, span: crate::ast::Span) -> crate::ast::Span {
        match self {
            Input::Il(_) => span,
            Input::PlcOpen(i) => i.map.to_xml(span),
            Input::Snippet(s) => s.to_file(span),
            Input::Exp(i) => i.map.to_xml(span),
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
            Input::Exp(i) => {
                let mut out = i.diagnostics.clone();
                out.extend(diags.into_iter().map(|d| i.to_exp(d)));
                out
            }
        };
        out.extend(self.source().read_diagnostics.iter().cloned());
        out.sort_by_key(|d| (d.span.lo, d.span.hi));
        crate::diag::limit(&mut out);
        out
    }
}

/// Whether a source is XML, by its text: it starts with `<` after an
/// optional byte order mark and whitespace. No IL text does (it starts with
/// a keyword, a comment or a pragma), and XML always does (a declaration
/// `<?xml`, a comment or the root element), so PLC tools' own extensions
/// (`.smbp`, `.plcprj`, `.TcPOU`) and a project saved as `.il` or `.txt`
/// are read for what they are. A name ending in `.xml` (any case) is XML
/// whatever its text, as before: an empty or broken `.xml` file gets the XML
/// parser's one error, not the IL parser's many.
pub fn is_xml(name: &str, text: &str) -> bool {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.trim_start_matches([' ', '\t', '\r', '\n'])
        .starts_with('<')
        || std::path::Path::new(name)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}

#[cfg(test)]
mod tests {
    use super::is_xml;

    #[test]
    fn xml_is_known_by_its_first_character() {
        for text in [
            "<?xml version=\"1.0\"?><project/>",
            "\u{feff}<?xml version=\"1.0\"?><project/>",
            "\u{feff} \r\n\t<?xml version=\"1.0\"?><project/>",
            "\n\n<project/>",
            "<!-- exported --><project/>",
        ] {
            for name in ["a.smbp", "a.il", "a.txt", "a.TcPOU", "a", "a.xml"] {
                assert!(is_xml(name, text), "{name}: {text:?}");
            }
        }
        for text in [
            "PROGRAM p END_PROGRAM",
            "(* <project> *) PROGRAM p END_PROGRAM",
            "{extern} FUNCTION f : INT END_FUNCTION",
            "\u{feff}PROGRAM p END_PROGRAM",
            "",
        ] {
            assert!(!is_xml("a.il", text), "{text:?}");
            assert!(!is_xml("a.smbp", text), "{text:?}");
            // A `.xml` name is XML whatever its text.
            assert!(is_xml("A.XML", text), "{text:?}");
        }
    }
}
