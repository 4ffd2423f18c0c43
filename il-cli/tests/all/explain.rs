//! `ilc explain CODE` for every diagnostic code, and `docs/diagnostics.md`,
//! which is generated from `il_codegen::codes::all()` by this test
//! (refresh it with `IL_BLESS=1 cargo test -p il-cli --test all explain`).

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

use il_codegen::codes::{self, CodeInfo};

/// Codes whose explanation has no IL example yet, with one written here.
/// Each example is checked: `ilc check` must report exactly that code.
/// When the compiler's explanation gains an example, the test says so and
/// the entry goes.
const SUPPLEMENTS: &[(&str, &str)] = &[
    (
        "IL0117",
        "\
FUNCTION Fact : INT
VAR_INPUT n : INT; END_VAR
    LD   n
    Fact             (* Fact calls itself *)
    ST   Fact
END_FUNCTION
",
    ),
    (
        "IL0119",
        "\
PROGRAM Main
VAR a, b : BOOL; END_VAR
    LD   a
    JMP  done
    ST   b           (* after JMP, and no label: never runs *)
done:
    ST   b
END_PROGRAM
",
    ),
    (
        "IL0120",
        "\
PROGRAM Main
VAR a, b : BOOL; END_VAR
    LD   a
spare:               (* no jump goes here *)
    ST   b
END_PROGRAM
",
    ),
    (
        "IL0121",
        "\
FUNCTION F : INT
VAR_INPUT a : INT; END_VAR
    LD   a
    ST   F
END_FUNCTION
PROGRAM Main
VAR b : BOOL; END_VAR
    LD   b
    CALC F(a := 1)   (* CALC of a FUNCTION: jump around a plain call *)
END_PROGRAM
",
    ),
    (
        "IL0122",
        "\
PROGRAM Main
VAR x : INT; END_VAR
    LD   10
    DIV  0
    ST   x
END_PROGRAM
",
    ),
    (
        "IL0125",
        "\
PROGRAM Main
VAR v : ARRAY[1..4] OF INT; x : INT; END_VAR
    LD   v[5]
    ST   x
END_PROGRAM
",
    ),
    (
        "IL0126",
        "\
PROGRAM Main
VAR my__flag : BOOL; END_VAR
    LD   my__flag
END_PROGRAM
",
    ),
];

/// Codes that have no example anywhere, and why.
const NO_EXAMPLE: &[(&str, &str)] = &[
    ("IL0026", "It needs a source file over 4 GiB."),
    (
        "IL0118",
        "The front end already refuses a label, jump, CAL or RET inside parentheses \
         with IL0016, so the checker's IL0118 is not reached from IL source today.",
    ),
];

/// An IL example in an explanation: an indented line after a blank line.
fn has_il_example(explanation: &str) -> bool {
    explanation.contains("\n\n    ")
}

fn ilc(args: &[&str], stdin: Option<&str>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env_remove("NO_COLOR")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run ilc");
    let mut pipe = child.stdin.take().expect("stdin");
    pipe.write_all(stdin.unwrap_or("").as_bytes())
        .expect("write stdin");
    drop(pipe);
    child.wait_with_output().expect("ilc output")
}

fn all() -> Vec<&'static CodeInfo> {
    codes::all().collect()
}

#[test]
fn every_code_has_a_title_and_an_example() {
    let all = all();
    assert!(all.len() > 40, "only {} codes", all.len());
    let mut seen = std::collections::HashSet::new();
    let mut missing = Vec::new();
    for c in &all {
        assert!(
            c.code.len() == 6
                && c.code.starts_with("IL")
                && c.code[2..].bytes().all(|b| b.is_ascii_digit()),
            "bad code {:?}",
            c.code
        );
        assert!(seen.insert(c.code), "{} listed twice", c.code);
        assert!(!c.title.trim().is_empty(), "{} has no title", c.code);
        assert!(
            !c.title.contains('\n'),
            "{}'s title is not one line",
            c.code
        );
        assert!(
            !c.explanation.trim().is_empty(),
            "{} has no explanation",
            c.code
        );
        if !has_il_example(c.explanation) {
            missing.push(c.code);
        }
    }
    let mut known: Vec<&str> = SUPPLEMENTS
        .iter()
        .map(|(c, _)| *c)
        .chain(NO_EXAMPLE.iter().map(|(c, _)| *c))
        .collect();
    known.sort();
    missing.sort();
    assert_eq!(
        missing, known,
        "codes whose explanation lacks an IL example (left) differ from the \
         supplemented ones in this test (right): add or drop entries"
    );
}

