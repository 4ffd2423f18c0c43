//! UTF-8 and UTF-16 by the standard library, for a build without the
//! `encodings` feature (`il!` by default): encoding_rs's tables are about
//! 1.7 s of a user's cold build, and most sources are UTF-8. A file in a
//! code page is then an error (IL0040) that names the feature.

pub use Utf::{Be as UTF_16BE, Le as UTF_16LE, Utf8 as UTF_8};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Utf {
    Utf8,
    Le,
    Be,
}

pub type Codec = Utf;

/// Nothing is guessed: a file that is not UTF-8 is an error.
pub const GUESS: Option<Codec> = None;

/// The WHATWG labels of the three encodings.
pub fn for_label(label: &[u8]) -> Option<Codec> {
    let label = label.to_ascii_lowercase();
    match &label[..] {
        b"utf-8" | b"utf8" | b"unicode-1-1-utf-8" | b"unicode11utf8" | b"unicode20utf8"
        | b"x-unicode20utf8" => Some(UTF_8),
        b"utf-16" | b"utf-16le" | b"ucs-2" | b"unicode" | b"csunicode" | b"iso-10646-ucs-2"
        | b"unicodefeff" => Some(UTF_16LE),
        b"utf-16be" | b"unicodefffe" => Some(UTF_16BE),
        _ => None,
    }
}

pub fn name(codec: Codec) -> &'static str {
    match codec {
        Utf::Utf8 => "UTF-8",
        Utf::Le => "UTF-16LE",
        Utf::Be => "UTF-16BE",
    }
}

/// `bytes` in `codec`, each sequence it does not define read as U+FFFD, and
/// the first such: its offset in the text and its bytes.
pub fn decode(bytes: &[u8], codec: Codec) -> (String, Option<(usize, Vec<u8>)>) {
    let mut text = String::with_capacity(bytes.len());
    let mut first = None;
    match codec {
        Utf::Utf8 => {
            for chunk in bytes.utf8_chunks() {
                text.push_str(chunk.valid());
                if !chunk.invalid().is_empty() {
                    first.get_or_insert((text.len(), chunk.invalid().to_vec()));
                    text.push('\u{FFFD}');
                }
            }
        }
        Utf::Le | Utf::Be => {
            let unit = |p: &[u8]| match codec {
                Utf::Be => u16::from_be_bytes([p[0], p[1]]),
                _ => u16::from_le_bytes([p[0], p[1]]),
            };
            let pairs = bytes.chunks_exact(2);
            let odd = pairs.remainder().to_vec();
            // A lead surrogate and an odd byte at the end are one bad
            // sequence (one U+FFFD), as encoding_rs and the WHATWG decoder
            // read them.
            let lead_at_end =
                bytes.len() >= 3 && (0xD800..0xDC00).contains(&unit(&bytes[bytes.len() - 3..]));
            for c in char::decode_utf16(pairs.map(unit)) {
                match c {
                    Ok(c) => text.push(c),
                    Err(e) => {
                        let unit = e.unpaired_surrogate();
                        let b = match codec {
                            Utf::Be => unit.to_be_bytes(),
                            _ => unit.to_le_bytes(),
                        };
                        first.get_or_insert((text.len(), b.to_vec()));
                        text.push('\u{FFFD}');
                    }
                }
            }
            if !odd.is_empty() && !lead_at_end {
                first.get_or_insert((text.len(), odd));
                text.push('\u{FFFD}');
            }
        }
    }
    (text, first)
}
