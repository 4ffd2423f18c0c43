//! Which edition of IEC 61131-3 the compiler accepts. By default it takes the
//! 3rd-edition and vendor forms that real projects use (pragmas, implicit
//! widening conversions, partial bit access); [`Standard::Iec2003`] refuses
//! each of them with an error that names the form. Each stage that accepts
//! such a form calls [`Standard::refuse`] at that point, so the form is
//! decided once, where it is recognised. [`Dialect`] says which
//! Instruction List a text source is in: IEC's, or a vendor's listing that
//! is translated to it (`--dialect m221`).

use crate::ast::Span;
use crate::diag::Diagnostic;

pub mod codes;
pub use codes::CODES;

/// The edition of IEC 61131-3 a program is checked against.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Standard {
    /// The 3rd edition (2013) and the vendor forms of CODESYS-family tools
    /// and Beremiz: pragmas, implicit widening, partial access. The default.
    #[default]
    Iec2013,
    /// Strictly the 2nd edition (2003): each 3rd-edition form is an error.
    Iec2003,
}

impl Standard {
    /// The standard named `iec2003`/`2003`/`ed2` or `iec2013`/`2013`/`ed3`
    /// (case-insensitive), as `--std=` and `il!(..., std = "...")` take it.
    pub fn from_name(name: &str) -> Option<Standard> {
        match name.to_ascii_lowercase().as_str() {
            "iec2003" | "2003" | "ed2" => Some(Standard::Iec2003),
            "iec2013" | "2013" | "ed3" => Some(Standard::Iec2013),
            _ => None,
        }
    }

    /// The name [`Standard::from_name`] reads.
    pub fn name(self) -> &'static str {
        match self {
            Standard::Iec2013 => "iec2013",
            Standard::Iec2003 => "iec2003",
        }
    }

    /// Whether 3rd-edition forms are errors.
    pub fn strict(self) -> bool {
        self == Standard::Iec2003
    }

    /// The error for a 3rd-edition form at `span`, when this standard
    /// refuses it (`None`: the form is accepted).
    pub fn refuse(self, feature: Feature, span: Span) -> Option<Diagnostic> {
        self.strict().then(|| feature.diagnostic(span))
    }
}

impl std::str::FromStr for Standard {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Standard::from_name(s)
            .ok_or_else(|| format!("unknown standard `{s}`: use `iec2003` or `iec2013`"))
    }
}

/// The language a source that is not XML is written in: IEC 61131-3 IL
/// (the default), or a vendor's Instruction List that is translated to it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Dialect {
    /// IEC 61131-3 Instruction List (with the vendor forms [`Standard`]
    /// allows).
    #[default]
    Iec,
    /// A Modicon M221 (Machine Expert Basic, SoMachine Basic) or Twido
    /// (TwidoSuite) listing: one M221 instruction a line, `%Ln:` labels,
    /// `SRn:` subroutines, `(*@ %TM0 ... *)` configuration comments
    /// ([`crate::m221`], docs/semantics.md "Modicon M221 dialect").
    M221,
}

impl Dialect {
    /// The dialect named `iec` or `m221` (also `twido`), case-insensitive,
    /// as `--dialect` and `il!(..., dialect = "...")` take it.
    pub fn from_name(name: &str) -> Option<Dialect> {
        match name.to_ascii_lowercase().as_str() {
            "iec" => Some(Dialect::Iec),
            "m221" | "twido" => Some(Dialect::M221),
            _ => None,
        }
    }

    /// The name [`Dialect::from_name`] reads.
    pub fn name(self) -> &'static str {
        match self {
            Dialect::Iec => "iec",
            Dialect::M221 => "m221",
        }
    }

    /// `file` as an input of a program: XML is read by its content, as
    /// always ([`crate::pipeline::Input::by_content`]); other text is IEC
    /// IL or this dialect's listing.
    pub fn input(self, file: crate::diag::SourceFile) -> crate::pipeline::Input {
        use crate::pipeline::{Input, is_xml};
        match self {
            Dialect::M221 if !is_xml(&file.name, &file.text) => Input::m221(file),
            _ => Input::by_content(file),
        }
    }
}

impl std::str::FromStr for Dialect {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Dialect::from_name(s).ok_or_else(|| format!("unknown dialect `{s}`: use `iec` or `m221`"))
    }
}

/// A 3rd-edition or vendor form that [`Standard::Iec2003`] refuses.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Feature {
    /// `{ ... }`.
    Pragma,
    /// A value of type `from` used where `to` is expected (the names as IEC
    /// spells them).
    Widening {
        /// The value's type.
        from: String,
        /// The wider type it becomes.
        to: String,
    },
    /// `v.3`, `v.%X3`, `v.%B1` ...: as written.
    PartialAccess(String),
    /// `AT %I*` (as written) in VAR_INPUT or VAR_OUTPUT (`section`): a
    /// CODESYS-family placement; Ed.2 2.4.1.1 allows it only in VAR.
    PartlyInInterface {
        /// The address as written.
        text: String,
        /// `VAR_INPUT` or `VAR_OUTPUT`.
        section: &'static str,
    },
}

impl Feature {
    /// The error naming the form.
    pub fn diagnostic(&self, span: Span) -> Diagnostic {
        let (code, msg, label, help) = match self {
            Feature::Pragma => (
                codes::PRAGMA,
                "pragmas `{ ... }` are a 3rd-edition feature".to_string(),
                "pragma",
                "remove the pragma, or check with the default standard (iec2013)".to_string(),
            ),
            Feature::Widening { from, to } => (
                codes::IMPLICIT_CONVERSION,
                format!("implicit conversion {from} → {to} is a 3rd-edition feature"),
                "converted implicitly",
                format!("convert explicitly with {from}_TO_{to}"),
            ),
            Feature::PartialAccess(text) => (
                codes::PARTIAL_ACCESS,
                format!("partial access `{text}` is a 3rd-edition feature"),
                "partial access",
                "mask and shift with AND and SHR, or check with the default standard (iec2013)"
                    .to_string(),
            ),
            Feature::PartlyInInterface { text, section } => (
                codes::PARTLY_IN_INTERFACE,
                format!("a partly specified address `{text}` in {section} is a vendor form"),
                "partly specified address",
                "declare the variable in VAR (the 2nd edition binds `%I*` there only), or check with the default standard (iec2013)"
                    .to_string(),
            ),
        };
        Diagnostic::error(code, span, msg)
            .with_label(label)
            .with_help(help)
    }
}
