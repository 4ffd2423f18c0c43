//! `il_codegen::format`: the layout of a messy file (a golden file), and on
//! every IL file we have (the examples, the test programs, the shared
//! corpus): a file is formatted unless it has syntax errors, formatting it
//! again changes nothing, and the formatted file compiles to the same Rust
//! (or to the same diagnostics, at the same lines).

use il_codegen::diag::SourceFile;
use il_codegen::format::{FormatOptions, KeywordCase, format};
use il_codegen::{EmitOptions, Program};
use std::path::{Path, PathBuf};

const DIR: &str = env!("CARGO_MANIFEST_DIR");

fn fmt(name: &str, text: &str, keywords: KeywordCase) -> String {
    let f = SourceFile::new(name, text);
    format(&f, &FormatOptions { keywords }).unwrap_or_else(|d| panic!("{name}: {d:?}"))
}

#[test]
fn a_messy_file_is_laid_out_as_plc_ides_show_it() {
    let dir = Path::new(DIR).join("tests/format");
    let text = std::fs::read_to_string(dir.join("messy.il")).unwrap();
    let out = fmt("messy.il", &text, KeywordCase::AsTheFile);
    il_testkit::golden::assert_golden(&dir, "messy.formatted", &out);
    assert_eq!(
        fmt("messy.il", &out, KeywordCase::AsTheFile),
        out,
        "idempotent"
    );
    let lower = fmt("messy.il", &text, KeywordCase::Lower);
    assert!(lower.contains("    andn  stop"), "{lower}");
    assert!(lower.contains("end_function_block"), "{lower}");
    // Names, literals and addresses keep their case.
    assert!(
        lower.contains("R_TRIG") && lower.contains("edge.Q"),
        "{lower}"
    );
    let kept = fmt("messy.il", &text, KeywordCase::Preserve);
    assert!(
        kept.contains("function_block Motor") && kept.contains("    andn  stop"),
        "{kept}"
    );
}

#[test]
fn a_file_with_syntax_errors_is_not_formatted() {
    let f = SourceFile::new(
        "bad.il",
        "PROGRAM p\nVAR x : INT END_VAR\n LD x\nEND_PROGRAM\n",
    );
    let errs = format(&f, &FormatOptions::default()).unwrap_err();
    assert!(errs.iter().all(|d| d.is_error()) && !errs.is_empty());
}

#[test]
fn crlf_and_a_byte_order_mark_are_kept() {
    let out = fmt(
        "w.il",
        "\u{feff}PROGRAM p\r\nVAR x:INT; END_VAR\r\n LD x\r\n  ST x\r\nEND_PROGRAM\r\n",
        KeywordCase::AsTheFile,
    );
    assert_eq!(
        out,
        "\u{feff}PROGRAM p\r\nVAR x : INT; END_VAR\r\n    LD  x\r\n    ST  x\r\nEND_PROGRAM\r\n"
    );
}

/// Every IL file we have: (path, text).
fn all_files() -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut add = |dir: PathBuf, exts: &[&str]| {
        let Ok(rd) = std::fs::read_dir(&dir) else {
            println!("SKIPPED: {} not found", dir.display());
            return;
        };
        let mut v: Vec<PathBuf> = rd
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| {
                p.extension()
                    .and_then(|e| e.to_str())
                    .is_some_and(|e| exts.contains(&e))
            })
            .collect();
        v.sort();
        files.extend(v);
    };
    let root = Path::new(DIR).join("..");
    add(root.join("examples"), &["il"]);
    add(root.join("tests/plc"), &["il"]);
    add(root.join("il-codegen/tests/format"), &["il"]);
    add(root.join("../shared/corpus"), &["il", "txt", "test"]);
    files
}

/// What a program compiles to: its Rust, or its diagnostics by code and line.
fn meaning(f: SourceFile) -> String {
    let checked = Program::new().il(f.clone()).check();
    match checked.emit(EmitOptions::default()) {
        Some(e) => e.iter().map(|e| e.text.clone()).collect(),
        None => checked
            .diagnostics()
            .iter()
            .flatten()
            .map(|d| format!("{} {}\n", d.code, f.line_col(d.span.lo).0))
            .collect(),
    }
}

#[test]
fn every_file_we_have_keeps_its_meaning_and_formats_once() {
    let (mut formatted, mut refused) = (0, Vec::new());
    for path in all_files() {
        let name = path.display().to_string();
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let f = SourceFile::new(name.clone(), text);
        let out = match format(&f, &FormatOptions::default()) {
            Ok(out) => out,
            Err(d) => {
                // Only a file with syntax errors may be refused.
                assert!(d.iter().all(|d| d.code != "IL0049"), "{name}: {:?}", d);
                refused.push(name);
                continue;
            }
        };
        formatted += 1;
        let g = SourceFile::new(name.clone(), out.clone());
        assert_eq!(
            format(&g, &FormatOptions::default()).as_deref(),
            Ok(out.as_str()),
            "{name}: not idempotent"
        );
        assert_eq!(meaning(f), meaning(g), "{name}: the meaning changed");
    }
    println!("formatted {formatted} files; not formatted (syntax errors): {refused:?}");
    assert!(formatted >= 40, "only {formatted} files formatted");
}
