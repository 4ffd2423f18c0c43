//! Hostile input: IL names that collide with Rust keywords, prelude and
//! primitive names and the emitter's own helper names, and comments and
//! strings that try to close a Rust string or comment or to inject items.
//! `plc-hostile/hostile.il` is compiled through build.rs and `il!(file = ...)` (so
//! the crate builds only if the generated code does, under
//! `#![deny(warnings)]`) and run here; the same sources go through the file
//! writer, whose output must hold exactly the expected items.

use il_codegen::diag::{SourceFile, has_errors};
use il_std::{Cycle, STRING, WSTRING};

const HOSTILE: &str = include_str!("../../plc-hostile/hostile.il");

macro_rules! hostile_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Default as DefaultFb, Option as OptionFb, Result, Self_, Some as some, r#fn};

            #[test]
            fn keyword_named_program_runs_as_written() {
                let mut ctx = Cycle::new();
                let mut p = r#fn::default();
                p.x = true;
                p.call(&mut ctx);
                assert_eq!(ctx.fault_count(), 0);
                // `CAL crate(fn := 1, match := 2, self := 3, safe := 4)` of a
                // block named Option with keyword-named inputs.
                assert_eq!(p.crate_.sum, 10);
                assert_eq!(p.r#match, 10);
                // The function `Some` with inputs None, Default, core ...
                assert_eq!(p.r#loop, 36);
                assert_eq!(some(&mut ctx, 1, 2, 3, 4, 5, 6, 7, 8), 36);
                // The block named Default, with outputs named like the prelude.
                assert_eq!(p.super_.Some, 7);
                assert!(p.super_.None && p.super_.il_std);
                assert_eq!(p.super_.kind, Result::self_);
                assert_eq!(p.Self_fb.q, 1);
                assert!(p.long_fb.q);
                // Each of the nine hostile comments sits on a line that counts.
                assert_eq!(p.n, 9);
                // Hostile strings are data, concatenated in reverse order.
                let last: String = p.last.chars().collect();
                assert_eq!(
                    last,
                    "} } fn injected2() {r#\" \"# \\ \\\\ \\n*/ fn injected() {} /*\"); std::process::exit(1); //"
                );
                assert_eq!(p.s, STRING::<120>::from_str_truncating("\r\n\t$'\"").0);
                assert_eq!(p.w, WSTRING::<80>::from_str_truncating("\"); fn w() {} //").0);
                // A loop through a label named like a keyword, then a jump to
                // the label `match`.
                assert_eq!(p.ctx, 3);
                assert!(p.flag);
                // R_EDGE inputs named x and memory_x (the emitter's edge
                // memory is `__edge_memory_<name>`).
                assert!(p.edge_x && !p.edge_memory_x);
                p.memory_x = true;
                p.call(&mut ctx);
                assert!(!p.edge_x && p.edge_memory_x);
                assert_eq!(p.Self_fb.q, 2);
                let _: OptionFb = p.crate_.clone();
                let _: DefaultFb = p.super_.clone();
                let _: Self_ = p.Self_fb.clone();
            }
        }
    };
}

hostile_tests!(hostile_build);
hostile_tests!(hostile_macro);