#[test]
fn ilc_explain_prints_every_code() {
    for c in all() {
        let expected = format!("{}: {}\n\n{}\n", c.code, c.title, c.explanation.trim_end());
        for spelling in [c.code.to_string(), c.code.to_ascii_lowercase()] {
            let out = ilc(&["explain", &spelling], None);
            assert!(out.status.success(), "ilc explain {spelling}: {out:?}");
            assert_eq!(String::from_utf8_lossy(&out.stdout), expected);
            assert!(out.stderr.is_empty(), "{spelling}: {out:?}");
        }
    }
    let out = ilc(&["explain", "IL9999"], None);
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("no diagnostic code `IL9999`"));
}

/// What `ilc check` says about a supplement (on stdin, without colour).
fn check_output(src: &str) -> String {
    let out = ilc(&["check", "--color", "never", "-"], Some(src));
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn supplements_report_their_code() {
    for (code, src) in SUPPLEMENTS {
        let said = check_output(src);
        let codes: Vec<&str> = said
            .lines()
            .filter(|l| l.starts_with("error[") || l.starts_with("warning["))
            .filter_map(|l| l.split_once('[')?.1.split_once(']').map(|(c, _)| c))
            .collect();
        assert_eq!(codes, [*code], "{code}'s example reports:\n{said}");
    }
}

fn render_docs() -> String {
    let all = all();
    let mut s = String::new();
    s.push_str(
        "<!-- @generated by il-cli/tests/explain.rs from il_codegen::codes::all(). \
         Do not edit: refresh with `IL_BLESS=1 cargo test -p il-cli --test all explain`. -->\n\n",
    );
    s.push_str("# Diagnostic codes\n\n");
    s.push_str(
        "Every message of the compiler carries a code: `IL0001`..`IL0099` come from the \
         front end (reading the text: lexer, parser, declarations), `IL0100`..`IL0199` from \
         the checker (names, types, the current result, jumps, calls), `IL0201` and up from \
         the PLCopen XML import. The same text is \
         printed by `ilc explain CODE` (the code is case-insensitive):\n\n\
         ```sh\ncargo run -p il-cli -- explain IL0106\n```\n\n\
         `ilc check FILE` prints the messages with the IL line and column, `ilc check \
         --message-format json FILE` as one JSON object per line; a build script \
         (`il_codegen::Builder`) and `il!` report the same codes. IL0119 (unreachable \
         instruction), IL0120 (unused label) and IL0127 for the initial value of a located \
         variable (the host owns the process image) are warnings, and so are IL0203 and IL0204 (parts \
         of a PLCopen project that are left out); everything else is an error, \
         and no file with an error produces code.\n\n",
    );
    s.push_str("| code | meaning |\n|---|---|\n");
    for c in &all {
        s.push_str(&format!(
            "| [{}](#{}) | {} |\n",
            c.code,
            c.code.to_ascii_lowercase(),
            c.title.replace('|', "\\|")
        ));
    }
    for c in &all {
        s.push_str(&format!("\n## {}\n\n**{}**\n\n", c.code, c.title));
        s.push_str(c.explanation.trim_end());
        s.push('\n');
        if let Some((_, src)) = SUPPLEMENTS.iter().find(|(k, _)| *k == c.code) {
            s.push_str("\nFor example (this example is not yet part of `ilc explain`):\n\n```\n");
            s.push_str(src);
            s.push_str("```\n\n`ilc check` says:\n\n```text\n");
            s.push_str(check_output(src).trim_end());
            s.push_str("\n```\n");
        }
        if let Some((_, why)) = NO_EXAMPLE.iter().find(|(k, _)| *k == c.code) {
            s.push_str(&format!("\nNo example: {why}\n"));
        }
    }
    s
}

#[test]
fn docs_diagnostics_md_is_up_to_date() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/diagnostics.md");
    let want = render_docs();
    if std::env::var_os("IL_BLESS").is_some() {
        std::fs::write(&path, &want).expect("write docs/diagnostics.md");
        return;
    }
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        have == want,
        "docs/diagnostics.md is out of date with il_codegen::codes::all(); \
         refresh it with `IL_BLESS=1 cargo test -p il-cli --test all explain`"
    );
}
