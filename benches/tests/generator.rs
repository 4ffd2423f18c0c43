//! The generated IL is valid: the checker accepts it without errors.

use il_bench::generator;
use il_codegen::diag::SourceFile;

fn assert_clean(name: &str, text: String) {
    let file = SourceFile::new(name, text);
    let diags = il_codegen::check_source(&file);
    let errors: Vec<_> = diags.iter().filter(|d| d.is_error()).collect();
    assert!(errors.is_empty(), "{name}: {errors:#?}");
}

#[test]
fn big_pou_of_1k_lines_checks() {
    assert_clean("big1k.il", generator::big_pou(1000, 1));
}

#[test]
fn many_small_pous_check() {
    assert_clean("many.il", generator::many_pous(50, 1));
}
