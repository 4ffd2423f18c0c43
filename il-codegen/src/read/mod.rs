//! Reading a source file from disk, the one way every front end does it
//! (`ilc`, the build-script `Builder`, `il!(file = ...)`): bounded in size
//! before and while reading, and decoded to text. PLC IDEs on Windows export
//! in the engineer's code page (CODESYS V2.3 `.EXP` files in Windows-1252 or
//! Windows-1251), so a file is read as:
//!
//! 1. what its byte order mark says (UTF-8, UTF-16LE, UTF-16BE);
//! 2. UTF-16 without a mark when its start is ASCII with every other byte 0;
//! 3. UTF-8 when it is valid UTF-8;
//! 4. otherwise the [`Encoding`] the project names (`ilc --encoding`,
//!    `Builder::encoding`, `il!(..., encoding = "...")`), or the one an XML
//!    declaration names (`<?xml ... encoding="ISO-8859-1"?>`), or, when
//!    none is named, Windows-1252 with a warning (IL0039) that says so.
//!
//! A byte sequence that the chosen encoding does not define becomes U+FFFD
//! and an error (IL0040) at its line and column; the first one is reported.

use std::fmt;
use std::io::Read;
use std::path::Path;

use crate::ast::Span;
use crate::diag::{Diagnostic, SourceFile};

#[cfg(feature = "encodings")]
#[path = "codec_rs.rs"]
mod codec;
#[cfg(not(feature = "encodings"))]
#[path = "codec_std.rs"]
mod codec;

/// The largest source file read (256 MiB): far above any real IL program or
/// PLCopen project (a million IL lines is about 30 MB), and refused before
/// the compiler spends memory proportional to it.
pub const MAX_SOURCE_BYTES: u64 = 256 << 20;

crate::diag::codes::codes! {
    GUESSED_ENCODING = "IL0039", "a source that is not UTF-8, read as Windows-1252",
        "The file is not UTF-8 text and the project names no encoding, so it was read as Windows-1252, the code page of Western European Windows, in which PLC IDEs such as CODESYS V2.3 export (`.EXP`). The warning points at the first byte that is not UTF-8. A program of several such files (a CODESYS project exported one object per file) gets one warning, at the first of them, whose note names the others.\n\n    $ ilc check motor.exp\n    warning[IL0039]: `motor.exp` is not UTF-8; read as Windows-1252 (set the encoding with `--encoding`, `Builder::encoding` or `il!(…, encoding = …)`)\n     --> motor.exp:3:25\n      |\n    3 |     LD n (* Drehzahl erhöhen *)\n      |                         ^ byte 0xF6, read as `ö`\n\nIf the file is in another code page (Russian comments read as Windows-1252 look like `Ïóñê íàñîñà`), name it: `ilc --encoding windows-1251 check x.exp`, `Builder::new().encoding(\"windows-1251\")` in build.rs, `il!(file = \"x.exp\", encoding = \"windows-1251\")`, or the language server's initialization option `{\"encoding\": \"windows-1251\"}`. Naming `windows-1252` silences the warning. Any WHATWG encoding label is accepted: `windows-1250` ... `windows-1258`, `iso-8859-2` ... `iso-8859-16`, `koi8-r`, `shift_jis`, `gbk`, `utf-16le`; `iso-8859-1` and `latin1` are read as Windows-1252, which extends them. A file that is valid UTF-8 is always read as UTF-8, and one with a byte order mark as the mark says.\n\nOr convert the file once: `iconv -f windows-1252 -t utf-8 x.exp > x.il`.";
    INVALID_BYTES = "IL0040", "bytes that are not text in the source's encoding",
        "The file holds a byte sequence that its encoding does not define: a file read as UTF-8 (it has a UTF-8 byte order mark, or the project names `utf-8`) with a byte that is no UTF-8, an odd byte or a lone surrogate in UTF-16, or a byte that the named code page leaves undefined (0xAA in Windows-1253). The error points at the first such sequence, which is read as U+FFFD (`\u{FFFD}`); nothing is generated.\n\n    $ ilc --encoding utf-8 check x.exp\n    error[IL0040]: `x.exp` is not valid UTF-8: byte 0xF6 at line 2 is no text in it\n\nName the encoding the file is really in (`--encoding windows-1252`), or repair the bytes.\n\nA build without il-codegen's `encodings` feature (`il!` unless `il-macros` is given `features = [\"encodings\"]`) reads UTF-8 and UTF-16 only: there a file in a Windows or ISO code page is this error, whose help names the feature.";
}

