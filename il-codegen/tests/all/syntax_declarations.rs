//! Declarations: VAR sections and qualifiers, AT, lists, initial values,
//! TYPE ... END_TYPE, CONFIGURATION / RESOURCE / TASK / PROGRAM ... WITH.

use crate::syntax_common::*;

#[test]
fn every_var_section_and_qualifier() {
    let b = decls(
        "VAR a : INT; END_VAR\nVAR_INPUT b : BOOL; END_VAR\nVAR_OUTPUT c : BOOL; END_VAR\nVAR_IN_OUT d : INT; END_VAR\n\
         VAR_EXTERNAL CONSTANT e : INT; END_VAR\nVAR_GLOBAL RETAIN f : INT; END_VAR\nVAR_TEMP g : INT; END_VAR\n\
         VAR NON_RETAIN h : INT; END_VAR\nVAR CONSTANT RETAIN i : INT := 1; END_VAR",
    );
    let kinds: Vec<_> = b.iter().map(|b| b.kind).collect();
    use VarKind::*;
    assert_eq!(
        kinds,
        [Var, Input, Output, InOut, External, Global, Temp, Var, Var]
    );
    assert!(b[4].constant);
    assert_eq!(b[5].retain, Retain::Retain);
    assert_eq!(b[7].retain, Retain::NonRetain);
    assert!(b[8].constant && b[8].retain == Retain::Retain);
}

#[test]
fn lists_locations_edges_and_initial_values() {
    let b = decls(
        "VAR_INPUT\n  a, b, c : BOOL R_EDGE;\n  d : BOOL F_EDGE;\nEND_VAR\n\
         VAR\n  led AT %QX0.0 : BOOL := TRUE;\n  w AT %IW3 : WORD;\n  any AT %I* : BOOL;\n  n : INT := -1;\n\
         t : TIME := T#1s;\n  arr : ARRAY [0..9, -2..2] OF INT := [1, 2, 3(0)];\n  s : STRING[20] := 'abc';\n\
         ws : WSTRING(10);\n  p : Point := (x := 1, y := 2);\n  r : INT (0..100) := 5;\n  c : Color := Color#Red;\nEND_VAR",
    );
    let d = &b[0].decls[0];
    assert_eq!(
        d.names.iter().map(|n| &*n.name).collect::<Vec<_>>(),
        ["a", "b", "c"]
    );
    assert_eq!(d.edge, Some(Edge::Rising));
    assert_eq!(b[0].decls[1].edge, Some(Edge::Falling));
    let v = &b[1].decls;
    let loc = v[0].location.as_ref().unwrap();
    assert_eq!(
        (loc.area, loc.size, loc.path.clone()),
        (Area::Output, AddrSize::X, vec![0, 0])
    );
    assert!(
        matches!(&v[0].init, Some(Initializer::Simple(Operand::Lit(l))) if l.kind == LitKind::Bool(true))
    );
    assert_eq!(v[1].location.as_ref().unwrap().size, AddrSize::W);
    assert!(v[2].location.as_ref().unwrap().partial);
    assert!(
        matches!(&v[3].init, Some(Initializer::Simple(Operand::Lit(l))) if l.kind == LitKind::Int(IntValue::new(-1)))
    );
    match (&v[5].ty, &v[5].init) {
        (TypeSpec::Array { dims, elem, .. }, Some(Initializer::Array { elems, .. })) => {
            assert_eq!(dims.len(), 2);
            assert!(
                matches!(&dims[1].lo, ConstExpr::Lit(l) if l.kind == LitKind::Int(IntValue::new(-2)))
            );
            assert!(matches!(&**elem, TypeSpec::Named(n) if n.is("INT")));
            assert_eq!(elems.len(), 3);
            assert!(matches!(&elems[2].0, Some(l) if l.kind == LitKind::Int(IntValue::new(3))));
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        &v[6].ty,
        TypeSpec::String {
            wide: false,
            len: Some(_),
            ..
        }
    ));
    assert!(matches!(
        &v[7].ty,
        TypeSpec::String {
            wide: true,
            len: Some(_),
            ..
        }
    ));
    assert!(matches!(&v[8].init, Some(Initializer::Struct { fields, .. }) if fields.len() == 2));
    assert!(matches!(&v[9].ty, TypeSpec::Subrange { base, .. } if base.is("INT")));
    assert!(matches!(
        &v[10].init,
        Some(Initializer::Simple(Operand::Lit(Literal {
            kind: LitKind::Enum(_),
            ..
        })))
    ));
}

