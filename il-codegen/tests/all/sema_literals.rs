//! Literal typing from use, including generic standard functions applied to
//! untyped literals (a "pending" call typed by its first use).

use il_codegen::diag::SourceFile;

fn errors(body: &str) -> Vec<(String, String)> {
    let src = format!(
        "FUNCTION_BLOCK T\nVAR k : INT; s : SINT; b : BOOL; r : REAL; x : INT; END_VAR\n{body}\nEND_FUNCTION_BLOCK\n"
    );
    let f = SourceFile::new("t.il", src);
    il_codegen::Program::new().il(f).check().diagnostics()[0]
        .iter()
        .filter(|d| d.is_error())
        .map(|d| (d.code.to_string(), d.message.clone()))
        .collect()
}

#[test]
fn pending_calls_take_the_type_of_their_first_use() {
    assert_eq!(errors("LD 5\nMAX 3\nST s"), []);
    assert_eq!(errors("LD k\nMUX 10, 20, 30\nST x"), []);
    assert_eq!(
        errors("LD 1\nMAX 2\nADD r\nST r"),
        [],
        "typed by the REAL operand"
    );
    assert_eq!(errors("LD k\nMUX 1, 0\nST b"), [], "BOOL from the store");
}

#[test]
fn a_pending_call_reaching_a_label_takes_its_default_type() {
    // Across a jump the use is not known yet: the call is emitted with its
    // default type (DINT for integer literals), as a literal reaching a label is.
    let e = errors("LD k\nMUX 1, 0\nJMP l\nl: ST x");
    assert_eq!(
        e,
        [(
            "IL0106".to_string(),
            "`x` is INT, but the current result is DINT; narrowing is never implicit: convert with DINT_TO_INT".to_string()
        )]
    );
    assert_eq!(
        errors("LD k\nMUX INT#1, 0\nJMP l\nl: ST x"),
        [],
        "a typed literal fixes it"
    );
}

#[test]
fn pending_calls_still_check_ranges_and_types() {
    let e = errors("LD k\nMUX 300, 1\nST s");
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].0, "IL0116");
    assert!(e[0].1.contains("300"), "{e:?}");
}

#[test]
fn literal_only_arithmetic_is_exact_and_range_checked() {
    assert_eq!(errors("LD 2\nMUL( 2\nADD 3\n)\nST s"), []);
    let e = errors("LD 127\nADD 1\nST s");
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].0, "IL0116");
}

/// Hundreds of labels: every instruction is checked and emitted (the label
/// analysis once settled one label per round and dropped code after 64).
#[test]
fn many_labels_settle_and_nothing_is_dropped() {
    let mut body = String::from("LD 0\nST n\n");
    for i in 0..300 {
        body.push_str(&format!(
            "l{i}: LD n\nADD 1\nST n\nGT 1000\nJMPC l{}\n",
            i + 1
        ));
    }
    body.push_str("l300: LD n\nST n\n");
    // A backward loop in the middle as well.
    body.push_str("back: LD n\nSUB 1\nST n\nGT 10\nJMPC back\n");
    let src = format!("FUNCTION_BLOCK T\nVAR n : INT; END_VAR\n{body}END_FUNCTION_BLOCK\n");
    let f = SourceFile::new("t.il", src);
    let program = il_codegen::Program::new().il(f);
    let checked = program.check();
    let c = checked
        .emit(Default::default())
        .unwrap_or_else(|| panic!("{:?}", checked.diagnostics()))
        .remove(0);
    // Only `l0` (never jumped to) is worth a warning; no unreachable code.
    assert_eq!(c.warnings.len(), 1, "{:?}", c.warnings);
    assert_eq!(c.warnings[0].code, "IL0120");
    let code = c.text.clone();
    assert_eq!(code.matches("wrapping_add").count(), 300);
    assert_eq!(code.matches("wrapping_sub").count(), 1);
}
