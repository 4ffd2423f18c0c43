//! Sources in the Windows code pages PLC IDEs export in, through the
//! build-script `Builder` (the one reader, `il_codegen::read`, decodes them;
//! its unit tests cover the rules byte by byte).

use il_codegen::Builder;
use std::path::PathBuf;

/// A PROGRAM with German umlauts in a comment and a STRING literal, in
/// Windows-1252 (`ö` is 0xF6, `ß` 0xDF, `ä` 0xE4).
const GERMAN_1252: &[u8] = b"(* Gr\xF6\xDFe der F\xFCllstandsanzeige *)\nPROGRAM Anzeige\nVAR text : STRING[20] := 'Gr\xF6\xDFe'; n : INT; END_VAR\n    LD text (* L\xE4nge *)\n    LEN\n    ST n\nEND_PROGRAM\n";

/// A PROGRAM with Russian comments in Windows-1251 ("Пуск насоса": start the pump).
const RUSSIAN_1251: &[u8] = b"(* \xCF\xF3\xF1\xEA \xED\xE0\xF1\xEE\xF1\xE0 *)\nPROGRAM Nasos\nVAR pusk, nasos : BOOL; END_VAR\n    LD pusk (* \xEF\xF3\xF1\xEA *)\n    ST nasos\nEND_PROGRAM\n";

fn dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("il-enc-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(d.join("out")).unwrap();
    d
}

fn build(
    d: &std::path::Path,
    file: &str,
    bytes: &[u8],
    encoding: Option<&str>,
) -> Result<String, String> {
    let src = d.join(file);
    std::fs::write(&src, bytes).unwrap();
    let mut b = Builder::new()
        .file(&src)
        .out_dir(d.join("out"))
        .cargo_directives(false);
    if let Some(e) = encoding {
        b = b.encoding(e);
    }
    match b.compile() {
        Ok(paths) => Ok(std::fs::read_to_string(&paths[0]).unwrap()),
        Err(e) => Err(e.to_string()),
    }
}

#[test]
fn windows_1252_is_read_without_a_setting_and_with_one() {
    let d = dir("1252");
    for encoding in [None, Some("windows-1252"), Some("latin1")] {
        let rs = build(&d, "anzeige.exp", GERMAN_1252, encoding).unwrap();
        // The generated Rust is UTF-8; the comments quote the decoded lines.
        assert!(rs.contains("// 4: LD text (* Länge *)"), "{rs}");
        // A STRING literal holds the UTF-8 of the decoded text, as in a
        // UTF-8 source.
        assert!(rs.contains(r#"from_str_truncating("Größe")"#), "{rs}");
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn windows_1251_needs_its_name() {
    let d = dir("1251");
    let rs = build(&d, "nasos.exp", RUSSIAN_1251, Some("windows-1251")).unwrap();
    assert!(rs.contains("// 4: LD pusk (* пуск *)"), "{rs}");
    // Unnamed, it is read as Windows-1252: it compiles (only comments differ).
    let rs = build(&d, "nasos.exp", RUSSIAN_1251, None).unwrap();
    assert!(rs.contains("// 4: LD pusk (* ïóñê *)"), "{rs}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn an_unknown_encoding_and_invalid_bytes_fail_the_build() {
    let d = dir("bad");
    let e = build(&d, "nasos.exp", RUSSIAN_1251, Some("cp-1251")).unwrap_err();
    assert!(e.starts_with("error: unknown encoding `cp-1251`: use a WHATWG encoding label, such as utf-8, windows-1252, windows-1251"), "{e}");
    let e = build(&d, "anzeige.exp", GERMAN_1252, Some("utf-8")).unwrap_err();
    assert!(
        e.contains("error[IL0040]: `")
            && e.contains("anzeige.exp` is not valid UTF-8: byte 0xF6 at line 1 is no text in it"),
        "{e}"
    );
    assert!(e.contains("anzeige.exp:1:6"), "{e}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn the_guess_is_a_warning_of_the_file() {
    let f = il_codegen::read::decode("anzeige.exp", GERMAN_1252.to_vec(), Default::default());
    let checked = il_codegen::Program::new().source(f).check();
    assert!(!checked.has_errors());
    let out = checked.render(false);
    assert!(
        out.starts_with("warning[IL0039]: `anzeige.exp` is not UTF-8; read as Windows-1252 (set the encoding with `--encoding`, `Builder::encoding` or `il!(…, encoding = …)`)\n --> anzeige.exp:1:6\n"),
        "{out}"
    );
}

#[test]
fn a_program_of_many_guessed_files_gets_one_warning_naming_the_others() {
    let files = ["a.exp", "b.exp", "c.exp"].map(|n| {
        // One PROGRAM per file, each with its own name and an `ä` (0xE4).
        let mut bytes = b"(* L\xE4nge *)\nPROGRAM P_".to_vec();
        bytes.extend_from_slice(&n.as_bytes()[..1]);
        bytes.extend_from_slice(b"\nVAR x : INT; END_VAR\n    LD 1\n    ST x\nEND_PROGRAM\n");
        il_codegen::read::decode(n, bytes, Default::default())
    });
    let checked = files
        .into_iter()
        .fold(il_codegen::Program::new(), il_codegen::Program::source)
        .check();
    let guesses: Vec<(usize, &il_codegen::Diagnostic)> = checked
        .diagnostics()
        .iter()
        .enumerate()
        .flat_map(|(k, d)| d.iter().filter(|d| d.code == "IL0039").map(move |d| (k, d)))
        .collect();
    assert_eq!(guesses.len(), 1, "{}", checked.render(false));
    let (k, d) = guesses[0];
    assert_eq!(k, 0);
    assert_eq!(
        d.notes,
        [
            "2 other file(s) of this program are not UTF-8 either and were read as Windows-1252: `b.exp`, `c.exp`"
        ]
    );
}
