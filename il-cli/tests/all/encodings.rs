//! Sources in the Windows code pages PLC IDEs export in: `ilc check`,
//! `emit` and `run` with and without `--encoding` (the LSP's option is
//! tested in `lsp`).

use super::run::{ilc, text};
use std::path::PathBuf;

/// German umlauts in Windows-1252: in comments and in a STRING literal.
pub(crate) const GERMAN_1252: &[u8] = b"(* F\xFCllstand *)\nPROGRAM Anzeige\nVAR text : STRING[20] := 'Gr\xF6\xDFe'; n : INT; END_VAR\n    LD text (* L\xE4nge *)\n    LEN\n    ST n\nEND_PROGRAM\n";

/// Russian comments in Windows-1251 ("Пуск насоса": start the pump).
pub(crate) const RUSSIAN_1251: &[u8] = b"(* \xCF\xF3\xF1\xEA \xED\xE0\xF1\xEE\xF1\xE0 *)\nPROGRAM Nasos\nVAR pusk, nasos : BOOL; END_VAR\n    LD pusk (* \xEF\xF3\xF1\xEA *)\n    ST nasos\nEND_PROGRAM\n";

fn file(name: &str, bytes: &[u8]) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ilc_encodings");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p.display().to_string()
}

#[test]
fn check_guesses_windows_1252_with_a_warning() {
    let f = file("anzeige.exp", GERMAN_1252);
    let o = ilc(&["check", &f]);
    assert_eq!(o.status.code(), Some(0));
    let want = format!(
        "warning[IL0039]: `{f}` is not UTF-8; read as Windows-1252 (set the encoding with `--encoding`, `Builder::encoding` or `il!(…, encoding = …)`)
 --> {f}:1:5
  |
1 | (* Füllstand *)
  |     ^ byte 0xFC, read as `ü`
  |
  = help: if the file is in another code page, name it: `--encoding windows-1251` (Cyrillic), `windows-1250` (Central European), `iso-8859-15` ...

warning: 1 warning emitted
"
    );
    assert_eq!(text(&o.stderr), want);
    // Named, it is silent; the flag goes before or after the subcommand.
    for args in [
        ["check", "--encoding", "windows-1252", &f],
        ["--encoding", "CP1252", "check", &f],
    ] {
        let o = ilc(&args);
        assert_eq!(o.status.code(), Some(0));
        assert_eq!(text(&o.stderr), "", "{args:?}");
    }
}

#[test]
fn check_reads_windows_1251_when_named() {
    let f = file("nasos.exp", RUSSIAN_1251);
    let o = ilc(&["check", "--encoding", "windows-1251", &f]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(text(&o.stderr), "");
    let o = ilc(&["emit", "--encoding", "windows-1251", &f]);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        text(&o.stdout).contains("// 4: LD pusk (* пуск *)"),
        "{}",
        text(&o.stdout)
    );
    // JSON too carries the guess, with its position.
    let o = ilc(&["check", "--message-format", "json", &f]);
    let out = text(&o.stdout);
    assert!(out.contains(r#""code":"IL0039""#), "{out}");
    assert!(out.contains(r#""line":1,"column":4"#), "{out}");
}

#[test]
fn run_shows_the_decoded_string() {
    let f = file("anzeige_run.exp", GERMAN_1252);
    let o = ilc(&["run", &f, "--cycles", "1", "--encoding", "windows-1252"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    // The STRING holds the UTF-8 of `Größe`: 7 bytes, as in a UTF-8 source.
    assert!(out.contains("'Größe'"), "{out}");
    assert!(out.contains("'Größe'  7"), "{out}");
    assert_eq!(text(&o.stderr), "");
}

#[test]
fn bytes_invalid_in_the_named_encoding_are_an_error_at_their_place() {
    let f = file("anzeige_utf8.exp", GERMAN_1252);
    let o = ilc(&["check", "--encoding", "utf-8", &f]);
    assert_eq!(o.status.code(), Some(1));
    let e = text(&o.stderr);
    assert!(
        e.starts_with(&format!(
            "error[IL0040]: `{f}` is not valid UTF-8: byte 0xFC at line 1 is no text in it\n --> {f}:1:5\n"
        )),
        "{e}"
    );
}

#[test]
fn an_unknown_encoding_is_a_usage_error() {
    let f = file("nasos_bad.exp", RUSSIAN_1251);
    let o = ilc(&["check", "--encoding", "win1251", &f]);
    assert_eq!(o.status.code(), Some(2));
    let e = text(&o.stderr);
    assert!(
        e.contains("unknown encoding `win1251`: use a WHATWG encoding label, such as utf-8, windows-1252, windows-1251"),
        "{e}"
    );
}
