//! `ilc` as a user runs it: exit status, what goes to stdout and stderr.

use il_testkit::json;

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

const VALID: &str = "\
PROGRAM main
VAR
    a : BOOL;
    b : BOOL;
END_VAR
    LD a
    AND b
    ST b
END_PROGRAM
";

/// A missing operand and an unknown word: errors for any IL parser.
const BROKEN: &str = "\
PROGRAM main
VAR
    a : BOOL;
END_VAR
    LD
    ST a
END_PROGRAM
";

fn ilc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env_remove("NO_COLOR")
        .output()
        .expect("run ilc")
}

fn ilc_stdin(args: &[&str], input: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run ilc");
    child.stdin.take().unwrap().write_all(input).unwrap();
    child.wait_with_output().unwrap()
}

/// A file under the target's temporary folder.
fn temp_file(name: &str, content: &[u8]) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc-cli-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, content).unwrap();
    p.to_string_lossy().into_owned()
}

fn code(o: &Output) -> i32 {
    o.status.code().expect("exited normally")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn help_and_version_exit_0() {
    let o = ilc(&["--help"]);
    assert_eq!(code(&o), 0);
    let h = stdout(&o);
    assert!(h.contains("Examples:") && h.contains("ilc check"), "{h}");
    assert!(h.contains("Exit status:"), "{h}");
    let o = ilc(&["check", "--help"]);
    assert_eq!(code(&o), 0);
    assert!(stdout(&o).contains("--message-format"));
    let o = ilc(&["--version"]);
    assert_eq!(code(&o), 0);
    assert!(stdout(&o).starts_with(&format!("ilc {}", env!("CARGO_PKG_VERSION"))));
}

#[test]
fn usage_errors_exit_2() {
    for args in [
        &[][..],
        &["check"],
        &["frobnicate"],
        &["check", "--no-such-flag", "a.il"],
        &["check", "--message-format", "xml", "a.il"],
        &["check", "--color", "sometimes", "a.il"],
    ] {
        let o = ilc(args);
        assert_eq!(code(&o), 2, "ilc {args:?}: {}", stderr(&o));
        assert!(
            o.stdout.is_empty() || args.is_empty(),
            "ilc {args:?} wrote to stdout"
        );
    }
}

#[test]
fn valid_file_is_silent_and_exits_0() {
    let f = temp_file("valid.il", VALID.as_bytes());
    for extra in [
        &[][..],
        &["--message-format", "json"],
        &["--color", "always"],
    ] {
        let mut args = vec!["check"];
        args.extend_from_slice(extra);
        args.push(&f);
        let o = ilc(&args);
        assert_eq!(code(&o), 0, "{}", stderr(&o));
        assert!(o.stdout.is_empty(), "stdout: {}", stdout(&o));
        assert!(o.stderr.is_empty(), "stderr: {}", stderr(&o));
    }
}

#[test]
fn stdin_is_dash() {
    let o = ilc_stdin(&["check", "-"], VALID.as_bytes());
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(o.stderr.is_empty());
}

#[test]
fn missing_file_names_the_path_and_exits_1() {
    let valid = temp_file("valid2.il", VALID.as_bytes());
    let o = ilc(&["check", "does/not/exist.il", &valid]);
    assert_eq!(code(&o), 1);
    let e = stderr(&o);
    assert!(e.contains("`does/not/exist.il`"), "{e}");
    assert!(e.contains("no such file"), "{e}");
    assert!(o.stdout.is_empty());
    // In JSON mode stdout stays clean too.
    let o = ilc(&["check", "--message-format", "json", "does/not/exist.il"]);
    assert_eq!(code(&o), 1);
    assert!(o.stdout.is_empty());
    assert!(stderr(&o).contains("does/not/exist.il"));
}

#[test]
fn a_directory_is_a_clear_error() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let o = ilc(&["check", dir.to_str().unwrap()]);
    assert_eq!(code(&o), 1);
    assert!(stderr(&o).contains("is a directory"), "{}", stderr(&o));
}

#[test]
fn color_follows_the_flag() {
    let o = ilc(&["check", "--color", "always", "missing.il"]);
    assert!(stderr(&o).contains('\x1b'));
    let o = ilc(&["check", "--color", "never", "missing.il"]);
    assert!(!stderr(&o).contains('\x1b'));
    // auto: stderr is a pipe here, so no colour.
    let o = ilc(&["check", "missing.il"]);
    assert!(!stderr(&o).contains('\x1b'));
}

#[test]
fn errors_are_rendered_and_exit_1() {
    let f = temp_file("broken.il", BROKEN.as_bytes());
    let o = ilc(&["check", &f]);
    assert_eq!(code(&o), 1);
    assert!(o.stdout.is_empty());
    let e = stderr(&o);
    assert!(e.starts_with("error[IL"), "{e}");
    assert!(e.contains(&format!(" --> {f}:5:")), "{e}");
    assert!(e.contains("check failed: "), "{e}");
    assert!(!e.contains('\x1b'));
    let o = ilc(&["check", "--color", "always", &f]);
    assert!(stderr(&o).contains('\x1b'));
}