/// Inline `il!` with hostile comments (a raw string needs `r##"` here: the
/// IL holds `"#`).
mod inline {
    il_macros::il!(
        r##"
FUNCTION_BLOCK r (* "#); fn injected() {} // *)
VAR_INPUT async, in0 : INT; END_VAR
VAR_OUTPUT out : INT; END_VAR
    LD   in0 (* */ } } fn injected2() { /* *)
    ADD  1   (* a line separator, a paragraph separator *)
    ST   out (* "# r#" *)
END_FUNCTION_BLOCK
"##
    );

    #[test]
    fn runs() {
        let mut ctx = il_std::Cycle::new();
        let mut b = r {
            in0: 41,
            ..Default::default()
        };
        b.call(&mut ctx);
        assert_eq!(b.out, 42);
    }
}

/// The file writer (`ilc emit`, build.rs): the text parses, and its items are
/// exactly those generated for the POUs and types, whatever the comments hold.
#[test]
fn the_written_file_holds_exactly_the_expected_items() {
    let file = SourceFile::new("hostile.il", HOSTILE);
    let text = il_codegen::Program::new()
        .il(file.clone())
        .check()
        .files(Default::default())
        .expect("compiles")
        .remove(0);
    let parsed = syn::parse_file(&text).expect("the written file parses");
    let mut names = Vec::new();
    for item in &parsed.items {
        use quote::ToTokens;
        match item {
            syn::Item::Struct(s) => names.push(format!("struct {}", s.ident)),
            syn::Item::Enum(e) => names.push(format!("enum {}", e.ident)),
            syn::Item::Fn(f) => names.push(format!("fn {}", f.sig.ident)),
            syn::Item::Impl(i) => {
                let trait_ = i
                    .trait_
                    .as_ref()
                    .map(|(p, _)| p.to_token_stream().to_string());
                names.push(format!(
                    "impl {}for {}",
                    trait_.map(|t| t + " ").unwrap_or_default(),
                    i.self_ty.to_token_stream()
                ));
            }
            other => panic!("unexpected item {}", other.to_token_stream()),
        }
    }
    let long = format!("L{}end_FB", "ong_name_".repeat(27));
    let mut expected = vec![
        "enum Result".to_string(),
        "impl :: il_std :: trace :: AsValue for Result".to_string(),
        "fn Some".to_string(),
    ];
    for fb in ["Option", "Default", "Self_", long.as_str(), "r#fn"] {
        expected.push(format!("struct {fb}"));
        expected.push(format!("impl :: core :: default :: Default for {fb}"));
        // `call` and friends, then `visit` (emit/visit.rs)
        expected.push(format!("impl for {fb}"));
        expected.push(format!("impl for {fb}"));
        expected.push(format!("impl :: il_std :: FunctionBlock for {fb}"));
        expected.push(format!("impl :: il_std :: trace :: Visit for {fb}"));
    }
    names.sort();
    expected.sort();
    assert_eq!(names, expected);

    // Every IL line with code is a `// N: ...` comment; none of them holds a
    // line break, a control character or a bidirectional control (rustc
    // refuses those even in comments): they are written as escapes.
    let comments: Vec<&str> = text
        .lines()
        .map(str::trim_start)
        .filter(|l| l.starts_with("// ") && !l.starts_with("// @generated"))
        .collect();
    assert!(comments.len() > 100);
    for c in &comments {
        let (n, rest) = c[3..].split_once(": ").expect("// N: text");
        let n: usize = n.parse().expect("a line number");
        // `*/` is broken up (`* /`): comment text stays inert even
        // inside a block comment (emit/text.rs).
        assert!(!c.contains("*/"), "{c}");
        assert!(
            file.line_text(n)
                .trim()
                .replace("*/", "* /")
                .starts_with(rest.split(" (*").next().unwrap_or(""))
        );
    }
    for bad in [
        '\r', '\u{b}', '\u{c}', '\u{85}', '\u{2028}', '\u{2029}', '\u{202e}', '\u{2066}',
        '\u{200f}',
    ] {
        assert!(!text.contains(bad), "{bad:?} reached the written file");
    }
    assert!(text.contains(r"(* \u{202e} bidi \u{2066} isolate \u{2069} \u{200f} *)"));
    assert!(text.contains(r"(* line\u{2028}separator\u{2029}paragraph nel *)"));
    assert!(text.contains(r#"// 131: LD   n (* "); std::process::exit(1); // *)"#));
}

/// The same file beside another source (as build.rs compiles several files
/// into one program): the same text.
#[test]
fn the_builder_writer_agrees() {
    let hostile = SourceFile::new("hostile.il", HOSTILE);
    let other = SourceFile::new(
        "other.il",
        "FUNCTION_BLOCK Other\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_FUNCTION_BLOCK\n",
    );
    let one = il_codegen::Program::new()
        .il(hostile.clone())
        .check()
        .files(Default::default())
        .expect("compiles");
    let two = il_codegen::Program::new()
        .il(hostile)
        .il(other)
        .check()
        .files(Default::default())
        .expect("compiles");
    assert_eq!(one[0], two[0]);
}

/// The emitter's helper names are not IEC identifiers (`__` is refused):
/// declaring one is a clear error, never generated code.
#[test]
fn helper_names_are_refused() {
    for name in [
        "__ctx",
        "__ret",
        "__cr_bool",
        "__save_0",
        "__fb",
        "__v_x",
        "__ix0",
        "__a0",
        "__o0",
        "__in0",
        "__pc",
        "__dispatch",
        "__edge_x",
        "__edge_memory_x",
        "__il_line",
        "x__y",
        "self_",
        "i32_",
    ] {
        let src = format!(
            "PROGRAM P\nVAR {name} : INT; END_VAR\n    LD {name}\n    ST {name}\nEND_PROGRAM\n"
        );
        let diags = il_codegen::Program::new()
            .il(SourceFile::new("p.il", src))
            .check()
            .into_diagnostics()
            .remove(0);
        assert!(has_errors(&diags), "{name}");
        assert_eq!(diags[0].code, "IL0126", "{name}: {}", diags[0].message);
    }
}
