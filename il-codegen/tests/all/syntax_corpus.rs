//! Every IL file of the shared corpus is accepted, or refused with located
//! diagnostics that name the non-standard construct.

use il_codegen::ast::parse;
use il_codegen::ast::*;
use il_codegen::diag::{Diagnostic, SourceFile};

const CORPUS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus");

fn load(name: &str) -> Option<(SourceFile, CompilationUnit, Vec<Diagnostic>)> {
    let dir = std::path::Path::new(CORPUS);
    if !dir.is_dir() {
        println!("SKIPPED: ../shared/corpus not found");
        return None;
    }
    let text = std::fs::read_to_string(dir.join(name)).expect(name);
    let f = SourceFile::new(name, text);
    let (u, d) = parse(&f);
    Some((f, u, d))
}

fn show(f: &SourceFile, d: &[Diagnostic]) -> String {
    d.iter()
        .map(|d| {
            let (l, c) = f.line_col(d.span.lo);
            format!("{}:{l}:{c}: {} {}\n", f.name, d.code, d.message)
        })
        .collect()
}

fn pou<'a>(u: &'a CompilationUnit, name: &str) -> &'a Pou {
    u.items
        .iter()
        .find_map(|i| match i {
            Item::Pou(p) if p.name.is(name) => Some(p),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no POU {name}"))
}

fn count_instrs(body: &[Stmt]) -> usize {
    body.iter()
        .map(|s| match s {
            Stmt::Instr(Instr {
                kind: InstrKind::Deferred { body, .. },
                ..
            }) => 1 + count_instrs(body),
            Stmt::Instr(_) => 1,
            Stmt::Label(_) => 0,
        })
        .sum()
}

fn clean(name: &str) -> Option<CompilationUnit> {
    let (f, u, d) = load(name)?;
    assert!(
        d.is_empty(),
        "{name} should parse without diagnostics:\n{}",
        show(&f, &d)
    );
    Some(u)
}

#[test]
fn annex_f_cmd_monitor() {
    let Some(u) = clean("beremiz_matiec_cmd_monitor_il.txt") else {
        return;
    };
    let p = pou(&u, "CMD_MONITOR");
    assert_eq!(p.kind, PouKind::FunctionBlock);
    assert_eq!(p.var_blocks.len(), 3);
    assert_eq!(p.var_blocks[0].decls.len(), 7);
    assert_eq!(count_instrs(&p.body), 16);
    let deferred = p.body.iter().find_map(|s| match s {
        Stmt::Instr(Instr {
            kind: InstrKind::Deferred {
                op, first, body, ..
            },
            ..
        }) => Some((*op, first.as_deref().cloned(), body.len())),
        _ => None,
    });
    let (op, first, n) = deferred.expect("OR( ... )");
    assert_eq!(op, ExprOp::Or);
    assert!(matches!(first, Some(Operand::Var(v)) if v.base.is("MAN_CMD")));
    assert_eq!(n, 2);
    assert!(p.body.iter().any(|s| matches!(
        s,
        Stmt::Instr(Instr {
            kind: InstrKind::FbInput {
                op: FbInputOp::In,
                ..
            },
            ..
        })
    )));
    assert!(p.body.iter().any(|s| matches!(
        s,
        Stmt::Instr(Instr {
            kind: InstrKind::Reset { .. },
            ..
        })
    )));
}

#[test]
fn annex_f_fwd_rev_mon() {
    let Some(u) = clean("beremiz_matiec_fwd_rev_mon_il.txt") else {
        return;
    };
    let p = pou(&u, "FWD_REV_MON");
    assert_eq!(
        p.var_blocks.iter().map(|b| b.decls.len()).sum::<usize>(),
        21
    );
    assert!(p.body.iter().any(|s| matches!(
        s,
        Stmt::Instr(Instr {
            kind: InstrKind::FbInput {
                op: FbInputOp::S1,
                ..
            },
            ..
        })
    )));
    assert_eq!(
        p.body
            .iter()
            .filter(|s| matches!(
                s,
                Stmt::Instr(Instr {
                    kind: InstrKind::Call { args: None, .. },
                    ..
                })
            ))
            .count(),
        2
    );
}

#[test]
fn annex_f_stack_int() {
    let Some(u) = clean("beremiz_matiec_stack_int_il.txt") else {
        return;
    };
    let p = pou(&u, "STACK_INT");
    let inputs = &p.var_blocks[0];
    assert_eq!(inputs.kind, VarKind::Input);
    assert_eq!(inputs.decls[0].names.len(), 2);
    assert_eq!(inputs.decls[0].edge, Some(Edge::Rising));
    // `R1 : BOOL` and `IN : INT` are variables, and `LD R1` loads one.
    assert!(inputs.decls.iter().any(|d| d.names[0].is("R1")));
    let labels: Vec<_> = p
        .body
        .iter()
        .filter_map(|s| {
            if let Stmt::Label(l) = s {
                Some(&*l.name)
            } else {
                None
            }
        })
        .collect();
    assert_eq!(
        labels,
        ["RESET", "POP_STK", "PUSH_STK", "ZRO_OUT", "SET_OUT"]
    );
    let neg = p.body.iter().any(|s| {
        matches!(
            s,
            Stmt::Instr(Instr {
                kind: InstrKind::Load {
                    operand: Operand::Lit(Literal {
                        kind: LitKind::Int(n),
                        ..
                    }),
                    ..
                },
                ..
            }) if n.get() == -1
        )
    });
    assert!(neg, "LD -1");
    let call = p.body.iter().find_map(|s| match s {
        Stmt::Instr(Instr {
            kind:
                InstrKind::Call {
                    target,
                    args: Some(a),
                    ..
                },
            ..
        }) => match &**a {
            CallArgs::Formal(a) => Some((target.clone(), a.len())),
            CallArgs::NonFormal(_) => None,
        },
        _ => None,
    });
    let (target, n) = call.expect("CAL LIMIT(...)");
    assert!(matches!(target, Operand::Var(v) if v.base.is("LIMIT")));
    assert_eq!(n, 3);
    let array = &p.var_blocks[2].decls[0].ty;
    assert!(matches!(array, TypeSpec::Array { dims, .. } if dims.len() == 1));
}

#[test]
fn annex_f_weigh() {
    let Some(u) = clean("beremiz_matiec_weigh_il.txt") else {
        return;
    };
    let p = pou(&u, "WEIGH");
    assert_eq!(p.kind, PouKind::Function);
    assert!(matches!(&p.return_type, Some(TypeSpec::Named(t)) if t.is("WORD")));
    let calls: Vec<_> = p
        .body
        .iter()
        .filter_map(|s| match s {
            Stmt::Instr(Instr {
                kind:
                    InstrKind::FnCall {
                        name,
                        args: CallArgs::NonFormal(a),
                    },
                ..
            }) if a.is_empty() => Some(name.name.to_string()),
            _ => None,
        })
        .collect();
    assert_eq!(calls, ["BCD_TO_INT", "INT_TO_BCD"]);
}

#[test]
fn echidna_and_zplc_files() {
    for name in [
        "61131_echidna_blink.il",
        "61131_echidna_ctu.il",
        "61131_echidna_rpiface-updown.il",
        "61131_echidna_sine.il",
        "eduardojvieira_ZPLC_blinky_2a44dc4.il",
        "eduardojvieira_ZPLC_jumps.il",
        "eduardojvieira_ZPLC_logic.il",
        "Autonomy-Logic_STruCpp_state-display.il",
    ] {
        let Some(_) = clean(name) else { return };
    }
    let Some(u) = clean("61131_echidna_blink.il") else {
        return;
    };
    let Some(Item::Configuration(c)) = u.items.get(1) else {
        panic!("configuration")
    };
    assert_eq!(c.resources.len(), 1);
    assert!(c.resources[0].tasks[0].interval.is_some());
    assert!(
        c.resources[0].programs[0]
            .task
            .as_ref()
            .is_some_and(|t| t.is("task1"))
    );
    let p = pou(&u, "test");
    // `down: cal fedge(` — a label before a multi-line CAL.
    assert!(
        p.body
            .iter()
            .any(|s| matches!(s, Stmt::Label(l) if l.is("down")))
    );
}

#[test]
fn echidna_factorial_operand_list_is_a_call_of_add() {
    // `add cycle, 1` is the extensible ADD called as an operator: ADD(CR, cycle, 1).
    // (The file is refused later by the checker: recursion, `dbg`, `_exit`.)
    let Some((f, u, d)) = load("61131_echidna_factorial.il") else {
        return;
    };
    assert!(d.is_empty(), "{}", show(&f, &d));
    assert_eq!(u.items.len(), 3);
    let p = pou(&u, "test");
    assert!(p.body.iter().any(|s| matches!(s, Stmt::Instr(Instr {
        kind: InstrKind::FnCall { name, args: CallArgs::NonFormal(a) }, ..
    }) if name.is("ADD") && a.len() == 2)));
}

#[test]
fn hiperiondev_names_its_non_standard_parts() {
    let Some((f, _, d)) = load("hiperiondev_il_parser_test2.il") else {
        return;
    };
    let shown = show(&f, &d);
    assert!(d.iter().any(|d| d.code == "IL0011"), "{shown}");
    assert!(
        d.iter()
            .any(|d| d.code == "IL0008" && d.message.contains("`;` comments")),
        "{shown}"
    );
    assert!(
        d.iter()
            .any(|d| d.code == "IL0018" && d.help.as_deref() == Some("write -12.0e-5")),
        "{shown}"
    );
    assert!(d.iter().any(|d| d.code == "IL0012"), "{shown}");
    // JMPNC is accepted silently; no other kinds of error.
    assert!(
        d.iter()
            .all(|d| ["IL0008", "IL0011", "IL0012", "IL0018"].contains(&d.code)),
        "{shown}"
    );
}

#[test]
fn plcemu_knuth_names_its_non_standard_parts() {
    let Some((f, _, d)) = load("kalamara_plcemu_knuth.il") else {
        return;
    };
    let shown = show(&f, &d);
    assert!(
        d.iter()
            .any(|d| d.code == "IL0022" && d.message.contains("`F` is not an IEC address size")),
        "{shown}"
    );
    assert!(
        d.iter()
            .all(|d| ["IL0008", "IL0011", "IL0022"].contains(&d.code)),
        "{shown}"
    );
}

#[test]
fn matiec_basic_code_st_and_sfc() {
    let Some((f, u, d)) = load("beremiz_matiec_basic_code.test") else {
        return;
    };
    let shown = show(&f, &d);
    assert!(d.iter().any(|d| d.code == "IL0009"), "{shown}");
    assert!(d.iter().any(|d| d.code == "IL0010"), "{shown}");
    // `NOT TRUE` (bar0031) is refused: NOT takes no operand.
    assert!(
        d.iter()
            .any(|d| d.code == "IL0004" && f.line_col(d.span.lo).0 == 255),
        "{shown}"
    );
    assert!(
        d.iter()
            .all(|d| ["IL0004", "IL0008", "IL0009", "IL0010"].contains(&d.code)),
        "{shown}"
    );
    // All 44 IL functions, the ST POUs, the SFC program and the configuration.
    assert_eq!(u.items.len(), 49);
}

#[test]
fn matiec_identifier_template() {
    let Some((f, u, d)) = load("beremiz_matiec_identifier_as_variable2.test") else {
        return;
    };
    let shown = show(&f, &d);
    // ST bodies of the helpers, `NOT XXXX`, and the `{#include}` pragma.
    assert!(
        d.iter()
            .all(|d| ["IL0004", "IL0009", "IL0025"].contains(&d.code)),
        "{shown}"
    );
    let p = pou(&u, "bar95");
    assert_eq!(count_instrs(&p.body), 27);
}

#[test]
fn every_corpus_file_is_accepted_or_located() {
    let dir = std::path::Path::new(CORPUS);
    if !dir.is_dir() {
        println!("SKIPPED: ../shared/corpus not found");
        return;
    }
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_string())
            .unwrap_or_default();
        if !["il", "txt", "test"].contains(&ext.as_str()) || name == "SOURCES.txt" {
            continue;
        }
        let Some((f, _, d)) = load(&name) else { return };
        for d in &d {
            assert!(
                !d.message.is_empty() && d.span.hi as usize <= f.text.len(),
                "{name}: {d:?}"
            );
            assert!(d.code.starts_with("IL00"), "{name}: {d:?}");
        }
        println!("{name}: {} diagnostics", d.len());
    }
}
