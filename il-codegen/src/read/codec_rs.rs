//! The codecs of `encoding_rs` (feature `encodings`): every WHATWG encoding,
//! the Windows and ISO code pages that PLC IDEs export in among them.

use encoding_rs::DecoderResult;

pub type Codec = &'static encoding_rs::Encoding;

pub const UTF_8: Codec = encoding_rs::UTF_8;
pub const UTF_16LE: Codec = encoding_rs::UTF_16LE;
pub const UTF_16BE: Codec = encoding_rs::UTF_16BE;

/// What a file that is not UTF-8 is read as when nothing names its encoding:
/// Windows-1252, in which CODESYS V2.3 exports on Western European Windows.
pub const GUESS: Option<Codec> = Some(encoding_rs::WINDOWS_1252);

pub fn for_label(label: &[u8]) -> Option<Codec> {
    // "replacement" (the label of ISO-2022-KR and a few others) decodes any
    // file to one U+FFFD: no way to read IL.
    encoding_rs::Encoding::for_label(label).filter(|&e| e != encoding_rs::REPLACEMENT)
}

pub fn name(codec: Codec) -> &'static str {
    codec.name()
}

/// `bytes` in `codec`, each sequence it does not define read as U+FFFD, and
/// the first such: its offset in the text and its bytes.
pub fn decode(bytes: &[u8], codec: Codec) -> (String, Option<(usize, Vec<u8>)>) {
    let mut decoder = codec.new_decoder_without_bom_handling();
    let mut text = String::with_capacity(
        decoder
            .max_utf8_buffer_length_without_replacement(bytes.len())
            .unwrap_or(bytes.len()),
    );
    let (mut at, mut first) = (0, None);
    loop {
        let (result, read) =
            decoder.decode_to_string_without_replacement(&bytes[at..], &mut text, true);
        at += read;
        match result {
            DecoderResult::InputEmpty => break,
            DecoderResult::OutputFull => text.reserve(bytes.len() - at + 16),
            DecoderResult::Malformed(len, after) => {
                // The bad sequence ends `after` bytes before `at`.
                let end = at - after as usize;
                let start = end.saturating_sub(len as usize);
                first.get_or_insert((text.len(), bytes[start..end].to_vec()));
                text.push('\u{FFFD}');
            }
        }
    }
    (text, first)
}
