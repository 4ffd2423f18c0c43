//! A real build script, as the README writes it (`fn main() -> Result<(),
//! il_codegen::Error>` with `?`), on IL with an error: cargo shows the
//! rendered diagnostic as rustc would, line by line, not the escaped `Debug`
//! dump of a struct. Builds a small crate of its own with cargo (offline,
//! its own target directory under the workspace's `target/tests`).

use std::path::Path;
use std::process::Command;

#[test]
fn a_failing_build_script_prints_the_rendered_diagnostics() {
    let ws = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let ws = ws.canonicalize().expect("workspace root");
    let dir = ws.join("target/tests/build-script/bad-plc");
    let _ = std::fs::remove_dir_all(dir.join("src"));
    std::fs::create_dir_all(dir.join("src")).unwrap();
    std::fs::write(
        dir.join("Cargo.toml"),
        format!(
            "[package]\nname = \"bad-plc\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
             [build-dependencies]\nil-codegen = {{ path = {:?} }}\n\n[workspace]\n",
            ws.join("il-codegen")
        ),
    )
    .unwrap();
    std::fs::write(
        dir.join("build.rs"),
        "fn main() -> Result<(), il_codegen::Error> {\n    il_codegen::Builder::new().file(\"plc/bad.il\").compile()?;\n    Ok(())\n}\n",
    )
    .unwrap();
    std::fs::create_dir_all(dir.join("plc")).unwrap();
    std::fs::write(
        dir.join("plc/bad.il"),
        "PROGRAM Bad\nVAR n : DINT; r : REAL; END_VAR\n    LD n\n    ADD r\n    ST n\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(dir.join("src/lib.rs"), "").unwrap();
    // The workspace's versions of the dependencies, all in the local cache.
    std::fs::copy(ws.join("Cargo.lock"), dir.join("Cargo.lock")).unwrap();
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let out = Command::new(cargo)
        .args(["build", "--offline", "--quiet"])
        .current_dir(&dir)
        .env("CARGO_TARGET_DIR", dir.join("target"))
        .env_remove("RUSTFLAGS")
        .output()
        .expect("run cargo");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "the build must fail:\n{stderr}");
    // Cargo shows the build script's stderr: `Error: ` and then our text.
    assert!(
        stderr.lines().any(|l| l.contains("error[IL0106]")),
        "no rendered diagnostic line:\n{stderr}"
    );
    assert!(
        stderr
            .lines()
            .any(|l| l.trim_start().starts_with("--> plc/bad.il:4:")),
        "no `-->` line of its own:\n{stderr}"
    );
    assert!(!stderr.contains("rendered:"), "a struct dump:\n{stderr}");
    assert!(!stderr.contains("\\n"), "escaped line breaks:\n{stderr}");
}
