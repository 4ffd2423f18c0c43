//! `ilc check`: read, check, report.

use std::io::{self, IsTerminal, Write};

use il_codegen::diag::{Severity, render, to_json};

/// How diagnostics are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Human,
    Json,
}

#[derive(Clone, Copy, Debug, Default)]
pub struct Totals {
    pub errors: usize,
    pub warnings: usize,
    /// Files that could not be read.
    pub unreadable: usize,
}

/// Decide whether to colour: `always`, `never`, or `auto` (stderr is a
/// terminal and `NO_COLOR` is unset or empty).
pub fn use_color(when: &str) -> bool {
    match when {
        "always" => true,
        "never" => false,
        _ => {
            io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
        }
    }
}

/// Run `ilc check` over `paths`, writing JSON to `out` and everything else to
/// `err`. Returns the totals; the caller turns them into the exit status.
#[allow(clippy::too_many_arguments)]
pub fn run(
    paths: &[String],
    format: Format,
    color: bool,
    verbose: bool,
    front: crate::input::Front,
    progress: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Totals {
    let mut totals = Totals::default();
    let mut files = Vec::new();
    let mut bar = crate::progress::Progress::new(progress, paths.len());
    for (k, path) in paths.iter().enumerate() {
        bar.reading(k + 1, err);
        match front.read(path) {
            Ok(f) => files.push(f),
            Err(msg) => {
                bar.clear(err);
                totals.unreadable += 1;
                let _ = writeln!(err, "{}", error_line(color, &msg));
            }
        }
    }
    bar.stage("Checking", err);
    // The files form one program, as with `ilc emit` and the build-script
    // Builder: a FUNCTION_BLOCK of one file may be used in another.
    // An XML file (its text starts with `<`, or named `.xml`) is a PLCopen
    // project: its IL is checked with the rest and its diagnostics point
    // into the XML.
    let program = front.program(files);
    let checked = program.check();
    bar.clear(err);
    for (input, diags) in checked.reports() {
        let file = input.source();
        for d in diags {
            match d.severity {
                Severity::Error => totals.errors += 1,
                Severity::Warning => totals.warnings += 1,
            }
        }
        match format {
            Format::Human => {
                let _ = err.write_all(render(file, diags, color).as_bytes());
            }
            Format::Json => {
                for d in diags {
                    let _ = writeln!(out, "{}", to_json(file, d));
                }
            }
        }
    }
    if verbose && format == Format::Human {
        skipped(&checked, err);
    }
    if format == Format::Human
        && let Some(s) = summary(&totals)
    {
        let line = if totals.errors + totals.unreadable > 0 {
            error_line(color, &s)
        } else {
            warning_line(color, &s)
        };
        let _ = writeln!(err, "{line}");
    }
    bar.finish(err);
    let _ = out.flush();
    let _ = err.flush();
    // The process ends after this: freeing the tree and the checked IR one
    // allocation at a time (about 5% of `ilc check` on a 100k-line POU) is
    // left to the operating system.
    std::mem::forget(checked);
    totals
}

/// `--verbose`: one note per object of a CODESYS export that was not
/// compiled (libraries, the PLC configuration, visualisations ...; an
/// object exported twice).
fn skipped(checked: &il_codegen::Checked, err: &mut dyn Write) {
    for input in checked.inputs() {
        let il_codegen::Input::Exp(e) = input else {
            continue;
        };
        for (k, o) in e.objects().iter().enumerate() {
            let line = e.exp.line_of(o.keyword.start as u32);
            let what = match &o.kind {
                il_codegen::exp::ObjectKind::Skipped(what) => format!("{what} `{}`", o.name),
                _ if e.is_left_out(k) => format!("`{}`, the same as an object read before", o.name),
                _ => continue,
            };
            let _ = writeln!(err, "note: {}:{line}: skipped {what}", e.exp.name);
        }
    }
}

fn plural(n: usize, word: &str) -> String {
    if n == 1 {
        format!("1 {word}")
    } else {
        format!("{n} {word}s")
    }
}

fn summary(t: &Totals) -> Option<String> {
    let mut parts = Vec::new();
    if t.errors > 0 {
        parts.push(plural(t.errors, "error"));
    }
    if t.warnings > 0 {
        parts.push(plural(t.warnings, "warning"));
    }
    if t.unreadable > 0 {
        parts.push(format!("{} not read", plural(t.unreadable, "file")));
    }
    if parts.is_empty() {
        return None;
    }
    Some(if t.errors + t.unreadable > 0 {
        format!("check failed: {}", parts.join(", "))
    } else {
        format!("{} emitted", parts.join(", "))
    })
}

pub fn error_line(color: bool, msg: &str) -> String {
    if color {
        format!("\x1b[1m\x1b[91merror\x1b[0m\x1b[1m: {msg}\x1b[0m")
    } else {
        format!("error: {msg}")
    }
}

fn warning_line(color: bool, msg: &str) -> String {
    if color {
        format!("\x1b[1m\x1b[93mwarning\x1b[0m\x1b[1m: {msg}\x1b[0m")
    } else {
        format!("warning: {msg}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summaries() {
        assert_eq!(summary(&Totals::default()), None);
        let t = Totals {
            errors: 1,
            warnings: 2,
            unreadable: 0,
        };
        assert_eq!(summary(&t).unwrap(), "check failed: 1 error, 2 warnings");
        let t = Totals {
            errors: 0,
            warnings: 1,
            unreadable: 0,
        };
        assert_eq!(summary(&t).unwrap(), "1 warning emitted");
        let t = Totals {
            errors: 0,
            warnings: 0,
            unreadable: 2,
        };
        assert_eq!(summary(&t).unwrap(), "check failed: 2 files not read");
    }
}
