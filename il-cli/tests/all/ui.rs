//! `ilc check` end to end on small programs in `tests/ui/*.il`: the exit
//! status and the full output (human and JSON) are compared with
//! `tests/ui/*.txt`. Re-bless with `IL_BLESS=1 cargo test -p il-cli --test all ui`.

use il_testkit::golden;

use std::path::Path;
use std::process::Command;

#[test]
fn ui_snapshots() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/ui");
    let mut inputs: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "il"))
        .collect();
    inputs.sort();
    assert!(!inputs.is_empty());
    let mut names = Vec::new();
    for input in &inputs {
        let file = input.file_name().unwrap().to_str().unwrap();
        let mut out = String::new();
        for format in ["human", "json"] {
            // Run in the folder with a relative path: snapshots do not depend
            // on where the checkout is.
            let o = Command::new(env!("CARGO_BIN_EXE_ilc"))
                .current_dir(&dir)
                .args([
                    "check",
                    "--color",
                    "never",
                    "--message-format",
                    format,
                    file,
                ])
                .output()
                .unwrap();
            out.push_str(&format!(
                "=== ilc check --message-format {format} {file}\n--- exit {}\n--- stdout\n{}--- stderr\n{}",
                o.status.code().unwrap_or(-1),
                String::from_utf8_lossy(&o.stdout),
                String::from_utf8_lossy(&o.stderr)
            ));
        }
        let name = input.file_stem().unwrap().to_str().unwrap().to_string();
        golden::assert_golden(&dir, &name, &out);
        names.push(name);
    }
    golden::assert_no_stale(&dir, &names.iter().map(String::as_str).collect::<Vec<_>>());
}
