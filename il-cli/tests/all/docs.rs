//! Every Rust snippet of `README.md` and `docs/guide.md` is an excerpt of
//! real code, so none can go stale. The line before each ```` ```rust ````
//! fence names its source in an HTML comment (invisible when rendered):
//!
//! - `<!-- emitted from: examples/plc/traffic_light.il -->`: an excerpt of
//!   what `ilc emit` writes for that IL file (several files, separated by
//!   commas, are one program; their outputs are read one after the other);
//! - `<!-- excerpt of: examples/src/motor_starter.rs -->`: an excerpt of a
//!   file that is compiled (an example, a test, a golden file).
//!
//! The snippet's lines, trimmed, must appear in the source in the same order
//! (not necessarily adjacent), each exactly. Blank lines and elisions are
//! skipped: a line that is only `...`, `..` or `// ...`, or that contains
//! ` ... `. Fences of other languages (`text`, `toml`, `sh`) are not checked.

use std::path::{Path, PathBuf};

/// The documents whose snippets are checked, relative to the workspace.
const DOCS: &[&str] = &["README.md", "docs/guide.md"];

/// Where a snippet comes from.
#[derive(Debug, PartialEq)]
enum Marker {
    /// `ilc emit` of these IL (or PLCopen XML) files, as one program.
    Emitted(Vec<String>),
    /// A file of the workspace, as it is.
    Excerpt(String),
}

/// One ```` ```rust ```` block of a document.
#[derive(Debug)]
struct Snippet {
    /// `README.md:123`, the line of the opening fence.
    at: String,
    marker: Option<Marker>,
    lines: Vec<String>,
}

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn parse_marker(line: &str) -> Option<Marker> {
    let inner = line
        .trim()
        .strip_prefix("<!--")?
        .strip_suffix("-->")?
        .trim();
    if let Some(files) = inner.strip_prefix("emitted from:") {
        let files = files.split(',').map(|f| f.trim().to_string()).collect();
        Some(Marker::Emitted(files))
    } else {
        let file = inner.strip_prefix("excerpt of:")?;
        Some(Marker::Excerpt(file.trim().to_string()))
    }
}

/// The Rust blocks of a Markdown text (fences may be indented, as in a
/// list item); each with the marker on the last non-blank line before it.
fn snippets(doc: &str, text: &str) -> Vec<Snippet> {
    let mut out = Vec::new();
    let mut lines = text.lines().enumerate();
    let mut previous: Option<&str> = None;
    while let Some((n, line)) = lines.next() {
        let t = line.trim();
        let Some(info) = t.strip_prefix("```") else {
            if !t.is_empty() {
                previous = Some(t);
            }
            continue;
        };
        let body: Vec<String> = lines
            .by_ref()
            .map(|(_, l)| l)
            .take_while(|l| l.trim() != "```")
            .map(str::to_string)
            .collect();
        let lang = info.split(',').next().unwrap_or("").trim();
        if lang == "rust" {
            out.push(Snippet {
                at: format!("{doc}:{}", n + 1),
                marker: previous.and_then(parse_marker),
                lines: body,
            });
        }
        previous = None;
    }
    out
}

fn is_elision(line: &str) -> bool {
    matches!(line, "..." | ".." | "// ...") || line.contains(" ... ")
}

/// The text a snippet must be an excerpt of.
fn source_text(marker: &Marker) -> Result<String, String> {
    match marker {
        Marker::Excerpt(path) => std::fs::read_to_string(workspace().join(path))
            .map_err(|e| format!("cannot read `{path}`: {e}")),
        Marker::Emitted(paths) => {
            let mut program = il_codegen::Program::new();
            for path in paths {
                let file = il_codegen::read::read_source(
                    &workspace().join(path),
                    path,
                    Default::default(),
                )
                .map_err(|e| e.to_string())?;
                program = program.source(file);
            }
            let checked = program.check();
            eprint!("{}", checked.render(false));
            let rust: Option<Vec<String>> = checked.files(Default::default());
            rust.map(|files| files.concat())
                .ok_or_else(|| format!("{paths:?} does not compile"))
        }
    }
}

