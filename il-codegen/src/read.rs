//! Reading a source file from disk, the one way every front end does it
//! (`ilc`, the build-script `Builder`, `il!(file = ...)`): bounded in size
//! before and while reading, UTF-8 only, with the position of the first bad
//! byte and a hint for the encodings PLC tools actually write.

use std::fmt;
use std::io::Read;
use std::path::Path;

use crate::diag::SourceFile;

/// The largest source file read (256 MiB): far above any real IL program or
/// PLCopen project (a million IL lines is about 30 MB), and refused before
/// the compiler spends memory proportional to it.
pub const MAX_SOURCE_BYTES: u64 = 256 << 20;

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

/// Read `path` as a [`SourceFile`] named `name` (what messages show).
pub fn read_source(path: &Path, name: &str) -> Result<SourceFile, ReadError> {
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
    decode(name, bytes).map_err(err)
}

/// Read standard input (or any stream) the same way, named `name`.
pub fn read_stream(input: impl Read, name: &str) -> Result<SourceFile, ReadError> {
    let err = |reason: String| ReadError {
        path: name.to_string(),
        reason,
    };
    let bytes = read_bounded(input, 0).map_err(err)?;
    decode(name, bytes).map_err(err)
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

/// UTF-8 text without its byte order mark, or why not.
pub fn decode(name: &str, bytes: Vec<u8>) -> Result<SourceFile, String> {
    if let Some(order) = utf16(&bytes) {
        return Err(format!(
            "it is UTF-16 text ({order}), not UTF-8; convert it first, e.g. `iconv -f UTF-16 -t UTF-8`"
        ));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let ok = &e.as_bytes()[..at];
        let line = ok.iter().filter(|&&b| b == b'\n').count() + 1;
        let col = ok.iter().rev().take_while(|&&b| b != b'\n').count() + 1;
        format!(
            "it is not UTF-8 text (invalid byte 0x{:02X} at line {line}, byte {col} of the line); \
             convert it to UTF-8 first, e.g. `iconv -f latin1 -t utf-8`",
            e.as_bytes()[at]
        )
    })?;
    // A UTF-8 byte order mark (Windows PLC tools write one) is not source text.
    let text = match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_string(),
        None => text,
    };
    Ok(SourceFile::new(name, text))
}

/// The byte order of UTF-16 text: from its byte order mark, or, without one,
/// from ASCII text in which every other byte is zero.
fn utf16(bytes: &[u8]) -> Option<&'static str> {
    match bytes {
        [0xFF, 0xFE, ..] => return Some("little-endian, with a byte order mark"),
        [0xFE, 0xFF, ..] => return Some("big-endian, with a byte order mark"),
        _ => {}
    }
    let head = &bytes[..bytes.len().min(256) & !1];
    if head.len() < 8 {
        return None;
    }
    let pairs = || head.chunks_exact(2);
    if pairs().all(|p| p[1] == 0 && p[0] != 0) {
        Some("little-endian")
    } else if pairs().all(|p| p[0] == 0 && p[1] != 0) {
        Some("big-endian")
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf16_is_named_with_its_byte_order() {
        let le: Vec<u8> = "PROGRAM p\n"
            .encode_utf16()
            .flat_map(u16::to_le_bytes)
            .collect();
        let mut bom = vec![0xFF, 0xFE];
        bom.extend(&le);
        let be: Vec<u8> = "PROGRAM p\n"
            .encode_utf16()
            .flat_map(u16::to_be_bytes)
            .collect();
        for (bytes, want) in [
            (bom, "UTF-16 text (little-endian, with a byte order mark)"),
            (le, "UTF-16 text (little-endian)"),
            (be, "UTF-16 text (big-endian)"),
        ] {
            let e = decode("a.il", bytes).unwrap_err();
            assert!(e.contains(want), "{e}");
            assert!(!e.contains("latin1"), "{e}");
        }
    }

    #[test]
    fn latin1_names_the_line_and_byte() {
        let e = decode("a.il", b"PROGRAM p\n(* Gr\xF6\xDFe *)\n".to_vec()).unwrap_err();
        assert!(e.contains("line 2, byte 6") && e.contains("latin1"), "{e}");
    }

    #[test]
    fn a_utf8_bom_is_dropped() {
        let f = decode("a.il", b"\xEF\xBB\xBFPROGRAM p".to_vec()).unwrap();
        assert_eq!(f.text, "PROGRAM p");
    }

    #[test]
    fn an_endless_device_is_cut_off_at_the_limit() {
        // `/dev/zero` as a stream: bounded, then refused.
        let e = read_stream(std::io::repeat(0), "/dev/zero").unwrap_err();
        assert!(e.to_string().contains("too large"), "{e}");
        assert!(e.to_string().contains("at most 256 MiB"), "{e}");
    }

    #[test]
    fn a_directory_and_a_missing_file() {
        let dir = std::env::temp_dir();
        let e = read_source(&dir, "tmp").unwrap_err();
        assert_eq!(e.reason, "it is a directory");
        let e = read_source(Path::new("/no/such/file.il"), "x.il").unwrap_err();
        assert_eq!(e.to_string(), "cannot read `x.il`: no such file");
    }
}