#[test]
fn type_declarations() {
    let u = ok(
        "TYPE\n  Color : (Red, Green := 5, Blue) := Green;\n  Point : STRUCT\n    x : INT;\n    y : INT := 2;\n  END_STRUCT;\n\
         Grid : ARRAY [1..3, 1..3] OF Point;\n  Pct : INT (0..100);\n  Speed : REAL;\n  Name : STRING[32];\nEND_TYPE",
    );
    let Item::Types(t) = &u.items[0] else {
        panic!()
    };
    assert_eq!(t.len(), 6);
    assert!(
        matches!(&t[0].spec, TypeSpec::Enum { values, .. } if values.len() == 3 && values[1].value.is_some())
    );
    assert!(t[0].init.is_some());
    assert!(matches!(&t[1].spec, TypeSpec::Struct { fields, .. } if fields.len() == 2));
    assert!(matches!(&t[2].spec, TypeSpec::Array { dims, .. } if dims.len() == 2));
    assert!(matches!(&t[3].spec, TypeSpec::Subrange { .. }));
    assert!(matches!(&t[4].spec, TypeSpec::Named(n) if n.is("REAL")));
    assert!(matches!(&t[5].spec, TypeSpec::String { .. }));
}

#[test]
fn configuration_resource_task_program() {
    let u = ok(
        "CONFIGURATION cfg\n  VAR_GLOBAL g : INT; END_VAR\n  RESOURCE r1 ON cpu\n    VAR_GLOBAL h : BOOL; END_VAR\n\
         TASK fast (INTERVAL := T#10ms, PRIORITY := 1);\n    TASK ev (SINGLE := trig, PRIORITY := 2);\n\
         PROGRAM RETAIN main WITH fast : Main (a := g, b => h);\n    PROGRAM other : Other;\n  END_RESOURCE\nEND_CONFIGURATION",
    );
    let Item::Configuration(c) = &u.items[0] else {
        panic!()
    };
    assert!(c.name.is("cfg"));
    assert_eq!(c.globals.len(), 1);
    assert_eq!(c.resources.len(), 1);
    let r = &c.resources[0];
    assert!(r.name.as_ref().unwrap().is("r1") && r.on.as_ref().unwrap().is("cpu"));
    assert_eq!(r.globals.len(), 1);
    assert_eq!(r.tasks.len(), 2);
    assert!(
        matches!(&r.tasks[0].interval, Some(Operand::Lit(l)) if l.kind == LitKind::Time { nanos: 10_000_000, long: false })
    );
    assert!(matches!(&r.tasks[0].priority, Some(l) if l.kind == LitKind::Int(IntValue::new(1))));
    assert!(r.tasks[1].single.is_some());
    let p = &r.programs[0];
    assert_eq!(p.retain, Retain::Retain);
    assert!(p.task.as_ref().unwrap().is("fast") && p.program.is("Main"));
    assert_eq!(p.args.len(), 2);
    assert!(r.programs[1].task.is_none());
}

#[test]
fn configuration_without_resource() {
    let u = ok(
        "configuration config1\ntask task1 (interval := t#50ms, priority := 1);\nprogram program1 with task1: prog1;\nend_configuration",
    );
    let Item::Configuration(c) = &u.items[0] else {
        panic!()
    };
    assert_eq!(c.resources.len(), 1);
    assert!(c.resources[0].name.is_none());
    assert_eq!(c.resources[0].programs.len(), 1);
}

#[test]
fn function_header_and_result_type() {
    let p = pou("FUNCTION f : INT\nVAR_INPUT a : INT; END_VAR\nLD a\nST f\nEND_FUNCTION");
    assert_eq!(p.kind, PouKind::Function);
    assert!(matches!(p.return_type, Some(TypeSpec::Named(ref t)) if t.is("INT")));
    let p = pou("FUNCTION g : STRING[10]\nLD 'x'\nST g\nEND_FUNCTION");
    assert!(matches!(p.return_type, Some(TypeSpec::String { .. })));
    // Declarations on the header line.
    let p = pou("PROGRAM p VAR x : INT; END_VAR\nLD x\nEND_PROGRAM");
    assert_eq!(p.var_blocks.len(), 1);
    assert_eq!(p.body.len(), 1);
}

// ------------------------------------------------------------ refused

#[test]
fn missing_semicolon_names_the_declaration() {
    let m = err1(
        "PROGRAM p\nVAR\n  x : INT\n  y : BOOL;\nEND_VAR\nEND_PROGRAM",
        "IL0023",
        3,
        10,
    );
    assert_eq!(m, "expected `;` after the declaration of `x`");
}