/// `Ok` when every line of the snippet is found in `source`, in order.
fn check(snippet: &[String], source: &str) -> Result<(), String> {
    let source: Vec<&str> = source.lines().map(str::trim).collect();
    let mut next = 0;
    for line in snippet.iter().map(|l| l.trim()) {
        if line.is_empty() || is_elision(line) {
            continue;
        }
        match source[next..].iter().position(|s| *s == line) {
            Some(i) => next += i + 1,
            None if source.contains(&line) => {
                return Err(format!(
                    "`{line}` is in the source, but not after the line before it"
                ));
            }
            None => return Err(format!("`{line}` is not in the source")),
        }
    }
    Ok(())
}

fn all_snippets() -> Vec<Snippet> {
    DOCS.iter()
        .flat_map(|doc| {
            let text = std::fs::read_to_string(workspace().join(doc)).unwrap();
            snippets(doc, &text)
        })
        .collect()
}

#[test]
fn every_rust_snippet_is_an_excerpt_of_its_source() {
    let snippets = all_snippets();
    assert!(
        snippets.len() >= 20,
        "only {} snippets found",
        snippets.len()
    );
    let mut wrong = Vec::new();
    for s in &snippets {
        let Some(marker) = &s.marker else {
            wrong.push(format!(
                "{}: no `<!-- emitted from: FILE.il -->` or `<!-- excerpt of: FILE -->` on the line before",
                s.at
            ));
            continue;
        };
        if let Err(e) = source_text(marker).and_then(|src| check(&s.lines, &src)) {
            wrong.push(format!("{} ({marker:?}): {e}", s.at));
        }
    }
    assert!(wrong.is_empty(), "stale snippets:\n{}", wrong.join("\n"));
}

#[test]
fn an_altered_or_reordered_line_is_caught() {
    let s = all_snippets()
        .into_iter()
        .find(|s| matches!(s.marker, Some(Marker::Emitted(_))) && s.lines.len() > 3)
        .expect("an emitted snippet");
    let src = source_text(s.marker.as_ref().unwrap()).unwrap();
    assert_eq!(check(&s.lines, &src), Ok(()));
    let kept: Vec<usize> = (0..s.lines.len())
        .filter(|&i| !s.lines[i].trim().is_empty() && !is_elision(s.lines[i].trim()))
        .collect();
    let mut altered = s.lines.clone();
    altered[kept[1]].push_str(" // altered");
    assert!(
        check(&altered, &src)
            .unwrap_err()
            .contains("is not in the source")
    );
    let mut swapped = s.lines.clone();
    swapped.swap(kept[0], kept[kept.len() - 1]);
    if s.lines[kept[0]].trim() != s.lines[kept[kept.len() - 1]].trim() {
        assert!(check(&swapped, &src).unwrap_err().contains("not after"));
    }
}

#[test]
fn markers_fences_and_elisions_are_read_as_documented() {
    let doc = "\
text
<!-- emitted from: a.il, b/c.il -->

```rust
let x = 1;
    ...
```
```text
```rust inside text is not a fence
```
<!-- excerpt of: examples/src/lib.rs -->
  ```rust,ignore
  a ... b
  ```
```rust
unmarked
```
";
    let s = snippets("doc.md", doc);
    assert_eq!(s.len(), 3, "{s:?}");
    assert_eq!(
        s[0].marker,
        Some(Marker::Emitted(vec!["a.il".into(), "b/c.il".into()]))
    );
    assert_eq!(s[0].at, "doc.md:4");
    assert_eq!(s[0].lines, ["let x = 1;", "    ..."]);
    assert_eq!(
        s[1].marker,
        Some(Marker::Excerpt("examples/src/lib.rs".into()))
    );
    assert_eq!(s[2].marker, None);
    assert_eq!(check(&s[1].lines, ""), Ok(()), "an elided line is skipped");
    assert!(check(&s[0].lines, "let x = 2;").is_err());
}

/// The README's library example, as it stands there.
#[test]
fn the_readmes_library_example_compiles_the_motor() {
    let text = std::fs::read_to_string(workspace().join("examples/motor.il")).unwrap();
    let file = il_codegen::SourceFile::new("examples/motor.il", text);
    let checked = il_codegen::Program::new().source(file).check();
    eprint!("{}", checked.render(false));
    let rust: Option<Vec<String>> = checked.files(Default::default());
    let rust = rust.expect("the motor compiles");
    assert!(rust[0].contains("pub struct Motor {"), "{}", rust[0]);
}
