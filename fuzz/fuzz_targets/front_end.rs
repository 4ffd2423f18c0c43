//! Fuzz the IL front end: any bytes through the parser, and every diagnostic
//! through every renderer. Nothing may panic, overflow the stack or hang.
//!
//! Run (nightly and cargo-fuzz needed):
//!     cargo install cargo-fuzz
//!     cd fuzz && cargo +nightly fuzz run front_end corpus/front_end ../../shared/corpus
#![no_main]

use il_codegen::diag::{SourceFile, render, render_short, to_json};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // Sources are text: the CLI refuses non-UTF-8 files before parsing, so
    // feed the lossy decoding, which still holds every odd character.
    let text = String::from_utf8_lossy(data).into_owned();
    let file = SourceFile::new("fuzz.il", text);
    let (_unit, diags) = il_codegen::syntax::parse(&file);
    // Rendering dominates the cost: the first diagnostics are enough to reach
    // every rendering path.
    let shown = &diags[..diags.len().min(16)];
    let _ = render(&file, shown, false);
    let _ = render(&file, shown, true);
    for d in shown {
        let _ = render_short(&file, d);
        let j = to_json(&file, d);
        assert!(!j.contains('\n'));
    }
});
