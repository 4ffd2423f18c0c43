//! `ilc fmt`: lay out IL files as PLC IDEs show them (`il_codegen::format`),
//! in place, or `--check` that they already are.

use il_codegen::diag::{SourceFile, render};
use il_codegen::format::{FormatOptions, format};
use std::io::{Read, Write};
use std::path::Path;

/// How one run went: files changed (or, with `--check`, that would change)
/// and files not formatted (unreadable, syntax errors, not UTF-8).
#[derive(Default)]
pub struct Totals {
    pub changed: usize,
    pub failed: usize,
}

pub fn run(
    files: &[String],
    check: bool,
    opts: FormatOptions,
    color: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Totals {
    let mut t = Totals::default();
    for name in files {
        let bytes = if name == "-" {
            let mut b = Vec::new();
            std::io::stdin().read_to_end(&mut b).map(|_| b)
        } else {
            std::fs::read(name)
        };
        let bytes = match bytes {
            Ok(b) => b,
            Err(e) => {
                let _ = writeln!(err, "error: cannot read `{name}`: {e}");
                t.failed += 1;
                continue;
            }
        };
        // Written back as read: a file in a code page would come back as
        // UTF-8, so it is left alone.
        let Ok(text) = String::from_utf8(bytes) else {
            let _ = writeln!(
                err,
                "error: `{name}` is not UTF-8 text; `ilc fmt` writes files in the encoding they are read in, UTF-8 only (convert it first: `iconv -f windows-1252 -t utf-8`)"
            );
            t.failed += 1;
            continue;
        };
        let file = SourceFile::new(name.clone(), text);
        let formatted = match format(&file, &opts) {
            Ok(f) => f,
            Err(diags) => {
                let _ = err.write_all(render(&file, &diags, color).as_bytes());
                let _ = writeln!(err, "error: `{name}` is not formatted");
                t.failed += 1;
                continue;
            }
        };
        if name == "-" {
            let _ = out.write_all(formatted.as_bytes());
            continue;
        }
        if formatted == file.text {
            continue;
        }
        t.changed += 1;
        if check {
            let _ = writeln!(out, "{name}: not formatted");
            if let Some((n, was, now)) = first_difference(&file.text, &formatted) {
                let _ = writeln!(out, "  line {n}:\n  - {was}\n  + {now}");
            }
            continue;
        }
        if let Err(e) = write_atomically(Path::new(name), &formatted) {
            let _ = writeln!(err, "error: cannot write `{name}`: {e}");
            t.failed += 1;
            t.changed -= 1;
        }
    }
    t
}

fn first_difference<'a>(a: &'a str, b: &'a str) -> Option<(usize, &'a str, &'a str)> {
    let mut la = a.lines();
    let mut lb = b.lines();
    let mut n = 0;
    loop {
        n += 1;
        match (la.next(), lb.next()) {
            (Some(x), Some(y)) if x == y => {}
            (None, None) => return None,
            (x, y) => return Some((n, x.unwrap_or(""), y.unwrap_or(""))),
        }
    }
}

/// Replace `path` by `text`: written beside it and renamed over it, so an
/// interrupted run leaves the old file or the new one, never half of it.
fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("file");
    let tmp = dir.join(format!(".{name}.ilc-fmt.{}", std::process::id()));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.sync_all()?;
        if let Ok(meta) = std::fs::metadata(path) {
            std::fs::set_permissions(&tmp, meta.permissions())?;
        }
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}
