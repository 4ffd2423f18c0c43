//! Helpers shared by the syntax tests.
#![allow(dead_code)]

pub use il_codegen::ast::parse;
pub use il_codegen::ast::*;
pub use il_codegen::diag::{Diagnostic, SourceFile};

/// Parse and fail on any diagnostic.
pub fn ok(src: &str) -> CompilationUnit {
    let f = SourceFile::new("t.il", src);
    let (u, d) = parse(&f);
    assert!(
        d.is_empty(),
        "unexpected diagnostics for\n{src}\n{}",
        show(&f, &d)
    );
    u
}

/// The body of `PROGRAM p` around the given lines.
pub fn body(lines: &str) -> Vec<Stmt> {
    let u = ok(&format!("PROGRAM p\n{lines}\nEND_PROGRAM\n"));
    match u.items.into_iter().next() {
        Some(Item::Pou(p)) => p.body,
        other => panic!("{other:?}"),
    }
}

/// The instructions of a body (labels dropped).
pub fn instrs(lines: &str) -> Vec<InstrKind> {
    body(lines)
        .into_iter()
        .filter_map(|s| match s {
            Stmt::Instr(i) => Some(i.kind),
            Stmt::Label(_) => None,
        })
        .collect()
}

pub fn one(line: &str) -> InstrKind {
    let mut v = instrs(line);
    assert_eq!(v.len(), 1, "{line}: {v:?}");
    v.remove(0)
}

pub fn pou(src: &str) -> Pou {
    match ok(src).items.into_iter().next() {
        Some(Item::Pou(p)) => p,
        other => panic!("{other:?}"),
    }
}

pub fn decls(vars: &str) -> Vec<VarBlock> {
    pou(&format!("FUNCTION_BLOCK f\n{vars}\nEND_FUNCTION_BLOCK")).var_blocks
}

pub fn show(f: &SourceFile, d: &[Diagnostic]) -> String {
    d.iter()
        .map(|d| {
            let (l, c) = f.line_col(d.span.lo);
            format!("{l}:{c}: {} {} [{}]\n", d.code, d.message, d.label)
        })
        .collect()
}

/// (code, line, column, message) of every diagnostic.
pub fn errs(src: &str) -> Vec<(&'static str, usize, usize, String)> {
    let f = SourceFile::new("t.il", src);
    let (_, d) = parse(&f);
    d.iter()
        .map(|d| {
            let (l, c) = f.line_col(d.span.lo);
            (d.code, l, c, d.message.clone())
        })
        .collect()
}

/// Exactly one diagnostic, with this code, line and column; returns its message.
pub fn err1(src: &str, code: &str, line: usize, col: usize) -> String {
    let e = errs(src);
    assert_eq!(e.len(), 1, "expected one diagnostic for\n{src}\ngot {e:#?}");
    assert_eq!((e[0].0, e[0].1, e[0].2), (code, line, col), "{e:#?}");
    e[0].3.clone()
}

/// The name of a plain variable operand.
pub fn name_of(o: &Operand) -> String {
    match o {
        Operand::Var(v) if v.path.is_empty() => v.base.name.to_string(),
        other => panic!("not a plain variable: {other:?}"),
    }
}

pub fn lit(o: &Operand) -> &LitKind {
    match o {
        Operand::Lit(l) => &l.kind,
        other => panic!("not a literal: {other:?}"),
    }
}

/// The literal operand of `LD <text>`.
pub fn ld_lit(text: &str) -> Literal {
    match one(&format!("LD {text}")) {
        InstrKind::Load {
            operand: Operand::Lit(l),
            ..
        } => l,
        other => panic!("{text}: {other:?}"),
    }
}
