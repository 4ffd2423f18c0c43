//! `ilc emit`: compile IL files to Rust, to stdout or into a directory.

use il_codegen::diag::render::render;
use std::io::Write;
use std::path::Path;

/// Compile `files` as one program (an XML file is a PLCopen project). Diagnostics go to `err`; the Rust code to
/// `out`, or to `<dir>/<stem>.rs` per input (two inputs with one stem are refused;
/// written only when every file
/// compiles, each atomically and only when changed). Returns success.
pub fn run(
    files: &[String],
    dir: Option<&Path>,
    color: bool,
    front: crate::input::Front,
    progress: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> bool {
    // Two inputs with one stem would write one file: refuse before reading
    // or writing anything (`-`, standard input, becomes `stdin.rs`).
    let paths = match dir {
        Some(d) => {
            let names = files
                .iter()
                .map(|f| Path::new(if f == "-" { "stdin" } else { f }));
            match il_codegen::output_paths(d, names) {
                Ok(p) => p,
                Err(e) => {
                    let _ = write!(err, "{e}");
                    return false;
                }
            }
        }
        None => Vec::new(),
    };
    let mut sources = Vec::new();
    let mut ok = true;
    let mut bar = crate::progress::Progress::new(progress, files.len());
    for (k, f) in files.iter().enumerate() {
        bar.reading(k + 1, err);
        match front.read(f) {
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
    let program = front.program(sources);
    let mut checked = program.check();
    // The syntax tree is not needed for code: its memory is reused for
    // the text.
    checked.drop_syntax();
    let opts = il_codegen::EmitOptions {
        line_markers: true,
        ..Default::default()
    };
    let compiled = checked.emit(opts);
    bar.clear(err);
    let Some(compiled) = compiled else {
        let _ = write!(err, "{}", checked.render(color));
        return false;
    };
    for (k, unit) in compiled.iter().enumerate() {
        let src = unit.input().source();
        if !unit.warnings.is_empty() {
            let _ = write!(err, "{}", render(src, &unit.warnings, color));
        }
        let code = &unit.file_text();
        match paths.get(k) {
            None => {
                let _ = out.write_all(code.as_bytes());
            }
            Some(path) => {
                if let Err(e) = il_codegen::write_if_changed(path, code) {
                    let _ = writeln!(err, "error: cannot write `{}`: {e}", path.display());
                    return false;
                }
            }
        }
    }
    bar.finish(err);
    // The process ends after this: freeing the checked IR one allocation at
    // a time is left to the operating system.
    std::mem::forget(compiled);
    std::mem::forget(checked);
    true
}
