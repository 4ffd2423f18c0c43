//! The state of one translation ([`Lx`]: the XML, the IL written so far,
//! the diagnostics) and which of the project's elements are written
//! ([`Selection`]), shared by the passes that write the IL (`write.rs`,
//! `config.rs`, `decls.rs`).

use std::collections::{HashMap, HashSet};

use crate::diag::Diagnostic;
use crate::plcopen::map::Writer;

/// The translation under way: the XML, the IL text with its map, the
/// diagnostics.
pub(super) struct Lx<'i> {
    pub xml: &'i str,
    pub w: Writer,
    pub diags: Vec<Diagnostic>,
    /// Function blocks of the project with a standard block's name, by
    /// upper-case name: the name they are compiled under (`TON_LogicLab`),
    /// which every variable of that type is written with.
    pub renamed: HashMap<String, String>,
    /// The names renamed so in each library, for one warning per library.
    pub lib_renamed: Vec<Vec<String>>,
}

/// Which elements are written, by index into the project's lists.
pub(super) struct Selection {
    pub pous: Vec<bool>,
    pub types: Vec<bool>,
    pub globals: Vec<bool>,
    /// The names each IL POU's body uses (upper case), by POU index.
    pub used: Vec<HashSet<String>>,
}
