//! PLCopen TC6 XML import: the interchange format of Beremiz, OpenPLC and
//! CODESYS.
//!
//! [`Import::new`] reads a `<project>` and writes one IL source text holding
//! its data types (`TYPE ... END_TYPE`), the POUs whose body is `<IL>` (their
//! interface from the XML's variable declarations) and its configurations.
//! POUs in ST, FBD, LD or SFC are reported by name (a warning, IL0203) and
//! left out. The IL text goes through the normal pipeline; every diagnostic
//! is then moved back into the XML text ([`Import::to_xml`]), so messages
//! quote the XML file's own lines and columns.
//!
//! A `VAR_EXTERNAL CONSTANT` that names exactly one `VAR_GLOBAL CONSTANT` of
//! the project's configurations becomes a local `VAR CONSTANT` with the
//! global's initial value (the checker does not translate `VAR_EXTERNAL`
//! yet, and a constant cannot differ between the two). A configuration
//! whose program instances run a POU that was not translated is left out
//! with a warning (IL0204).
//!
//! A source is XML by its text ([`crate::pipeline::is_xml`]: it starts
//! with `<`), or by a `.xml` name; a LogicLab root (`<plcProject>`,
//! `<plcLibrary>`) goes to [`crate::logiclab`], with the same parser and
//! map; XML whose root is neither is one error (IL0202) naming its root.
//!
//! Reading XML is the `plcopen` feature (roxmltree and the translation): on
//! by default in il-codegen, off by default in il-macros (an `il!` user who
//! reads XML names it); without it, an XML source is one error (IL0210)
//! saying how to turn it on.

#[cfg(feature = "plcopen")]
mod limits;
pub(crate) mod map;
#[cfg(feature = "plcopen")]
pub(crate) mod nodes;
#[cfg(feature = "plcopen")]
pub(crate) mod text;
#[cfg(feature = "plcopen")]
pub(crate) mod translate;
#[cfg(feature = "plcopen")]
pub(crate) mod validate;

pub use map::SpanMap;

use std::collections::HashMap;

#[cfg(feature = "plcopen")]
use crate::ast::Span;
use crate::diag::{Diagnostic, SourceFile};

