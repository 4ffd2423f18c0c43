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

#[test]
fn matiec_style_program_checks_in_pous_iec2c_translates() {
    let text = generator::matiec_program(2000, 1);
    let pous: Vec<&str> = text.split("END_FUNCTION_BLOCK").collect();
    assert!(pous.len() >= 5, "{} POUs", pous.len());
    for p in &pous {
        let n = p.lines().count();
        assert!(n <= generator::MATIEC_POU_LINES + 10, "a POU of {n} lines");
    }
    // The forms iec2c (6bb2c33) refuses or stops on are not there.
    assert!(!text.contains(":= T#") && !text.contains("\n    S    "));
    assert!(text.lines().count() >= 2000);
    assert_clean("matiec.il", text);
}
