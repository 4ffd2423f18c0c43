//! Refused input: every kind of syntax error, its code, place and message;
//! recovery at the next line; robustness against pathological input.

use crate::syntax_common::*;

fn prog(lines: &str) -> String {
    format!("PROGRAM p\nVAR x, y : BOOL; END_VAR\n{lines}\nEND_PROGRAM\n")
}

/// One diagnostic on line 3 (the first body line of `prog`).
fn line3(lines: &str, code: &str, col: usize) -> String {
    err1(&prog(lines), code, 3, col)
}

#[test]
fn missing_operand() {
    assert_eq!(line3("LD", "IL0003", 1), "expected an operand after `LD`");
    assert_eq!(
        line3("andn", "IL0003", 1),
        "expected an operand after `andn`"
    );
    assert_eq!(line3("ST", "IL0003", 1), "expected an operand after `ST`");
    assert_eq!(line3("PV", "IL0003", 1), "expected an operand after `PV`");
    assert_eq!(line3("&N", "IL0003", 1), "expected an operand after `&N`");
}

#[test]
fn operand_not_allowed() {
    assert_eq!(
        line3("NOT x", "IL0004", 5),
        "`NOT` takes no operand: it complements the current result"
    );
    let f = SourceFile::new("t", prog("NOT x"));
    assert_eq!(
        parse(&f).1[0].help.as_deref(),
        Some("to load the complement of `x` write `LDN x`")
    );
    assert_eq!(line3("RETC x", "IL0004", 6), "`RETC` takes no operand");
}

#[test]
fn jump_and_call_targets() {
    assert_eq!(line3("JMPC", "IL0006", 1), "expected a label after `JMPC`");
    assert_eq!(line3("JMP 5", "IL0006", 1), "expected a label after `JMP`");
    assert_eq!(
        line3("CAL", "IL0007", 1),
        "expected a function block instance after `CAL`"
    );
    assert_eq!(
        line3("CAL (IN := x)", "IL0007", 1),
        "expected a function block instance after `CAL`"
    );
}

#[test]
fn one_instruction_per_line() {
    assert_eq!(
        line3("LD x ST y", "IL0030", 6),
        "unexpected `ST` after the instruction"
    );
    assert_eq!(
        line3("LD x, 1", "IL0030", 5),
        "`LD` takes one operand, not a list"
    );
    assert_eq!(
        line3("LD x y", "IL0030", 6),
        "unexpected `y` after the instruction"
    );
}

#[test]
fn not_an_instruction() {
    assert_eq!(
        line3("5", "IL0031", 1),
        "expected an instruction, found `5`"
    );
    assert_eq!(
        line3("%IX0.0", "IL0031", 1),
        "expected an instruction, found `%IX0.0`"
    );
}

#[test]
fn argument_list_not_closed() {
    let e = errs(&prog("CAL fb(IN := x\nLD y\nST x"));
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].0, e[0].1), ("IL0015", 3));
    assert_eq!(e[0].3, "missing `)` to close the argument list");
}

#[test]
fn parentheses() {
    // A `)` without `(`.
    assert_eq!(line3(")", "IL0015", 1), "this `)` has no matching `(`");
    // A `(` never closed: reported at the `(`, and the POU still ends.
    let e = errs(&prog("LD x\nAND( y\nOR x"));
    assert_eq!(
        e.iter()
            .map(|e| (e.0, e.1, e.2, e.3.as_str()))
            .collect::<Vec<_>>(),
        [("IL0015", 4, 4, "this `(` is never closed")]
    );
}

#[test]
fn no_jumps_labels_calls_or_returns_inside_parentheses() {
    let e = errs(&prog(
        "LD x\nAND(\nLD y\nJMPC l\ninner: OR x\nCAL fb\nRET\n)\nl: ST x",
    ));
    let got: Vec<_> = e.iter().map(|e| (e.0, e.1, e.3.as_str())).collect();
    assert_eq!(
        got,
        [
            ("IL0016", 6, "a jump is not allowed inside parentheses"),
            (
                "IL0016",
                7,
                "a label is not allowed inside parentheses (`inner:`)"
            ),
            ("IL0016", 8, "CAL is not allowed inside parentheses"),
            ("IL0016", 9, "RET is not allowed inside parentheses"),
        ]
    );
}

