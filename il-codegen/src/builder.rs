//! The build-script API, after prost-build:
//!
//! ```no_run
//! // build.rs
//! fn main() -> Result<(), il_codegen::Error> {
//!     il_codegen::Builder::new().file("plc/motor.il").compile()?;
//!     Ok(())
//! }
//! ```
//! writes `$OUT_DIR/motor.rs`, which the crate includes with
//! `include!(concat!(env!("OUT_DIR"), "/motor.rs"));`.
//!
//! A PLCopen TC6 XML project joins the same program with
//! `.plcopen_file("plc/project.xml")` (or `.file`, which knows XML by its
//! text) and becomes `$OUT_DIR/project.rs`.

mod report;

use crate::diag::render::render;
use crate::pipeline::{Input, Program};
use std::fmt;
use std::path::{Path, PathBuf};

/// Compiles IL files to Rust files, for build scripts.
#[derive(Clone, Debug, Default)]
pub struct Builder {
    /// Each file, and whether it was given as PLCopen XML (else its
    /// content decides: [`is_xml`](crate::pipeline::is_xml)).
    files: Vec<(PathBuf, bool)>,
    out_dir: Option<PathBuf>,
    cargo_directives: Option<bool>,
    serde: bool,
    standard: crate::Standard,
    /// [`Builder::dialect`].
    dialect: crate::Dialect,
    /// [`Builder::encoding`]'s label, checked by `compile`.
    encoding: Option<String>,
}

/// A failed build: every diagnostic of every file, rendered like rustc.
pub struct Error {
    rendered: String,
    /// When the IL has errors: each output file with the input's errors as
    /// `compile_error!`s, for [`Builder::compile_or_report`].
    deferred: Option<Vec<(PathBuf, String)>>,
}

/// The rendered diagnostics, as [`Display`](fmt::Display) shows them: a
/// build script's `fn main() -> Result<(), il_codegen::Error>` prints its
/// error with `Debug`, and a struct dump (`Error { rendered: "error[IL0106]
/// ...\n" }`) would put every message on one escaped line.
impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.rendered)
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.rendered)
    }
}

impl std::error::Error for Error {}

impl Error {
    /// A failure that is not about the IL (no file to put it in).
    fn plain(rendered: String) -> Self {
        Error {
            rendered,
            deferred: None,
        }
    }
}

impl Builder {
    /// A builder with no files; output goes to `$OUT_DIR`.
    pub fn new() -> Self {
        Builder::default()
    }

    /// Add a source file (relative paths are relative to the crate root,
    /// where cargo runs build scripts): IL, or a PLCopen TC6 XML project
    /// when its text is XML (starts with `<`) or its name ends in `.xml`,
    /// as with [`Builder::plcopen_file`].
    pub fn file(mut self, path: impl AsRef<Path>) -> Self {
        self.files.push((path.as_ref().to_path_buf(), false));
        self
    }

    /// Add a PLCopen TC6 XML project (as exported by Beremiz, OpenPLC or
    /// CODESYS): its POUs with IL bodies, data types and configurations
    /// join the program, and become `<stem>.rs`. POUs in other languages
    /// are left out with a warning; diagnostics show the XML's lines.
    pub fn plcopen_file(mut self, path: impl AsRef<Path>) -> Self {
        self.files.push((path.as_ref().to_path_buf(), true));
        self
    }

    /// Add several files.
    pub fn files<P: AsRef<Path>>(mut self, paths: impl IntoIterator<Item = P>) -> Self {
        self.files
            .extend(paths.into_iter().map(|p| (p.as_ref().to_path_buf(), false)));
        self
    }

    /// Where to write the `.rs` files (default: `$OUT_DIR`).
    pub fn out_dir(mut self, dir: impl AsRef<Path>) -> Self {
        self.out_dir = Some(dir.as_ref().to_path_buf());
        self
    }

    /// Whether to print `cargo:rerun-if-changed` and `cargo:warning` lines
    /// (default: when running inside a build script, i.e. `OUT_DIR` is set).
    pub fn cargo_directives(mut self, on: bool) -> Self {
        self.cargo_directives = Some(on);
        self
    }

    /// Derive `serde::Serialize` and `serde::Deserialize` on the generated
    /// user types, FB/PROGRAM structs and RETAIN snapshots (default: off).
    /// The crate then depends on `serde` (with `derive`) and on `il-std`
    /// with its `serde` feature.
    pub fn serde(mut self, on: bool) -> Self {
        self.serde = on;
        self
    }