/// Why a source file could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReadError {
    /// The path as given.
    pub path: String,
    /// What went wrong, in a sentence.
    pub reason: String,
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot read `{}`: {}", self.path, self.reason)
    }
}

impl std::error::Error for ReadError {}

/// The encoding a project names for its sources that are not UTF-8: a
/// WHATWG label (`windows-1251`, `latin1`, `koi8-r`, `utf-16le` ...), or
/// none ([`Encoding::default`]): then such a file is read as Windows-1252
/// with a warning (IL0039).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Encoding(Option<codec::Codec>);

/// A few names for messages that list what is valid.
/// How to read code pages where a build leaves them out.
const NEEDS_FEATURE: &str = "Windows and ISO code pages need il-codegen's `encodings` feature (on by default; for `il!`: `il-macros = { version = \"0.1\", features = [\"encodings\"] }`)";

const SOME_NAMES: &str = "utf-8, windows-1252, windows-1251, windows-1250, iso-8859-15, iso-8859-2, koi8-r, shift_jis, gbk, utf-16le";

impl Encoding {
    /// The encoding a label names (WHATWG labels, any case: `windows-1251`,
    /// `cp1251`, `latin1`), or an error that lists valid names.
    pub fn from_label(label: &str) -> Result<Encoding, String> {
        match codec::for_label(label.trim().as_bytes()) {
            Some(e) => Ok(Encoding(Some(e))),
            None if cfg!(not(feature = "encodings")) => Err(format!(
                "encoding `{label}` is not read by this build, which reads UTF-8 and UTF-16 only: {NEEDS_FEATURE}"
            )),
            None => Err(format!(
                "unknown encoding `{label}`: use a WHATWG encoding label, such as {SOME_NAMES}"
            )),
        }
    }

    /// The encoding's canonical name (`windows-1251`), or `None` when none
    /// is named.
    pub fn name(&self) -> Option<&'static str> {
        self.0.map(codec::name)
    }
}

/// Read `path` as a [`SourceFile`] named `name` (what messages show), in
/// `encoding` when it is not UTF-8 (see the module's rules).
pub fn read_source(path: &Path, name: &str, encoding: Encoding) -> Result<SourceFile, ReadError> {
    let err = |reason: String| ReadError {
        path: name.to_string(),
        reason,
    };
    let meta = std::fs::metadata(path).map_err(|e| err(io_reason(&e)))?;
    if meta.is_dir() {
        return Err(err("it is a directory".into()));
    }
    // A regular file's size is known: refuse before reading a byte.
    if meta.is_file() && meta.len() > MAX_SOURCE_BYTES {
        return Err(err(too_large(meta.len())));
    }
    let file = std::fs::File::open(path).map_err(|e| err(io_reason(&e)))?;
    // Sized from the file's length (and one byte to see the end): read by
    // doubling, a 1.2 MB file took 2 MB.
    let hint = if meta.is_file() {
        meta.len() as usize + 1
    } else {
        0
    };
    let bytes = read_bounded(file, hint).map_err(err)?;
    Ok(decode(name, bytes, encoding))
}

/// Read standard input (or any stream) the same way, named `name`.
pub fn read_stream(
    input: impl Read,
    name: &str,
    encoding: Encoding,
) -> Result<SourceFile, ReadError> {
    let err = |reason: String| ReadError {
        path: name.to_string(),
        reason,
    };
    let bytes = read_bounded(input, 0).map_err(err)?;
    Ok(decode(name, bytes, encoding))
}

/// At most [`MAX_SOURCE_BYTES`] from a stream whose size is unknown (a pipe,
/// a device such as `/dev/zero`): streamed, and cut off one byte past the
/// limit; `hint`: the expected length plus one, if known.
fn read_bounded(input: impl Read, hint: usize) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::with_capacity(hint);
    input
        .take(MAX_SOURCE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| io_reason(&e))?;
    if bytes.len() as u64 > MAX_SOURCE_BYTES {
        return Err(too_large(bytes.len() as u64));
    }
    Ok(bytes)
}

fn too_large(len: u64) -> String {
    format!(
        "it is too large ({}{len} bytes; a source file is at most {} MiB)",
        if len > MAX_SOURCE_BYTES + 1 {
            ""
        } else {
            "at least "
        },
        MAX_SOURCE_BYTES >> 20
    )
}