#[test]
fn nesting_limit() {
    let depth = 300;
    let mut s = String::from("LD x\n");
    for _ in 0..depth {
        s.push_str("AND( x\n");
    }
    for _ in 0..depth {
        s.push_str(")\n");
    }
    let e = errs(&prog(&s));
    assert!(!e.is_empty());
    assert_eq!(e[0].0, "IL0017");
    assert_eq!(e[0].3, "parentheses are nested more than 256 deep");
    assert_eq!(e[0].1, 3 + 1 + 256);
    // The POU after the excess is still parsed, and the excess is one diagnostic.
    let mut s = String::from("LD x\n");
    s.push_str(&"AND( x\n".repeat(300));
    let src = format!(
        "{}END_PROGRAM\nPROGRAM q\nLD x\nEND_PROGRAM",
        prog(&s).trim_end().trim_end_matches("END_PROGRAM")
    );
    let f = SourceFile::new("t", src);
    let (u, d) = parse(&f);
    assert_eq!(
        d.iter().map(|d| d.code).collect::<Vec<_>>(),
        ["IL0015", "IL0017"],
        "{}",
        show(&f, &d)
    );
    assert_eq!(u.items.len(), 2);
    // 256 deep is fine.
    let mut s = String::from("LD x\n");
    s.push_str(&"OR( y\n".repeat(256));
    s.push_str(&")\n".repeat(256));
    ok(&prog(&s));
}

#[test]
fn non_iec_constructs_are_named() {
    assert_eq!(
        line3("LD x ; load", "IL0008", 6),
        "`;` comments are not IEC 61131-3; write (* ... *)"
    );
    assert_eq!(
        line3("x := y;", "IL0009", 1),
        "this is a Structured Text statement (`x := y;`); only Instruction List is supported"
    );
    assert_eq!(
        line3("IF x THEN y := 1; END_IF;", "IL0009", 1),
        "this is a Structured Text statement (`IF x THEN y := 1; END_IF;`); only Instruction List is supported"
    );
    assert_eq!(
        line3("fb.a[1] := 3;", "IL0009", 1).split(';').next(),
        Some("this is a Structured Text statement (`fb.a[1] := 3")
    );
    assert_eq!(
        line3("INITIAL_STEP s1:\nEND_STEP", "IL0010", 1),
        "SFC (STEP/TRANSITION/ACTION) is not supported"
    );
    // Pragmas are ignored (tests/all/dialect.rs has them everywhere).
    assert!(errs(&prog("LD x {pragma}")).is_empty());
    // Vendor built-ins are function calls: the checker reports unknown functions.
    assert!(matches!(one("dbg 1"), InstrKind::FnCall { .. }));
    assert!(matches!(one("_exit"), InstrKind::FnCall { .. }));
}

#[test]
fn st_skips_the_rest_of_the_pou_only() {
    let src = "FUNCTION_BLOCK a\nc := 1;\nIF c THEN\nEND_IF;\nEND_FUNCTION_BLOCK\nPROGRAM b\nLD 1\nEND_PROGRAM";
    let f = SourceFile::new("t", src);
    let (u, d) = parse(&f);
    assert_eq!(d.iter().map(|d| d.code).collect::<Vec<_>>(), ["IL0009"]);
    assert_eq!(u.items.len(), 2);
}

