//! The new user's path, as the README tells it: a crate of their own with
//! `il!`, another with build.rs, both binaries around the two-file tank
//! controller of `tests/new-user/plc` (an enum, a struct, a subrange, timers,
//! a counter, a FUNCTION with an output, jumps, direct addresses), then a
//! deliberate mistake in the IL of each.
//!
//! The two crates are built by cargo outside this workspace, offline, with
//! path dependencies and one target directory of their own under
//! `target/tests/new-user` (this workspace's is locked by the running
//! `cargo test`). They must build without a single warning: generated code
//! in a binary, inside a `mod`, glob-imported, uses few of its items.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The top of the libraries of both crates: a user who wants every public
/// item documented and clippy's pedantic lints (the test runs clippy).
const LIB_HEADER: &str =
    "//! The tank controller.\n#![warn(missing_docs, clippy::pedantic)]\n#![deny(warnings)]\n";

/// The main.rs of both crates: the shared host loop, printed.
const MAIN: &str = "use plc::*;\ninclude!(\"host.rs\");\n\nfn main() {\n    for line in run() {\n        println!(\"{line}\");\n    }\n}\n";

/// The same loop in this workspace, through `il!(files = [...])`.
mod host {
    use il_tests::tank_macro::{Tank, TankState};
    include!("../../new-user/host.rs");
}

fn plc_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("new-user/plc")
}

#[test]
fn the_tank_from_two_files_fills_holds_and_drains() {
    let lines = host::run();
    // 18 scans of 50 reach 900 raw = 90 %, the high mark.
    assert!(lines[17].contains("Filling") && lines[17].contains("pump true"));
    assert!(lines[18].contains("Full") && lines[18].contains("pump false"));
    assert!(lines[18].contains("fills 1"), "{}", lines[18]);
    assert!(lines[18].contains("lamp false"));
    assert!(lines[29].contains("Full"));
    assert!(lines[30].contains("Draining"), "{}", lines[30]);
    // 900 raw drains 100 a scan: at 5 % or less it is Idle again, and stays
    // Idle while the drain is asked for.
    let last = lines.last().unwrap();
    assert!(last.contains("Idle") && last.contains("fills 1"), "{last}");
    assert!(lines[5].contains("lamp true"), "the lamp follows the pump");
}

/// The Cargo.toml of a user's crate.
enum Manifest<'a> {
    /// The README's, for a build.rs user (`"build.rs"`) or an `il!` user (`"il!"`).
    Readme(&'a str),
    /// A package depending on il-std and on these lines (`{il-macros}`
    /// stands for il-macros).
    Extra(&'a str),
}
use Manifest::{Extra, Readme};

/// The ```` ```toml ```` block after `<!-- Cargo.toml of a KIND user -->`
/// in the README; the guide shows the same.
fn readme_manifest(kind: &str) -> String {
    let marker = format!("<!-- Cargo.toml of a {kind} user -->");
    let block = |doc: &str| -> String {
        let text = std::fs::read_to_string(workspace().join(doc)).unwrap();
        let at = text
            .find(&marker)
            .unwrap_or_else(|| panic!("{doc} has no `{marker}`"));
        let rest = text[at..].split_once("```toml\n").expect("a toml block").1;
        rest.split_once("```").expect("closed").0.to_string()
    };
    let readme = block("README.md");
    assert_eq!(readme, block("docs/guide.md"), "README and guide differ");
    readme
}

/// `name = "0.1"` of this workspace's crates as path dependencies, after
/// checking that the README names them and their version as they are.
fn local(manifest: &str) -> String {
    let ws = workspace();
    let version = std::fs::read_to_string(ws.join("Cargo.toml")).unwrap();
    assert!(
        version.contains("\nversion = \"0.1.0\"\n"),
        "the README's \"0.1\" is stale"
    );
    let mut out = String::new();
    for line in manifest.lines() {
        match line.strip_suffix(" = \"0.1\"") {
            Some(krate) if krate.starts_with("il-") => {
                assert!(
                    ws.join(krate).join("Cargo.toml").exists(),
                    "no crate {krate}"
                );
                out.push_str(&format!("{krate} = {{ path = {:?} }}\n", ws.join(krate)));
            }
            _ => {
                out.push_str(line);
                out.push('\n');
            }
        }
    }
    out
}

/// A crate of the user's, written into `root/name`.
fn write_crate(root: &Path, name: &str, cargo_extra: Manifest, files: &[(&str, &str)]) -> PathBuf {
    let ws = workspace();
    let dir = root.join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("src")).unwrap();
    std::fs::create_dir_all(dir.join("plc")).unwrap();
    let dep = |c: &str| format!("{c} = {{ path = {:?} }}\n", ws.join(c));
    let manifest = match cargo_extra {
        // The README's whole Cargo.toml, with this workspace's crates as
        // path dependencies.
        Readme(kind) => local(&readme_manifest(kind)).replace("name = \"tank\"", &format!("name = \"{name}\"")),
        Extra(extra) => format!(
            "[package]\nname = \"{name}\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
             [dependencies]\n{}{extra}\n",
            dep("il-std")
        )
        .replace("{il-macros}", &dep("il-macros")),
    };
    std::fs::write(dir.join("Cargo.toml"), format!("{manifest}\n[workspace]\n")).unwrap();
    for f in ["types.il", "tank.il"] {
        std::fs::copy(plc_dir().join(f), dir.join("plc").join(f)).unwrap();
    }
    std::fs::copy(plc_dir().join("../host.rs"), dir.join("src/host.rs")).unwrap();
    for (path, text) in files {
        std::fs::write(dir.join(path), text).unwrap();
    }
    // This workspace's versions of the dependencies, all in the local cache.
    std::fs::copy(ws.join("Cargo.lock"), dir.join("Cargo.lock")).unwrap();
    dir
}

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .canonicalize()
        .expect("workspace root")
}

