//! Semantic analysis: names, types, the type of the current result (CR) at
//! every instruction, and control flow. Produces the checked [`ir::Program`].

mod address;
pub mod codes;
mod config;
mod decls;
mod docs;
mod env;
mod flow;
mod graph;
pub(crate) mod heap_arrays;
mod init;
mod interface;
mod literals;
mod name_index;
mod nesting;
mod partial_address;
mod recursion;
mod resolve;
mod stdfb;
mod stdfn;
mod typedecls;
pub mod widen;

// The IR and its types live in `crate::ir`, the public contract; the
// checker names them as its own.
use crate::ast::{self, Span};
pub(crate) use crate::diag::suggest;
use crate::diag::{Diagnostic, SourceFile};
pub(crate) use crate::ir::{self, types};
pub use address::parse_address;
pub use codes::CODES;

/// Whether `name` (any case) is a standard function block or function of
/// il-std: a POU of that name is refused (IL0104), so the LogicLab import,
/// which meets them in the vendor's library, renames such a block and
/// leaves such a function out, and says so.
#[cfg(feature = "plcopen")]
pub(crate) fn is_standard_pou(name: &str) -> bool {
    let key = name.to_ascii_uppercase();
    stdfb::lookup(&key).is_some() || stdfn::is_std(&key)
}

/// Check several files as one program (a FUNCTION_BLOCK of one file used in
/// another) against a standard. Returns one program and one diagnostic
/// list per file. `cr_steps`: record [`ir::CheckedPou::cr_steps`] (for
/// tools; without it they are empty).
pub fn check_all(
    units: &[(&SourceFile, &ast::CompilationUnit)],
    standard: crate::dialect::Standard,
    cr_steps: bool,
) -> (Vec<ir::Program>, Vec<Vec<Diagnostic>>) {
    let (programs, diags, _) = check_recorded(units, standard, cr_steps, false);
    (programs, diags)
}

/// [`check_all`], and with `resolutions` the resolution table (spans in
/// each unit's IL text; `None` when not asked).
pub(crate) fn check_recorded(
    units: &[(&SourceFile, &ast::CompilationUnit)],
    standard: crate::dialect::Standard,
    cr_steps: bool,
    resolutions: bool,
) -> (
    Vec<ir::Program>,
    Vec<Vec<Diagnostic>>,
    Option<ir::Resolutions>,
) {
    let mut cxs: Vec<Cx> = units
        .iter()
        .map(|(file, _)| Cx {
            file,
            diags: Vec::new(),
            standard,
            cr_steps,
            names: resolutions.then(Vec::new),
        })
        .collect();
    let asts: Vec<&ast::CompilationUnit> = units.iter().map(|(_, u)| *u).collect();
    let mut env = decls::collect(&mut cxs, &asts);
    heap_arrays::mark_heap(&mut cxs, &mut env, &asts);
    let mut programs = Vec::new();
    for (f, unit) in asts.iter().enumerate() {
        let types = env
            .types
            .defs
            .iter()
            .filter(|(tf, _)| *tf == f)
            .map(|(_, d)| d.clone())
            .collect();
        let configs = env
            .configs
            .iter()
            .filter(|(cf, _)| *cf == f)
            .map(|(_, c)| c.clone())
            .collect();
        let mut program = ir::Program {
            file: cxs[f].file.name.clone(),
            types,
            pous: Vec::new(),
            configs,
        };
        for pou in unit.items.iter().filter_map(|i| match i {
            ast::Item::Pou(p) => Some(p),
            _ => None,
        }) {
            let this = |s: &&env::PouSig| s.file == f && s.span == pou.name.span;
            if let Some(sig) = env.pou(&pou.name.name).filter(this) {
                if let Some(checked) = flow::check_pou(&mut cxs[f], &env, pou, sig) {
                    program.pous.push(checked);
                }
            } else if let Some(sig) = env.duplicates.iter().find(this) {
                // Its errors are reported; the program has an error anyway.
                let _ = flow::check_pou(&mut cxs[f], &env, pou, sig);
            }
        }
        programs.push(program);
    }
    recursion::check_recursion(&mut cxs, &env, &asts);
    nesting::check_nesting(&mut cxs, &env, &asts);
    // Before the signatures give their variables away (the table numbers
    // variables by them).
    let table = resolutions.then(|| {
        let noted = cxs
            .iter_mut()
            .map(|c| c.names.take().unwrap_or_default())
            .collect();
        flow::table(&env, &asts, noted)
    });
    // Nothing reads the signatures any more: each checked POU takes its
    // variables from its own (a checked POU is pushed only for the
    // signature its name finds).
    for p in programs.iter_mut().flat_map(|p| &mut p.pous) {
        if let Some(sig) = env.pous.get_mut(&p.name.to_ascii_uppercase()) {
            p.vars = std::mem::take(&mut sig.vars);
        }
    }
    (programs, cxs.into_iter().map(|c| c.diags).collect(), table)
}

/// What every pass shares: the file (for line numbers) and the diagnostics.
pub(crate) struct Cx<'a> {
    pub file: &'a SourceFile,
    pub diags: Vec<Diagnostic>,
    /// Under the 2nd edition each 3rd-edition form is an error ([`Cx::feature`]).
    pub standard: crate::dialect::Standard,
    /// Record the CR at every step ([`ir::CrStep`]): only tools read them,
    /// and for the compiler they were a seventh of the checked program.
    pub cr_steps: bool,
    /// The names resolved in this file, when the resolution table is asked
    /// for ([`ir::Resolutions`]; `None`: not recorded).
    pub names: Option<flow::Noted>,
}

impl Cx<'_> {
    /// A 3rd-edition form is used at `span`: an error under the 2nd edition.
    pub fn feature(&mut self, feature: crate::dialect::Feature, span: Span) {
        if let Some(d) = self.standard.refuse(feature, span) {
            self.diags.push(d);
        }
    }
    pub fn line(&self, span: Span) -> u32 {
        self.file.line_of(span.lo) as u32
    }
    pub fn err(
        &mut self,
        code: &'static str,
        span: Span,
        msg: impl Into<String>,
    ) -> &mut Diagnostic {
        self.diags.push(Diagnostic::error(code, span, msg));
        self.diags.last_mut().expect("just pushed")
    }
    pub fn warn(
        &mut self,
        code: &'static str,
        span: Span,
        msg: impl Into<String>,
    ) -> &mut Diagnostic {
        self.diags.push(Diagnostic::warning(code, span, msg));
        self.diags.last_mut().expect("just pushed")
    }
}

pub use flow::default_const;