    /// Check against this edition of IEC 61131-3 (default
    /// [`Standard::Iec2013`](crate::Standard::Iec2013): 3rd-edition and vendor
    /// forms such as pragmas, implicit widening and partial bit access are
    /// accepted). [`Standard::Iec2003`](crate::Standard::Iec2003) refuses each
    /// of them with an error that names it.
    pub fn standard(mut self, standard: crate::Standard) -> Self {
        self.standard = standard;
        self
    }

    /// The Instruction List the text sources are written in (default
    /// [`Dialect::Iec`](crate::Dialect::Iec)): with
    /// [`Dialect::M221`](crate::Dialect::M221) each file that is not XML is
    /// a Modicon M221 / TwidoSuite listing, translated to IEC IL as an
    /// `.smbp` project is (docs/semantics.md, "Modicon M221 dialect").
    /// XML files are read by their content either way.
    pub fn dialect(mut self, dialect: crate::Dialect) -> Self {
        self.dialect = dialect;
        self
    }

    /// The encoding of the sources that are not UTF-8: a WHATWG label such
    /// as `"windows-1251"` (Cyrillic), `"windows-1250"`, `"iso-8859-15"`;
    /// PLC IDEs on Windows export in the machine's code page. A file that is
    /// valid UTF-8 (or has a byte order mark) is read as such all the same.
    /// Without it such a file is read as Windows-1252 with a warning
    /// (IL0039); an unknown label fails [`Builder::compile`].
    pub fn encoding(mut self, label: impl Into<String>) -> Self {
        self.encoding = Some(label.into());
        self
    }

    /// `strict(true)` is [`Builder::standard`]`(Standard::Iec2003)`;
    /// `strict(false)` the default, `Standard::Iec2013`.
    pub fn strict(self, on: bool) -> Self {
        self.standard(if on {
            crate::Standard::Iec2003
        } else {
            crate::Standard::Iec2013
        })
    }

    /// Compile every file. Nothing is written unless every file compiles;
    /// each output is written atomically and only when its content changed.
    /// Returns the paths of the generated files.
    ///
    /// Each input becomes `<stem>.rs` in the output directory. Two inputs
    /// with the same stem (`a/m.il` and `b/m.xml`, also `M.il` and `m.il`,
    /// which are one file on macOS and Windows) are refused before anything
    /// is read or written, with an error naming both.
    ///
    /// The output directory keeps a manifest, `.il-codegen-outputs`, of the
    /// files the Builder wrote. A later build removes the listed files it no
    /// longer produces (an input was dropped or renamed), so that a stale
    /// `include!` fails instead of compiling old code; it removes only files
    /// that still begin with the `// @generated by il-codegen` header, never
    /// a file it did not write or that was edited since. Several Builders of
    /// one build script may share a directory: each keeps its own manifest
    /// (`.il-codegen-outputs-1` for the second, in the order they compile),
    /// and none removes a file another wrote in the same run.
    pub fn compile(self) -> Result<Vec<PathBuf>, Error> {
        let cargo = self
            .cargo_directives
            .unwrap_or_else(|| std::env::var_os("OUT_DIR").is_some());
        let out_dir = match self.out_dir.clone().or_else(|| std::env::var_os("OUT_DIR").map(PathBuf::from)) {
            Some(d) => d,
            None => return Err(Error::plain("error: no output directory: OUT_DIR is not set (call Builder::out_dir outside build scripts)".into())),
        };
        // Refuse two inputs that share an output before reading anything, so
        // that nothing already written is lost or replaced by half a program.
        let out_paths = output_paths(&out_dir, self.files.iter().map(|(p, _)| p.as_path()))
            .map_err(Error::plain)?;
        let encoding = match &self.encoding {
            Some(label) => crate::read::Encoding::from_label(label)
                .map_err(|e| Error::plain(format!("error: {e}\n")))?,
            None => crate::read::Encoding::default(),
        };
        let mut sources = Vec::new();
        let mut failed = String::new();
        for (path, xml) in &self.files {
            if cargo {
                println!("cargo:rerun-if-changed={}", path.display());
            }
            match crate::read::read_source(path, &path.display().to_string(), encoding) {
                Ok(file) => {
                    sources.push(if *xml {
                        Input::plcopen(file)
                    } else {
                        self.dialect.input(file)
                    });
                }
                Err(e) => failed.push_str(&format!(
                    "error: cannot read {} `{}`: {}\n",
                    if *xml {
                        "PLCopen XML file"
                    } else {
                        "source file"
                    },
                    e.path,
                    e.reason
                )),
            }
        }
        if !failed.is_empty() {
            return Err(Error::plain(failed));
        }
        // All files form one program: a FUNCTION_BLOCK of one is usable in another.
        let program = sources
            .into_iter()
            .fold(Program::new().standard(self.standard), Program::input);
        let checked = program.check();
        let opts = crate::emit::Options {
            serde: self.serde,
            line_markers: true,
        };
        let Some(outputs) = checked.emit(opts) else {
            let deferred = checked
                .reports()
                .zip(&out_paths)
                .map(|((input, diags), path)| {
                    let errors: Vec<String> = diags
                        .iter()
                        .filter(|d| d.is_error())
                        .map(|d| crate::diag::render_short(input.source(), d))
                        .collect();
                    (
                        path.clone(),
                        report::error_file(&input.source().name, &errors),
                    )
                })
                .collect();
            return Err(Error {
                rendered: checked.render(false),
                deferred: Some(deferred),
            });
        };
        let mut planned = Vec::new();
        for (out, path) in outputs.iter().zip(out_paths) {
            if cargo && !out.warnings.is_empty() {
                for line in render(out.input().source(), &out.warnings, false).lines() {
                    println!("cargo:warning={line}");
                }
            }
            planned.push((path, out.file_text()));
        }
        let inputs: Vec<PathBuf> = self.files.iter().map(|(p, _)| p.clone()).collect();
        let (k, earlier) = slot(&out_dir, &inputs, &out_paths_of(&planned));
        let mut written = Vec::new();
        for (path, code) in &planned {
            write_if_changed(path, code).map_err(|e| {
                Error::plain(format!("error: cannot write `{}`: {e}", path.display()))
            })?;
            written.push(path.clone());
        }
        remove_stale(&out_dir, &written, k, &earlier).map_err(Error::plain)?;
        Ok(written)
    }
}

