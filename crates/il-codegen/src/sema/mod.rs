//! Semantic analysis: names, types, the type of the current result (CR) at
//! every instruction, and control flow. Produces the checked [`ir::Program`].

pub mod codes;
mod decls;
mod flow;
pub mod ir;
mod stdfb;
mod sig_mock;
mod stdfn;
pub mod types;

use crate::ast::{self, Span};
use crate::diag::{Diagnostic, SourceFile};
pub use codes::CODES;

/// Check a parsed unit. Returns the checked program (whatever could be
/// checked) and the diagnostics; the program may be emitted only when no
/// diagnostic is an error.
pub fn check(file: &SourceFile, unit: &ast::CompilationUnit) -> (ir::Program, Vec<Diagnostic>) {
    let mut cx = Cx { file, diags: Vec::new() };
    let env = decls::collect(&mut cx, unit);
    let mut program = ir::Program::default();
    for pou in unit.items.iter().filter_map(|i| match i {
        ast::Item::Pou(p) => Some(p),
        _ => None,
    }) {
        if let Some(checked) = flow::check_pou(&mut cx, &env, pou) {
            program.pous.push(checked);
        }
    }
    decls::check_recursion(&mut cx, &env, unit);
    (program, cx.diags)
}

/// What every pass shares: the file (for line numbers) and the diagnostics.
pub(crate) struct Cx<'a> {
    pub file: &'a SourceFile,
    pub diags: Vec<Diagnostic>,
}

impl Cx<'_> {
    pub fn line(&self, span: Span) -> u32 {
        self.file.line_col(span.lo).0 as u32
    }
    pub fn err(&mut self, code: &'static str, span: Span, msg: impl Into<String>) -> &mut Diagnostic {
        self.diags.push(Diagnostic::error(code, span, msg));
        self.diags.last_mut().expect("just pushed")
    }
    pub fn warn(&mut self, code: &'static str, span: Span, msg: impl Into<String>) -> &mut Diagnostic {
        self.diags.push(Diagnostic::warning(code, span, msg));
        self.diags.last_mut().expect("just pushed")
    }
}

/// Case-insensitive "did you mean": the closest of `candidates` to `name`.
pub(crate) fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let up = name.to_ascii_uppercase();
    let mut best: Option<(usize, &str)> = None;
    for c in candidates {
        let d = edit_distance(&up, &c.to_ascii_uppercase());
        let limit = (up.len().max(c.len()) / 3).max(1);
        if d <= limit && best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, c));
        }
    }
    best.map(|(_, c)| c)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

/// Whether `name` is a standard function block of il-std.
pub(crate) fn is_std_fb(name: &str) -> bool {
    stdfb::lookup(name).is_some()
}
