//! What every name of the program names, as the checker resolved it: the
//! one resolution table that tools (the language server's definition,
//! references, rename, highlight and hover) read instead of resolving
//! names again. Recorded only when asked ([`crate::Program::resolutions`]).

use crate::ast::{PouKind, Span, VarKind};

/// An index into [`Resolutions::symbols`].
pub type SymbolId = usize;

/// What a symbol is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SymbolKind {
    /// A FUNCTION, FUNCTION_BLOCK or PROGRAM.
    Pou(PouKind),
    /// Variable `index` of POU `pou`, in the order of [`super::CheckedPou::vars`].
    Var {
        /// The POU that declares it.
        pou: SymbolId,
        /// Its index among the POU's variables.
        index: usize,
        /// Its section.
        kind: VarKind,
        /// For a VAR_EXTERNAL: the configuration's global of that name.
        global: Option<SymbolId>,
    },
    /// A label of a POU's body.
    Label {
        /// The POU.
        pou: SymbolId,
    },
    /// A user type (`TYPE name : ... END_TYPE`).
    Type,
    /// A field of a STRUCT type.
    Field {
        /// The STRUCT.
        ty: SymbolId,
    },
    /// A value of an enumeration type.
    EnumValue {
        /// The enumeration.
        ty: SymbolId,
    },
    /// A CONFIGURATION.
    Config,
    /// A RESOURCE of a configuration.
    Resource {
        /// The configuration.
        config: SymbolId,
    },
    /// A VAR_GLOBAL of a configuration (or of one of its resources).
    Global {
        /// The configuration.
        config: SymbolId,
    },
    /// A PROGRAM instance of a configuration.
    ProgramInstance {
        /// The configuration.
        config: SymbolId,
    },
    /// A standard function (no declaration: its name is il-std's).
    StdFunction,
    /// A standard function block (no declaration).
    StdBlock,
    /// An input or output of a standard function block.
    StdMember {
        /// The block ([`SymbolKind::StdBlock`]).
        block: SymbolId,
        /// An input (else an output).
        input: bool,
    },
}

/// Where a symbol is declared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Decl {
    /// The input (in the order of [`crate::Checked::inputs`]).
    pub file: usize,
    /// Its name in the declaration, in the file the user wrote.
    pub span: Span,
}

/// A named thing of the program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Symbol {
    /// As declared (a standard one: as il-std spells it).
    pub name: String,
    /// What it is.
    pub kind: SymbolKind,
    /// Its declaration; `None` for the standard functions and blocks.
    pub decl: Option<Decl>,
}

/// The resolution table of a checked program.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Resolutions {
    /// Every symbol a name of the program names.
    pub symbols: Vec<Symbol>,
    /// Per input: every name written (declarations included: each names
    /// itself) and its symbol, sorted by position, one entry per span, in
    /// the positions of the file the user wrote.
    pub uses: Vec<Vec<(Span, SymbolId)>>,
}

impl Resolutions {
    /// The name at byte `offset` of input `file` (a name holding it, or
    /// ending right at it: the cursor after a name) and its symbol. Where
    /// an import wrote declarations that stand on a use (an M221 listing
    /// declares each object where it is first used), the use's symbol.
    pub fn at(&self, file: usize, offset: usize) -> Option<(Span, SymbolId)> {
        let uses = self.uses.get(file)?;
        let off = offset as u32;
        let i = uses.partition_point(|(s, _)| s.lo <= off);
        let (s, id) = *uses.get(i.checked_sub(1)?)?;
        if !(off >= s.lo && off <= s.hi) {
            return None;
        }
        // A symbol written twice here is declared and used here; one
        // written once is used here unless this is its declaration.
        let here = uses[..i].iter().rev().take_while(|(x, _)| *x == s).count();
        let same = &uses[i - here..i];
        let twice = |id: SymbolId| same.iter().filter(|(_, y)| *y == id).count() > 1;
        let is_decl = |id: SymbolId| {
            (self.symbols.get(id).and_then(|x| x.decl))
                .is_some_and(|d| d.file == file && d.span == s)
        };
        let best = (same.iter().find(|(_, y)| twice(*y)))
            .or_else(|| same.iter().find(|(_, y)| !is_decl(*y)));
        Some(best.map_or((s, id), |u| *u))
    }

    /// Every place symbol `id` is written, its declaration included:
    /// (input, span), in input and position order.
    pub fn uses_of(&self, id: SymbolId) -> impl Iterator<Item = (usize, Span)> + '_ {
        self.uses.iter().enumerate().flat_map(move |(f, u)| {
            u.iter()
                .filter(move |(_, s)| *s == id)
                .map(move |(span, _)| (f, *span))
        })
    }
}
