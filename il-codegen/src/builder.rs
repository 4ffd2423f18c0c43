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
//! `.plcopen_file("plc/project.xml")` and becomes `$OUT_DIR/project.rs`.

use crate::diag::render::render;
use crate::pipeline::{Input, Program};
use std::fmt;
use std::path::{Path, PathBuf};

/// Compiles IL files to Rust files, for build scripts.
#[derive(Clone, Debug, Default)]
pub struct Builder {
    /// Each file, and whether it is PLCopen XML.
    files: Vec<(PathBuf, bool)>,
    out_dir: Option<PathBuf>,
    cargo_directives: Option<bool>,
    serde: bool,
}

/// A failed build: every diagnostic of every file, rendered like rustc.
#[derive(Debug)]
pub struct Error {
    rendered: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.rendered)
    }
}

impl std::error::Error for Error {}

impl Builder {
    /// A builder with no files; output goes to `$OUT_DIR`.
    pub fn new() -> Self {
        Builder::default()
    }

    /// Add an IL source file (relative paths are relative to the crate root,
    /// where cargo runs build scripts).
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

    /// Compile every file. Nothing is written unless every file compiles;
    /// each output is written atomically and only when its content changed.
    /// Returns the paths of the generated files.
    pub fn compile(self) -> Result<Vec<PathBuf>, Error> {
        let cargo = self
            .cargo_directives
            .unwrap_or_else(|| std::env::var_os("OUT_DIR").is_some());
        let out_dir = match self.out_dir.clone().or_else(|| std::env::var_os("OUT_DIR").map(PathBuf::from)) {
            Some(d) => d,
            None => return Err(Error { rendered: "error: no output directory: OUT_DIR is not set (call Builder::out_dir outside build scripts)".into() }),
        };
        let mut sources = Vec::new();
        let mut failed = String::new();
        for (path, xml) in &self.files {
            if cargo {
                println!("cargo:rerun-if-changed={}", path.display());
            }
            match crate::read::read_source(path, &path.display().to_string()) {
                Ok(file) => {
                    sources.push(if *xml {
                        Input::plcopen(file)
                    } else {
                        Input::il(file)
                    });
                }
                Err(e) => failed.push_str(&format!(
                    "error: cannot read {} file `{}`: {}\n",
                    if *xml { "PLCopen XML" } else { "IL" },
                    e.path,
                    e.reason
                )),
            }
        }
        if !failed.is_empty() {
            return Err(Error { rendered: failed });
        }
        // All files form one program: a FUNCTION_BLOCK of one is usable in another.
        let program = sources.into_iter().fold(Program::new(), Program::input);
        let checked = program.check();
        let opts = crate::emit::Options {
            serde: self.serde,
            line_markers: true,
        };
        let Some(outputs) = checked.emit(opts) else {
            return Err(Error {
                rendered: checked.render(false),
            });
        };
        let mut planned = Vec::new();
        for (out, (path, _)) in outputs.iter().zip(&self.files) {
            if cargo && !out.warnings.is_empty() {
                for line in render(out.input().source(), &out.warnings, false).lines() {
                    println!("cargo:warning={line}");
                }
            }
            let code = out.file_text();
            let stem = path
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_else(|| "il".into());
            planned.push((out_dir.join(format!("{stem}.rs")), code));
        }
        let mut written = Vec::new();
        for (path, code) in planned {
            write_if_changed(&path, &code).map_err(|e| Error {
                rendered: format!("error: cannot write `{}`: {e}", path.display()),
            })?;
            written.push(path);
        }
        Ok(written)
    }
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
    fn unreadable_text_names_its_position_and_encoding() {
        let dir = std::env::temp_dir().join(format!("il-builder-enc-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let latin1 = dir.join("latin1.il");
        std::fs::write(&latin1, b"PROGRAM p\n(* Gr\xF6\xDFe *)\nEND_PROGRAM\n").unwrap();
        let utf16 = dir.join("utf16.il");
        let mut bytes = vec![0xFF, 0xFE];
        bytes.extend("PROGRAM p\n".encode_utf16().flat_map(u16::to_le_bytes));
        std::fs::write(&utf16, bytes).unwrap();
        for (file, want) in [
            (&latin1, "invalid byte 0xF6 at line 2, byte 6 of the line"),
            (
                &utf16,
                "UTF-16 text (little-endian, with a byte order mark)",
            ),
        ] {
            let e = Builder::new()
                .file(file)
                .out_dir(&dir)
                .cargo_directives(false)
                .compile()
                .unwrap_err();
            assert!(e.to_string().contains(want), "{e}");
            assert!(e.to_string().contains(&file.display().to_string()), "{e}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
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
}