#[test]
fn instructions_outside_a_pou() {
    let e = errs("LD %IX0.0\nST %QX0.0\n");
    assert_eq!(
        e.iter()
            .map(|e| (e.0, e.1, e.2, e.3.as_str()))
            .collect::<Vec<_>>(),
        [(
            "IL0011",
            1,
            1,
            "IL instructions must be inside a PROGRAM, FUNCTION or FUNCTION_BLOCK"
        )]
    );
    // A following POU still parses.
    let f = SourceFile::new("t", "LD x\nPROGRAM p\nLD y\nEND_PROGRAM");
    let (u, d) = parse(&f);
    assert_eq!(d.len(), 1);
    assert_eq!(u.items.len(), 1);
}

#[test]
fn lexical_errors() {
    let e = errs("PROGRAM p\n(* open\nLD x\n");
    assert!(
        e.iter()
            .any(|e| (e.0, e.1, e.2, e.3.as_str())
                == ("IL0002", 2, 1, "this comment is never closed")),
        "{e:?}"
    );
    assert!(
        e.iter().any(|e| e.3 == "missing END_PROGRAM for `p`"),
        "{e:?}"
    );
    assert_eq!(
        line3("LD x @@", "IL0001", 6),
        "`@@` has no meaning in Instruction List"
    );
    assert_eq!(
        line3("LD é", "IL0001", 4),
        "`é` has no meaning in Instruction List"
    );
}

#[test]
fn begin_il_errors() {
    assert_eq!(line3("END_IL", "IL0028", 1), "END_IL without BEGIN_IL");
    assert_eq!(
        err1(&prog("LD x\nBEGIN_IL\nST y\nEND_IL"), "IL0028", 4, 1),
        "BEGIN_IL must come before the first instruction"
    );
}

#[test]
fn all_errors_of_a_file_with_recovery_at_the_next_line() {
    let src = "\
FUNCTION_BLOCK fb
VAR_INPUT a : BOOL; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
LD
ST q
NOT a
AND a
JMPC
LD a
ST q q
ST q
END_FUNCTION_BLOCK
";
    let f = SourceFile::new("t.il", src);
    let (u, d) = parse(&f);
    let got: Vec<_> = d
        .iter()
        .map(|d| {
            let (l, c) = f.line_col(d.span.lo);
            (d.code, l, c)
        })
        .collect();
    assert_eq!(
        got,
        [
            ("IL0003", 4, 1),
            ("IL0004", 6, 5),
            ("IL0006", 8, 1),
            ("IL0030", 10, 6)
        ]
    );
    let Item::Pou(p) = &u.items[0] else { panic!() };
    assert!(p.name.is("fb"));
    assert_eq!(p.var_blocks.len(), 2);
    // The valid lines are all there: ST q, AND a, LD a, ST q.
    let kinds: Vec<_> = p
        .body
        .iter()
        .map(|s| match s {
            Stmt::Instr(i) => format!("{:?}", std::mem::discriminant(&i.kind)),
            Stmt::Label(_) => "label".into(),
        })
        .collect();
    assert_eq!(kinds.len(), 4, "{:?}", p.body);
}

#[test]
fn errors_in_several_pous_are_all_reported() {
    let e = errs(
        "PROGRAM a\nLD\nEND_PROGRAM\nFUNCTION f : INT\nJMP\nEND_FUNCTION\nFUNCTION_BLOCK b\nVAR x : ; END_VAR\nEND_FUNCTION_BLOCK",
    );
    assert_eq!(
        e.iter().map(|e| (e.0, e.1)).collect::<Vec<_>>(),
        [("IL0003", 2), ("IL0006", 5), ("IL0023", 8)]
    );
}

// ------------------------------------------------------------ robustness

/// A small deterministic generator (no dependencies).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

