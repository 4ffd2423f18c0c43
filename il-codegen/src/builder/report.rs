//! [`Builder::compile_or_report`]: a failed build that reads like rustc's
//! and that editors find.
//!
//! Measured with cargo 1.95 (see the guide, "Build errors in editors"): a
//! build script that returns `Err` has its stderr shown inside cargo's
//! "failed to run custom build command ... --- stderr" wrapper, indented, so
//! the `$rustc` problem matcher of VS Code's rust-analyzer extension (its
//! first pattern is anchored, `^(warning|warn|error)...`) finds nothing.
//! `cargo::error=` lines are not indented, but each is prefixed with
//! `error: <package>@<version>: `, so the matcher's location pattern
//! (`^[\s->=]*(.*?):(\d+):(\d+)`) takes that prefix as part of the file
//! name. rust-analyzer reads neither as a diagnostic: its check reads only
//! rustc's JSON messages. So an IL error is handed to rustc itself: the
//! output file of each input becomes `compile_error!`s, one per error, whose
//! text is the rustc layout (`IL0106: message`, `--> plc/tank.il:88:5`, the
//! snippet). rustc prints `error: IL0106: ...` with the arrow on the next
//! line, which the matcher reads as the IL file's line and column, and its
//! JSON message is what rust-analyzer shows.

use super::{Builder, GENERATED, write_if_changed};
use std::path::PathBuf;

/// The text of an output file that holds an input's errors.
pub(super) fn error_file(name: &str, errors: &[String]) -> String {
    let mut out = format!(
        "{GENERATED} from {}. Do not edit: edit the IL source and rebuild.\n\
         // The IL has errors: rustc reports each (Builder::compile_or_report).\n",
        crate::pipeline::file::sanitize_comment(name)
    );
    for e in errors {
        out.push_str("::core::compile_error!(");
        out.push_str(&crate::emit::text::str_lit(e));
        out.push_str(");\n");
    }
    out
}

impl Builder {
    /// Compile every file, as [`Builder::compile`] does, and report a
    /// failure the way rustc reports its own, for a build script whose
    /// `main` is this one call:
    ///
    /// ```no_run
    /// // build.rs, in `fn main()`
    /// il_codegen::Builder::new().file("plc/tank.il").compile_or_report();
    /// ```
    ///
    /// Errors in the IL do not fail the build script: each input's output
    /// file holds one `compile_error!` per error of that input instead of
    /// its code, so the crate's `include!` fails with rustc's
    /// `error: IL0106: message` followed by `--> plc/tank.il:LINE:COL` and
    /// the IL snippet, where editors' rustc problem matchers and
    /// rust-analyzer find it. The script is rerun when an input changes, so
    /// fixing the IL rebuilds the code. Failures that are not about the IL
    /// (an input that cannot be read, an unwritable output directory) fail
    /// the build script with `cargo::error=` lines. Returns the generated
    /// files (empty on failure).
    pub fn compile_or_report(self) -> Vec<PathBuf> {
        match self.compile() {
            Ok(written) => written,
            Err(e) => {
                match e.deferred {
                    Some(files) => {
                        for (path, text) in &files {
                            if let Err(err) = write_if_changed(path, text) {
                                println!("cargo::error=cannot write `{}`: {err}", path.display());
                            }
                        }
                    }
                    None => {
                        // cargo puts `error: <package>@<version>: ` before
                        // each line: an `error: ` of ours would be doubled.
                        for line in e.rendered.lines() {
                            let line = line.strip_prefix("error: ").unwrap_or(line);
                            println!("cargo::error={line}");
                        }
                    }
                }
                Vec::new()
            }
        }
    }
}
