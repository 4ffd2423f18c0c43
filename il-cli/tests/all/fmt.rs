//! `ilc fmt` as a user runs it: in place, `--check`, standard input, and
//! files it leaves alone (syntax errors, not UTF-8), each with its status.

use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

fn ilc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run ilc")
}

fn dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ilc-fmt-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

const MESSY: &str = "program p\nvar\n  a:bool;\n  bb : bool; (* b *)\nend_var\n  ld a\n andn bb\n    st bb (* out *)\nend_program\n";
const TIDY: &str = "program p\nvar\n    a  : bool;\n    bb : bool;   (* b *)\nend_var\n    ld   a\n    andn bb\n    st   bb   (* out *)\nend_program\n";

#[test]
fn check_lists_then_fmt_rewrites_in_place() {
    let d = dir("inplace");
    let (messy, tidy) = (d.join("messy.il"), d.join("tidy.il"));
    std::fs::write(&messy, MESSY).unwrap();
    std::fs::write(&tidy, TIDY).unwrap();
    let (m, t) = (messy.to_str().unwrap(), tidy.to_str().unwrap());
    let out = ilc(&["fmt", "--check", m, t]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("messy.il: not formatted"), "{stdout}");
    assert!(
        stdout.contains("line 3:\n  -   a:bool;\n  +     a  : bool;"),
        "{stdout}"
    );
    assert!(!stdout.contains("tidy.il"), "{stdout}");
    assert_eq!(
        std::fs::read_to_string(&messy).unwrap(),
        MESSY,
        "--check writes nothing"
    );
    let out = ilc(&["fmt", m, t]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(std::fs::read_to_string(&messy).unwrap(), TIDY);
    assert_eq!(ilc(&["fmt", "--check", m, t]).status.code(), Some(0));
    // No temporary file is left beside them.
    assert_eq!(std::fs::read_dir(&d).unwrap().count(), 2);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn standard_input_to_standard_output_and_keyword_case() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(["fmt", "--keywords", "upper", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write;
    child
        .stdin
        .take()
        .unwrap()
        .write_all(MESSY.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("PROGRAM p\nVAR\n    a  : bool;"), "{text}");
    assert!(text.contains("    ANDN bb\n"), "{text}");
}

#[test]
fn files_it_cannot_format_are_left_as_they_are() {
    let d = dir("refused");
    let (bad, cp) = (d.join("bad.il"), d.join("cp.il"));
    let broken = "PROGRAM p\n  LD (\nEND_PROGRAM\n";
    std::fs::write(&bad, broken).unwrap();
    std::fs::write(&cp, b"PROGRAM p (* Gr\xF6\xDFe *)\nEND_PROGRAM\n").unwrap();
    let out = ilc(&[
        "fmt",
        bad.to_str().unwrap(),
        cp.to_str().unwrap(),
        "/no/such.il",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("bad.il:2:"),
        "the syntax error, located: {err}"
    );
    assert!(err.contains("is not formatted"), "{err}");
    assert!(err.contains("cp.il` is not UTF-8"), "{err}");
    assert!(err.contains("cannot read `/no/such.il`"), "{err}");
    assert_eq!(std::fs::read_to_string(&bad).unwrap(), broken);
    assert_eq!(
        std::fs::read(&cp).unwrap(),
        b"PROGRAM p (* Gr\xF6\xDFe *)\nEND_PROGRAM\n"
    );
    let _ = std::fs::remove_dir_all(&d);
}
