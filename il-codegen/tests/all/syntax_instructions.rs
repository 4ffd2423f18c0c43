//! Instructions: every operator of Table 52 and its modifiers, deferred
//! parentheses, labels, calls (Table 53) and FB input operators (Table 54).

use crate::syntax_common::*;

#[test]
fn load_store_set_reset() {
    assert!(
        matches!(one("LD x"), InstrKind::Load { negate: false, operand } if name_of(&operand) == "x")
    );
    assert!(matches!(one("LDN x"), InstrKind::Load { negate: true, .. }));
    assert!(matches!(
        one("ST x"),
        InstrKind::Store { negate: false, .. }
    ));
    assert!(matches!(
        one("STN x"),
        InstrKind::Store { negate: true, .. }
    ));
    assert!(matches!(one("S x"), InstrKind::Set { .. }));
    assert!(matches!(one("R x"), InstrKind::Reset { .. }));
    assert!(matches!(one("NOT"), InstrKind::Not));
}

#[test]
fn expression_operators_and_modifiers() {
    use ExprOp::*;
    let cases = [
        ("AND", And, false),
        ("ANDN", And, true),
        ("&", And, false),
        ("&N", And, true),
        ("OR", Or, false),
        ("ORN", Or, true),
        ("XOR", Xor, false),
        ("XORN", Xor, true),
        ("ADD", Add, false),
        ("SUB", Sub, false),
        ("MUL", Mul, false),
        ("DIV", Div, false),
        ("MOD", Mod, false),
        ("GT", Gt, false),
        ("GE", Ge, false),
        ("EQ", Eq, false),
        ("NE", Ne, false),
        ("LE", Le, false),
        ("LT", Lt, false),
    ];
    for (text, op, neg) in cases {
        match one(&format!("{text} y")) {
            InstrKind::Expr {
                op: o,
                negate,
                operand,
            } => {
                assert_eq!((o, negate), (op, neg), "{text}");
                assert_eq!(name_of(&operand), "y");
            }
            other => panic!("{text}: {other:?}"),
        }
    }
    // `&N` glued to its operand is still `&N` then the operand... only with a space;
    // `&x` is `&` with operand x.
    assert!(
        matches!(one("&x"), InstrKind::Expr { op: And, negate: false, operand } if name_of(&operand) == "x")
    );
}

#[test]
fn jumps_calls_returns_with_conditions() {
    use Cond::*;
    for (text, cond) in [
        ("JMP", Always),
        ("JMPC", IfTrue),
        ("JMPCN", IfFalse),
        ("JMPNC", IfFalse),
    ] {
        let k = instrs(&format!("{text} l\nl: LD x"));
        assert!(
            matches!(&k[0], InstrKind::Jump { cond: c, label } if *c == cond && label.is("l")),
            "{text}"
        );
    }
    for (text, cond) in [
        ("CAL", Always),
        ("CALC", IfTrue),
        ("CALCN", IfFalse),
        ("CALNC", IfFalse),
    ] {
        assert!(
            matches!(one(&format!("{text} fb")), InstrKind::Call { cond: c, args: None, .. } if c == cond),
            "{text}"
        );
    }
    for (text, cond) in [
        ("RET", Always),
        ("RETC", IfTrue),
        ("RETCN", IfFalse),
        ("RETNC", IfFalse),
    ] {
        assert!(
            matches!(one(text), InstrKind::Return { cond: c } if c == cond),
            "{text}"
        );
    }
}

#[test]
fn fb_input_operators_table_54() {
    use FbInputOp::*;
    for (text, op) in [
        ("S1", S1),
        ("R1", R1),
        ("CLK", Clk),
        ("CU", Cu),
        ("CD", Cd),
        ("PV", Pv),
        ("IN", In),
        ("PT", Pt),
    ] {
        match one(&format!("{text} inst")) {
            InstrKind::FbInput { op: o, instance } => {
                assert_eq!(o, op);
                assert_eq!(name_of(&instance), "inst");
            }
            other => panic!("{text}: {other:?}"),
        }
    }
    // S, R and LD with an instance are the input operators of SR/RS/CTD: the checker decides.
    assert!(matches!(one("S rs1"), InstrKind::Set { .. }));
    assert!(matches!(one("R ctu1"), InstrKind::Reset { .. }));
    assert!(matches!(one("LD ctd1"), InstrKind::Load { .. }));
}

#[test]
fn operator_names_are_variables_in_the_operand_field() {
    let k = instrs("LD R1\nST IN\nAND S\nLD PV.Q\nR1 R1");
    assert_eq!(
        name_of(match &k[0] {
            InstrKind::Load { operand, .. } => operand,
            _ => panic!(),
        }),
        "R1"
    );
    assert_eq!(
        name_of(match &k[1] {
            InstrKind::Store { target, .. } => target,
            _ => panic!(),
        }),
        "IN"
    );
    assert_eq!(
        name_of(match &k[2] {
            InstrKind::Expr { operand, .. } => operand,
            _ => panic!(),
        }),
        "S"
    );
    assert!(
        matches!(&k[3], InstrKind::Load { operand: Operand::Var(v), .. } if v.base.is("PV") && v.path.len() == 1)
    );
    assert!(matches!(
        &k[4],
        InstrKind::FbInput {
            op: FbInputOp::R1,
            ..
        }
    ));
}

