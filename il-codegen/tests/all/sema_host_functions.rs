//! Host functions: `{extern}` before a FUNCTION declares one whose body the
//! crate provides in Rust. Where the pragma may stand, what such a FUNCTION
//! may declare, and how it is called.

use crate::checked::{errors, errors_std};

const HOST: &str = "{extern}\nFUNCTION log_value : BOOL\nVAR_INPUT v : INT; END_VAR\nVAR_OUTPUT seen : INT; END_VAR\nVAR_IN_OUT n : DINT; END_VAR\nEND_FUNCTION\n";

fn checked_pous(src: &str) -> Vec<il_codegen::ir::CheckedPou> {
    let f = il_codegen::diag::SourceFile::new("t.il", src);
    il_codegen::Program::new()
        .il(f)
        .check()
        .into_ir()
        .expect("no errors")
        .remove(0)
        .pous
}

#[test]
fn a_host_function_is_called_like_any_function() {
    let src = "{extern}\nFUNCTION clamp : INT\nVAR_INPUT v, hi : INT; END_VAR\nEND_FUNCTION\nPROGRAM P\nVAR x : INT; y : INT; END_VAR\n    LD x\n    clamp 100\n    ST y\n    CAL clamp(v := x, hi := 5)\n    ST y\nEND_PROGRAM\n";
    assert_eq!(errors(src), []);
    // Its interface is checked like any FUNCTION's.
    let e = errors(&src.replace("clamp 100", "clamp 100, 3"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].1, 8);
    let pous = checked_pous(src);
    let f = pous.iter().find(|p| p.name == "clamp").unwrap();
    assert!(f.host && f.body.is_empty());
    assert!(!pous.iter().find(|p| p.name == "P").unwrap().host);
    // A FUNCTION, and the in-outs and outputs, all in one host declaration.
    assert!(checked_pous(HOST)[0].host);
}

#[test]
fn comments_and_other_pragmas_may_stand_between_extern_and_the_function() {
    let src = HOST.replace(
        "{extern}\n",
        "(* provided by the runtime *)\n{ EXTERN } // the driver\n{attribute 'hide'}\n",
    );
    let pous = checked_pous(&src);
    assert!(pous[0].host);
    // Without the pragma it is an ordinary FUNCTION with an empty body.
    let pous = checked_pous(&HOST.replace("{extern}\n", "{attribute 'extern_impl'}\n"));
    assert!(!pous[0].host);
}

#[test]
fn extern_marks_a_function_block_or_program_too() {
    // A CODESYS POU whose body is not IL is host-provided the same way.
    let src = "{extern}\nFUNCTION_BLOCK F\nVAR_INPUT i : INT; END_VAR\nVAR_OUTPUT o : INT; END_VAR\nEND_FUNCTION_BLOCK\n{extern}\nPROGRAM P\nVAR_OUTPUT q : BOOL; END_VAR\nEND_PROGRAM\n";
    assert_eq!(errors(src), []);
    let pous = checked_pous(src);
    assert!(pous.iter().all(|p| p.host), "{pous:?}");
    // Locals would be dropped silently: IL0140, as for a FUNCTION.
    let e = errors("{extern}\nFUNCTION_BLOCK F\nVAR t : INT; END_VAR\nEND_FUNCTION_BLOCK\n");
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].0, "IL0140");
    assert!(
        e[0].3.contains("host FUNCTION_BLOCK `F` declares VAR"),
        "{}",
        e[0].3
    );
}

#[test]
fn extern_stands_before_a_pou_only() {
    let pou = "PROGRAM P\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_PROGRAM\n";
    let cases = [
        (
            pou.replace("    LD x\n", "    {extern}\n    LD x\n"),
            3,
            "inside a declaration",
        ),
        (
            format!("{{extern}}\nTYPE e : (A, B); END_TYPE\n{pou}"),
            1,
            "before a TYPE block",
        ),
        (
            format!("{pou}{{extern}}\nCONFIGURATION C\nPROGRAM p : P;\nEND_CONFIGURATION\n"),
            6,
            "before a CONFIGURATION",
        ),
        (
            format!("{pou}(* end *) {{extern}}\n"),
            6,
            "after the last declaration",
        ),
    ];
    for (src, line, what) in cases {
        let e = errors(&src);
        assert_eq!(e.len(), 1, "{src}: {e:?}");
        assert_eq!((e[0].0.as_str(), e[0].1), ("IL0037", line), "{src}");
        assert!(e[0].3.contains(what), "{src}: {}", e[0].3);
    }
    // Inside a comment it is no pragma at all.
    assert_eq!(errors(&format!("(* {{extern}} *)\n{pou}")), []);
}

#[test]
fn a_host_function_declares_its_interface_only() {
    let body = HOST.replace("END_FUNCTION", "    LD v\n    ST log_value\nEND_FUNCTION");
    let e = errors(&body);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].0.as_str(), e[0].1, e[0].2), ("IL0140", 6, 5));
    assert!(e[0].3.contains("has instructions"), "{}", e[0].3);
    let local = HOST.replace("END_FUNCTION", "VAR t : INT; END_VAR\nEND_FUNCTION");
    let e = errors(&local);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].0.as_str(), e[0].1), ("IL0140", 6));
    assert!(e[0].3.contains("declares VAR"), "{}", e[0].3);
}

#[test]
fn extern_is_a_pragma_and_refused_under_iec2003() {
    let e = errors_std(HOST, il_codegen::Standard::Iec2003);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].0.as_str(), e[0].1), ("IL0301", 1));
}

#[test]
fn the_emitted_code_checks_the_host_signature_instead_of_a_body() {
    let f = il_codegen::diag::SourceFile::new("t.il", HOST);
    let out = il_codegen::Program::new()
        .il(f)
        .check()
        .emit(Default::default())
        .expect("emits")
        .remove(0)
        .text;
    assert!(
        out.contains(
            "const _: fn(&mut ::il_std::Cycle, i16, &mut i32, &mut i16) -> bool = log_value;"
        ),
        "{out}"
    );
    assert!(!out.contains("pub fn log_value"), "{out}");
    assert!(
        out.contains(
            "`fn log_value(ctx: &mut ::il_std::Cycle, v: i16, n: &mut i32, seen: &mut i16) -> bool`"
        ),
        "{out}"
    );
}
