//! RETAIN storage: a file that is always a whole, checked state.
//!
//! The file is a 24-byte header and a payload:
//!
//! | offset | size | content |
//! |--------|------|---------|
//! | 0      | 8    | `ILRETAIN` |
//! | 8      | 4    | format version, little-endian (1) |
//! | 12     | 8    | payload length, little-endian |
//! | 20     | 4    | CRC-32 (IEEE) of the payload, little-endian |
//! | 24     | …    | payload: JSON `{"vars": <the generated RETAIN snapshot>, "located": [...]}` |
//!
//! `located` holds the bytes of the located RETAIN variables (`AT %MW0` in a
//! RETAIN section), which live in the process image, by name and address: a
//! variable whose address changed since the file was written is left at its
//! initial value.
//!
//! [`save`] writes a temporary file beside the target, syncs it, renames it
//! over the target and syncs the directory, so that after a crash or power
//! loss at any moment the file is the old state or the new one. A file that
//! fails the checks (a truncated copy, a disk error, another program's file)
//! is reported as [`RetainError::Corrupt`] and the runtime starts from initial
//! values: never from garbage. JSON keeps the format readable and the
//! snapshot's field names checkable (a program with a RETAIN variable that
//! the file lacks does not load it). Its one gap is a REAL holding NaN or
//! an infinity, which JSON cannot hold: every state is read back before it is
//! written, and one that does not read back is not saved (the file keeps the
//! last state that did, and the runtime's report says why).

use std::fmt;
use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use il_std::{Located, ProcessImage};
use serde::{Deserialize, Serialize};

use crate::Plc;

const MAGIC: &[u8; 8] = b"ILRETAIN";
const VERSION: u32 = 1;
const HEADER: usize = 24;

/// Why a retain file was not used.
#[derive(Debug)]
pub enum RetainError {
    /// It could not be read or written.
    Io(io::Error),
    /// Its content fails a check: the reason.
    Corrupt(String),
}

impl fmt::Display for RetainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RetainError::Io(e) => write!(f, "retain file: {e}"),
            RetainError::Corrupt(m) => write!(f, "retain file is corrupt: {m}"),
        }
    }
}

impl std::error::Error for RetainError {}

impl From<io::Error> for RetainError {
    fn from(e: io::Error) -> Self {
        RetainError::Io(e)
    }
}

/// The file's bytes for `payload`.
pub fn encode(payload: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(HEADER + payload.len());
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(&crc32fast::hash(payload).to_le_bytes());
    out.extend_from_slice(payload);
    out
}

/// The payload of a file's bytes, after every check.
pub fn decode(file: &[u8]) -> Result<&[u8], RetainError> {
    let bad = |m: &str| Err(RetainError::Corrupt(m.to_string()));
    if file.len() < HEADER {
        return bad(&format!("{} bytes, shorter than its header", file.len()));
    }
    let (head, payload) = file.split_at(HEADER);
    if &head[..8] != MAGIC {
        return bad("not a retain file (no ILRETAIN mark)");
    }
    let le4 = |b: &[u8]| u32::from_le_bytes([b[0], b[1], b[2], b[3]]);
    let version = le4(&head[8..12]);
    if version != VERSION {
        return bad(&format!(
            "format version {version}, this runtime reads {VERSION}"
        ));
    }
    let mut len = [0u8; 8];
    len.copy_from_slice(&head[12..20]);
    let len = u64::from_le_bytes(len);
    if len != payload.len() as u64 {
        return bad(&format!(
            "header says {len} payload bytes, the file has {} (truncated?)",
            payload.len()
        ));
    }
    if crc32fast::hash(payload) != le4(&head[20..24]) {
        return bad("checksum mismatch");
    }
    Ok(payload)
}

/// The temporary file [`save`] writes first: the target's name plus `.tmp`.
pub fn temp_path(path: &Path) -> PathBuf {
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(".tmp");
    path.with_file_name(name)
}

/// Writes `payload` to `path` atomically (see the module's documentation).
pub fn save(path: &Path, payload: &[u8]) -> io::Result<()> {
    let tmp = temp_path(path);
    let mut f = File::create(&tmp)?;
    f.write_all(&encode(payload))?;
    // The data must be on disk before the rename makes it the file.
    f.sync_all()?;
    drop(f);
    fs::rename(&tmp, path)?;
    // And the rename itself must be on disk before we count the state saved.
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    File::open(dir)?.sync_all()
}

/// The payload of the file at `path`; `Ok(None)` when there is no file.
pub fn load(path: &Path) -> Result<Option<Vec<u8>>, RetainError> {
    match fs::read(path) {
        Ok(bytes) => decode(&bytes).map(|p| Some(p.to_vec())),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(e.into()),
    }
}

