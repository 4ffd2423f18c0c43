//! Compiles the IL program with il-codegen's Builder, turns `scans.txt` into
//! the firmware's input table, and writes the `memory.x` that cortex-m-rt's
//! `link.x` includes: `memory-budget.x`, the budget of a small part. (No
//! `memory.x` beside Cargo.toml: the linker would find that one first.)

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));

    // `$OUT_DIR/pump.rs`; the Builder prints its own rerun-if-changed lines.
    if let Err(e) = il_codegen::Builder::new().file("plc/pump.il").compile() {
        panic!("\n{e}");
    }
    // The size check (BENCHMARKS.md) adds a larger program to the same
    // firmware: IL_EXTRA=FILE.il, whose PROGRAM is named by IL_EXTRA_PROGRAM.
    println!("cargo:rerun-if-env-changed=IL_EXTRA");
    println!("cargo:rerun-if-env-changed=IL_EXTRA_PROGRAM");
    let mut extra = String::new();
    if let Some(file) = std::env::var_os("IL_EXTRA") {
        let program = std::env::var("IL_EXTRA_PROGRAM")
            .expect("IL_EXTRA_PROGRAM names the PROGRAM of IL_EXTRA");
        let files = il_codegen::Builder::new()
            .file(&file)
            .compile()
            .unwrap_or_else(|e| panic!("\n{e}"));
        for f in files {
            writeln!(extra, "include!({:?});", f.display()).unwrap();
        }
        writeln!(extra, "pub type Extra = {program};").unwrap();
        println!("cargo:rustc-cfg=il_extra");
    }
    println!("cargo:rustc-check-cfg=cfg(il_extra)");
    std::fs::write(out.join("extra.rs"), &extra).expect("OUT_DIR is writable");

    let table = std::fs::read_to_string("scans.txt").expect("scans.txt is beside build.rs");
    println!("cargo:rerun-if-changed=scans.txt");
    let rust = scans_rs(&table).unwrap_or_else(|e| panic!("scans.txt: {e}"));
    std::fs::write(out.join("scans.rs"), rust).expect("OUT_DIR is writable");

    // IL_EXTRA_TRACE: the extra program's variables are traced too, through
    // its `visit`; that code (and float formatting) outgrows the budget of
    // memory-budget.x, so that build links into the LM3S6965's whole memory.
    println!("cargo:rerun-if-env-changed=IL_EXTRA_TRACE");
    println!("cargo:rustc-check-cfg=cfg(il_extra_trace)");
    let traced = !extra.is_empty() && std::env::var_os("IL_EXTRA_TRACE").is_some();
    let memory = if traced {
        println!("cargo:rustc-cfg=il_extra_trace");
        "MEMORY\n{\n  FLASH : ORIGIN = 0x00000000, LENGTH = 256K\n  RAM : ORIGIN = 0x20000000, LENGTH = 64K\n}\n"
            .to_string()
    } else {
        std::fs::read_to_string("memory-budget.x").expect("memory-budget.x is beside build.rs")
    };
    std::fs::write(out.join("memory.x"), memory).expect("OUT_DIR is writable");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory-budget.x");
}

/// `scans.txt` as Rust: `CYCLES`, `STEP_MS` and `SETS`, the changes of the
/// simulated field's input terminals (`src/io.rs`), numbered as the
/// addresses they are wired to.
fn scans_rs(table: &str) -> Result<String, String> {
    let (mut cycles, mut step, mut sets) = (None, None, String::new());
    for (n, line) in table.lines().enumerate() {
        let line = line.trim();
        let at = |e: String| format!("line {}: {e}", n + 1);
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let (head, rest) = line
            .split_once(' ')
            .ok_or_else(|| at(format!("`{line}`")))?;
        let rest = rest.trim();
        match head {
            "cycles" => cycles = Some(rest.parse::<u32>().map_err(|e| at(e.to_string()))?),
            "step" => {
                let ms = rest
                    .strip_suffix("ms")
                    .ok_or_else(|| at("the step is in ms".into()))?;
                step = Some(ms.parse::<u32>().map_err(|e| at(e.to_string()))?);
            }
            scan => {
                let scan: u32 = scan
                    .parse()
                    .map_err(|_| at(format!("`{scan}` is not a scan number")))?;
                let (addr, value) = rest
                    .split_once('=')
                    .ok_or_else(|| at("not ADDRESS=VALUE".into()))?;
                let input = if let Some(bit) = addr.strip_prefix("%IX") {
                    let (byte, bit) = bit
                        .split_once('.')
                        .ok_or_else(|| at("%IX needs byte.bit".into()))?;
                    let on = match value {
                        "TRUE" => true,
                        "FALSE" => false,
                        v => return Err(at(format!("`{v}` is not TRUE or FALSE"))),
                    };
                    if byte != "0" {
                        return Err(at("the field has digital terminals %IX0.0 to %IX0.7".into()));
                    }
                    format!("Input::Digital({bit}, {on})")
                } else if let Some(word) = addr.strip_prefix("%IW") {
                    let v: u16 = value
                        .parse()
                        .map_err(|_| at(format!("`{value}` is not a WORD")))?;
                    format!("Input::Analog({word}, {v})")
                } else {
                    return Err(at(format!("`{addr}`: only %IX and %IW inputs")));
                };
                writeln!(sets, "    ({scan}, {input}),").unwrap();
            }
        }
    }
    let cycles = cycles.ok_or("no `cycles` line")?;
    let step = step.ok_or("no `step` line")?;
    Ok(format!(
        "// Generated by build.rs from scans.txt.\n\
         pub const CYCLES: u32 = {cycles};\n\
         pub const STEP_MS: u32 = {step};\n\
         pub const SETS: &[(u32, Input)] = &[\n{sets}];\n"
    ))
}
