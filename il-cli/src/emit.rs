//! `ilc emit`: compile IL files to Rust, to stdout or into a directory.

use il_codegen::diag::render::render;
use std::io::Write;
use std::path::Path;

/// Compile `files` as one program (a `.xml` file is a PLCopen project). Diagnostics go to `err`; the Rust code to
/// `out`, or to `<dir>/<stem>.rs` per input (written only when every file
/// compiles, each atomically and only when changed). Returns success.
pub fn run(
    files: &[String],
    dir: Option<&Path>,
    color: bool,
    progress: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> bool {
    let mut sources = Vec::new();
    let mut ok = true;
    let mut bar = crate::progress::Progress::new(progress, files.len());
    for (k, f) in files.iter().enumerate() {
        bar.reading(k + 1, err);
        match crate::check::read_source(f) {
            Ok(src) => sources.push(src),
            Err(e) => {
                bar.clear(err);
                let _ = writeln!(err, "{}", crate::check::error_line(color, &e));
                ok = false;
            }
        }
    }
    if !ok {
        bar.clear(err);
        return false;
    }
    bar.stage("Compiling", err);
    let program = sources
        .into_iter()
        .fold(il_codegen::Program::new(), il_codegen::Program::source);
    let checked = program.check();
    let opts = il_codegen::emit::Options {
        line_markers: true,
        ..Default::default()
    };
    let compiled = checked.emit(opts);
    bar.clear(err);
    let Some(compiled) = compiled else {
        let _ = write!(err, "{}", checked.render(color));
        return false;
    };
    for unit in &compiled {
        let src = unit.input().source();
        if !unit.warnings.is_empty() {
            let _ = write!(err, "{}", render(src, &unit.warnings, color));
        }
        let code = &unit.file_text();
        match dir {
            None => {
                let _ = out.write_all(code.as_bytes());
            }
            Some(d) => {
                let stem = Path::new(&src.name)
                    .file_stem()
                    .map_or_else(|| "stdin".into(), |s| s.to_string_lossy().into_owned());
                let path = d.join(format!("{stem}.rs"));
                if let Err(e) = il_codegen::write_if_changed(&path, code) {
                    let _ = writeln!(err, "error: cannot write `{}`: {e}", path.display());
                    return false;
                }
            }
        }
    }
    bar.finish(err);
    true
}