#[test]
fn no_panic_on_mutated_input() {
    let seeds = [
        "PROGRAM p\nVAR x : INT := 1; a : ARRAY [0..2] OF INT := [1, 2(3)]; END_VAR\nLD x\nAND( y\nOR z\n)\nCAL f(IN := x, Q => y)\nl: JMPC l\nEND_PROGRAM",
        "TYPE c : (r, g := 2); s : STRUCT a : INT; END_STRUCT; END_TYPE\nCONFIGURATION k RESOURCE r ON c TASK t (INTERVAL := T#1s); PROGRAM i WITH t : p (a := 1); END_RESOURCE END_CONFIGURATION",
        "FUNCTION f : INT\nLD 'a$$' \nST \"w\"\nLD T#1h_2m\nLD D#2001-01-01\nLD %IX1.2\nLIMIT 1, 2\nEND_FUNCTION",
    ];
    let alphabet: &[&str] = &[
        "(",
        ")",
        "(*",
        "*)",
        "\n",
        ";",
        ":",
        ":=",
        "=>",
        ",",
        "'",
        "\"",
        "%",
        "#",
        "-",
        ".",
        "..",
        "[",
        "]",
        "LD",
        "AND(",
        "END_VAR",
        "VAR",
        "END_PROGRAM",
        "PROGRAM",
        "TYPE",
        "CONFIGURATION",
        "x",
        "1",
        "T#",
        "{",
        "é",
        "STRUCT",
        "END_STRUCT",
    ];
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for seed in seeds {
        for _ in 0..400 {
            let mut s = seed.to_string();
            for _ in 0..(rng.next() % 6 + 1) {
                let mut at = (rng.next() as usize) % (s.len() + 1);
                while !s.is_char_boundary(at) {
                    at -= 1;
                }
                if rng.next().is_multiple_of(3) && at < s.len() {
                    let mut end = at + 1;
                    while !s.is_char_boundary(end) {
                        end += 1;
                    }
                    s.replace_range(at..end, "");
                } else {
                    s.insert_str(at, alphabet[(rng.next() as usize) % alphabet.len()]);
                }
            }
            let f = SourceFile::new("fuzz", s.clone());
            let (_, d) = parse(&f);
            for d in d {
                assert!(
                    d.span.lo <= d.span.hi && d.span.hi as usize <= s.len(),
                    "{s:?}: {d:?}"
                );
            }
        }
    }
}

#[test]
fn large_inputs_take_linear_time() {
    let line = "LD x\nAND( y\nOR z\n)\nST x\nl1: JMPC l1\n";
    let small = prog(&line.repeat(2_000));
    let big = prog(&line.repeat(40_000));
    let time = |s: &str| {
        let f = SourceFile::new("big", s);
        let t = std::time::Instant::now();
        let (_, d) = parse(&f);
        assert!(d.is_empty());
        t.elapsed()
    };
    let ts = time(&small);
    let tb = time(&big);
    // 20x the input: allow generous noise, but not quadratic growth (400x).
    assert!(
        tb < ts * 80 + std::time::Duration::from_millis(200),
        "small {ts:?}, big {tb:?}"
    );
    // Many errors, too.
    let bad = prog(&"LD\nNOT x\n)\n".repeat(20_000));
    let f = SourceFile::new("bad", bad);
    let t = std::time::Instant::now();
    let (_, d) = parse(&f);
    // Capped: the first 200 by position and one IL0032 counting the rest.
    assert_eq!(d.len(), 201);
    assert_eq!(d[200].code, "IL0032");
    assert!(
        d[200].message.starts_with("59800 more diagnostics"),
        "{}",
        d[200].message
    );
    assert!(d[200].is_error());
    assert!(t.elapsed() < std::time::Duration::from_secs(20));
}

#[test]
fn lexer_errors_past_the_limit_are_counted_not_kept() {
    // 20,000 stray characters on one line: the lexer keeps the first 200
    // of its diagnostics and counts the rest, so the file shows the same
    // list and the same count as when every one was held (16,000 of them
    // on one line were 5.5 MB, twice).
    let f = SourceFile::new("t.il", prog(&format!("LD x {}\n", "# ".repeat(20_000))));
    let (_, d) = parse(&f);
    assert_eq!(d.len(), 201);
    assert!(d[..200].iter().all(|d| d.code != "IL0032"));
    assert_eq!(d[200].code, "IL0032");
    assert!(
        d[200].message.starts_with("19800 more diagnostics") && d[200].is_error(),
        "{}",
        d[200].message
    );
}