#[test]
fn case_insensitive() {
    let p = pou("program P\nvar X : int; end_var\nld x\nSt X\nJmpC l\nl: rEt\nend_program");
    assert_eq!(p.body.len(), 5);
    assert!(matches!(
        &p.body[0],
        Stmt::Instr(Instr {
            kind: InstrKind::Load { .. },
            ..
        })
    ));
    assert_eq!(p.var_blocks[0].kind, VarKind::Var);
}

#[test]
fn spans_point_at_the_source() {
    let src = "PROGRAM p\n  LDN  abc.q\nEND_PROGRAM";
    let u = ok(src);
    let Item::Pou(p) = &u.items[0] else { panic!() };
    let Stmt::Instr(i) = &p.body[0] else { panic!() };
    assert_eq!(&src[i.op_span.range()], "LDN");
    assert_eq!(&src[i.span.range()], "LDN  abc.q");
    assert_eq!(&src[p.name.span.range()], "p");
    assert_eq!(&src[p.end_span.range()], "END_PROGRAM");
    assert_eq!(&src[p.span.range()], src);
}

#[test]
fn operands_with_paths_indexes_and_bits() {
    match one("LD a.b[i, 2].c.3") {
        InstrKind::Load {
            operand: Operand::Var(v),
            ..
        } => {
            assert!(v.base.is("a"));
            assert_eq!(v.path.len(), 4);
            assert!(matches!(&v.path[1], Accessor::Index(ix, _) if ix.len() == 2));
            assert!(matches!(
                v.path[3],
                Accessor::Part {
                    size: AddrSize::Default,
                    index: 3,
                    ..
                }
            ));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn deferred_short_and_long_forms() {
    match one("AND( x\nOR y\n)") {
        InstrKind::Deferred {
            op: ExprOp::And,
            negate: false,
            first: Some(f),
            body,
            ..
        } => {
            assert_eq!(name_of(&f), "x");
            assert_eq!(body.len(), 1);
        }
        other => panic!("{other:?}"),
    }
    match one("ORN(\nLD x\nAND y\n)") {
        InstrKind::Deferred {
            op: ExprOp::Or,
            negate: true,
            first: None,
            body,
            ..
        } => assert_eq!(body.len(), 2),
        other => panic!("{other:?}"),
    }
    // Glued operand, as in plcemu: `ADD(%MD3`.
    assert!(matches!(
        one("ADD(%MD3\nDIV %MD0\n)"),
        InstrKind::Deferred {
            first: Some(f),
            ..
        } if matches!(*f, Operand::Addr(_))
    ));
    assert!(matches!(
        one("&N( a\n)"),
        InstrKind::Deferred {
            op: ExprOp::And,
            negate: true,
            ..
        }
    ));
}

#[test]
fn deferred_nested_four_deep() {
    let k = one("ADD( a\nMUL(\nLD b\nSUB( c\nDIV( d\nMOD e\n)\n)\n)\n)");
    let mut depth = 0;
    let mut cur = &k;
    while let InstrKind::Deferred { body, .. } = cur {
        depth += 1;
        match body.iter().rev().find_map(|s| match s {
            Stmt::Instr(i) if matches!(i.kind, InstrKind::Deferred { .. }) => Some(&i.kind),
            _ => None,
        }) {
            Some(next) => cur = next,
            None => break,
        }
    }
    assert_eq!(depth, 4);
}

#[test]
fn deferred_close_span_and_instr_span() {
    let src = "PROGRAM p\nAND( x\n)\nEND_PROGRAM";
    let u = ok(src);
    let Item::Pou(p) = &u.items[0] else { panic!() };
    let Stmt::Instr(i) = &p.body[0] else { panic!() };
    let InstrKind::Deferred { close_span, .. } = &i.kind else {
        panic!()
    };
    assert_eq!(&src[close_span.range()], ")");
    assert_eq!(&src[i.span.range()], "AND( x\n)");
}

#[test]
fn labels_alone_and_before_instructions() {
    let b = body("start:\nLD x\nnext: ST y\n  (* comment *)\nlast:");
    assert!(matches!(&b[0], Stmt::Label(l) if l.is("start")));
    assert!(matches!(&b[2], Stmt::Label(l) if l.is("next")));
    assert!(matches!(
        &b[3],
        Stmt::Instr(Instr {
            kind: InstrKind::Store { .. },
            ..
        })
    ));
    assert!(matches!(&b[4], Stmt::Label(l) if l.is("last")));
    assert_eq!(b.len(), 5);
}

#[test]
fn function_calls_non_formal_and_formal() {
    match one("LIMIT 0, 100") {
        InstrKind::FnCall {
            name,
            args: CallArgs::NonFormal(a),
        } => {
            assert!(name.is("LIMIT"));
            assert_eq!(a.len(), 2);
        }
        other => panic!("{other:?}"),
    }
    assert!(
        matches!(one("BCD_TO_INT"), InstrKind::FnCall { args: CallArgs::NonFormal(a), .. } if a.is_empty())
    );
    assert!(
        matches!(one("SIN x"), InstrKind::FnCall { args: CallArgs::NonFormal(a), .. } if a.len() == 1)
    );
    match one("LIMIT(MN := 0, IN := x, MX := 100)") {
        InstrKind::FnCall {
            args: CallArgs::Formal(a),
            ..
        } => {
            assert_eq!(a.len(), 3);
            assert!(a[1].name.is("IN"));
        }
        other => panic!("{other:?}"),
    }
    match one("LIMIT(\n  MN := 0,\n  IN := x,\n  MX := 100\n)") {
        InstrKind::FnCall {
            args: CallArgs::Formal(a),
            ..
        } => assert_eq!(a.len(), 3),
        other => panic!("{other:?}"),
    }
}

#[test]
fn cal_three_forms_of_table_53() {
    // 1. formal list, one line, with an output.
    match one("CAL C10(CU := %IX10, PV := 15, Q => done, NOT QD => nd)") {
        InstrKind::Call {
            cond: Cond::Always,
            target,
            args: Some(args),
        } => {
            let CallArgs::Formal(a) = *args else {
                panic!("a formal list: {args:?}")
            };
            assert_eq!(name_of(&target), "C10");
            assert_eq!(a.len(), 4);
            assert!(matches!(&a[0].kind, ParamKind::Input(Operand::Addr(_))));
            assert!(
                matches!(&a[2].kind, ParamKind::Output { negate: false, target } if name_of(target) == "done")
            );
            assert!(matches!(&a[3].kind, ParamKind::Output { negate: true, .. }));
        }
        other => panic!("{other:?}"),
    }
    // 1b. formal list over several lines, `=>` included.
    match one("CAL C10(\n    CU := x,\n    R := c.q,\n    Q => done\n   )") {
        InstrKind::Call { args: Some(a), .. } => {
            assert!(matches!(&*a, CallArgs::Formal(a) if a.len() == 3), "{a:?}")
        }
        other => panic!("{other:?}"),
    }
    // 2. loads and stores of the inputs, then CAL.
    let k = instrs("LD 15\nST C10.PV\nCAL C10");
    assert!(matches!(&k[2], InstrKind::Call { args: None, .. }));
    // 3. input operators.
    assert!(matches!(one("PV C10"), InstrKind::FbInput { .. }));
    // non-formal list, empty list, array element as target.
    assert!(
        matches!(one("CAL f(10, e_1, 'x')"), InstrKind::Call { args: Some(a), .. } if matches!(&*a, CallArgs::NonFormal(a) if a.len() == 3))
    );
    assert!(
        matches!(one("CAL f()"), InstrKind::Call { args: Some(a), .. } if matches!(&*a, CallArgs::Formal(a) if a.is_empty()))
    );
    assert!(
        matches!(one("CALC timers[2]"), InstrKind::Call { target: Operand::Var(v), .. } if v.path.len() == 1)
    );
    assert!(matches!(
        one("CALCN f (IN := TRUE)"),
        InstrKind::Call {
            cond: Cond::IfFalse,
            args: Some(_),
            ..
        }
    ));
}

#[test]
fn begin_il_end_il() {
    let p = pou(
        "FUNCTION_BLOCK fb\nVAR x : BOOL; END_VAR\nBEGIN_IL\n  LD x\n  ST x\nEND_IL\nEND_FUNCTION_BLOCK",
    );
    assert!(p.begin_il);
    assert_eq!(p.body.len(), 2);
    let e = err1("PROGRAM p\nBEGIN_IL\nLD x\nEND_PROGRAM", "IL0028", 2, 1);
    assert_eq!(e, "missing END_IL");
}

#[test]
fn kas_ide_spellings() {
    assert!(matches!(
        one("JMPNC l"),
        InstrKind::Jump {
            cond: Cond::IfFalse,
            ..
        }
    ));
    assert!(matches!(
        one("CALNC fb"),
        InstrKind::Call {
            cond: Cond::IfFalse,
            ..
        }
    ));
    assert!(matches!(
        one("RETNC"),
        InstrKind::Return {
            cond: Cond::IfFalse
        }
    ));
}

#[test]
fn comments_everywhere() {
    let b = body("(* a *) LD x (* b *)\n(* multi\nline *)\nST y (* c *)");
    assert_eq!(b.len(), 2);
}