fn cargo(dir: &Path, target: &Path, args: &[&str]) -> Output {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    Command::new(cargo)
        .args(args)
        .arg("--offline")
        .current_dir(dir)
        .env("CARGO_TARGET_DIR", target)
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .output()
        .expect("run cargo")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Builds and runs the crate: no warning anywhere, and the same time-line
/// as [`run_here`].
fn builds_clean_and_runs(dir: &Path, target: &Path) {
    let out = cargo(dir, target, &["run", "--quiet"]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{}:\n{stderr}", dir.display());
    assert!(
        !stderr.contains("warning"),
        "{} warns:\n{stderr}",
        dir.display()
    );
    let stdout = text(&out.stdout);
    let got: Vec<&str> = stdout.lines().collect();
    assert_eq!(got, host::run(), "{}", dir.display());
    // The library's `deny(warnings)` makes clippy's warnings errors.
    if dir.join("src/lib.rs").exists() {
        let out = cargo(dir, target, &["clippy", "--quiet", "--lib"]);
        let stderr = text(&out.stderr);
        assert!(
            out.status.success(),
            "clippy on {}:\n{stderr}",
            dir.display()
        );
        assert!(!stderr.contains("warning"), "{stderr}");
    }
}

/// `tank.il` with an INT stored into the BOOL `pump`; returns the line and
/// column the error must name.
fn break_tank(dir: &Path) -> (usize, usize) {
    let path = dir.join("plc/tank.il");
    let good = std::fs::read_to_string(&path).unwrap();
    let bad = good.replacen("    LD   valve.open\n", "    LD   high\n", 1);
    assert_ne!(good, bad);
    std::fs::write(&path, &bad).unwrap();
    let line = bad.lines().position(|l| l == "    LD   high").unwrap() + 2;
    (line, 5)
}

#[test]
fn a_new_users_crates_build_without_warnings_and_show_il_errors() {
    let ws = workspace();
    let root = ws.join("target/tests/new-user");
    let target = root.join("target");

    // 1. `il!` in a library that asks for docs and clippy's pedantic lints,
    //    and in a binary: both files in one call, in a `mod`, glob-imported.
    let macro_lib =
        format!("{LIB_HEADER}il_macros::il!(files = [\"plc/types.il\", \"plc/tank.il\"]);\n");
    let with_macro = write_crate(
        &root,
        "tank-macro",
        Readme("il!"),
        &[
            ("src/lib.rs", &macro_lib),
            (
                "src/main.rs",
                &format!(
                    "mod plc {{\n    il_macros::il!(files = [\"plc/types.il\", \"plc/tank.il\"]);\n}}\n{MAIN}"
                ),
            ),
        ],
    );
    builds_clean_and_runs(&with_macro, &target);

    // 2. build.rs as the README writes it, a library including the files at
    //    its root and a binary including them in a `mod`.
    //    The README quotes these lines (il-cli's docs test checks it).
    let build_rs = r#"
// build.rs
fn main() {
    il_codegen::Builder::new()
        .file("plc/types.il")
        .file("plc/tank.il")
        .compile_or_report();
}
"#;
    let include = r#"
// src/lib.rs, or inside a `mod` of src/main.rs
include!(concat!(env!("OUT_DIR"), "/types.rs"));
include!(concat!(env!("OUT_DIR"), "/tank.rs"));
"#;
    let with_build = write_crate(
        &root,
        "tank-build",
        Readme("build.rs"),
        &[
            ("build.rs", build_rs),
            ("src/lib.rs", &format!("{LIB_HEADER}{include}")),
            ("src/main.rs", &format!("mod plc {{\n{include}}}\n{MAIN}")),
        ],
    );
    builds_clean_and_runs(&with_build, &target);

    // 3. A mistake in the IL: both front ends report it as rustc reports its
    //    own, `error: IL0106: ...` with the IL file's arrow on the next line,
    //    which is what the `$rustc` problem matcher of VS Code's
    //    rust-analyzer extension reads (its patterns: a line
    //    `^(warning|warn|error)(?:\[(.*?)\])?: (.*)$`, then
    //    `^[\s->=]*(.*?):([1-9]\d*):([1-9]\d*)\s*$`).
    for dir in [&with_macro, &with_build] {
        let (line, col) = break_tank(dir);
        let out = cargo(dir, &target, &["build", "--quiet"]);
        let stderr = text(&out.stderr);
        assert!(!out.status.success(), "the build must fail:\n{stderr}");
        let lines: Vec<&str> = stderr.lines().collect();
        let at = lines
            .iter()
            .position(|l| *l == "error: IL0106: `pump` is BOOL, but the current result is INT")
            .unwrap_or_else(|| panic!("no rustc-like error line:\n{stderr}"));
        let arrow = format!("--> plc/tank.il:{line}:{col}");
        assert_eq!(lines[at + 1].trim_start(), arrow, "{stderr}");
        assert!(stderr.contains("|     ST   pump"), "no snippet:\n{stderr}");
        assert!(!stderr.contains("custom build command"), "{stderr}");
    }
    // A failure that is not about the IL fails the build script, with one
    // `error:` line from cargo.
    let script = with_build.join("build.rs");
    let text_rs = std::fs::read_to_string(&script).unwrap();
    std::fs::write(&script, text_rs.replace("plc/tank.il", "plc/missing.il")).unwrap();
    let out = cargo(&with_build, &target, &["build", "--quiet"]);
    let stderr = text(&out.stderr);
    assert!(!out.status.success(), "the build must fail:\n{stderr}");
    assert!(
        stderr
            .lines()
            .any(|l| l
                .starts_with("error: tank-build@0.1.0: cannot read source file `plc/missing.il`")),
        "{stderr}"
    );

    // 4. A PLCopen project in `il!`: il-macros leaves the XML import out by
    //    default (its cold build is the issue-16 target), so the call fails
    //    with IL0210 saying which feature to name; named, it builds and runs.
    let xml_main = "mod plc {\n    il_macros::il!(file = \"plc/counter.xml\");\n}\n\nfn main() {\n    let mut ctx = il_std::Cycle::new();\n    let mut c = plc::Counter::default();\n    c.call(&mut ctx);\n    c.call(&mut ctx);\n    println!(\"count {}\", c.Count);\n}\n";
    let files = [("src/main.rs", xml_main), ("plc/counter.xml", COUNTER_XML)];
    let without = write_crate(&root, "xml-default", Extra("{il-macros}"), &files);
    let out = cargo(&without, &target, &["build", "--quiet"]);
    let stderr = text(&out.stderr);
    assert!(!out.status.success(), "the build must fail:\n{stderr}");
    assert!(stderr.contains("IL0210"), "{stderr}");
    assert!(
        stderr.contains(r#"`il-macros = { version = "0.1", features = ["plcopen"] }`"#),
        "the message must say what to write:\n{stderr}"
    );
    let named = format!(
        "il-macros = {{ path = {:?}, features = [\"plcopen\"] }}\n",
        ws.join("il-macros")
    );
    let with = write_crate(&root, "xml-feature", Extra(&named), &files);
    let out = cargo(&with, &target, &["run", "--quiet"]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(!stderr.contains("warning"), "warns:\n{stderr}");
    assert_eq!(text(&out.stdout), "count 2\n");
}

/// A PLCopen TC6 project with one IL function block: counts its calls.
const COUNTER_XML: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="t"/>
  <types>
    <dataTypes/>
    <pous>
      <pou name="Counter" pouType="functionBlock">
        <interface>
          <inputVars><variable name="Reset"><type><BOOL/></type></variable></inputVars>
          <outputVars><variable name="Count"><type><INT/></type></variable></outputVars>
        </interface>
        <body><IL><xhtml:p><![CDATA[LD Reset
JMPC clear
LD Count
ADD 1
ST Count
RET
clear:
LD 0
ST Count]]></xhtml:p></IL></body>
      </pou>
    </pous>
  </types>
  <instances><configurations/></instances>
</project>
"#;
