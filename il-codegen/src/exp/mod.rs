//! CODESYS V2.3 / TwinCAT 2 `.EXP` import (the export format of CODESYS 2.3
//! and the IDEs built on it: WAGO, Beckhoff TwinCAT 2, OWEN, ABB ...).
//!
//! [`Import::new`] cuts a file into its objects (`split`); the objects of
//! every `.EXP` input of a program are then read together (`project`),
//! because a project is usually exported one object per file: its global
//! variable lists, constants and task configuration are the whole
//! project's. Each file becomes IL text ([`write`]) that goes through the
//! normal pipeline; a [`SpanMap`] moves every diagnostic back into the
//! `.EXP` file, at its own line and column.
//!
//! What CODESYS writes that the IL text needs said another way:
//! - a nested comment (`@NESTEDCOMMENTS := 'Yes'`) loses its inner
//!   delimiters, and `STRING(20)` is `STRING[20]` (both byte for byte);
//! - `END_STRUCT` before `END_TYPE` gets its `;`;
//! - global variable lists (no CONFIGURATION in a CODESYS project) become
//!   the VAR_GLOBALs of one generated CONFIGURATION, and every IL PROGRAM
//!   or FUNCTION_BLOCK that names a global gets the VAR_EXTERNAL that IEC
//!   asks for (a global CONSTANT becomes a local `VAR CONSTANT`, which a
//!   FUNCTION may use too, and its value replaces its name in array bounds);
//! - the task configuration (`RESOURCE ... END_RESOURCE`) is that
//!   CONFIGURATION's resource; without one, `PLC_PRG` runs every cycle;
//! - a POU whose body is not IL (ST, CFC, FBD, LD, SFC) keeps its interface
//!   (inputs, outputs, in-outs) and is host-provided, as an `{extern}`
//!   FUNCTION is, with one warning naming its language;
//! - libraries, visualisations, the PLC configuration and other objects
//!   that are no code are skipped ([`Import::objects`] lists them).

#[cfg(feature = "exp")]
mod actions;
#[cfg(feature = "exp")]
mod config;
#[cfg(feature = "exp")]
mod decls;
#[cfg(feature = "exp")]
mod facts;
#[cfg(feature = "exp")]
mod project;
#[cfg(feature = "exp")]
mod scan;
#[cfg(feature = "exp")]
mod split;
#[cfg(feature = "exp")]
mod write;

#[cfg(feature = "exp")]
pub(crate) use project::assemble;

/// Without the `exp` feature there is nothing to read together.
#[cfg(not(feature = "exp"))]
pub(crate) fn assemble(_: &mut [&mut Import]) {}

use std::ops::Range;

use crate::ast::PouKind;
#[cfg(feature = "exp")]
use crate::ast::Span;
use crate::diag::{Diagnostic, SourceFile};
use crate::plcopen::SpanMap;

