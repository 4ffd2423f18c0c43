//! Compiles `plc/*.il` to Rust in `OUT_DIR` with the build-script front end.
//! All files of one `Builder` form one program (a FUNCTION_BLOCK of one file
//! may be used in another); `src/lib.rs` includes the generated files.

use std::path::PathBuf;

fn main() {
    let mut files: Vec<PathBuf> = std::fs::read_dir("plc")
        .expect("examples/plc exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    files.sort();
    // New or removed files; the Builder itself asks to rerun when one changes.
    println!("cargo:rerun-if-changed=plc");
    if let Err(e) = il_codegen::Builder::new().files(&files).compile() {
        // The error renders every diagnostic with the IL line and column.
        panic!("\n{e}");
    }
}
