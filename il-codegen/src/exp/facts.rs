//! What the import learns of the whole project before it writes any file's
//! IL: the globals of the global lists, which POU needs which, the task
//! configuration, the called programs and the IL actions ([`Facts`]). Kept
//! apart from the passes that fill it (`project.rs`, `config.rs`) and those
//! that read it (`write.rs`, `actions.rs`, `config.rs`), so none of them
//! imports another for it.

use std::collections::{BTreeSet, HashMap, HashSet};
use std::ops::Range;

use crate::ast::PouKind;

/// A `TASK` of the task configuration and the programs it calls.
#[derive(Clone, Debug)]
pub(super) struct Task {
    /// `TASK t (PRIORITY := 1, INTERVAL := T#200ms);`
    pub(super) decl: Range<usize>,
    pub(super) name: String,
    pub(super) programs: Vec<(String, String, Range<usize>)>,
}

/// A global variable of a global variable list.
#[derive(Clone, Debug)]
pub(super) struct Global {
    pub(super) name: String,
    pub(super) at: Option<String>,
    /// Type and initial value as IL text (constants in bounds replaced).
    pub(super) ty: String,
    pub(super) init: Option<String>,
    pub(super) constant: bool,
    pub(super) retain: bool,
    /// Where it is declared: import and range in its `.EXP` text, and
    /// that file's name and line (for the note of a diagnostic about it
    /// in the CONFIGURATION, which another file may hold).
    pub(super) import: usize,
    pub(super) range: Range<usize>,
    pub(super) file: String,
    pub(super) line: usize,
}

/// What the IL text of every file needs to know of the whole project.
#[derive(Debug, Default)]
pub(super) struct Facts {
    pub(super) globals: Vec<Global>,
    /// Integer constants by upper-case name: their literal.
    pub(super) constants: HashMap<String, String>,
    /// Per IL POU (upper-case name): the globals it needs, by index.
    pub(super) needs: HashMap<String, BTreeSet<usize>>,
    /// The import that writes the CONFIGURATION.
    pub(super) holder: Option<usize>,
    /// The task configuration: its import, object and tasks.
    pub(super) tasks: Option<(usize, usize, Vec<Task>)>,
    /// Whether the project has a PROGRAM PLC_PRG.
    pub(super) plc_prg: bool,
    /// IL PROGRAMs that another POU calls (`CAL Prog`, `CAL Prog.Action`),
    /// by upper-case name: CODESYS's programs are one instance each, which
    /// any POU may call. Each is written as a FUNCTION_BLOCK with one
    /// global instance of its name; a task runs it through a PROGRAM
    /// `Name_RUN` that calls that instance.
    pub(super) called: HashSet<String>,
    /// The IL actions of IL function blocks: upper-case block name →
    /// upper-case action names.
    pub(super) actions: HashMap<String, Vec<String>>,
}

impl Facts {
    /// The globals IL POU `name` needs.
    pub(super) fn needed_by(&self, name: &str) -> impl Iterator<Item = &Global> {
        self.needs
            .get(&name.to_ascii_uppercase())
            .into_iter()
            .flatten()
            .map(|&g| &self.globals[g])
    }

    /// Whether `name` is a PROGRAM that other POUs call (see `called`).
    pub(super) fn is_called(&self, name: &str) -> bool {
        self.called.contains(&name.to_ascii_uppercase())
    }

    /// Whether block `ty` (upper case) has an IL action named `action`.
    pub(super) fn has_action(&self, ty: &str, action: &str) -> bool {
        self.actions
            .get(ty)
            .is_some_and(|a| a.iter().any(|n| n.eq_ignore_ascii_case(action)))
    }

    /// The value of an integer global constant (`MAX_PUMPS` → `3`).
    pub(super) fn constant_value(&self, name: &str) -> Option<&str> {
        self.constants
            .get(&name.to_ascii_uppercase())
            .map(String::as_str)
    }

    /// The VAR_EXTERNAL (and local `VAR CONSTANT`) blocks IL POU `name`
    /// needs for the globals it names, as IL text ("" when none).
    pub(super) fn implicit_blocks(&self, name: &str, kind: PouKind) -> String {
        let Some(needs) = self.needs.get(&name.to_ascii_uppercase()) else {
            return String::new();
        };
        let (mut ext, mut cons) = (String::new(), String::new());
        for &g in needs {
            let g = &self.globals[g];
            match (&g.init, g.constant) {
                (Some(init), true) => {
                    cons.push_str(&format!("\t{} : {} := {};\n", g.name, g.ty, init));
                }
                _ if kind != PouKind::Function => {
                    ext.push_str(&format!("\t{} : {};\n", g.name, g.ty));
                }
                _ => {}
            }
        }
        let mut out = String::new();
        if !ext.is_empty() {
            out.push_str("VAR_EXTERNAL\n");
            out.push_str(&ext);
            out.push_str("END_VAR\n");
        }
        if !cons.is_empty() {
            out.push_str("VAR CONSTANT\n");
            out.push_str(&cons);
            out.push_str("END_VAR\n");
        }
        out
    }
}