/// The codes of the EXP import.
pub mod codes {
    crate::diag::codes::codes! {
    NOT_IL = "IL0401", "POU body not in IL: compiled as its interface",
        "A POU of a CODESYS export whose body is not Instruction List (Structured Text, CFC, FBD, LD or SFC) keeps its interface: its inputs, outputs and in-outs are compiled, so IL POUs can call it, and its body is not. In generated Rust it is host-provided, as an `{extern}` FUNCTION is: the crate supplies the body (see the guide, \"Bringing a project in\"); the interpreter (`ilc run`) runs its interface only. One warning per POU names the language.\n\n    FUNCTION_BLOCK Ramp\n    VAR_INPUT x : INT; END_VAR\n    (* @END_DECLARATION := '0' *)\n    y := y + x;          (* Structured Text *)\n    END_FUNCTION_BLOCK";
    UNKNOWN_HEADER = "IL0402", "unknown header in a CODESYS export",
        "CODESYS 2.3 writes each object of an export with header comments: `(* @NESTEDCOMMENTS := 'Yes' *)`, `(* @PATH := '...' *)`, `(* @OBJECTFLAGS := ... *)`, `(* @SYMFILEFLAGS := ... *)`, `(* @END_DECLARATION := '0' *)`, `(* @GLOBAL_VARIABLE_LIST := '...' *)`, `(* @OBJECT_END := '...' *)`, `(* @CONNECTIONS := ... *)`. A comment of the form `(* @NAME := ... *)` between or in objects with another name is not one of them: the file was edited, or comes from another tool. The header is ignored; the objects are still read.\n\n    (* @NESTEDCOMENTS := 'Yes' *)   (* misspelt *)";
    UNKNOWN_OBJECT = "IL0403", "text that starts no object of a CODESYS export",
        "Between objects, a CODESYS export holds only header comments and objects: a POU (`PROGRAM`, `FUNCTION`, `FUNCTION_BLOCK`, then its `ACTION`s), a `TYPE`, a global variable list (`VAR_GLOBAL`), the task configuration (`RESOURCE`), a library reference (`LIBRARY`), and objects that are no code (`PLC_CONFIGURATION`, `_WORKSPACE`, `_ALARMCONFIG`, visualisations ...). The line is skipped; the objects around it are still read.\n\n    END_FUNCTION_BLOCK\n    LD x        (* after the POU's end *)";
    TRUNCATED = "IL0404", "object of a CODESYS export cut short",
        "An object ends before its end keyword: the file ends, or the next object starts, before `END_PROGRAM`, `END_FUNCTION_BLOCK`, `END_FUNCTION`, `END_TYPE`, `END_ACTION`, `END_RESOURCE` or `END_LIBRARY`. The export was cut off or edited. The object is left out; the others are still checked.\n\n    FUNCTION_BLOCK Motor\n    VAR_INPUT on : BOOL; END_VAR\n    (* @END_DECLARATION := '0' *)\n    LD on\n    (* file ends here *)";
    MISMATCHED_END = "IL0405", "POU of a CODESYS export ended by another END_ keyword",
        "A POU ends with the END_ keyword of another kind of POU (`END_PROGRAM` after `FUNCTION_BLOCK`). The export was edited. The error is at the END_ keyword.\n\n    FUNCTION_BLOCK Motor\n    ...\n    END_PROGRAM";
    DUPLICATE_OBJECT = "IL0406", "two objects of a CODESYS project with one name",
        "Two objects of the project (in one `.EXP` file or in two) have the same name but different text: two POUs, two TYPEs, or two global variables. The second is left out, with this error at its name; the first is compiled. An object exported twice with the same text (as a project's objects are when exported under two names) is read once.\n\n    a.EXP: FUNCTION_BLOCK Motor ... END_FUNCTION_BLOCK\n    b.EXP: FUNCTION_BLOCK Motor ... (another body) END_FUNCTION_BLOCK";
    NOT_IEC_ADDRESS = "IL0408", "address of a CODESYS global that is no IEC address",
        "A global of a CODESYS export is located at an address the compiler does not bind: one whose size letter IEC 61131-3 does not have (OWEN's targets write `%IR3.0` for a REAL input), or a hierarchical one (`%IX1.0.3`, `%QW9.1.0`: module, channel ...); the compiler binds `%IXbyte.bit`, `%IXbit`, `%IBn`, `%IWn`, `%IDn`, `%ILn` and the same for %Q and %M. The variable is compiled as a global without an address, with this warning: the host reads or writes it as a field of the configuration, and binds it to the target's I/O itself.\n\n    VAR_GLOBAL\n        AI_0 AT %IR3.0 : REAL;\n    END_VAR";
    NOT_GLOBALS = "IL0409", "block of a CODESYS global variable list not compiled",
        "A global variable list of a CODESYS export is compiled as the VAR_GLOBAL blocks of the generated CONFIGURATION. Another block in it (CODESYS writes `VAR_CONFIG` in the object `Variable_Configuration`, which gives addresses to variables of program and block instances) is left out with this warning.\n\n    (* @GLOBAL_VARIABLE_LIST := 'Variable_Configuration' *)\n    VAR_CONFIG\n        PLC_PRG.motor.q AT %QX0.0 : BOOL;\n    END_VAR";
    NOT_BUILT = "IL0410", "CODESYS export import not built in",
        "A CODESYS V2.3 export (a `.exp` name, or text that starts with an object header such as `(* @NESTEDCOMMENTS := 'Yes' *)`) reached a build of the compiler without its `exp` feature, which reads exports. `il-codegen` (build.rs, `ilc`) has the feature by default; `il-macros` leaves it out by default, so that the many crates whose `il!` calls read only IL text do not compile the export reader. A crate that reads an export in `il!` names the feature:\n\n    il-macros = { version = \"0.1\", features = [\"exp\"] }";
    ACTION = "IL0407", "ACTION after a FUNCTION",
        "CODESYS 2.3 FUNCTION_BLOCKs and PROGRAMs can have actions (`ACTION name: ... END_ACTION` after the POU): code that runs on the POU's variables, called as `CAL inst.name` or, inside the POU, `CAL name`. A FUNCTION has no variables that last, so no actions: an ACTION after a FUNCTION is this error, at its `ACTION` keyword, and the rest of the project is still checked.\n\n    FUNCTION Twice : INT ... END_FUNCTION\n    ACTION Reset:\n    LD 0\n    ST Twice\n    END_ACTION";
    }
}
pub use codes::CODES;