fn out_paths_of(planned: &[(PathBuf, String)]) -> Vec<PathBuf> {
    planned.iter().map(|(p, _)| p.clone()).collect()
}

/// The output file of each input: `<dir>/<stem>.rs` (`il.rs` for a path
/// without a stem). Two inputs with the same stem, compared without regard to
/// case (macOS and Windows file systems do not distinguish `m.rs` from
/// `M.rs`), are an error naming both: the second would silently replace the
/// first.
pub fn output_paths<'a>(
    dir: &Path,
    inputs: impl IntoIterator<Item = &'a Path>,
) -> Result<Vec<PathBuf>, String> {
    let mut seen: Vec<(String, &Path)> = Vec::new();
    let mut paths = Vec::new();
    let mut clashes = String::new();
    for input in inputs {
        let stem = input
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "il".into());
        let file = format!("{stem}.rs");
        let key = file.to_lowercase();
        if let Some((_, first)) = seen.iter().find(|(k, _)| *k == key) {
            clashes.push_str(&format!(
                "error: `{}` and `{}` would both be written to `{}`; rename one of them \
                 (each input becomes `<stem>.rs` in the output directory)\n",
                first.display(),
                input.display(),
                dir.join(&file).display()
            ));
        } else {
            seen.push((key, input));
        }
        paths.push(dir.join(file));
    }
    if clashes.is_empty() {
        Ok(paths)
    } else {
        Err(clashes)
    }
}

/// The Builder's record of the files it wrote into an output directory, so
/// that a later build removes the ones it no longer produces (a stale file
/// would keep an old `include!` compiling against code that is gone).
const MANIFEST: &str = ".il-codegen-outputs";

/// The first bytes of every generated file; a file without them was not
/// written by the Builder (or was edited since) and is never removed.
const GENERATED: &str = "// @generated by il-codegen";

/// For each output directory, the input lists of the Builders of this
/// process (one build-script run) that wrote into it, in order: the k-th
/// keeps its own manifest, so that Builders sharing a directory never remove
/// each other's files. A Builder compiled again (same inputs) keeps its slot.
type Runs = std::collections::HashMap<PathBuf, Vec<Vec<PathBuf>>>;

