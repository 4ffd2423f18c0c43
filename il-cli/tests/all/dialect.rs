//! `--std`: `ilc check`, `emit` and `run` accept the 3rd-edition forms by
//! default and refuse each of them under `--std=iec2003`.

use std::path::PathBuf;
use std::process::{Command, Output};

/// A pragma, an implicit widening and a partial access.
const THIRD_EDITION: &str = "\
{attribute 'qualified_only'}
PROGRAM main
VAR
    s : SINT := 5;
    i : INT;
    w : WORD;
END_VAR
    LD s
    ST i
    LD TRUE
    ST w.3
END_PROGRAM
";

fn ilc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run ilc")
}

fn file() -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc-dialect-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("third.il");
    std::fs::write(&p, THIRD_EDITION).unwrap();
    p.to_string_lossy().into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn the_default_accepts_3rd_edition_forms() {
    let f = file();
    for args in [
        vec!["check", f.as_str()],
        vec!["check", "--std=iec2013", f.as_str()],
        vec!["emit", f.as_str()],
        vec!["run", "--cycles", "1", f.as_str()],
    ] {
        let o = ilc(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    }
    let run = String::from_utf8_lossy(&ilc(&["run", "--cycles", "1", &f]).stdout).into_owned();
    assert!(run.contains('8'), "w.3 set: w = 8\n{run}");
}

#[test]
fn iec2003_refuses_each_form_with_its_code() {
    let f = file();
    for cmd in ["check", "emit", "run"] {
        let o = ilc(&[cmd, "--std=iec2003", &f]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{cmd}: {e}");
        for (code, msg) in [
            ("IL0301", "pragmas `{ ... }` are a 3rd-edition feature"),
            (
                "IL0302",
                "implicit conversion SINT → INT is a 3rd-edition feature",
            ),
            ("IL0303", "partial access `w.3` is a 3rd-edition feature"),
        ] {
            assert!(e.contains(&format!("error[{code}]: {msg}")), "{cmd}: {e}");
        }
    }
}

#[test]
fn an_unknown_standard_is_a_usage_error() {
    let o = ilc(&["check", "--std=iec1993", &file()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("iec2003"), "{}", stderr(&o));
}
