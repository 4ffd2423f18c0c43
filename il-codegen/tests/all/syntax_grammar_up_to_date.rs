//! The checked-in parser `src/syntax/grammar.rs` must be what lalrpop makes of
//! `src/syntax/grammar.lalrpop`. `IL_BLESS=1` rewrites it.

use std::path::Path;

#[test]
fn grammar_rs_is_up_to_date() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/syntax");
    let tmp = std::env::temp_dir().join(format!("il-grammar-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    std::fs::create_dir_all(&tmp).unwrap();
    std::fs::copy(dir.join("grammar.lalrpop"), tmp.join("grammar.lalrpop")).unwrap();
    lalrpop::Configuration::new()
        .set_in_dir(&tmp)
        .set_out_dir(&tmp)
        .force_build(true)
        .emit_rerun_directives(false)
        .log_quiet()
        .process_dir(&tmp)
        .expect("lalrpop failed on grammar.lalrpop");
    let fresh = std::fs::read_to_string(tmp.join("grammar.rs")).unwrap();
    let _ = std::fs::remove_dir_all(&tmp);
    let target = dir.join("grammar.rs");
    let current = std::fs::read_to_string(&target).unwrap_or_default();
    if std::env::var_os("IL_BLESS").is_some() {
        if current != fresh {
            std::fs::write(&target, fresh).unwrap();
        }
        return;
    }
    assert!(
        current == fresh,
        "src/syntax/grammar.rs is out of date with grammar.lalrpop: run `IL_BLESS=1 cargo test -p il-codegen --test all syntax_grammar_up_to_date`"
    );
}
