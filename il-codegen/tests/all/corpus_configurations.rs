//! The echidna corpus files end with a CONFIGURATION. Their bodies use
//! echidna built-ins (`dbg`, `_exit`, `piface_write`), which are not IEC and
//! are refused (see il-cli/tests/corpus.rs); here those lines are
//! dropped, and the configurations must be accepted: no diagnostic at or
//! after the CONFIGURATION line. The blink program, which has nothing else
//! non-standard, then compiles whole, configuration included.

use il_codegen::diag::{Severity, SourceFile};

const CORPUS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus");

fn without_builtins(text: &str) -> String {
    text.lines()
        .map(|l| {
            let first = l
                .split_whitespace()
                .next()
                .unwrap_or("")
                .to_ascii_lowercase();
            if ["dbg", "_exit", "piface_write"].contains(&first.as_str()) {
                "" // keep the line numbers
            } else {
                l
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn echidna_configurations_are_accepted() {
    let dir = std::path::Path::new(CORPUS);
    if !dir.exists() {
        println!(
            "SKIPPED: ../shared/corpus not found (corpus tests need the shared folder beside the checkout)"
        );
        return;
    }
    let mut seen = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if !name.starts_with("61131_echidna_") {
            continue;
        }
        let text = without_builtins(&std::fs::read_to_string(&path).unwrap());
        let config_line = text
            .lines()
            .position(|l| {
                l.trim_start()
                    .to_ascii_lowercase()
                    .starts_with("configuration")
            })
            .unwrap_or_else(|| panic!("{name}: no CONFIGURATION"))
            + 1;
        let file = SourceFile::new(name.clone(), text);
        let program = il_codegen::Program::new().il(file.clone());
        let checked = program.check();
        let diags = &checked.diagnostics()[0];
        for d in diags {
            let (line, _) = file.line_col(d.span.lo);
            assert!(
                line < config_line,
                "{name}:{line}: {} {} (in the CONFIGURATION)",
                d.code,
                d.message
            );
        }
        if name == "61131_echidna_blink.il" {
            assert!(
                diags.iter().all(|d| d.severity != Severity::Error),
                "{name}: {diags:?}"
            );
            let out = checked
                .emit(Default::default())
                .unwrap_or_else(|| panic!("{name}: {diags:?}"))
                .remove(0)
                .text
                .to_string();
            assert!(
                out.contains("pub struct config1"),
                "{name}: no configuration struct"
            );
        }
        seen += 1;
    }
    assert_eq!(seen, 5, "the five echidna files");
}