/// The text of `bytes` (without a byte order mark) as the module's rules
/// read it, with a warning when the encoding was guessed and an error at the
/// first byte sequence that is no text in the encoding used.
pub fn decode(name: &str, mut bytes: Vec<u8>, encoding: Encoding) -> SourceFile {
    if let Some((enc, bom)) = for_bom(&bytes) {
        return decode_in(name, &bytes[bom..], enc);
    }
    if let Some(big) = utf16(&bytes) {
        let enc = if big {
            codec::UTF_16BE
        } else {
            codec::UTF_16LE
        };
        return decode_in(name, &bytes, enc);
    }
    let bad = match String::from_utf8(bytes) {
        Ok(text) => return SourceFile::new(name, text),
        Err(e) => {
            let bad = e.utf8_error().valid_up_to();
            bytes = e.into_bytes();
            bad
        }
    };
    if let Some(enc) = encoding.0.or_else(|| xml_declared(&bytes)) {
        return decode_in(name, &bytes, enc);
    }
    let Some(guess) = codec::GUESS else {
        // A build without code pages: the file is read as UTF-8, and the
        // error says how to read it otherwise.
        let mut file = decode_in(name, &bytes, codec::UTF_8);
        if let Some(d) = file.read_diagnostics.last_mut() {
            d.help = Some(format!(
                "name the encoding the file is in (`encoding = \"windows-1252\"`); {NEEDS_FEATURE}"
            ));
        }
        return file;
    };
    let mut file = decode_in(name, &bytes, guess);
    // A single-byte code page reads each byte as one character, so the text
    // of the bytes before the first bad one ends where that byte's character
    // starts.
    let at = codec::decode(&bytes[..bad], guess).0.len();
    let shown = file
        .text
        .get(at..)
        .and_then(|t| t.chars().next())
        .unwrap_or('\u{FFFD}');
    let span = Span::new(at, at + shown.len_utf8());
    file.read_diagnostics.insert(
        0,
        Diagnostic::warning(
            GUESSED_ENCODING,
            span,
            format!(
                "`{name}` is not UTF-8; read as Windows-1252 (set the encoding with `--encoding`, `Builder::encoding` or `il!(…, encoding = …)`)"
            ),
        )
        .with_label(format!("byte 0x{:02X}, read as `{shown}`", bytes[bad]))
        .with_help("if the file is in another code page, name it: `--encoding windows-1251` (Cyrillic), `windows-1250` (Central European), `iso-8859-15` ..."),
    );
    file
}

/// The encoding a byte order mark names, and the mark's length.
fn for_bom(bytes: &[u8]) -> Option<(codec::Codec, usize)> {
    match bytes {
        [0xEF, 0xBB, 0xBF, ..] => Some((codec::UTF_8, 3)),
        [0xFF, 0xFE, ..] => Some((codec::UTF_16LE, 2)),
        [0xFE, 0xFF, ..] => Some((codec::UTF_16BE, 2)),
        _ => None,
    }
}

/// The encoding an XML declaration names (`<?xml version="1.0"
/// encoding="ISO-8859-1"?>`), for an XML file that is not UTF-8 and whose
/// project names none: the file says what it is.
fn xml_declared(bytes: &[u8]) -> Option<codec::Codec> {
    let decl = bytes.strip_prefix(b"<?xml")?;
    let decl = &decl[..decl.windows(2).position(|w| w == b"?>")?];
    let at = decl.windows(8).position(|w| w == b"encoding")?;
    let rest = decl[at + 8..]
        .trim_ascii_start()
        .strip_prefix(b"=")?
        .trim_ascii_start();
    let (&quote, rest) = rest.split_first()?;
    let label = &rest[..rest.iter().position(|&b| b == quote)?];
    codec::for_label(label)
}