/// The codes of the PLCopen import.
pub mod codes {
    crate::diag::codes::codes! {
    MALFORMED_XML = "IL0201", "malformed XML",
        "The file is not well-formed XML, so it cannot be read as a PLCopen project. The message gives the line and column where the XML parser stopped.\n\n    <pou name=\"Main\" pouType=\"program\">\n      <body><IL><xhtml:p>LD a</IL></body>   <!-- </xhtml:p> missing -->";
    BAD_PROJECT = "IL0202", "not a valid PLCopen project",
        "The XML is well-formed but is not a PLCopen TC6 project, or lacks something one must have. A source whose text starts with `<` (after a byte order mark and blank space) is read as XML whatever its name, so another tool's XML (a SoMachine Basic `.smbp`, a TwinCAT `.TcPOU`) gets this one error, which names its root element and namespace: the compiler reads IL text, PLCopen TC6 projects, whose root is `<project>` in PLCopen's namespace (`http://www.plcopen.org/xml/tc6_0201`, `tc6_0200`) or in none, and LogicLab / Arduino PLC IDE projects and libraries (`<plcProject>`, `<plcLibrary>`: IL0420 ...). Export such a program as PLCopen XML or as IL text. Inside a project, the error is a POU without `name` or `pouType`, a variable without `<type>`, a FUNCTION without `<returnType>`.\n\n    <?xml version=\"1.0\" encoding=\"utf-8\"?>\n    <ProjectDescriptor>   <!-- SoMachine Basic's root, not PLCopen's <project> -->\n\n    <pou name=\"Main\">   <!-- pouType=\"program\" missing -->";
    NOT_IL = "IL0203", "POU body not in IL",
        "Only POUs whose body is Instruction List (`<body><IL>`) are translated. A POU in Structured Text, FBD, LD or SFC is left out with this warning; the other POUs still compile. A POU that uses a left-out one gets an `unknown type` error.\n\n    <pou name=\"CounterST\" pouType=\"functionBlock\">\n      <body><ST><xhtml:p>Cnt := Cnt + 1;</xhtml:p></ST></body>";
    NOT_TRANSLATED = "IL0204", "PLCopen element left out",
        "A part of the project is left out, with this warning: actions and transitions of a POU, access variables, and a configuration whose program instance runs a POU that was not translated (because its body is not IL).\n\n    <task name=\"main\" priority=\"1\" interval=\"T#10ms\">\n      <pouInstance name=\"prg\" typeName=\"MainFBD\"/>   <!-- MainFBD's body is FBD -->";
    UNTRANSLATABLE = "IL0205", "PLCopen element cannot be translated",
        "The project uses something IL has no equivalent for, e.g. a `<pointer>` type.\n\n    <variable name=\"p\"><type><pointer><baseType><INT/></baseType></pointer></type></variable>";
    BAD_ATTRIBUTE = "IL0206", "invalid attribute value",
        "An attribute that becomes part of the IL text holds something it cannot: a name that is not an IEC identifier (letters, digits and single `_`, not starting with a digit, not a keyword, at most 255 characters), an initial value that is not one literal or name, a bound, length or priority that is not a number, an address that is not a direct address, a task interval that is not a duration. The element (a variable, type, POU, task ...) is left out; nothing of the value reaches the IL text.\n\n    <variable name=\"x; END_VAR\"><type><INT/></type></variable>\n    <pou name=\"\" pouType=\"program\">   <!-- empty name -->";
    TOO_DEEP = "IL0207", "PLCopen element nested too deep",
        "Types and values nest at most 64 levels deep (`<array>` in `<array>`, `<struct>` in `<struct>`, `<arrayValue>` in `<arrayValue>` ...). Declare the inner levels as named data types and refer to them with `<derived>`.\n\n    <type><array><dimension lower=\"0\" upper=\"1\"/><baseType><array> ... (65 levels)";
    TOO_COMPLEX = "IL0208", "XML element too complex",
        "An element has more than 128 attributes, or more than 64 namespace declarations (`xmlns`, `xmlns:p`) are in scope at once. Reading such XML costs time that grows with the square of its size, so the file is refused before it is read; no PLCopen project needs this many.\n\n    <variable name=\"x\" a1=\"\" a2=\"\" ... a129=\"\">";
    BODY_ESCAPES = "IL0209", "IL body reaches outside its POU",
        "The text of an `<IL>` body is copied into the POU as it is, so it must not end the POU (`END_PROGRAM`, `END_FUNCTION_BLOCK` ...), start another POU, a `TYPE` or a `CONFIGURATION`, or open a comment `(*` that it does not close (which would swallow what follows). The POU is left out.\n\n    <IL><xhtml:p>LD a\n    END_PROGRAM\n    PROGRAM Other ...</xhtml:p></IL>";
    NOT_BUILT = "IL0210", "PLCopen XML import not built in",
        "An XML source (a PLCopen project: its text starts with `<`, or its name ends in `.xml`) reached a build of the compiler without its `plcopen` feature, which reads XML. `il-codegen` (build.rs, `ilc`) has the feature by default; `il-macros` leaves it out by default, so that the many crates whose `il!` calls read only IL compile no XML parser. A crate that reads an XML file in `il!` names the feature:\n\n    il-macros = { version = \"0.1\", features = [\"plcopen\"] }";
    }
}
pub use codes::CODES;

#[cfg(feature = "plcopen")]
use codes::{MALFORMED_XML, TOO_COMPLEX};

/// Longest identifier the import accepts: far above any real project, small
/// enough that quoting one in a message stays readable (a longer word in a
/// diagnostic is not looked up among the POUs left out).
pub(crate) const MAX_NAME: usize = 255;

#[cfg(feature = "plcopen")]
use translate::Translation;

/// What an import made of the XML (without the `plcopen` feature, only the
/// error that says so).
#[cfg(not(feature = "plcopen"))]
struct Translation {
    text: String,
    map: SpanMap,
    diags: Vec<Diagnostic>,
    pous: Vec<PouInfo>,
    folders: Vec<(std::ops::Range<usize>, String)>,
    globals: std::collections::HashSet<String>,
}

