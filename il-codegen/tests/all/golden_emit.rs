//! Golden files of the emitted Rust: `golden/*.il` → `golden/*.rs`.
//! Refresh with `IL_BLESS=1 cargo test -p il-codegen --test all golden_emit`.

use il_codegen::diag::SourceFile;
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
        let program = il_codegen::Program::new().il(file);
        let checked = program.check();
        let opts = il_codegen::EmitOptions {
            line_markers: true,
            ..Default::default()
        };
        let code = match checked.emit(opts) {
            Some(e) => e[0].file_text(),
            None => panic!("{}", checked.render(false)),
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

/// The emitter writes text that only `il!` turns into tokens: every golden
/// input's text (as `il!` gets it, and as the file build.rs writes) must
/// parse as a Rust file.
#[test]
fn emitted_text_of_every_golden_input_parses_as_rust() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let mut n = 0;
    for il in std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
    {
        if il.extension().is_none_or(|e| e != "il") {
            continue;
        }
        let file = SourceFile::new("g.il", std::fs::read_to_string(&il).unwrap());
        let checked = il_codegen::Program::new().il(file).check();
        for serde in [false, true] {
            let opts = il_codegen::EmitOptions {
                serde,
                ..Default::default()
            };
            let e = checked.emit(opts).expect("golden inputs compile");
            if let Err(err) = syn::parse_file(&e[0].text) {
                panic!("{}: {err}\n{}", il.display(), e[0].text);
            }
        }
        let files = checked.files(Default::default()).unwrap();
        syn::parse_file(&files[0]).unwrap_or_else(|err| panic!("{}: {err}", il.display()));
        n += 1;
    }
    assert!(n >= 6, "{n} golden inputs");
}
