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
pub(crate) mod reuse;
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
use flow::Noted;

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
    let (programs, diags, _) = check_recorded(units, standard, cr_steps, false, None);
    (programs, diags)
}

/// [`check_all`], and with `resolutions` the resolution table (spans in
/// each unit's IL text; `None` when not asked). With a `cache`, each POU's
/// results are kept in it, and those its `reuse` allows are taken from it
/// instead of checking their POUs again (see `reuse.rs`).
pub(crate) fn check_recorded(
    units: &[(&SourceFile, &ast::CompilationUnit)],
    standard: crate::dialect::Standard,
    cr_steps: bool,
    resolutions: bool,
    mut cache: Option<&mut reuse::Cache>,
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
    // The names noted by the declarations' passes, then by each POU.
    let mut pre: Vec<Noted> = cxs
        .iter_mut()
        .map(|c| c.names.as_mut().map(std::mem::take).unwrap_or_default())
        .collect();
    let (mut old, mut old_ir, reuse) = match cache.as_deref_mut() {
        Some(c) => (
            std::mem::take(&mut c.results),
            std::mem::take(&mut c.old_ir),
            c.reuse.take(),
        ),
        None => Default::default(),
    };
    // Every diagnostic of the edited file that is reused must have a place
    // in the new text, or nothing is reused.
    let pou_count = |u: &ast::CompilationUnit| {
        u.items
            .iter()
            .filter(|i| matches!(i, ast::Item::Pou(_)))
            .count()
    };
    let reuse = reuse.filter(|r| {
        old.len() == asts.len()
            && old.iter().zip(&asts).all(|(o, u)| o.len() == pou_count(u))
            && old.get(r.file).is_some_and(|pous| {
                pous.iter()
                    .enumerate()
                    .filter(|(k, _)| r.reuses(r.file, *k))
                    .flat_map(|(_, p)| p.iter().flat_map(|p| &p.diags))
                    .all(|d| r.move_diag(&mut d.clone()))
            })
    });
    let mut results: Vec<Vec<Option<reuse::PouResult>>> = Vec::with_capacity(asts.len());
    let mut checked = 0;
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
        let mut mine = Vec::new();
        let pous = unit.items.iter().filter_map(|i| match i {
            ast::Item::Pou(p) => Some(p),
            _ => None,
        });
        for (k, pou) in pous.enumerate() {
            let this = |s: &&env::PouSig| s.file == f && s.span == pou.name.span;
            let main = env.pou(&pou.name.name).filter(this);
            let sig = main.or_else(|| env.duplicates.iter().find(this));
            let Some(sig) = sig else {
                mine.push(None);
                continue;
            };
            let kept = reuse
                .filter(|r| r.reuses(f, k))
                .and_then(|r| Some((r, old.get_mut(f)?.get_mut(k)?.take()?)))
                .filter(|(r, res)| r.takes(res));
            let result = match kept {
                Some((r, mut res)) => {
                    // Its checked IR, if it had one, comes back from the last check.
                    let mut ir = match res.ir {
                        Some(i) => old_ir.get_mut(f).and_then(|v| v.get_mut(i)?.take()),
                        None => None,
                    };
                    if f == r.file {
                        if k > r.pou {
                            r.move_pou(&mut res, ir.as_mut());
                        } else {
                            r.move_pou_diags(&mut res);
                        }
                    }
                    cxs[f].diags.extend(res.diags.iter().cloned());
                    res.ir = ir.map(|p| {
                        program.pous.push(p);
                        program.pous.len() - 1
                    });
                    res
                }
                None => {
                    checked += 1;
                    let before = cxs[f].diags.len();
                    // Its names apart (`None`: none are noted).
                    let saved = cxs[f].names.as_mut().map(std::mem::take);
                    let pou_ir = flow::check_pou(&mut cxs[f], &env, pou, sig);
                    let noted = match saved {
                        Some(s) => cxs[f].names.replace(s),
                        None => None,
                    }
                    .unwrap_or_default();
                    // A duplicate's errors are reported; the program has an error anyway.
                    let ir = pou_ir.filter(|_| main.is_some()).map(|p| {
                        program.pous.push(p);
                        program.pous.len() - 1
                    });
                    let diags = cxs[f].diags[before..].to_vec();
                    let lines_in_text =
                        reuse::lines_in_text(&diags, ir.and_then(|i| program.pous.get(i)));
                    reuse::PouResult {
                        diags,
                        noted,
                        ir,
                        lines_in_text,
                    }
                }
            };
            mine.push(Some(result));
        }
        results.push(mine);
        programs.push(program);
    }
    recursion::check_recursion(&mut cxs, &env, &asts);
    nesting::check_nesting(&mut cxs, &env, &asts);
    // Before the signatures give their variables away (the table numbers
    // variables by them).
    let table = resolutions.then(|| {
        let post: Vec<Noted> = cxs
            .iter_mut()
            .map(|c| c.names.take().unwrap_or_default())
            .collect();
        let noted: Vec<Vec<&[(Span, flow::Key)]>> = (0..asts.len())
            .map(|f| {
                std::iter::once(&pre[f][..])
                    .chain(results[f].iter().flatten().map(|r| &r.noted[..]))
                    .chain(std::iter::once(&post[f][..]))
                    .collect()
            })
            .collect();
        flow::table(&env, &asts, &noted)
    });
    pre.clear();
    // Nothing reads the signatures any more: each checked POU takes its
    // variables from its own (a checked POU is pushed only for the
    // signature its name finds).
    for p in programs.iter_mut().flat_map(|p| &mut p.pous) {
        if let Some(sig) = env.pous.get_mut(&p.name.to_ascii_uppercase()) {
            p.vars = std::mem::take(&mut sig.vars);
        }
    }
    if let Some(c) = cache {
        c.results = results;
        c.checked = checked;
        c.applied = reuse;
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
