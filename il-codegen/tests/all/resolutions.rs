//! The resolution table ([`il_codegen::ir::Resolutions`]): what every name
//! of a program names. Pinned for corpus programs in `../resolutions`
//! (each name written, with its symbol and declaration; compared with the
//! language server's former index of its own when the table replaced it).
//! Refresh with `IL_BLESS=1 cargo test -p il-codegen --test all resolutions`.

use il_codegen::ir::{Resolutions, SymbolKind};
use il_codegen::{Checked, Program, SourceFile};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn check(files: &[(&str, String)]) -> Checked {
    let p = files
        .iter()
        .fold(Program::new().resolutions(true), |p, (n, t)| {
            p.source(SourceFile::new(n.to_string(), t.clone()))
        });
    p.check()
}

fn line_col(text: &str, off: u32) -> (usize, usize) {
    let before = &text[..off as usize];
    let line = before.matches('\n').count() + 1;
    let col = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
    (line, col)
}

/// Every name written, one line each: where, the name, what it names and
/// where that is declared.
fn dump(checked: &Checked) -> String {
    let t: &Resolutions = checked.resolutions().expect("asked for");
    let names: Vec<&str> = checked
        .inputs()
        .iter()
        .map(|i| i.source().name.as_str())
        .collect();
    let texts: Vec<&str> = checked
        .inputs()
        .iter()
        .map(|i| i.source().text.as_str())
        .collect();
    let mut out = String::new();
    for (f, uses) in t.uses.iter().enumerate() {
        for (span, id) in uses {
            let s = &t.symbols[*id];
            let (l, c) = line_col(texts[f], span.lo);
            let written = &texts[f][span.lo as usize..span.hi as usize];
            let kind = match s.kind {
                SymbolKind::Pou(k) => k.keyword().to_string(),
                SymbolKind::Var { kind, global, .. } => match global {
                    Some(g) => format!("{} of global {}", kind.keyword(), t.symbols[g].name),
                    None => kind.keyword().to_string(),
                },
                SymbolKind::StdMember { block, input } => format!(
                    "{} of {}",
                    if input { "input" } else { "output" },
                    t.symbols[block].name
                ),
                k => format!("{k:?}")
                    .split([' ', '{'])
                    .next()
                    .unwrap_or("")
                    .to_string(),
            };
            let decl = match s.decl {
                Some(d) if d.file == f && d.span == *span => "declared here".to_string(),
                Some(d) => {
                    let (dl, dc) = line_col(texts[d.file], d.span.lo);
                    format!("declared at {}:{dl}:{dc}", names[d.file])
                }
                None => "standard".to_string(),
            };
            out.push_str(&format!(
                "{}:{l}:{c} `{written}` -> {kind} {} ({decl})\n",
                names[f], s.name
            ));
        }
    }
    out
}

fn read(path: &Path) -> String {
    String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned()
}

#[test]
fn corpus_programs_resolve_as_pinned() {
    let bless = std::env::var_os("IL_BLESS").is_some();
    let mut examples: Vec<PathBuf> = std::fs::read_dir(root().join("examples/plc"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    examples.sort();
    let programs: Vec<(&str, Vec<PathBuf>)> = vec![
        ("examples", examples),
        ("jumps", vec![root().join("tests/plc/jumps.il")]),
        ("user_types", vec![root().join("tests/plc/user_types.il")]),
        ("cfg_forms", vec![root().join("tests/plc/cfg_forms.il")]),
        ("more_calls", vec![root().join("tests/plc/more_calls.il")]),
    ];
    let mut stale = Vec::new();
    for (name, files) in programs {
        let files: Vec<(String, String)> = files
            .iter()
            .map(|p| {
                (
                    p.file_name().unwrap().to_string_lossy().into_owned(),
                    read(p),
                )
            })
            .collect();
        let files: Vec<(&str, String)> =
            files.iter().map(|(n, t)| (n.as_str(), t.clone())).collect();
        let got = dump(&check(&files));
        let path = root().join(format!("il-codegen/tests/resolutions/{name}.txt"));
        if bless {
            std::fs::write(&path, &got).unwrap();
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(got.as_str()) {
            stale.push(name);
        }
    }
    assert!(
        stale.is_empty(),
        "resolutions differ from {stale:?}; review and run with IL_BLESS=1"
    );
}

/// The names the former index of the language server missed or could not
/// have: a VAR_EXTERNAL's global, enumeration values, unreachable code, a
/// file with a syntax error.
#[test]
fn what_the_table_adds() {
    let text = "TYPE Mode : (Idle, Run); END_TYPE\n\
        FUNCTION_BLOCK Fb\nVAR_EXTERNAL g : INT; END_VAR\nVAR m : Mode; END_VAR\n\
            LD Mode#Run\n    ST m\n    LD Idle\n    ST m\n    LD g\n    RET\n    LD g\n    ST g\nEND_FUNCTION_BLOCK\n\
        PROGRAM Main\nVAR f : Fb; END_VAR\n    CAL f\nEND_PROGRAM\n\
        CONFIGURATION C\nVAR_GLOBAL g : INT; END_VAR\nRESOURCE R ON PLC\nPROGRAM p : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n";
    let d = dump(&check(&[("a.il", text.to_string())]));
    for want in [
        "`g` -> VAR_EXTERNAL of global g g (declared here)",
        "a.il:5:4 `Mode` -> Type Mode (declared at a.il:1:6)",
        "a.il:5:9 `Run` -> EnumValue Run (declared at a.il:1:20)",
        "a.il:7:8 `Idle` -> EnumValue Idle (declared at a.il:1:14)",
        // After the RET: unreachable, still named.
        "a.il:11:8 `g` -> VAR_EXTERNAL of global g g (declared at a.il:3:14)",
        "a.il:12:8 `g` -> VAR_EXTERNAL of global g g (declared at a.il:3:14)",
        "`R` -> Resource R (declared here)",
        "`p` -> ProgramInstance p (declared here)",
        "`Main` -> PROGRAM Main (declared at a.il:14:9)",
    ] {
        assert!(d.contains(want), "{want}\nin\n{d}");
    }
    // A syntax error in one file: its names are still resolved.
    let lib = "FUNCTION_BLOCK Lib\nVAR_INPUT run : BOOL; END_VAR\nEND_FUNCTION_BLOCK\n";
    let main =
        "PROGRAM Main\nVAR l : Lib; x : INT; END_VAR\n    LD l.run\n    ST x )\nEND_PROGRAM\n";
    let checked = check(&[("lib.il", lib.into()), ("main.il", main.into())]);
    assert!(checked.has_errors());
    let d = dump(&checked);
    assert!(
        d.contains("main.il:3:10 `run` -> VAR_INPUT run (declared at lib.il:2:11)"),
        "{d}"
    );
}

/// Not asked for, nothing is recorded.
#[test]
fn not_recorded_unless_asked() {
    let checked = Program::new()
        .il(SourceFile::new(
            "a.il",
            "PROGRAM P\nVAR x : INT; END_VAR\n LD x\n ST x\nEND_PROGRAM\n",
        ))
        .check();
    assert!(checked.resolutions().is_none());
}