/// `bytes` decoded in `enc`, an error (IL0040) at the first sequence that is
/// no text in it (read as U+FFFD, as every later one).
fn decode_in(name: &str, bytes: &[u8], enc: codec::Codec) -> SourceFile {
    let (text, first) = codec::decode(bytes, enc);
    let mut file = SourceFile::new(name, text);
    if let Some((lo, seq)) = first {
        let hex: Vec<String> = seq.iter().map(|b| format!("0x{b:02X}")).collect();
        let (line, _) = file.line_col(lo as u32);
        let enc_name = codec::name(enc);
        file.read_diagnostics.push(
            Diagnostic::error(
                INVALID_BYTES,
                Span::new(lo, lo + '\u{FFFD}'.len_utf8()),
                format!(
                    "`{name}` is not valid {enc_name}: {} {} at line {line} {} no text in it",
                    if seq.len() == 1 { "byte" } else { "bytes" },
                    hex.join(" "),
                    if seq.len() == 1 { "is" } else { "are" },
                ),
            )
            .with_label(format!("not {enc_name}"))
            .with_help(
                "name the encoding the file is in, e.g. `--encoding windows-1252`, or repair the bytes (read as `\u{FFFD}`)",
            ),
        );
    }
    file
}

/// UTF-16 text without a byte order mark, by its start: ASCII text in which
/// every other byte is zero (`Some(true)`: big-endian). Such text is also
/// valid UTF-8, so this is asked first.
fn utf16(bytes: &[u8]) -> Option<bool> {
    let head = &bytes[..bytes.len().min(256) & !1];
    if head.len() < 8 {
        return None;
    }
    let pairs = || head.chunks_exact(2);
    if pairs().all(|p| p[1] == 0 && p[0] != 0) {
        Some(false)
    } else if pairs().all(|p| p[0] == 0 && p[1] != 0) {
        Some(true)
    } else {
        None
    }
}

fn io_reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".to_string(),
        std::io::ErrorKind::PermissionDenied => "permission denied".to_string(),
        _ => e.to_string(),
    }
}