/// What happened to one POU of the project.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PouInfo {
    /// The POU's name, as in the XML.
    pub name: String,
    /// `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION`.
    pub kind: &'static str,
    /// The body's language as TC6 names it: `IL`, `ST`, `FBD`, `LD`, `SFC`.
    pub language: String,
    /// Whether it is part of the IL text (only IL bodies are).
    pub translated: bool,
}

/// A PLCopen XML file translated to IL.
#[derive(Clone, Debug)]
pub struct Import {
    /// The XML file as read: what diagnostics point into.
    pub xml: SourceFile,
    /// The IL text made from it, under the XML file's name.
    pub il: SourceFile,
    /// The import's own diagnostics (XML errors, POUs left out), in XML
    /// positions.
    pub diagnostics: Vec<Diagnostic>,
    /// Every POU of the project, translated or not, in document order.
    pub pous: Vec<PouInfo>,
    /// Where the bytes of `il` came from in `xml`.
    pub map: SpanMap,
    /// The POUs left out: one look-up per diagnostic, not a scan of every
    /// POU.
    left_out: LeftOut,
    /// XML ranges of elements in a folder of the project's tree (LogicLab's
    /// workspace), with the folder's path, in document order.
    folders: Vec<(std::ops::Range<usize>, String)>,
    /// The upper-case names of the project's globals that are not
    /// CONSTANT, which LogicLab's POUs see without VAR_EXTERNAL: a FUNCTION
    /// naming one gets a note (IEC FUNCTIONs have no VAR_EXTERNAL).
    globals: std::collections::HashSet<String>,
    /// A Modicon M221 project or listing ([`Import::is_m221`]).
    m221: bool,
}

/// The POUs left out (not IL) by lower-case name, as an index into the
/// project's POUs. A look-up counts one step, for the one candidate a hash
/// look-up compares; whatever replaces it must count one per candidate
/// compared, so that a scan of every POU grows with the square of the
/// project in the scaling tests (`tests/all/plcopen_limits.rs`, which time nothing).
#[derive(Clone, Debug, Default)]
pub(crate) struct LeftOut(HashMap<String, usize>);

impl LeftOut {
    /// Note POU `k` named `name` (the first of a name is kept).
    pub(crate) fn note(&mut self, name: &str, k: usize) {
        self.0.entry(name.to_ascii_lowercase()).or_insert(k);
    }

    /// The POU named `name` (in any case), when it was left out.
    pub(crate) fn get(&self, name: &str) -> Option<usize> {
        crate::step_counter::add(1);
        self.0.get(&name.to_ascii_lowercase()).copied()
    }
}

/// A readable name for a TC6 body language.
pub(crate) fn language_name(tc6: &str) -> &'static str {
    match tc6 {
        "IL" => "Instruction List",
        "ST" => "Structured Text",
        "FBD" => "Function Block Diagram",
        "LD" => "Ladder Diagram",
        "SFC" => "Sequential Function Chart",
        // LogicLab's names (`<sourceCode type="...">`).
        "LD2" => "Ladder Diagram",
        "CFC" => "Continuous Function Chart",
        "EMBEDDED" => "code embedded in the target's firmware",
        _ => "another language",
    }
}

/// The byte offset of a 1-based line and character column.
#[cfg(feature = "plcopen")]
fn offset_of(text: &str, row: u32, col: u32) -> usize {
    let mut start = 0;
    for _ in 1..row {
        match text[start..].find('\n') {
            Some(k) => start += k + 1,
            None => return text.len(),
        }
    }
    let line = &text[start..];
    let line = &line[..line.find('\n').unwrap_or(line.len())];
    start
        + line
            .char_indices()
            .nth(col.saturating_sub(1) as usize)
            .map_or(line.len(), |(k, _)| k)
}