/// This Builder's slot in `dir`, and the files the other Builders of this
/// process wrote there (never removed as stale).
fn slot(dir: &Path, inputs: &[PathBuf], outputs: &[PathBuf]) -> (usize, Vec<String>) {
    let mut g = runs();
    let (runs, written) = &mut *g;
    let slots = runs.entry(dir.to_path_buf()).or_default();
    let k = match slots.iter().position(|s| s == inputs) {
        Some(k) => k,
        None => {
            slots.push(inputs.to_vec());
            slots.len() - 1
        }
    };
    let others = written
        .iter()
        .filter(|(d, _)| d == dir)
        .map(|(_, n)| n.clone())
        .collect();
    for p in outputs {
        if let Some(n) = p.file_name() {
            written.push((dir.to_path_buf(), n.to_string_lossy().into_owned()));
        }
    }
    (k, others)
}

/// The Builders of this process and the files they wrote, per directory.
type RunState = (Runs, Vec<(PathBuf, String)>);

fn runs() -> std::sync::MutexGuard<'static, RunState> {
    static RUNS: std::sync::LazyLock<std::sync::Mutex<RunState>> =
        std::sync::LazyLock::new(Default::default);
    // A poisoned lock only means another Builder panicked; the state is intact.
    RUNS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Remove the files of this Builder's previous manifest in `dir` that are
/// not among `now`, were not written by an earlier Builder of this run, and
/// still start with the `@generated` header; then record `now`.
/// Only bare `.rs` file names are trusted from the manifest: a line with a
/// path separator (an edited manifest) is ignored, so nothing outside `dir`
/// is touched.
fn remove_stale(dir: &Path, now: &[PathBuf], k: usize, earlier: &[String]) -> Result<(), String> {
    let manifest = dir.join(if k == 0 {
        MANIFEST.to_string()
    } else {
        format!("{MANIFEST}-{k}")
    });
    let names: Vec<String> = now
        .iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    if let Ok(old) = std::fs::read_to_string(&manifest) {
        let listed = old.lines().filter(|l| !l.starts_with('#')).filter(|name| {
            name.ends_with(".rs") && !name.contains(['/', '\\']) && !name.starts_with("..")
        });
        for name in listed {
            if names.iter().chain(earlier).any(|n| n == name) {
                continue;
            }
            let stale = dir.join(name);
            let ours = std::fs::read(&stale).is_ok_and(|b| b.starts_with(GENERATED.as_bytes()));
            if ours {
                std::fs::remove_file(&stale).map_err(|e| {
                    format!(
                        "error: cannot remove the stale output `{}`: {e}",
                        stale.display()
                    )
                })?;
            }
        }
    }
    let mut text = String::from(
        "# files written by il_codegen::Builder; on the next build the ones it no longer writes are removed\n",
    );
    for n in &names {
        text.push_str(n);
        text.push('\n');
    }
    write_if_changed(&manifest, &text)
        .map_err(|e| format!("error: cannot write `{}`: {e}", manifest.display()))
}

