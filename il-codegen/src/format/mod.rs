//! The IL formatter behind `ilc fmt` and the language server's formatting:
//! IL laid out as PLC IDEs show it. A body line has a label column, the
//! operator at column 4 (after a label, if it is shorter) and the operands
//! after the widest operator of the file; declarations are indented in
//! their `VAR` block and aligned by their `:`; trailing comments line up
//! across a block; keywords take the case the file mostly uses (or the one
//! asked).
//!
//! Only blanks and the case of keywords change: line breaks, comments,
//! pragmas and blank lines stay, a comment over several lines is kept as
//! written, and the result is lexed again and must give the same tokens,
//! or nothing is formatted. A file with syntax errors is not formatted.
//! Formatting is idempotent.

mod layout;
mod lines;

use crate::ast::Span;
use crate::diag::{Diagnostic, SourceFile};
use crate::syntax::lexer::{self, Tok};

/// The case of keywords (`VAR`, `END_VAR`, `LD`, `JMPC` ...; names,
/// literals and addresses are never changed).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum KeywordCase {
    /// The case most of the file's keywords have (upper on a tie).
    #[default]
    AsTheFile,
    /// `LD`, `END_VAR`.
    Upper,
    /// `ld`, `end_var`.
    Lower,
    /// As each is written.
    Preserve,
}

/// How to format.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FormatOptions {
    /// The case of keywords.
    pub keywords: KeywordCase,
}

/// `file`'s text laid out (see the module), or why it is not formatted:
/// its syntax errors, or one error saying what the formatter cannot lay
/// out, at its place.
pub fn format(file: &SourceFile, opts: &FormatOptions) -> Result<String, Vec<Diagnostic>> {
    let (_, diags) = crate::syntax::parse(file);
    if diags.iter().any(Diagnostic::is_error) {
        return Err(diags.into_iter().filter(Diagnostic::is_error).collect());
    }
    let refuse = |at: usize, why: &str| {
        vec![
            Diagnostic::error(
                crate::syntax::code::NOT_FORMATTED,
                Span::new(at, at + 1),
                format!("this file is not formatted: {why} here"),
            )
            .with_label(why.to_string()),
        ]
    };
    let (toks, _) = lexer::lex(&file.text);
    let lines = lines::split(&file.text, &toks).map_err(|e| refuse(e.0, e.1))?;
    let crlf = file.text.contains("\r\n");
    let mut out = layout::layout(&lines, opts, crlf);
    if file.text.starts_with('\u{feff}') {
        out.insert(0, '\u{feff}');
    }
    // The safety net: the same tokens, keywords up to case.
    let (again, _) = lexer::lex(&out);
    let same = |a: &[lexer::Spanned], sa: &str, b: &[lexer::Spanned], sb: &str| {
        let key = |(lo, t, hi): &lexer::Spanned,
                   s: &str|
         -> Option<(String, std::mem::Discriminant<Tok>)> {
            (lo != hi && *t != Tok::Nl)
                .then(|| (s[*lo..*hi].to_ascii_uppercase(), std::mem::discriminant(t)))
        };
        let ka: Vec<_> = a.iter().filter_map(|t| key(t, sa)).collect();
        let kb: Vec<_> = b.iter().filter_map(|t| key(t, sb)).collect();
        ka == kb
            && a.iter().filter(|t| t.1 == Tok::Nl).count()
                == b.iter().filter(|t| t.1 == Tok::Nl).count()
    };
    if !same(&toks, &file.text, &again, &out) {
        return Err(refuse(
            0,
            "the layout would change its tokens (a formatter bug: please report it)",
        ));
    }
    Ok(out)
}
