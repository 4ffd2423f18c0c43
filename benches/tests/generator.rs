//! The generated IL is valid: the checker accepts it without errors or
//! warnings (a warning such as "can never run" would mean the benchmarks
//! time less code than they claim).

use il_bench::generator;
use il_codegen::diag::SourceFile;

fn assert_clean(name: &str, text: String) {
    let file = SourceFile::new(name, text);
    let diags = il_codegen::Program::new()
        .il(file)
        .check()
        .into_diagnostics()
        .remove(0);
    assert!(diags.is_empty(), "{name}: {diags:#?}");
}

#[test]
fn big_pou_of_1k_lines_checks() {
    assert_clean("big1k.il", generator::big_pou(1000, 1));
    assert_clean("straight1k.il", generator::big_pou_straight(1000, 1));
}

#[test]
fn many_small_pous_check() {
    assert_clean("many.il", generator::many_pous(50, 1));
}