/// The language of a POU body (CODESYS writes no marker for IL and ST:
/// a text body is ST when it has a statement's `;`, an assignment's `:=`
/// or a control keyword outside parentheses, IL otherwise).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Language {
    /// Instruction List.
    Il,
    /// Structured Text.
    St,
    /// Continuous Function Chart (`_CFC_BODY`).
    Cfc,
    /// Function Block Diagram (`_FBD_BODY`).
    Fbd,
    /// Ladder Diagram (`_LD_BODY`).
    Ld,
    /// Sequential Function Chart.
    Sfc,
}

impl Language {
    /// The language's name, for messages.
    pub fn name(self) -> &'static str {
        match self {
            Language::Il => "Instruction List",
            Language::St => "Structured Text",
            Language::Cfc => "Continuous Function Chart (CFC)",
            Language::Fbd => "Function Block Diagram (FBD)",
            Language::Ld => "Ladder Diagram (LD)",
            Language::Sfc => "Sequential Function Chart (SFC)",
        }
    }
}

/// What an object of an export is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ObjectKind {
    /// A PROGRAM, FUNCTION_BLOCK or FUNCTION.
    Pou(PouKind),
    /// `TYPE ... END_TYPE`.
    Types,
    /// A global variable list (`VAR_GLOBAL` blocks).
    Globals,
    /// The task configuration (`RESOURCE ... END_RESOURCE`).
    Tasks,
    /// An object that is no code, skipped (what it is, in words).
    Skipped(&'static str),
}

impl ObjectKind {
    #[cfg(feature = "exp")]
    fn describe(&self) -> String {
        match self {
            ObjectKind::Pou(k) => k.keyword().to_string(),
            ObjectKind::Types => "TYPE".into(),
            ObjectKind::Globals => "global variable list".into(),
            ObjectKind::Tasks => "task configuration".into(),
            ObjectKind::Skipped(w) => w.to_string(),
        }
    }
}

/// An `ACTION name: ... END_ACTION` after its POU.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Action {
    /// Its name.
    pub name: String,
    /// The `ACTION` keyword.
    pub keyword: Range<usize>,
    /// Its body.
    pub body: Range<usize>,
    /// `END_ACTION`.
    pub end: Range<usize>,
    /// The body's language.
    pub language: Language,
}