/// The value of one located RETAIN variable.
#[derive(Serialize, Deserialize, Debug, PartialEq)]
struct LocatedValue {
    name: String,
    address: String,
    bytes: Vec<u8>,
}

/// A state to save: the snapshot and the located RETAIN variables' bytes.
#[derive(Serialize, Deserialize)]
pub(crate) struct Stored<R> {
    vars: R,
    located: Vec<LocatedValue>,
}

/// How many bytes a located variable occupies, from its address's size
/// letter (`None`: a bit).
fn size(l: &Located) -> Option<usize> {
    if l.bit.is_some() {
        return None;
    }
    match l.address.as_bytes().get(2) {
        Some(b'B') => Some(1),
        Some(b'W') => Some(2),
        Some(b'D') => Some(4),
        Some(b'L') => Some(8),
        _ => None,
    }
}

fn retained(ls: &'static [Located]) -> impl Iterator<Item = &'static Located> {
    ls.iter().filter(|l| l.retain && l.bound)
}

fn read_located(l: &Located, io: &ProcessImage) -> Vec<u8> {
    match (l.bit, size(l)) {
        (Some(b), _) => vec![u8::from(io.bit(l.area, l.byte, b))],
        (None, Some(n)) => (0..n).map(|i| io.byte(l.area, l.byte + i)).collect(),
        (None, None) => Vec::new(),
    }
}

/// The current state: taken between scans, cheaply (the scan thread does
/// this; serialising and writing are the retain thread's).
pub(crate) fn capture<P: Plc>(plc: &P, io: &ProcessImage) -> Stored<P::Retain> {
    Stored {
        vars: plc.retain(),
        located: retained(P::addresses())
            .map(|l| LocatedValue {
                name: l.name.to_string(),
                address: l.address.to_string(),
                bytes: read_located(l, io),
            })
            .collect(),
    }
}

/// The payload of a state, checked to read back: JSON has no NaN or
/// infinity (serde_json writes `null`), and a file that cannot be loaded
/// must not replace one that can.
pub(crate) fn payload<R: Serialize + serde::de::DeserializeOwned>(
    s: &Stored<R>,
) -> Result<Vec<u8>, String> {
    let p = serde_json::to_vec(s).map_err(|e| e.to_string())?;
    serde_json::from_slice::<Stored<R>>(&p).map_err(|e| {
        format!(
            "the state does not read back ({e}): a REAL or LREAL RETAIN variable that is NaN or infinite? The file keeps the last state that did"
        )
    })?;
    Ok(p)
}

/// Puts a payload back: the snapshot into `plc`, the located bytes into `io`.
/// Nothing is changed when the payload does not parse.
pub(crate) fn apply<P: Plc>(
    plc: &mut P,
    io: &mut ProcessImage,
    payload: &[u8],
) -> Result<(), RetainError> {
    let stored: Stored<P::Retain> = serde_json::from_slice(payload)
        .map_err(|e| RetainError::Corrupt(format!("payload does not match the program: {e}")))?;
    plc.restore(&stored.vars);
    for l in retained(P::addresses()) {
        let Some(v) = stored
            .located
            .iter()
            .find(|v| v.name == l.name && v.address == l.address)
        else {
            continue;
        };
        match (l.bit, size(l)) {
            (Some(b), _) if v.bytes.len() == 1 => io.set_bit(l.area, l.byte, b, v.bytes[0] != 0),
            (None, Some(n)) if v.bytes.len() == n => {
                for (i, &x) in v.bytes.iter().enumerate() {
                    io.set_byte(l.area, l.byte + i, x);
                }
            }
            _ => {}
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_damage_is_detected() {
        let good = encode(b"{\"vars\":null,\"located\":[]}");
        assert!(decode(&good).is_ok());
        for cut in 0..good.len() {
            assert!(decode(&good[..cut]).is_err(), "truncated at {cut}");
        }
        for i in 0..good.len() {
            let mut bad = good.clone();
            bad[i] ^= 0x10;
            assert!(decode(&bad).is_err(), "flipped byte {i}");
        }
    }

    #[test]
    fn save_replaces_and_load_reads_back() {
        let dir = std::env::temp_dir().join(format!("il-runtime-unit-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let p = dir.join("x.retain");
        assert!(load(&p).unwrap().is_none());
        save(&p, b"one").unwrap();
        save(&p, b"two").unwrap();
        assert_eq!(load(&p).unwrap().unwrap(), b"two");
        assert!(!temp_path(&p).exists());
        fs::write(&p, b"ILRETAIN garbage").unwrap();
        assert!(matches!(load(&p), Err(RetainError::Corrupt(_))));
        fs::remove_dir_all(&dir).unwrap();
    }
}