/// The text the XML parser reads: the file's, except that an XML
/// declaration after leading whitespace is blanked. XML (and roxmltree)
/// takes `<?xml` only as the very first characters, but editors and
/// concatenation leave blank lines before it, and the declaration says
/// nothing the import needs. Each of its characters becomes spaces of the
/// same length (line breaks stay), so every offset and line is the file's.
#[cfg(feature = "plcopen")]
fn parse_text(text: &str) -> std::borrow::Cow<'_, str> {
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let rest = body.trim_start_matches([' ', '\t', '\r', '\n']);
    let declaration = rest.len() < body.len()
        && rest
            .strip_prefix("<?xml")
            .is_some_and(|r| r.starts_with([' ', '\t', '\r', '\n']));
    let start = text.len() - rest.len();
    let end = declaration
        .then(|| rest.find("?>"))
        .flatten()
        .map(|k| start + k + 2);
    let Some(end) = end else {
        // No whitespace before it, or no declaration: the parser reads the
        // file as it is (and reports a declaration that never ends).
        return std::borrow::Cow::Borrowed(text);
    };
    let mut out = String::with_capacity(text.len());
    out.push_str(&text[..start]);
    for c in text[start..end].chars() {
        match c {
            '\n' | '\r' => out.push(c),
            _ => out.extend(std::iter::repeat_n(' ', c.len_utf8())),
        }
    }
    out.push_str(&text[end..]);
    std::borrow::Cow::Owned(out)
}

impl Import {
    /// Translate a PLCopen XML file. Never fails: a malformed file gives an
    /// import with an empty IL text and an error (IL0201) in `diagnostics`.
    pub fn new(xml: SourceFile) -> Import {
        let t = Self::translate(&xml);
        let m221 = cfg!(feature = "plcopen") && crate::m221::is_project(&xml.text);
        Self::of(xml, t, m221)
    }

    /// A Modicon M221 / TwidoSuite Instruction List listing (the text the
    /// IDE shows and exports, `--dialect m221`), translated to IEC IL as an
    /// `.smbp` project's rungs are ([`crate::m221`]); `xml` is then the
    /// listing, which diagnostics point into.
    pub fn m221_listing(file: SourceFile) -> Import {
        #[cfg(feature = "plcopen")]
        let t = crate::m221::translate_listing(&file.name, &file.text);
        #[cfg(not(feature = "plcopen"))]
        let t = Self::not_built(&file, "an M221 listing (`--dialect m221`)");
        Self::of(file, t, true)
    }

    fn of(xml: SourceFile, t: Translation, m221: bool) -> Import {
        let il = SourceFile::new(xml.name.clone(), t.text);
        let mut left_out = LeftOut::default();
        for (k, p) in t.pous.iter().enumerate().filter(|(_, p)| !p.translated) {
            left_out.note(&p.name, k);
        }
        Import {
            xml,
            il,
            diagnostics: t.diags,
            pous: t.pous,
            map: t.map,
            left_out,
            folders: t.folders,
            globals: t.globals,
            m221,
        }
    }

    /// Whether the source is a Modicon M221 program (an `.smbp` project or
    /// a listing), whose POUs run in order as one task.
    pub fn is_m221(&self) -> bool {
        self.m221
    }

    /// Without the `plcopen` feature: no IL, one error at the file's start.
    #[cfg(not(feature = "plcopen"))]
    fn translate(xml: &SourceFile) -> Translation {
        Self::not_built(xml, "XML (read as a PLCopen project)")
    }

    /// Without the `plcopen` feature: no IL, one error at the file's start.
    #[cfg(not(feature = "plcopen"))]
    fn not_built(xml: &SourceFile, what: &str) -> Translation {
        Translation {
            text: String::new(),
            map: SpanMap::default(),
            diags: vec![Diagnostic::not_built(
                codes::NOT_BUILT,
                xml,
                what,
                "XML",
                "plcopen",
            )],
            pous: Vec::new(),
            folders: Vec::new(),
            globals: Default::default(),
        }
    }

