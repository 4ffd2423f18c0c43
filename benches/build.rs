//! Compiles the scan benchmark programs `plc/*.il` with the build-script
//! front end, as a user's crate would.

use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-changed=plc");
    let mut files: Vec<PathBuf> = std::fs::read_dir("plc")
        .expect("benches/plc exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    files.sort();
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    il_codegen::Builder::new()
        .files(&files)
        .out_dir(&out)
        .compile()
        .unwrap_or_else(|e| panic!("\n{e}"));
}