#[test]
fn json_is_one_object_per_line() {
    let f = temp_file("broken2.il", BROKEN.as_bytes());
    let g = temp_file("valid3.il", VALID.as_bytes());
    let o = ilc(&["check", "--message-format", "json", &f, &g, &f]);
    assert_eq!(code(&o), 1);
    assert!(o.stderr.is_empty(), "stderr: {}", stderr(&o));
    let out = stdout(&o);
    assert!(out.ends_with('\n'));
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines.len() >= 2 && lines.len().is_multiple_of(2), "{out}");
    for line in lines {
        let v = json::parse(line);
        assert_eq!(json::get(&v, "file"), f.as_str());
        assert_eq!(json::get(&v, "severity"), "error");
        let c = json::get(&v, "code").as_str().expect("code");
        assert!(c.starts_with("IL"), "{c}");
        let l = json::get(&v, "line").as_u64().expect("line");
        assert!(l >= 1);
        let r = json::get(&v, "rendered").as_str().expect("rendered");
        assert!(r.starts_with("error[IL"));
    }
}

/// Unreachable code: a warning, not an error.
const WARNS: &str = "\
PROGRAM warns
VAR
    a : BOOL;
END_VAR
    LD a
    JMP done
    ST a
done:
    LD a
    ST a
END_PROGRAM
";

#[test]
fn warnings_alone_exit_0_but_are_printed() {
    let f = temp_file("warns.il", WARNS.as_bytes());
    let o = ilc(&["check", &f]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    let e = stderr(&o);
    assert!(e.starts_with("warning[IL"), "{e}");
    assert!(e.contains(&format!(" --> {f}:7:5")), "{e}");
    assert!(e.trim_end().ends_with("warning: 1 warning emitted"), "{e}");
    let o = ilc(&["check", "--message-format", "json", &f]);
    assert_eq!(code(&o), 0);
    assert!(o.stderr.is_empty());
    let v = json::parse(stdout(&o).trim_end());
    assert_eq!(json::get(&v, "severity"), "warning");
}

#[test]
fn explain_known_and_unknown_codes() {
    let o = ilc(&["explain", "il0003"]);
    assert_eq!(code(&o), 0);
    assert!(stdout(&o).starts_with("IL0003: "), "{}", stdout(&o));
    let o = ilc(&["explain", "IL9999"]);
    assert_eq!(code(&o), 1);
    assert!(stderr(&o).contains("IL9999"));
}

#[test]
fn every_file_is_checked_and_reported() {
    let bad = temp_file("broken3.il", BROKEN.as_bytes());
    let good = temp_file("valid4.il", VALID.as_bytes());
    let warns = temp_file("warns2.il", WARNS.as_bytes());
    let o = ilc(&["check", &bad, "missing.il", &good, &warns]);
    assert_eq!(code(&o), 1);
    let e = stderr(&o);
    assert!(e.contains(&format!(" --> {bad}:")), "{e}");
    assert!(e.contains("`missing.il`"), "{e}");
    assert!(e.contains(&format!(" --> {warns}:7:5")), "{e}");
    assert!(!e.contains(&good), "{e}");
    assert!(
        e.contains("1 warning") && e.contains("1 file not read"),
        "{e}"
    );
}

/// Files given together are one program: FWD_REV_MON uses CMD_MONITOR from
/// another file, and the only error left is the standard's own `FWD_REV_FF.Q`.
#[test]
fn files_are_checked_together() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus/");
    let (a, b) = (
        format!("{dir}beremiz_matiec_cmd_monitor_il.txt"),
        format!("{dir}beremiz_matiec_fwd_rev_mon_il.txt"),
    );
    if !std::path::Path::new(&a).exists() {
        println!("SKIPPED: ../shared/corpus not found");
        return;
    }
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(["check", "--color", "never", &a, &b])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert_eq!(err.matches("error[").count(), 1, "{err}");
    assert!(
        err.contains("error[IL0112]: SR has no input or output `Q`"),
        "{err}"
    );
    assert!(err.contains("did you mean `Q1`?"), "{err}");
}