/// One object of an export, by byte ranges of the `.EXP` text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Object {
    /// What it is.
    pub kind: ObjectKind,
    /// Its name (a global variable list's from its header).
    pub name: String,
    /// Its folder in the project (`@PATH`, `\/K14`; empty at the top).
    pub path: String,
    /// `@NESTEDCOMMENTS := 'Yes'` (the default): comments nest.
    pub nested: bool,
    /// Headers to end.
    pub span: Range<usize>,
    /// The keyword that opens it (`FUNCTION_BLOCK`, `TYPE`, `VAR_GLOBAL`).
    pub keyword: Range<usize>,
    /// The declarations: from the keyword to `@END_DECLARATION` (a TYPE,
    /// a global list, a task configuration: all of it).
    pub decl: Range<usize>,
    /// A POU's body, after `@END_DECLARATION`.
    pub body: Option<Range<usize>>,
    /// The body's language.
    pub language: Language,
    /// The END_ keyword.
    pub end: Option<Range<usize>>,
    /// A POU's actions.
    pub actions: Vec<Action>,
}

/// A `.EXP` file read as objects and translated to IL.
#[derive(Clone, Debug)]
pub struct Import {
    /// The `.EXP` file as read: what diagnostics point into.
    pub exp: SourceFile,
    /// The IL text made from it.
    pub il: SourceFile,
    /// The import's own diagnostics, in `.EXP` positions.
    pub diagnostics: Vec<Diagnostic>,
    /// Where the bytes of `il` came from in `exp`.
    pub map: SpanMap,
    objects: Vec<Object>,
    /// Objects left out of the IL text (duplicates), by index.
    left_out: Vec<bool>,
    /// The diagnostics of reading the objects (before the project's).
    #[cfg_attr(not(feature = "exp"), allow(dead_code))]
    split_diags: Vec<Diagnostic>,
    /// IL ranges of globals declared in another file, with a note saying
    /// where (the generated CONFIGURATION holds the whole project's).
    foreign: Vec<(Range<usize>, String)>,
    /// The upper-case names of the project's globals that are not
    /// CONSTANT: a FUNCTION naming one gets a note (IEC FUNCTIONs have no
    /// VAR_EXTERNAL; CODESYS lets them read globals).
    globals: std::collections::HashSet<String>,
    /// The POUs of the libraries the project references, by upper-case
    /// name, with the library's file name (`BLINK` → `Util.lib`).
    library_pous: std::collections::HashMap<String, String>,
}

/// Whether a source is a CODESYS export: its name ends in `.exp` (any
/// case), or its first comment is an object header (`(* @NESTEDCOMMENTS`,
/// `(* @PATH`, `(* @GLOBAL_VARIABLE_LIST`).
pub fn is_exp(name: &str, text: &str) -> bool {
    if std::path::Path::new(name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("exp"))
    {
        return true;
    }
    let t = text.strip_prefix('\u{feff}').unwrap_or(text).trim_start();
    let Some(rest) = t.strip_prefix("(*") else {
        return false;
    };
    let rest = rest.trim_start();
    ["@NESTEDCOMMENTS", "@PATH", "@GLOBAL_VARIABLE_LIST"]
        .iter()
        .any(|h| rest.starts_with(h))
}

impl Import {
    /// Read an export's objects and translate them on their own (a program
    /// of several files translates them again, together: `assemble`).
    #[cfg(feature = "exp")]
    pub fn new(exp: SourceFile) -> Import {
        let (mut objects, split_diags) = split::split(&exp.text);
        for o in &mut objects {
            if let Some(b) = &o.body {
                o.language = write::language(&exp.text, b.clone(), o.nested);
            }
            for a in &mut o.actions {
                a.language = write::language(&exp.text, a.body.clone(), o.nested);
            }
        }
        let left_out = vec![false; objects.len()];
        let mut i = Import {
            il: SourceFile::new(exp.name.clone(), String::new()),
            exp,
            diagnostics: Vec::new(),
            map: SpanMap::default(),
            objects,
            left_out,
            split_diags,
            foreign: Vec::new(),
            globals: Default::default(),
            library_pous: Default::default(),
        };
        let mut one = [&mut i];
        assemble(&mut one);
        i
    }

