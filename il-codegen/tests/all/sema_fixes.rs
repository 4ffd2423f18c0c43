//! The checker's quick fixes (`Diagnostic::fixes`): each one, applied to
//! the text, gives a program without that error: did-you-mean renames, the
//! conversion of the CR before a narrowing store, the declaration of an
//! undeclared store target, `T#` before a bare duration.

use il_codegen::Program;
use il_codegen::diag::{Diagnostic, SourceFile};

fn diags(text: &str) -> Vec<Diagnostic> {
    Program::new()
        .il(SourceFile::new("t.il", text))
        .check()
        .diagnostics()
        .iter()
        .flatten()
        .cloned()
        .collect()
}

/// The text with the first fix of the first diagnostic of `code` applied.
fn fixed(text: &str, code: &str) -> (String, String) {
    let ds = diags(text);
    let d = ds
        .iter()
        .find(|d| d.code == code)
        .unwrap_or_else(|| panic!("no {code} in {ds:?}"));
    let f = d.fixes.first().unwrap_or_else(|| panic!("no fix: {d:?}"));
    let mut out = text.to_string();
    for (span, new) in f.edits.iter().rev() {
        out.replace_range(span.lo as usize..span.hi as usize, new);
    }
    (f.title.clone(), out)
}

fn errors(text: &str) -> Vec<&'static str> {
    diags(text)
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect()
}

const HEAD: &str = "FUNCTION_BLOCK Fb\nVAR_INPUT go : BOOL; END_VAR\nVAR_OUTPUT running : BOOL; END_VAR\n    LD go\n    ST running\nEND_FUNCTION_BLOCK\n";

#[test]
fn renames_fix_misspelled_names() {
    for (body, title) in [
        ("    LD cuont\n    ST count\n", "Change to `count`"),
        (
            "    LD flag\n    JMPC dnoe\n    LD 1\n    ST count\ndone:\n",
            "Change to `done`",
        ),
        (
            "    CAL f(go := TRUE)\n    LD f.runing\n    ST flag\n",
            "Change to `running`",
        ),
        ("    LD 2\n    Twcie 3\n    ST count\n", "Change to `Twice`"),
    ] {
        let text = format!(
            "{HEAD}FUNCTION Twice : INT\nVAR_INPUT a : INT; b : INT; END_VAR\n    LD a\n    MUL b\n    ST Twice\nEND_FUNCTION\nPROGRAM Main\nVAR\n    count : INT;\n    flag : BOOL;\n    f : Fb;\nEND_VAR\n{body}END_PROGRAM\n"
        );
        let codes = errors(&text);
        assert_eq!(codes.len(), 1, "{codes:?} {text}");
        let (t, out) = fixed(&text, codes[0]);
        assert_eq!(t, title);
        assert_eq!(errors(&out), Vec::<&str>::new(), "{out}");
    }
    // A type.
    let text = "PROGRAM Main\nVAR\n    t : TNO;\nEND_VAR\nEND_PROGRAM\n";
    let code = errors(text)[0];
    let (t, out) = fixed(text, code);
    assert_eq!(t, "Change to `TON`");
    assert_eq!(errors(&out), Vec::<&str>::new(), "{out}");
}

#[test]
fn a_narrowing_store_gets_its_conversion_after_the_label() {
    let text = "PROGRAM Main\nVAR\n    big : DINT;\n    n : INT;\nEND_VAR\n    LD big\nL1:\tST n\nEND_PROGRAM\n";
    let code = errors(text)[0];
    let (t, out) = fixed(text, code);
    assert_eq!(t, "Convert the current result with `DINT_TO_INT`");
    assert!(out.contains("L1:\tDINT_TO_INT\n   \tST n\n"), "{out}");
    assert_eq!(errors(&out), Vec::<&str>::new(), "{out}");
}

#[test]
fn an_undeclared_store_target_is_declared_with_the_crs_type() {
    for (vars, want) in [
        // Before the END_VAR of the VAR block.
        (
            "VAR\n    x : REAL;\nEND_VAR\n",
            "VAR\n    x : REAL;\n    total : REAL;\nEND_VAR\n",
        ),
        // A block on one line.
        (
            "VAR x : REAL; END_VAR\n",
            "VAR x : REAL; total : REAL; END_VAR\n",
        ),
        // No VAR block: a new one after the others.
        (
            "VAR_INPUT x : REAL; END_VAR\n",
            "VAR_INPUT x : REAL; END_VAR\nVAR\n    total : REAL;\nEND_VAR\n",
        ),
    ] {
        let text = format!("FUNCTION_BLOCK Fb\n{vars}    LD x\n    ST total\nEND_FUNCTION_BLOCK\n");
        let code = errors(&text)[0];
        let (t, out) = fixed(&text, code);
        assert_eq!(t, "Declare `total : REAL` in VAR");
        assert!(out.contains(want), "{out}");
        assert_eq!(errors(&out), Vec::<&str>::new(), "{out}");
    }
    // No VAR at all: after the header.
    let text = "PROGRAM Main\n    LD TRUE\n    ST done\nEND_PROGRAM\n";
    // (`done` is near no name: the declaration is the only fix.)
    let (_, out) = fixed(text, errors(text)[0]);
    assert_eq!(
        out,
        "PROGRAM Main\nVAR\n    done : BOOL;\nEND_VAR\n    LD TRUE\n    ST done\nEND_PROGRAM\n"
    );
}

#[test]
fn a_bare_duration_gets_its_prefix() {
    let text = "PROGRAM Main\nVAR\n    t : TON;\nEND_VAR\n    LD 5s\n    ST t.PT\nEND_PROGRAM\n";
    let code = errors(text)[0];
    let (t, out) = fixed(text, code);
    assert_eq!(t, "Write `T#5s`");
    assert_eq!(errors(&out), Vec::<&str>::new(), "{out}");
}