#[test]
fn pathological_nesting_does_not_overflow() {
    // Deep deferred parentheses, argument lists and declarations.
    let cases = [
        prog(&"AND(\n".repeat(100_000)),
        prog(&format!("CAL f{}", "(".repeat(100_000))),
        format!(
            "PROGRAM p\nVAR x : T := {}1; END_VAR\nEND_PROGRAM",
            "(a := ".repeat(100_000)
        ),
        format!(
            "TYPE t : {} INT; END_TYPE",
            "ARRAY [1..2] OF ".repeat(100_000)
        ),
        format!("TYPE t : {} END_TYPE", "STRUCT a : ".repeat(100_000)),
        prog(&format!("LD a{}\nST x", "[b".repeat(100_000))),
    ];
    for (i, src) in cases.into_iter().enumerate() {
        let t = std::time::Instant::now();
        let (_, d) = parse(&SourceFile::new("d", src));
        assert!(!d.is_empty());
        println!("case {i}: {:?}", t.elapsed());
    }
}

#[test]
fn operand_expected_in_lists() {
    let e = errs(&prog("CAL fb(IN := )"));
    assert_eq!(
        e.iter()
            .map(|e| (e.0, e.1, e.2, e.3.as_str()))
            .collect::<Vec<_>>(),
        [("IL0003", 3, 14, "expected an operand after `:=`")]
    );
    assert_eq!(
        line3("LIMIT 1, ", "IL0003", 10),
        "expected an operand after `,`"
    );
}

#[test]
fn partial_address_only_in_declarations() {
    assert_eq!(
        line3("LD %I*", "IL0022", 4),
        "a partly specified address (`%I*`) may only appear in a declaration"
    );
}

#[test]
fn every_emitted_code_is_documented() {
    let srcs = [
        prog("LD\nNOT x\nJMP\nCAL\nLD x y\n5\n)\nAND( x\nJMP l\n)\nLD 1x\nLD T#1x\nLD D#2000-1-40\nLD 'x\nLD %Z\nLD x ; c\nLD @\n{p}"),
        "LD x\n".to_string(),
        "FUNCTION f\nLD x\nVAR y : ; END_VAR\nBEGIN_IL\nEND_FUNCTION_BLOCK\nCONFIGURATION c TASK t (X := 1); END_CONFIGURATION\n(*".to_string(),
    ];
    for src in srcs {
        let (_, d) = parse(&SourceFile::new("t", src));
        for d in d {
            let info = il_codegen::codes::lookup(d.code)
                .unwrap_or_else(|| panic!("{} is not in CODES", d.code));
            assert!(!info.explanation.is_empty());
        }
    }
}

#[test]
fn names_over_255_characters_are_refused_wherever_they_stand() {
    let at_limit = "n".repeat(255);
    let over = "n".repeat(256);
    let src = format!(
        "PROGRAM p\nVAR {at_limit} : BOOL; {over} : BOOL; END_VAR\n    LD {at_limit}\n    ST {over}\nEND_PROGRAM\n"
    );
    let f = il_codegen::diag::SourceFile::new("t.il", src.as_str());
    let d = il_codegen::Program::new()
        .il(f.clone())
        .check()
        .into_diagnostics();
    let long: Vec<(usize, usize)> = d[0]
        .iter()
        .filter(|d| d.code == "IL0034")
        .map(|d| f.line_col(d.span.lo))
        .collect();
    assert_eq!(long, [(2, 4 + 255 + 9 + 1), (4, 8)], "{:?}", d[0]);
    assert!(
        d[0].iter()
            .any(|d| d.message == "a name of 256 characters: names are at most 255"),
        "{:?}",
        d[0]
    );
}
