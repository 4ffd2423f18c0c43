//! The 3rd-edition and vendor forms accepted by default, and refused one by
//! one under `Standard::Iec2003` with an error that names the form.

use crate::checked::{errors, errors_std};
use il_codegen::Standard;

/// A program with a pragma in every place a comment may stand.
const PRAGMAS: &str = "{attribute 'qualified_only'}
{attribute 'hide'} PROGRAM p {before declarations}
VAR {in a block}
    x {after a name} : INT; {after a declaration}
    {on its own line}
    y : INT := 3 {before the semicolon};
END_VAR
{on its own line in the body}
    LD y {after an instruction}
    {a pragma
     over two lines}
    ADD 1 (* a comment *) {and a pragma}
    ST x
END_PROGRAM
{after the POU}
";

#[test]
fn pragmas_are_ignored_wherever_a_comment_may_stand() {
    assert_eq!(errors(PRAGMAS), []);
}

#[test]
fn pragmas_are_refused_under_iec2003_one_by_one() {
    let e = errors_std(PRAGMAS, Standard::Iec2003);
    assert_eq!(e.len(), 13, "{e:#?}");
    assert!(e.iter().all(|(code, ..)| code == "IL0301"), "{e:#?}");
    assert_eq!(
        e[0],
        (
            "IL0301".to_string(),
            1,
            1,
            "pragmas `{ ... }` are a 3rd-edition feature".to_string()
        )
    );
    let lines: Vec<usize> = e.iter().map(|e| e.1).collect();
    assert_eq!(lines, [1, 2, 2, 3, 4, 4, 5, 6, 8, 9, 10, 12, 15]);
}

#[test]
fn an_unterminated_pragma_is_an_error_at_its_start() {
    // Like an unclosed comment it swallows the rest of the file, END_PROGRAM too.
    let e = errors("PROGRAM p\n    LD 1 {never closed\n    ST x\nEND_PROGRAM\n");
    assert_eq!(e.len(), 2, "{e:#?}");
    assert_eq!(e[1].0, "IL0014");
    assert_eq!(
        e[0],
        (
            "IL0025".to_string(),
            2,
            10,
            "this pragma is never closed".to_string()
        )
    );
}