/// `ilc emit` on hostile input (tests/plc-hostile/hostile.il: comments and
/// strings that try to close a Rust comment or string or inject items, bidi
/// controls, line separators): it prints the file writer's text, in which
/// every `// N:` comment stays one harmless line (tests/hostile.rs checks the
/// items of that text with syn, and compiles and runs it).
#[test]
fn emit_of_hostile_comments_and_strings() {
    let src = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/plc-hostile/hostile.il"
    ))
    .unwrap();
    let path = temp_file("hostile.il", src.as_bytes());
    let o = ilc(&["emit", &path]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let text = stdout(&o);
    let file = il_codegen::diag::SourceFile::new(path.clone(), src);
    let written = il_codegen::Program::new()
        .il(file)
        .check()
        .files(Default::default())
        .expect("compiles")
        .remove(0);
    assert_eq!(text, written);
    for bad in [
        '\r', '\u{85}', '\u{2028}', '\u{2029}', '\u{202e}', '\u{2066}',
    ] {
        assert!(!text.contains(bad), "{bad:?} in the emitted text");
    }
    // The injection attempts are comments or string literals, nothing else.
    let injected = text.lines().filter(|l| l.contains("fn injected")).count();
    let as_comment = text
        .lines()
        .filter(|l| l.contains("fn injected") && l.trim_start().starts_with("// "))
        .count();
    let as_string = text
        .lines()
        .filter(|l| {
            l.contains("from_str_truncating(\"*/ fn injected() {} /*\")")
                || l.contains("from_str_truncating(\"} } fn injected2() {\")")
        })
        .count();
    assert_eq!(injected, as_comment + as_string, "{text}");
    assert_eq!((as_comment, as_string), (4, 2));
}

/// `ilc emit a/m.il b/m.il -o out` would write both to `out/m.rs`, the
/// second silently replacing the first: it is refused before anything is
/// written, naming both inputs.
#[test]
fn emit_refuses_two_inputs_with_one_output_name() {
    let a = temp_file("clash-a-m.il", b"");
    let dir = PathBuf::from(&a).parent().unwrap().join("clash");
    for sub in ["a", "b"] {
        std::fs::create_dir_all(dir.join(sub)).unwrap();
        std::fs::write(
            dir.join(sub).join("m.il"),
            format!("PROGRAM P{sub}\nVAR x : INT; END_VAR\n LD x\n ST x\nEND_PROGRAM\n"),
        )
        .unwrap();
    }
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("m.rs"), "// kept\n").unwrap();
    let (fa, fb) = (dir.join("a/m.il"), dir.join("b/m.il"));
    let (fa, fb, o) = (
        fa.to_str().unwrap(),
        fb.to_str().unwrap(),
        out.to_str().unwrap(),
    );
    let r = ilc(&["emit", fa, fb, "-o", o]);
    assert_eq!(code(&r), 1, "{}", stderr(&r));
    let e = stderr(&r);
    assert!(
        e.contains(fa) && e.contains(fb) && e.contains("m.rs"),
        "{e}"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("m.rs")).unwrap(),
        "// kept\n"
    );
    // Distinct stems are written, one file each.
    std::fs::write(
        dir.join("b/n.il"),
        "PROGRAM Q\nVAR x : INT; END_VAR\n LD x\n ST x\nEND_PROGRAM\n",
    )
    .unwrap();
    let fnn = dir.join("b/n.il");
    let r = ilc(&["emit", fa, fnn.to_str().unwrap(), "-o", o]);
    assert_eq!(code(&r), 0, "{}", stderr(&r));
    assert!(
        std::fs::read_to_string(out.join("m.rs"))
            .unwrap()
            .contains("pub struct Pa")
    );
    assert!(
        std::fs::read_to_string(out.join("n.rs"))
            .unwrap()
            .contains("pub struct Q")
    );
}

/// `--snippet`: the standard's Table 51, a bare instruction list, checked,
/// run (the fan follows the button unless inhibited) and emitted.
#[test]
fn snippet_files_check_run_and_emit() {
    let path = temp_file(
        "table51.il",
        b"START: LD %IX1       (* PUSH BUTTON *)\n       ANDN %MX5      (* NOT INHIBITED *)\n       ST %QX2        (* FAN ON *)\n",
    );
    let o = ilc(&["check", "--snippet", &path]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o = ilc(&[
        "run",
        "--snippet",
        &path,
        "--cycles",
        "3",
        "--set",
        "%IX0.1=TRUE@2",
        "--set",
        "%MX0.5=TRUE@3",
        "--watch",
        "%QX0.2",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let fan: Vec<String> = stdout(&o)
        .lines()
        .skip(1)
        .map(|l| l.split_whitespace().last().unwrap_or("").to_string())
        .collect();
    assert_eq!(fan, ["FALSE", "TRUE", "FALSE"], "{}", stdout(&o));
    let o = ilc(&["emit", "--snippet", &path]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stdout(&o).contains("pub struct table51"), "{}", stdout(&o));
    // Without --snippet the same file is instructions outside a POU.
    let o = ilc(&["check", &path]);
    assert_eq!(code(&o), 1);
    assert!(stderr(&o).contains("IL0011"), "{}", stderr(&o));
}
