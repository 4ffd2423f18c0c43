//! Temporary: the checker's resolution table against this index.
use super::*;
use il_codegen::{Program, SourceFile};

fn compare_dir(dir: &str, together: bool) -> (usize, Vec<String>) {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let mut files: Vec<_> = std::fs::read_dir(format!("{root}/{dir}"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    files.sort();
    if !together {
        let (mut n, mut out) = (0, Vec::new());
        for f in &files {
            let (a, b) = compare_files(&[f.clone()]);
            n += a;
            out.extend(b);
        }
        return (n, out);
    }
    compare_files(&files)
}

fn compare_files(files: &[std::path::PathBuf]) -> (usize, Vec<String>) {
    let mut p = Program::new().cr_steps(true).resolutions(true);
    for f in files {
        p = p.source(SourceFile::new(
            f.file_name().unwrap().to_string_lossy().into_owned(),
            String::from_utf8_lossy(&std::fs::read(f).unwrap()).into_owned(),
        ));
    }
    let checked = p.check();
    let ix = Index::build(&checked);
    let t = checked.resolutions().unwrap();
    let mut out = Vec::new();
    let mut n = 0;
    for (f, file) in ix.files.iter().enumerate() {
        let name = &checked.inputs()[f].source().name;
        let text = &checked.inputs()[f].source().text;
        for (span, target) in &file.refs {
            n += 1;
            let got = t.at(f, span.lo as usize).filter(|(s, _)| s == span);
            let want = match target {
                Target::Sym(s) => {
                    let sym = &ix.symbols[*s];
                    format!("{}@{}:{}", sym.name, sym.file, sym.span.lo)
                }
                Target::StdFn(x) => format!("stdfn {}", x.name),
                Target::StdFb(x) => format!("stdfb {}", x.name),
                Target::StdMember(b, i) => format!(
                    "stdmember {}.{}",
                    b.name,
                    b.inputs.iter().chain(b.outputs).nth(*i).unwrap().name
                ),
            };
            let have = got.map(|(_, id)| {
                let s = &t.symbols[id];
                match (s.decl, s.kind) {
                    (Some(d), _) => format!("{}@{}:{}", s.name, d.file, d.span.lo),
                    (None, ir::SymbolKind::StdFunction) => format!("stdfn {}", s.name),
                    (None, ir::SymbolKind::StdBlock) => format!("stdfb {}", s.name),
                    (None, ir::SymbolKind::StdMember { block, .. }) => {
                        format!("stdmember {}.{}", t.symbols[block].name, s.name)
                    }
                    _ => "?".into(),
                }
            });
            if have.as_deref() != Some(want.as_str()) {
                out.push(format!(
                    "{name}:{} `{}`: index {want}, table {have:?}",
                    span.lo,
                    &text[span.lo as usize..span.hi as usize]
                ));
            }
        }
        for (span, id) in &t.uses[f] {
            if file
                .refs
                .binary_search_by_key(&(span.lo, span.hi), |(s, _)| (s.lo, s.hi))
                .is_err()
            {
                out.push(format!(
                    "{name}:{} `{}`: only in the table: {}",
                    span.lo,
                    &text[span.lo as usize..span.hi as usize],
                    t.symbols[*id].name
                ));
            }
        }
    }
    (n, out)
}

#[test]
fn table_equals_index() {
    let mut all = Vec::new();
    for (d, together) in [
        ("tests/plc", true),
        ("examples/plc", true),
        ("benches/plc", true),
        ("il-codegen/tests/golden", false),
        ("tests/new-user/plc", true),
        ("il-cli/tests/ui", false),
        ("tests/differential/regressions", false),
    ] {
        let (n, out) = compare_dir(d, together);
        eprintln!("{d}: {n} refs, {} differences", out.len());
        all.extend(out);
    }
    for l in &all[..] {
        eprintln!("{l}");
    }
    // Names the table adds (enumeration values, resources, program
    // instances, types of TYPE aliases and globals) are not differences.
    let missed: Vec<_> = all
        .iter()
        .filter(|l| !l.contains("only in the table"))
        .collect();
    assert!(missed.is_empty(), "{missed:#?}");
}