#[test]
fn missing_end_var() {
    let e = errs("PROGRAM p\nVAR\n  x : INT;\nLD x\nST x\nEND_PROGRAM");
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].0, e[0].1, e[0].2), ("IL0013", 4, 1));
    assert_eq!(e[0].3, "missing END_VAR");
    let e = errs("PROGRAM p\nVAR\n  x : INT;\nEND_PROGRAM");
    assert_eq!(
        e.iter().map(|e| e.0).collect::<Vec<_>>(),
        ["IL0013"],
        "{e:?}"
    );
}

/// The note of a missing END_VAR points at the VAR keyword that opened the
/// block, however many tokens back (the parser has taken them from the
/// lexer long before).
#[test]
fn missing_end_var_names_the_open_block() {
    let decls: String = (0..200).map(|i| format!("  v{i} : INT;\n")).collect();
    let src =
        format!("PROGRAM p\nVAR_INPUT\n  a : BOOL;\nEND_VAR\n  VAR\n{decls}LD a\nEND_PROGRAM");
    let f = SourceFile::new("t.il", src.as_str());
    let (_, d) = parse(&f);
    let d = d.iter().find(|d| d.code == "IL0013").expect("IL0013");
    let (span, label) = &d.secondary[0];
    assert_eq!(label, "this block is not closed");
    assert_eq!(f.line_col(span.lo), (5, 3));
    assert_eq!(f.snippet(*span), "VAR");
}

#[test]
fn declaration_errors_recover_at_semicolon() {
    let e = errs(
        "PROGRAM p\nVAR\n  a : ;\n  b : INT;\n  c INT;\n  d : BOOL;\nEND_VAR\nLD d\nEND_PROGRAM",
    );
    assert_eq!(
        e.iter().map(|e| (e.0, e.1)).collect::<Vec<_>>(),
        [("IL0023", 3), ("IL0023", 5)],
        "{e:?}"
    );
}

#[test]
fn declarations_after_instructions() {
    let m = err1(
        "PROGRAM p\nLD x\nVAR x : BOOL; END_VAR\nEND_PROGRAM",
        "IL0012",
        3,
        1,
    );
    assert_eq!(m, "declarations must come before the instructions");
}

#[test]
fn missing_or_wrong_end_keyword() {
    assert_eq!(
        err1("FUNCTION_BLOCK Foo\nLD x\n", "IL0014", 3, 1),
        "missing END_FUNCTION_BLOCK for `Foo`"
    );
    assert_eq!(
        err1("FUNCTION_BLOCK Foo\nLD x\nEND_FUNCTION", "IL0014", 3, 1),
        "END_FUNCTION does not close FUNCTION_BLOCK `Foo`"
    );
    // A new POU while one is open.
    let e = errs("PROGRAM a\nLD x\nPROGRAM b\nLD y\nEND_PROGRAM");
    assert_eq!(
        e.iter().map(|e| (e.0, e.3.as_str())).collect::<Vec<_>>(),
        [("IL0014", "missing END_PROGRAM for `a`")]
    );
}

#[test]
fn result_type_rules() {
    assert_eq!(
        err1("FUNCTION f\nLD 1\nEND_FUNCTION", "IL0027", 1, 10),
        "FUNCTION `f` needs a result type"
    );
    assert_eq!(
        err1("PROGRAM p : INT\nEND_PROGRAM", "IL0027", 1, 13),
        "a PROGRAM has no result type"
    );
}

#[test]
fn type_errors() {
    let e = errs("TYPE\n  a : ;\n  b : INT;\nEND_TYPE");
    assert_eq!(
        e.iter().map(|e| (e.0, e.1)).collect::<Vec<_>>(),
        [("IL0023", 2)],
        "{e:?}"
    );
    let e = errs("TYPE\n  b : INT;\n");
    assert_eq!(
        e.iter().map(|e| (e.0, e.3.as_str())).collect::<Vec<_>>(),
        [("IL0014", "missing END_TYPE")]
    );
}

#[test]
fn configuration_errors() {
    let m = err1(
        "CONFIGURATION c\nTASK t (CYCLE := T#1s);\nEND_CONFIGURATION",
        "IL0024",
        2,
        9,
    );
    assert_eq!(
        m,
        "`CYCLE` is not a TASK parameter: use SINGLE, INTERVAL or PRIORITY"
    );
    let m = err1(
        "CONFIGURATION c\nPROGRAM p : q\nEND_CONFIGURATION",
        "IL0023",
        2,
        14,
    );
    assert_eq!(m, "expected `;` after the declaration of `p`");
    let e = errs("CONFIGURATION c\nTASK t (INTERVAL := T#1s);\n");
    assert_eq!(
        e.iter().map(|e| (e.0, e.3.as_str())).collect::<Vec<_>>(),
        [("IL0014", "missing END_CONFIGURATION")]
    );
}