    #[cfg(feature = "plcopen")]
    fn translate(xml: &SourceFile) -> Translation {
        let opts = roxmltree::ParsingOptions {
            allow_dtd: false,
            ..roxmltree::ParsingOptions::default()
        };
        let parsed = parse_text(&xml.text);
        let parsed = match limits::check(&xml.text) {
            Some(e) => {
                Err(
                    Diagnostic::error(TOO_COMPLEX, Span::new(e.at.start, e.at.end), e.message)
                        .with_label(e.label),
                )
            }
            None => roxmltree::Document::parse_with_options(&parsed, opts).map_err(|e| {
                let pos = e.pos();
                // Offsets are the file's (see `parse_text`); a character
                // of a blanked declaration may be wider in the file.
                let mut at = offset_of(&parsed, pos.row, pos.col);
                while !xml.text.is_char_boundary(at) {
                    at -= 1;
                }
                let width = xml.text[at..].chars().next().map_or(0, char::len_utf8);
                let msg = e.to_string();
                // roxmltree ends its messages with "at ROW:COL"; the
                // rendered diagnostic shows the place itself.
                let msg = match msg.rfind(" at ") {
                    Some(k) if msg[k + 4..].contains(':') => msg[..k].to_string(),
                    _ => msg,
                };
                Diagnostic::error(
                    MALFORMED_XML,
                    Span::new(at, at + width),
                    format!("malformed XML: {msg}"),
                )
                .with_label("the XML parser stopped here")
            }),
        };
        match parsed {
            Ok(doc) => translate::translate(&doc, &xml.text),
            Err(d) => Translation {
                text: String::new(),
                map: SpanMap::default(),
                diags: vec![d],
                pous: Vec::new(),
                folders: Vec::new(),
                globals: Default::default(),
            },
        }
    }

    /// Move a diagnostic about the IL text into the XML text (primary and
    /// secondary spans); a name of a POU that was left out gets a note.
    pub fn to_xml(&self, mut d: Diagnostic) -> Diagnostic {
        let word = self.il.snippet(d.span).trim();
        if let Some(p) = Some(word)
            .filter(|w| w.len() <= MAX_NAME)
            .and_then(|w| self.left_out.get(w))
            .map(|k| &self.pous[k])
        {
            d.notes.push(format!(
                "`{}` is a {} of this project whose body is {} ({}); it was not translated",
                p.name,
                p.kind,
                language_name(&p.language),
                p.language
            ));
        }
        if d.code == "IL0101" && self.globals.contains(&word.to_ascii_uppercase()) {
            d.notes.push(format!(
                "`{word}` is a global of this project: a PROGRAM or FUNCTION_BLOCK sees it, a FUNCTION does not (IEC FUNCTIONs have no VAR_EXTERNAL): pass it as an input"
            ));
        }
        d.span = self.map.to_xml(d.span);
        // The ranges are elements of the document, in its order, none in
        // another: the last that starts at or before the place holds it or
        // none does (one search per diagnostic, not a scan of the folders).
        let at = d.span.lo as usize;
        let k = self.folders.partition_point(|(r, _)| r.start <= at);
        if let Some((_, folder)) = k
            .checked_sub(1)
            .and_then(|k| self.folders.get(k))
            .filter(|(r, _)| r.contains(&at))
        {
            d.notes.push(format!("in the project's folder `{folder}`"));
        }
        // An edit of the translated IL is no edit of the XML.
        d.fixes.clear();
        for (s, _) in &mut d.secondary {
            *s = self.map.to_xml(*s);
        }
        d
    }

    /// For each IL line (index 0 is line 1), the XML line it came from:
    /// the line of its first non-blank character.
    pub fn xml_lines(&self) -> Vec<usize> {
        let mut start = 0usize;
        self.il
            .text
            .split('\n')
            .map(|line| {
                crate::step_counter::add(1);
                let lead = line.len() - line.trim_start().len();
                let off = u32::try_from(start + lead).unwrap_or(u32::MAX);
                start += line.len() + 1;
                // Only the line: counting the column's characters would cost
                // the XML line's length per IL line (a body on one XML line).
                self.xml.line_of(self.map.offset_to_xml(off))
            })
            .collect()
    }
}

// The one import test that reads the lexer's tokens; the others, through
// the public API, are tests/all/plcopen_*.rs.
#[cfg(all(test, feature = "plcopen"))]
mod tests;
