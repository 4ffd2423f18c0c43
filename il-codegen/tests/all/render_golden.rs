//! Golden snapshots of the diagnostic renderings (`tests/diag/*.txt`).
//! Re-bless with `IL_BLESS=1 cargo test -p il-codegen --test all render_golden`.

use il_codegen::ast::Span;
use il_codegen::diag::{Diagnostic, SourceFile, render, render_short, to_json};
use il_testkit::golden::{assert_golden, assert_no_stale, golden_dir};

const PROG: &str = "\
FUNCTION_BLOCK Motor
VAR_INPUT
    start : BOOL;
END_VAR
    LD
    AND(  start
\tST   run
END_FUNCTION_BLOCK
";

fn at(text: &str, needle: &str) -> Span {
    let lo = text
        .find(needle)
        .unwrap_or_else(|| panic!("{needle:?} not in the text"));
    Span::new(lo, lo + needle.len())
}

struct Case {
    name: &'static str,
    file: SourceFile,
    diags: Vec<Diagnostic>,
}

fn cases() -> Vec<Case> {
    let f = || SourceFile::new("motor.il", PROG);
    let ld = {
        let s = at(PROG, "    LD\n");
        Span::new(s.lo as usize + 4, s.lo as usize + 6)
    };
    let crlf = PROG.replace('\n', "\r\n");
    let uni = "PROGRAM Größe\n    LD ä + ö (* ünïcödé *)\nEND_PROGRAM";
    vec![
        Case {
            name: "error_label_note_help",
            file: f(),
            diags: vec![
                Diagnostic::error("IL0003", ld, "expected an operand after `LD`")
                    .with_label("this `LD` loads nothing")
                    .with_note("every load operator takes exactly one operand")
                    .with_help("write the value to load, e.g. `LD start`"),
            ],
        },
        Case {
            name: "warning_without_label",
            file: f(),
            diags: vec![Diagnostic::warning(
                "IL0900",
                at(PROG, "run"),
                "`run` is never declared",
            )],
        },
        Case {
            name: "secondary_span",
            file: f(),
            diags: vec![
                Diagnostic::error("IL0004", at(PROG, "AND("), "this `(` is never closed")
                    .with_label("opened here")
                    .with_secondary(at(PROG, "END_FUNCTION_BLOCK"), "the block ends here")
                    .with_secondary(at(PROG, "FUNCTION_BLOCK Motor"), "in this function block"),
            ],
        },
        Case {
            name: "eof_empty_span",
            file: f(),
            diags: vec![
                Diagnostic::error(
                    "IL0002",
                    Span::new(PROG.len(), PROG.len()),
                    "unexpected end of file",
                )
                .with_label("expected `)` here"),
            ],
        },
        Case {
            name: "eof_no_newline",
            file: SourceFile::new("short.il", "PROGRAM p\n    LD x"),
            diags: vec![
                Diagnostic::error("IL0002", Span::new(18, 18), "expected `END_PROGRAM`")
                    .with_label("the file ends here"),
            ],
        },
        Case {
            name: "span_past_end_and_reversed",
            file: SourceFile::new("odd.il", "LD x\n"),
            diags: vec![
                Diagnostic::error("IL0001", Span { lo: 400, hi: 9000 }, "past the end"),
                Diagnostic::error("IL0001", Span { lo: 4, hi: 1 }, "reversed"),
            ],
        },
        Case {
            name: "multi_line_span",
            file: f(),
            diags: vec![
                Diagnostic::error(
                    "IL0005",
                    at(PROG, "VAR_INPUT\n    start : BOOL;\nEND_VAR"),
                    "empty block",
                )
                .with_label("this block"),
            ],
        },
        Case {
            name: "sorted_several",
            file: f(),
            diags: vec![
                Diagnostic::error("IL0007", at(PROG, "run"), "third"),
                Diagnostic::warning("IL0900", at(PROG, "start :"), "first"),
                Diagnostic::error("IL0003", ld, "second").with_label("here"),
            ],
        },
        Case {
            name: "crlf_and_tab",
            file: SourceFile::new("crlf.il", crlf.clone()),
            diags: vec![
                Diagnostic::error("IL0006", at(&crlf, "ST   run"), "tabs and CRLF")
                    .with_label("here"),
            ],
        },
        Case {
            name: "unicode",
            file: SourceFile::new("uni.il", uni),
            diags: vec![
                Diagnostic::error("IL0008", at(uni, "ö"), "after a multi-byte character")
                    .with_label("column counts characters")
                    .with_secondary(at(uni, "Größe"), "name"),
            ],
        },
        Case {
            name: "empty_file",
            file: SourceFile::new("empty.il", ""),
            diags: vec![
                Diagnostic::error("IL0002", Span::new(0, 0), "expected a POU")
                    .with_label("nothing here"),
            ],
        },
    ]
}

#[test]
fn renderings_match_snapshots() {
    let dir = golden_dir(env!("CARGO_MANIFEST_DIR"), "diag");
    let mut names = Vec::new();
    for case in cases() {
        assert_golden(&dir, case.name, &render(&case.file, &case.diags, false));
        names.push(case.name);
    }
    assert_no_stale(
        &dir,
        &[names.as_slice(), &["short_forms", "json_lines", "color"]].concat(),
    );
}

#[test]
fn short_forms_match_snapshot() {
    let dir = golden_dir(env!("CARGO_MANIFEST_DIR"), "diag");
    let mut out = String::new();
    for case in cases() {
        for d in &case.diags {
            out.push_str(&format!(
                "== {}\n{}\n",
                case.name,
                render_short(&case.file, d)
            ));
        }
    }
    assert_golden(&dir, "short_forms", &out);
}

#[test]
fn json_matches_snapshot() {
    let dir = golden_dir(env!("CARGO_MANIFEST_DIR"), "diag");
    let mut out = String::new();
    for case in cases() {
        for d in &case.diags {
            let j = to_json(&case.file, d);
            assert!(!j.contains('\n'), "one line per diagnostic");
            out.push_str(&j);
            out.push('\n');
        }
    }
    assert_golden(&dir, "json_lines", &out);
}

#[test]
fn color_matches_snapshot() {
    let dir = golden_dir(env!("CARGO_MANIFEST_DIR"), "diag");
    let c = &cases()[0];
    let colored = render(&c.file, &c.diags, true);
    // Escapes shown as `\e` so that the snapshot is readable.
    assert_golden(&dir, "color", &colored.replace('\x1b', "\\e"));
}
