//! The environment the checker works in: every POU's interface, the
//! resolved user types, and the names of FBs and types while they resolve.

use super::ir::{Field, Init, TypeDef, Var};
use super::types::{Name, Ty};
use crate::ast::{self, PouKind, Span};
use std::collections::{HashMap, HashSet};

/// The interfaces of every POU of the unit, by upper-case name.
pub(crate) struct Env {
    pub pous: rustc_hash::FxHashMap<String, PouSig>,
    pub types: TypeTables,
    /// Checked configurations, with the index of the declaring file.
    pub configs: Vec<(usize, super::ir::ConfigDef)>,
    /// Bytes of each user FB (`FB:NAME`) and STRUCT (`S:NAME`), for the
    /// large-array rules (see `heap_arrays.rs`).
    pub sizes: Sizes,
    /// The signatures of POUs declared again under a name already taken:
    /// their bodies are still checked (against their own declarations), so
    /// that a duplicate name does not hide the real errors in them.
    pub duplicates: Vec<PouSig>,
    /// Whether an FB (upper-case name) holds anything RETAIN, directly or in
    /// a nested instance: memoised, because instance trees share subtrees and
    /// an unmemoised walk is exponential in the nesting depth.
    pub holds_retain: std::cell::RefCell<HashMap<String, bool>>,
}

/// The sizes of the user FBs/PROGRAMs (`FB:NAME`) and STRUCTs (`S:NAME`).
pub(crate) type Sizes = HashMap<String, u64>;

/// Resolved user types.
#[derive(Default)]
pub(crate) struct TypeTables {
    /// STRUCT key → its fields.
    pub structs: HashMap<String, Vec<Field>>,
    /// Enumeration key → (name as declared, shared with every constant and
    /// type of it, values).
    pub enums: HashMap<String, (Name, Vec<String>)>,
    /// Items to emit, with the index of the declaring file.
    pub defs: Vec<(usize, TypeDef)>,
}

impl TypeTables {
    /// The enumeration that has a value `name`, if exactly one has.
    pub fn enum_of_value(&self, name: &str) -> Option<(Name, String)> {
        let mut found = self.enums.values().filter_map(|(ty, vals)| {
            vals.iter()
                .find(|v| v.eq_ignore_ascii_case(name))
                .map(|v| (ty.clone(), v.clone()))
        });
        let first = found.next()?;
        found.next().is_none().then_some(first)
    }
}

/// Every name a declaration can refer to, across all files.
pub(crate) struct Names<'u> {
    /// POU key → (name as declared, kind).
    pub pous: HashMap<String, (String, PouKind)>,
    /// User type key → its declaration.
    pub types: HashMap<String, &'u ast::TypeDecl>,
    /// User type key → what it resolved to: filled once for every TYPE
    /// declaration before any POU is checked (`typedecls.rs`), so that a use
    /// reads the result instead of resolving (and reporting) again.
    pub resolved: std::cell::RefCell<HashMap<String, Resolved>>,
    pub(crate) depth: std::cell::Cell<u32>,
}

/// A TYPE declaration, resolved and checked.
pub(crate) struct Resolved {
    /// `None` after an error (reported at the declaration).
    pub ty: Option<Ty>,
    /// Subrange bounds, its own or those of the type it renames.
    pub range: Option<(i128, i128)>,
    /// The initial value its variables take when they give none: its own
    /// (`TYPE T : INT := 5`) or that of the type it renames.
    pub init: Option<Init>,
}

pub(crate) struct PouSig {
    pub kind: PouKind,
    pub name: String,
    pub vars: Vec<Var>,
    /// Name (any case) → index into `vars`.
    pub index: super::name_index::NameIndex,
    pub ret: Option<Ty>,
    /// Index of the source file that declares it.
    pub file: usize,
    /// Variables whose declaration had an error (their uses are not reported).
    pub poisoned: HashSet<String>,
    /// The POU's name where it is declared (a duplicate has another span).
    pub span: Span,
}

impl PouSig {
    pub fn var(&self, name: &str) -> Option<(usize, &Var)> {
        // Called for every variable reference: the index folds case itself.
        let i = self.index.get(name)?;
        Some((i, &self.vars[i]))
    }
    /// Inputs in declaration order (what a non-formal call fills).
    pub fn inputs(&self) -> impl Iterator<Item = (usize, &Var)> {
        self.vars
            .iter()
            .enumerate()
            .filter(|(_, v)| v.kind == ast::VarKind::Input)
    }
}

impl Env {
    pub fn pou(&self, name: &str) -> Option<&PouSig> {
        let mut buf = [0u8; 64];
        match buf.get_mut(..name.len()) {
            Some(b) => {
                b.copy_from_slice(name.as_bytes());
                b.make_ascii_uppercase();
                self.pous.get(std::str::from_utf8(b).ok()?)
            }
            None => self.pous.get(&name.to_ascii_uppercase()),
        }
    }
}
