//! The errors of checking one IL text through the pipeline, for the sema
//! topics.

use il_codegen::diag::SourceFile;

/// (code, line, column, message) of every error of `src`.
pub fn errors(src: &str) -> Vec<(String, usize, usize, String)> {
    errors_std(src, il_codegen::Standard::default())
}

/// [`errors`] against a standard.
pub fn errors_std(src: &str, std: il_codegen::Standard) -> Vec<(String, usize, usize, String)> {
    let f = SourceFile::new("t.il", src);
    il_codegen::Program::new()
        .standard(std)
        .il(f.clone())
        .check()
        .diagnostics()[0]
        .iter()
        .filter(|d| d.is_error())
        .map(|d| {
            let (l, c) = f.line_col(d.span.lo);
            (d.code.to_string(), l, c, d.message.clone())
        })
        .collect()
}