// The standard library's codec, checked against encoding_rs's.
#[cfg(all(test, feature = "encodings"))]
#[path = "codec_std.rs"]
mod codec_std;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[cfg(feature = "encodings")]
    fn the_standard_librarys_utf_codecs_agree_with_encoding_rs() {
        // Every sequence kind: ASCII, 2-4 byte UTF-8, stray continuation
        // bytes, truncated sequences, overlong forms, surrogates, odd UTF-16
        // lengths and lone surrogates; plus pseudo-random bytes.
        let mut cases: Vec<Vec<u8>> = vec![
            b"LD x (* \xC3\xA4 \xE2\x82\xAC \xF0\x9F\x98\x80 *)".to_vec(),
            b"\x80 \xC3 \xE2\x82 \xF0\x9F\x98 \xC0\xAF \xED\xA0\x80 \xFF".to_vec(),
            vec![
                0x41, 0x00, 0x00, 0xD8, 0x42, 0x00, 0x00, 0xDC, 0x00, 0xD8, 0x00, 0xDC, 0x43,
            ],
        ];
        let mut x: u32 = 0x2545_F491;
        for len in 0..200 {
            cases.push(
                (0..len)
                    .map(|_| {
                        x ^= x << 13;
                        x ^= x >> 17;
                        x ^= x << 5;
                        x as u8
                    })
                    .collect(),
            );
        }
        for bytes in &cases {
            for (ours, theirs) in [
                (codec_std::UTF_8, codec::UTF_8),
                (codec_std::UTF_16LE, codec::UTF_16LE),
                (codec_std::UTF_16BE, codec::UTF_16BE),
            ] {
                let (a, b) = (codec_std::decode(bytes, ours), codec::decode(bytes, theirs));
                assert_eq!(a.0, b.0, "{bytes:02X?} in {}", codec::name(theirs));
                // Where the first bad sequence is; its bytes as encoding_rs
                // cuts it (it may take a valid prefix's byte into it).
                assert_eq!(
                    a.1.map(|f| f.0),
                    b.1.map(|f| f.0),
                    "{bytes:02X?} in {}",
                    codec::name(theirs)
                );
                assert_eq!(codec_std::name(ours), codec::name(theirs));
            }
        }
        // It guesses nothing: a build without code pages refuses the file.
        assert_eq!(codec_std::GUESS, None);
        for label in ["utf-8", "UTF8", "utf-16", "utf-16be", "UnicodeFFFE"] {
            let (a, b) = (
                codec_std::for_label(label.as_bytes()).map(codec_std::name),
                codec::for_label(label.as_bytes()).map(codec::name),
            );
            assert_eq!(a, b, "{label}");
        }
    }

    #[test]
    #[cfg(not(feature = "encodings"))]
    fn without_code_pages_a_file_that_is_not_utf8_is_an_error_that_names_the_feature() {
        let f = decode(
            "a.il",
            b"PROGRAM p\n(* Gr\xF6\xDFe *)\n".to_vec(),
            Encoding::default(),
        );
        assert_eq!(f.text, "PROGRAM p\n(* Gr\u{FFFD}\u{FFFD}e *)\n");
        assert_eq!(codes(&f), [INVALID_BYTES]);
        let d = &f.read_diagnostics[0];
        assert_eq!(f.line_col(d.span.lo), (2, 6));
        assert!(
            d.help.as_deref().unwrap().contains("`encodings` feature"),
            "{d:?}"
        );
        let e = Encoding::from_label("windows-1251").unwrap_err();
        assert!(e.contains("`encodings` feature"), "{e}");
        assert_eq!(
            Encoding::from_label("utf-16le").unwrap().name(),
            Some("UTF-16LE")
        );
        // UTF-16 with a mark, and a lone surrogate in it.
        let f = decode(
            "a.il",
            vec![0xFF, 0xFE, 0x41, 0x00, 0x00, 0xD8, 0x42, 0x00],
            Encoding::default(),
        );
        assert_eq!(f.text, "A\u{FFFD}B");
        assert_eq!(codes(&f), [INVALID_BYTES]);
    }

    #[cfg(feature = "encodings")]
    fn named(label: &str) -> Encoding {
        Encoding::from_label(label).unwrap()
    }

    fn codes(f: &SourceFile) -> Vec<&str> {
        f.read_diagnostics.iter().map(|d| d.code).collect()
    }

    #[test]
    fn utf16_is_read_with_or_without_a_byte_order_mark() {
        let le: Vec<u8> = "PROGRAM p (* ä *)\n"
            .encode_utf16()
            .flat_map(u16::to_le_bytes)
            .collect();
        let mut bom = vec![0xFF, 0xFE];
        bom.extend(&le);
        let mut be: Vec<u8> = vec![0xFE, 0xFF];
        be.extend(
            "PROGRAM p (* ä *)\n"
                .encode_utf16()
                .flat_map(u16::to_be_bytes),
        );
        let bare: Vec<u8> = "PROGRAM p\n"
            .encode_utf16()
            .flat_map(u16::to_be_bytes)
            .collect();
        for (bytes, want) in [
            (bom, "PROGRAM p (* ä *)\n"),
            (le, "PROGRAM p (* ä *)\n"),
            (be, "PROGRAM p (* ä *)\n"),
            (bare, "PROGRAM p\n"),
        ] {
            let f = decode("a.il", bytes, Encoding::default());
            assert_eq!(f.text, want);
            assert!(f.read_diagnostics.is_empty());
        }
    }

    #[test]
    #[cfg(feature = "encodings")]
    fn not_utf8_is_read_as_windows_1252_with_a_warning_at_the_first_bad_byte() {
        let f = decode(
            "a.il",
            b"PROGRAM p\n(* \xC3\xA4 Gr\xF6\xDFe *)\n".to_vec(),
            Encoding::default(),
        );
        // The valid UTF-8 `ä` before the bad byte is read as Windows-1252 too.
        assert_eq!(f.text, "PROGRAM p\n(* Ã¤ Größe *)\n");
        assert_eq!(codes(&f), [GUESSED_ENCODING]);
        let d = &f.read_diagnostics[0];
        assert!(!d.is_error());
        assert_eq!(f.line_col(d.span.lo), (2, 9));
        assert_eq!(f.snippet(d.span), "ö");
        assert_eq!(d.label, "byte 0xF6, read as `ö`");
        assert!(
            d.message
                .starts_with("`a.il` is not UTF-8; read as Windows-1252")
        );
    }

    #[test]
    #[cfg(feature = "encodings")]
    fn a_named_encoding_reads_what_is_not_utf8_silently() {
        let f = decode(
            "a.il",
            b"(* \xCF\xF3\xF1\xEA *)\n".to_vec(),
            named("windows-1251"),
        );
        assert_eq!(f.text, "(* Пуск *)\n");
        assert!(f.read_diagnostics.is_empty());
        let f = decode("a.il", b"(* \xA4 *)".to_vec(), named("ISO-8859-15"));
        assert_eq!(f.text, "(* € *)");
        // Valid UTF-8 stays UTF-8 whatever is named.
        let f = decode("a.il", "(* ä *)".into(), named("windows-1251"));
        assert_eq!(f.text, "(* ä *)");
    }

    #[test]
    #[cfg(feature = "encodings")]
    fn bytes_invalid_in_the_named_encoding_are_an_error_where_they_are() {
        let f = decode(
            "a.il",
            b"PROGRAM p\n  (* \xF6 *)\n".to_vec(),
            named("utf-8"),
        );
        assert_eq!(codes(&f), [INVALID_BYTES]);
        let d = &f.read_diagnostics[0];
        assert!(d.is_error());
        assert_eq!(f.line_col(d.span.lo), (2, 6));
        assert_eq!(
            d.message,
            "`a.il` is not valid UTF-8: byte 0xF6 at line 2 is no text in it"
        );
        // Windows-1253 leaves 0xAA undefined; after the error, decoding goes on.
        let f = decode("a.il", b"(* \xAA \xE1 *)".to_vec(), named("windows-1253"));
        assert_eq!(f.text, "(* \u{FFFD} α *)");
        assert_eq!(codes(&f), [INVALID_BYTES]);
        // A UTF-8 byte order mark says UTF-8: a bad byte after it is an error.
        let f = decode(
            "a.il",
            b"\xEF\xBB\xBF(* \xF6 *)".to_vec(),
            Encoding::default(),
        );
        assert_eq!(codes(&f), [INVALID_BYTES]);
    }

    #[test]
    #[cfg(feature = "encodings")]
    fn an_xml_declaration_names_the_encoding_of_a_file_that_is_not_utf8() {
        let xml = b"<?xml version=\"1.0\" encoding='ISO-8859-15'?>\n<project>\xA4</project>";
        let f = decode("p.xml", xml.to_vec(), Encoding::default());
        assert!(f.text.ends_with("<project>€</project>"), "{}", f.text);
        assert!(f.read_diagnostics.is_empty());
        // The project's setting comes first.
        let f = decode("p.xml", xml.to_vec(), named("windows-1251"));
        assert!(f.text.ends_with("<project>¤</project>"), "{}", f.text);
    }

    #[test]
    #[cfg(feature = "encodings")]
    fn windows_1252_reads_its_unassigned_bytes_as_c1_controls() {
        // As the WHATWG standard says (the docs promise it): no error.
        let f = decode(
            "a.il",
            b"\x81\x8D\x8F\x90\x9D\x80".to_vec(),
            named("windows-1252"),
        );
        assert_eq!(f.text, "\u{81}\u{8D}\u{8F}\u{90}\u{9D}€");
        assert!(f.read_diagnostics.is_empty());
    }

    #[test]
    #[cfg(feature = "encodings")]
    fn encoding_names() {
        assert_eq!(named("CP1251").name(), Some("windows-1251"));
        // WHATWG: Latin-1 is read as Windows-1252, its superset.
        assert_eq!(named("latin1").name(), Some("windows-1252"));
        assert_eq!(Encoding::default().name(), None);
        let e = Encoding::from_label("win-1251").unwrap_err();
        assert!(e.starts_with("unknown encoding `win-1251`"), "{e}");
        assert!(e.contains("windows-1251"), "{e}");
        assert!(Encoding::from_label("iso-2022-kr").is_err());
    }

    #[test]
    fn a_utf8_bom_is_dropped() {
        let f = decode(
            "a.il",
            b"\xEF\xBB\xBFPROGRAM p".to_vec(),
            Encoding::default(),
        );
        assert_eq!(f.text, "PROGRAM p");
        assert!(f.read_diagnostics.is_empty());
    }

    #[test]
    fn an_endless_device_is_cut_off_at_the_limit() {
        // `/dev/zero` as a stream: bounded, then refused.
        let e = read_stream(std::io::repeat(0), "/dev/zero", Encoding::default()).unwrap_err();
        assert!(e.to_string().contains("too large"), "{e}");
        assert!(e.to_string().contains("at most 256 MiB"), "{e}");
    }

    #[test]
    fn a_directory_and_a_missing_file() {
        let dir = std::env::temp_dir();
        let e = read_source(&dir, "tmp", Encoding::default()).unwrap_err();
        assert_eq!(e.reason, "it is a directory");
        let e =
            read_source(Path::new("/no/such/file.il"), "x.il", Encoding::default()).unwrap_err();
        assert_eq!(e.to_string(), "cannot read `x.il`: no such file");
    }
}
