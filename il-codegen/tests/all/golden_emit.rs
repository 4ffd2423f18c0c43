//! Golden files of the emitted Rust: `golden/*.il` → `golden/*.rs`.
//! Refresh with `IL_BLESS=1 cargo test -p il-codegen --test all golden_emit`.

use il_codegen::diag::{SourceFile, render::render};
use std::path::Path;

#[test]
fn emitted_rust_matches_golden_files() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let bless = std::env::var_os("IL_BLESS").is_some();
    let mut inputs: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    inputs.sort();
    assert!(inputs.len() >= 6);
    let mut stale = Vec::new();
    for il in inputs {
        let name = format!("golden/{}", il.file_name().unwrap().to_string_lossy());
        let file = SourceFile::new(name, std::fs::read_to_string(&il).unwrap());
        let code = match il_codegen::compile_to_file(&file) {
            Ok((code, _)) => code,
            Err(d) => panic!("{}", render(&file, &d, false)),
        };
        let expected = il.with_extension("rs");
        if bless {
            std::fs::write(&expected, &code).unwrap();
        } else if std::fs::read_to_string(&expected).ok().as_deref() != Some(code.as_str()) {
            stale.push(expected.display().to_string());
        }
    }
    assert!(
        stale.is_empty(),
        "emitted code differs from {stale:?}; review and run with IL_BLESS=1"
    );
}
