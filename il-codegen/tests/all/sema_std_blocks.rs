//! The standard function blocks as the checker knows them: every block of
//! il-std's table is a type, and the 3rd edition's INT counters take their
//! calls, members and input operators.

use il_codegen::diag::SourceFile;

fn errors(src: &str) -> Vec<(String, String)> {
    let f = SourceFile::new("t.il", src);
    il_codegen::Program::new().il(f).check().diagnostics()[0]
        .iter()
        .filter(|d| d.is_error())
        .map(|d| (d.code.to_string(), d.message.clone()))
        .collect()
}

#[test]
fn every_block_of_the_table_is_a_type() {
    let decls: String = il_std::signature::FB_SIGNATURES
        .iter()
        .enumerate()
        .map(|(k, f)| format!("b{k} : {};\n", f.name))
        .collect();
    let src = format!("PROGRAM P\nVAR\n{decls}END_VAR\nLD TRUE\nEND_PROGRAM\n");
    assert_eq!(errors(&src), []);
}

#[test]
fn int_counters_take_calls_members_and_input_operators() {
    let src = "PROGRAM P
VAR
    c : CTU_INT;
    d : CTD_INT;
    e : CTUD_INT;
    x : BOOL;
    n : INT;
    q : BOOL;
END_VAR
    CAL  c(CU := x, PV := 3)
    LD   c.CV
    ST   n
    LD   x
    CU   c
    LD   5
    PV   c
    LD   c.Q
    ST   q
    LD   x
    CD   d
    LD   n
    PV   d
    LD   d.CV
    ST   n
    CAL  d(CD := x, LD := TRUE, PV := 3, Q => q)
    CAL  e(CU := x, CD := q, R := FALSE, LD := FALSE, PV := 2, CV => n)
    LD   x
    CU   e
    CD   e
    LD   e.QU
    AND  e.QD
    ST   q
END_PROGRAM
";
    assert_eq!(errors(src), []);
}

#[test]
fn int_counters_have_int_members() {
    let fb = |body: &str| {
        errors(&format!(
            "PROGRAM P\nVAR c : CTU_INT; d : CTD_INT; e : CTUD_INT; s : SINT; t : TIME; END_VAR\n{body}\nEND_PROGRAM\n"
        ))
    };
    // CV is INT: it does not narrow into a SINT.
    for body in ["LD c.CV\nST s", "LD d.CV\nST s", "LD e.CV\nST s"] {
        let e = fb(body);
        assert_eq!(e.len(), 1, "{body}: {e:?}");
        assert_eq!(e[0].0, "IL0106", "{body}: {e:?}");
    }
    // PV is INT: a TIME is not one.
    assert_eq!(fb("LD t\nPV c")[0].0, "IL0106");
    // A CTU_INT has no CD, a CTD_INT no CU (Table 54).
    assert_eq!(fb("LD TRUE\nCD c")[0].0, "IL0124");
    assert_eq!(fb("LD TRUE\nCU d")[0].0, "IL0124");
    assert_eq!(fb("CAL c(CD := TRUE)")[0].0, "IL0112");
}
