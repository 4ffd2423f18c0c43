//! The IL front end: lexer, lalrpop grammar, and the mapping of parse errors to
//! messages a PLC engineer can act on.
//!
//! `grammar.rs` is generated from `grammar.lalrpop` and checked in; the test
//! `syntax_grammar_up_to_date` regenerates it (`IL_BLESS=1` to update).

use crate::ast::{CompilationUnit, Span};
use crate::diag::{Diagnostic, SourceFile, codes::CodeInfo};

mod actions;
pub mod code;
pub mod errors;
mod host;
pub mod lexer;
mod literal_message;
pub(crate) mod reparse;
mod spans;

#[allow(clippy::all, clippy::pedantic, unused, unused_parens, unused_qualifications, non_snake_case, dead_code)]
#[rustfmt::skip]
mod grammar;

pub use literal_message::literal_message;

/// Diagnostic codes of the front end (IL0001..IL0099).
pub static CODES: &[CodeInfo] = code::CODES;

/// Parse a whole file. Always returns a tree (possibly partial) and every
/// syntax diagnostic of the file, sorted by position.
pub fn parse(file: &SourceFile) -> (CompilationUnit, Vec<Diagnostic>) {
    parse_std(file, crate::dialect::Standard::default())
}

/// [`parse`] against a standard: under the 2nd edition the 3rd-edition
/// forms the front end recognises (pragmas) are errors.
pub fn parse_std(
    file: &SourceFile,
    standard: crate::dialect::Standard,
) -> (CompilationUnit, Vec<Diagnostic>) {
    let (unit, diags, _) = parse_noted(file, standard);
    (unit, diags)
}

/// [`parse_std`], with the comments of the file that hold a `(*`: the
/// checker's errors in the text after one are named by
/// [`lexer::comments::name_nested`] too (the syntax errors already are).
pub(crate) fn parse_noted(
    file: &SourceFile,
    standard: crate::dialect::Standard,
) -> (
    CompilationUnit,
    Vec<Diagnostic>,
    Vec<lexer::comments::InnerOpen>,
) {
    if file.text.len() > u32::MAX as usize {
        let d = Diagnostic::error(
            code::TOO_LARGE,
            Span::default(),
            "this source file is larger than 4 GiB",
        )
        .with_label("file too large")
        .with_help("split the program into several files");
        return (CompilationUnit::default(), vec![d], Vec::new());
    }
    let mut lx = lexer::Lexer::new(&file.text, standard);
    let mut ctx = actions::Ctx::default();
    // The parser pulls the tokens from the lexer one at a time (their names
    // move into the tree instead of being copied); the messages of syntax
    // errors, which look at the tokens around the error, get them from
    // lexing again (the lexer is deterministic): only files with syntax
    // errors pay for it. A parser that stops early leaves the rest of the
    // file to lex, for the lexer's own diagnostics.
    let result = grammar::UnitParser::new().parse(&mut ctx, lx.by_ref());
    lx.by_ref().for_each(drop);
    let lexer::Finished {
        mut diags,
        host_marks,
        inner_opens,
    } = lx.finish_marked();
    let failed = result.is_err() || !ctx.errors.is_empty();
    let toks = if failed {
        lexer::lex_std(&file.text, standard).0
    } else {
        Vec::new()
    };
    let mut unit = match result {
        Ok(u) => u,
        Err(e) => {
            diags.extend(errors::parse_error(file, &toks, &e));
            CompilationUnit::default()
        }
    };
    for e in &ctx.errors {
        diags.extend(errors::parse_error(file, &toks, &e.error));
    }
    diags.extend(ctx.diags);
    host::mark(&mut unit, &host_marks, &mut diags);
    lexer::comments::name_nested(&file.text, &inner_opens, &mut diags);
    diags.sort_by_key(|d| (d.span.lo, d.span.hi));
    diags.dedup_by(|a, b| a.span == b.span && a.code == b.code);
    crate::diag::limit(&mut diags);
    (unit, diags, inner_opens)
}