/// Write via a temporary file and rename, so a reader never sees half a file;
/// skip the write when the content is unchanged, so cargo does not rebuild.
pub fn write_if_changed(path: &Path, content: &str) -> std::io::Result<()> {
    if std::fs::read(path).is_ok_and(|old| old == content.as_bytes()) {
        return Ok(());
    }
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let tmp = path.with_extension(format!("rs.tmp{}", std::process::id()));
    std::fs::write(&tmp, content)?;
    std::fs::rename(&tmp, path).inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_only_when_changed() {
        let dir = std::env::temp_dir().join(format!("il-builder-{}", std::process::id()));
        let p = dir.join("x.rs");
        write_if_changed(&p, "a").unwrap();
        let t1 = std::fs::metadata(&p).unwrap().modified().unwrap();
        std::thread::sleep(std::time::Duration::from_millis(20));
        write_if_changed(&p, "a").unwrap();
        assert_eq!(std::fs::metadata(&p).unwrap().modified().unwrap(), t1);
        write_if_changed(&p, "b").unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "b");
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn missing_file_is_an_error_naming_it() {
        let dir = std::env::temp_dir().join(format!("il-builder-miss-{}", std::process::id()));
        let e = Builder::new()
            .file("no/such/file.il")
            .out_dir(&dir)
            .cargo_directives(false)
            .compile()
            .unwrap_err();
        assert!(e.to_string().contains("no/such/file.il"), "{e}");
        assert!(!dir.join("file.rs").exists());
    }

    #[test]
    #[cfg(feature = "encodings")]
    fn text_in_other_encodings_is_read_and_bad_bytes_are_located() {
        let dir = std::env::temp_dir().join(format!("il-builder-enc-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let latin1 = dir.join("latin1.il");
        std::fs::write(&latin1, b"PROGRAM p\n(* Gr\xF6\xDFe *)\nEND_PROGRAM\n").unwrap();
        let utf16 = dir.join("utf16.il");
        let mut bytes = vec![0xFF, 0xFE];
        bytes.extend(
            "PROGRAM q\n(* Größe *)\nEND_PROGRAM\n"
                .encode_utf16()
                .flat_map(u16::to_le_bytes),
        );
        std::fs::write(&utf16, bytes).unwrap();
        // Windows-1252 (guessed) and UTF-16 (by its byte order mark).
        for file in [&latin1, &utf16] {
            let out = Builder::new()
                .file(file)
                .out_dir(&dir)
                .cargo_directives(false)
                .compile()
                .unwrap();
            let rs = std::fs::read_to_string(&out[0]).unwrap();
            assert!(rs.contains("pub struct"), "{rs}");
        }
        // Named UTF-8, the bad byte is an error at its line and column.
        let e = Builder::new()
            .file(&latin1)
            .out_dir(&dir)
            .cargo_directives(false)
            .encoding("utf-8")
            .compile()
            .unwrap_err()
            .to_string();
        assert!(e.contains("error[IL0040]"), "{e}");
        assert!(e.contains(&format!("{}:2:6", latin1.display())), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    #[cfg(feature = "plcopen")]
    fn plcopen_file_becomes_stem_rs_and_errors_show_xml_lines() {
        let dir = std::env::temp_dir().join(format!("il-builder-xml-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let xml = dir.join("cell.xml");
        let project = |body: &str| {
            format!(
                "<project>\n<types><pous>\n<pou name=\"P\" pouType=\"program\">\n\
                 <interface><localVars><variable name=\"x\"><type><INT/></type></variable>\
                 </localVars></interface>\n<body><IL><p><![CDATA[{body}]]></p></IL></body>\n\
                 </pou>\n</pous></types>\n</project>\n"
            )
        };
        std::fs::write(&xml, project("LD x\nADD 1\nST x\n")).unwrap();
        let build = || {
            Builder::new()
                .plcopen_file(&xml)
                .out_dir(dir.join("out"))
                .cargo_directives(false)
                .compile()
        };
        let written = build().unwrap();
        assert_eq!(written, [dir.join("out").join("cell.rs")]);
        let code = std::fs::read_to_string(&written[0]).unwrap();
        assert!(code.contains("pub struct P"), "{code}");
        assert!(code.contains("// 6: ADD 1"), "{code}");
        let t1 = std::fs::metadata(&written[0]).unwrap().modified().unwrap();
        std::thread::sleep(std::time::Duration::from_millis(20));
        build().unwrap();
        assert_eq!(
            std::fs::metadata(&written[0]).unwrap().modified().unwrap(),
            t1
        );
        std::fs::write(&xml, project("LD x\nADD y\nST x\n")).unwrap();
        let e = build().unwrap_err().to_string();
        assert!(e.contains("cell.xml:6:5"), "{e}");
        assert!(e.contains("6 | ADD y"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    fn temp(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("il-builder-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// Forget this process's Builders in `dir` when `run` changes: the next
    /// compile is the first Builder of a new build-script run.
    fn new_run(dir: &Path, run: &str) {
        static LAST: std::sync::Mutex<Vec<(PathBuf, String)>> = std::sync::Mutex::new(Vec::new());
        let mut last = LAST.lock().unwrap();
        if !last.iter().any(|(d, r)| d == dir && r == run) {
            last.retain(|(d, _)| d != dir);
            last.push((dir.to_path_buf(), run.to_string()));
            let mut g = runs();
            g.0.remove(dir);
            g.1.retain(|(d, _)| d != dir);
        }
    }

    fn prog(name: &str) -> String {
        format!("PROGRAM {name}\nVAR x : INT; END_VAR\n  LD x\n  ST x\nEND_PROGRAM\n")
    }

    #[test]
    #[cfg(feature = "plcopen")]
    fn two_inputs_with_one_stem_are_refused_and_nothing_is_written() {
        let dir = temp("clash");
        for (sub, file, pou) in [("a", "m.il", "A"), ("b", "m.il", "B"), ("c", "M.xml", "C")] {
            std::fs::create_dir_all(dir.join(sub)).unwrap();
            std::fs::write(dir.join(sub).join(file), prog(pou)).unwrap();
        }
        let out = dir.join("out");
        std::fs::create_dir_all(&out).unwrap();
        std::fs::write(out.join("m.rs"), "// earlier output\n").unwrap();
        let e = Builder::new()
            .file(dir.join("a/m.il"))
            .file(dir.join("b/m.il"))
            .out_dir(&out)
            .cargo_directives(false)
            .compile()
            .unwrap_err()
            .to_string();
        assert!(e.contains("a/m.il") && e.contains("b/m.il"), "{e}");
        assert!(e.contains("out/m.rs"), "{e}");
        assert_eq!(
            std::fs::read_to_string(out.join("m.rs")).unwrap(),
            "// earlier output\n"
        );
        // Case differs only: the same file on macOS and Windows.
        let e = Builder::new()
            .file(dir.join("a/m.il"))
            .plcopen_file(dir.join("c/M.xml"))
            .out_dir(&out)
            .cargo_directives(false)
            .compile()
            .unwrap_err()
            .to_string();
        assert!(e.contains("a/m.il") && e.contains("c/M.xml"), "{e}");
        assert_eq!(std::fs::read_dir(&out).unwrap().count(), 1);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn outputs_no_longer_produced_are_removed_only_if_the_builder_wrote_them() {
        let dir = temp("stale");
        for n in ["x", "y", "z"] {
            std::fs::write(dir.join(format!("{n}.il")), prog(&n.to_uppercase())).unwrap();
        }
        let out = dir.join("out");
        let build = |files: &[&str], run: &str| {
            new_run(&out, run);
            Builder::new()
                .files(files.iter().map(|f| dir.join(f)))
                .out_dir(&out)
                .cargo_directives(false)
                .compile()
        };
        build(&["x.il", "y.il", "z.il"], "1").unwrap();
        assert!(out.join("y.rs").exists() && out.join("z.rs").exists());
        // z.rs edited by hand since: no longer the Builder's to remove.
        std::fs::write(out.join("z.rs"), "// mine now\n").unwrap();
        // A file the Builder never wrote, and a manifest line pointing outside.
        std::fs::write(
            out.join("w.rs"),
            "// @generated by il-codegen, but not listed\n",
        )
        .unwrap();
        std::fs::write(
            dir.join("outside.rs"),
            "// @generated by il-codegen from x\n",
        )
        .unwrap();
        let m = std::fs::read_to_string(out.join(MANIFEST)).unwrap();
        std::fs::write(out.join(MANIFEST), format!("{m}../outside.rs\n")).unwrap();
        let written = build(&["x.il"], "2").unwrap();
        assert_eq!(written, [out.join("x.rs")]);
        assert!(out.join("x.rs").exists());
        assert!(!out.join("y.rs").exists(), "stale y.rs kept");
        assert_eq!(
            std::fs::read_to_string(out.join("z.rs")).unwrap(),
            "// mine now\n"
        );
        assert!(out.join("w.rs").exists() && dir.join("outside.rs").exists());
        let m = std::fs::read_to_string(out.join(MANIFEST)).unwrap();
        assert!(m.lines().any(|l| l == "x.rs") && !m.contains("y.rs"), "{m}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn builders_of_one_run_share_a_directory() {
        let dir = temp("shared");
        for n in ["x", "y"] {
            std::fs::write(dir.join(format!("{n}.il")), prog(&n.to_uppercase())).unwrap();
        }
        let out = dir.join("out");
        let build = |file: &str, run: &str| {
            new_run(&out, run);
            Builder::new()
                .file(dir.join(file))
                .out_dir(&out)
                .cargo_directives(false)
                .compile()
        };
        build("x.il", "1").unwrap();
        build("y.il", "1").unwrap();
        assert!(out.join("x.rs").exists() && out.join("y.rs").exists());
        assert!(out.join(format!("{MANIFEST}-1")).exists());
        // The next run of the same two Builders removes and rewrites nothing.
        let t = |f: &str| std::fs::metadata(out.join(f)).unwrap().modified().unwrap();
        let (tx, ty) = (t("x.rs"), t("y.rs"));
        std::thread::sleep(std::time::Duration::from_millis(20));
        build("x.il", "2").unwrap();
        assert!(
            out.join("y.rs").exists(),
            "the first Builder removed the second's file"
        );
        build("y.il", "2").unwrap();
        assert_eq!((t("x.rs"), t("y.rs")), (tx, ty));
        // A third run without the second Builder: its files stay (its own
        // manifest is not read), the first Builder's are kept as well.
        build("x.il", "3").unwrap();
        assert!(out.join("x.rs").exists() && out.join("y.rs").exists());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