    /// Without the `exp` feature: no IL, one error at the file's start.
    #[cfg(not(feature = "exp"))]
    pub fn new(exp: SourceFile) -> Import {
        let what = "a CODESYS export (.EXP)";
        let error = Diagnostic::not_built(codes::NOT_BUILT, &exp, what, "CODESYS export", "exp");
        Import {
            il: SourceFile::new(exp.name.clone(), String::new()),
            exp,
            diagnostics: vec![error],
            map: SpanMap::default(),
            objects: Vec::new(),
            left_out: Vec::new(),
            split_diags: Vec::new(),
            foreign: Vec::new(),
            globals: Default::default(),
            library_pous: Default::default(),
        }
    }

    /// The objects of the file, in order (skipped ones included: their
    /// kind says what they are).
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// Whether object `k` was left out (a duplicate of another).
    pub fn is_left_out(&self, k: usize) -> bool {
        self.left_out.get(k).copied().unwrap_or(false)
    }

    /// Move a diagnostic about the IL text into the `.EXP` text, with a
    /// note naming the object's folder (`@PATH`), or the file that declares
    /// a global of another file.
    pub fn to_exp(&self, mut d: Diagnostic) -> Diagnostic {
        let lo = d.span.lo as usize;
        if let Some((_, note)) = self.foreign.iter().find(|(r, _)| r.contains(&lo)) {
            d.notes.push(note.clone());
        }
        let word = self.il.snippet(d.span).trim();
        if d.code == "IL0101" && self.globals.contains(&word.to_ascii_uppercase()) {
            d.notes.push(format!(
                "`{word}` is a global of this project: a PROGRAM or FUNCTION_BLOCK sees it, a FUNCTION does not (IEC FUNCTIONs have no VAR_EXTERNAL): pass it as an input"
            ));
        }
        if matches!(d.code, "IL0101" | "IL0105" | "IL0114")
            && let Some(lib) = self.library_pous.get(&word.to_ascii_uppercase())
        {
            d.notes.push(format!(
                "`{word}` is a POU of the library `{lib}`, which this project references; the compiler has IEC's standard blocks and functions (il-std), not CODESYS's libraries: declare it with its interface as `{{extern}} FUNCTION_BLOCK {word}` (or `{{extern}} FUNCTION`), whose body the crate supplies, or add its IL source to the program"
            ));
        }
        d.span = self.map.to_xml(d.span);
        // The IL text is the export rewritten (`STRING(20)`, implicit
        // externals ...): an edit of it is no edit of the `.EXP` file.
        d.fixes.clear();
        if let Some(folder) = self.folder_at(d.span.lo) {
            d.notes.push(format!("in the project's folder `{folder}`"));
        }
        for (s, _) in &mut d.secondary {
            *s = self.map.to_xml(*s);
        }
        d
    }

    /// The project folder (`@PATH`, as `/K14/Pumps`) of the object at byte
    /// `at` of the `.EXP` text, when it is in one.
    pub fn folder_at(&self, at: u32) -> Option<String> {
        let at = at as usize;
        self.objects
            .iter()
            .find(|o| o.span.contains(&at) && !o.path.is_empty())
            .map(|o| o.path.replace("\\/", "/"))
    }

    /// For each IL line (index 0 is line 1), the `.EXP` line it came from.
    pub fn exp_lines(&self) -> Vec<usize> {
        let mut start = 0usize;
        self.il
            .text
            .split('\n')
            .map(|line| {
                let lead = line.len() - line.trim_start().len();
                let off = u32::try_from(start + lead).unwrap_or(u32::MAX);
                start += line.len() + 1;
                self.exp.line_of(self.map.offset_to_xml(off))
            })
            .collect()
    }

    /// A span of the `.EXP` text.
    #[cfg(feature = "exp")]
    fn span(r: &Range<usize>) -> Span {
        Span::new(r.start, r.end)
    }
}

#[cfg(all(test, feature = "exp"))]
mod tests;
