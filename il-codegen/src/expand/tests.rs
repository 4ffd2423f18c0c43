use super::{CALL_SITE, Expansion, Tok, expand};

fn s(v: &str) -> Tok {
    Tok::string(v, 1)
}
fn id(x: &str) -> Tok {
    Tok::Ident(x.to_string(), 2)
}
fn p(c: char) -> Tok {
    Tok::Punct(c, 3)
}
fn text(e: &Expansion) -> String {
    let errs: Vec<&str> = e.errors.iter().map(|(m, _)| m.as_str()).collect();
    format!("{}\n{}", e.code, errs.join("\n"))
}

const IL: &str = "FUNCTION_BLOCK F\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_FUNCTION_BLOCK\n";

#[test]
fn serde_flag_derives_and_unknown_flags_are_refused() {
    let plain = expand(&[s(IL)]);
    assert!(
        plain.errors.is_empty() && !plain.code.contains("serde"),
        "{}",
        text(&plain)
    );
    let with = expand(&[s(IL), p(','), id("serde")]);
    assert!(with.code.contains("::serde::Serialize"), "{}", text(&with));
    let with_comma = expand(&[s(IL), p(','), id("serde"), p(',')]);
    assert_eq!(with.code, with_comma.code);
    let bad = expand(&[s(IL), p(','), id("serdes")]);
    assert!(
        bad.code.is_empty() && bad.errors[0].0.contains("serde"),
        "{}",
        text(&bad)
    );
    assert_eq!(bad.errors[0].1, 2, "the error is at the unknown flag");
    let trailing = expand(&[s(IL), p(',')]);
    assert_eq!(trailing.code, plain.code);
}

#[test]
fn malformed_calls_say_how_il_is_called() {
    let cases: Vec<(Vec<Tok>, &str)> = vec![
        (vec![], "il! takes"),
        (vec![id("file")], "il! takes"),
        (vec![id("file"), p('='), id("x")], "il! takes"),
        (vec![id("files"), p('='), s("a.il")], "il! takes"),
        (
            vec![
                id("files"),
                p('='),
                Tok::Group {
                    open: '[',
                    inner: vec![],
                    span: 4,
                },
            ],
            "lists no file",
        ),
        (
            vec![
                id("files"),
                p('='),
                Tok::Group {
                    open: '[',
                    inner: vec![s("a.il"), p(','), s("a.il")],
                    span: 4,
                },
            ],
            "`a.il` is listed twice",
        ),
        (vec![s(IL), s(IL)], "il! takes"),
        (
            vec![Tok::Literal {
                text: "b\"LD x\"".into(),
                line: 1,
                column: 1,
                file: "src/lib.rs".into(),
                span: 5,
            }],
            "il! takes",
        ),
        (vec![id("r#file"), p('='), s("a.il")], "il! takes"),
    ];
    for (toks, want) in cases {
        let e = expand(&toks);
        assert!(e.code.is_empty(), "{toks:?}");
        assert_eq!(e.errors.len(), 1, "{toks:?}");
        assert!(e.errors[0].0.contains(want), "{toks:?}: {}", e.errors[0].0);
    }
    // A missing token is reported at the call.
    assert_eq!(expand(&[id("file"), p('=')]).errors[0].1, CALL_SITE);
}

#[test]
fn raw_and_escaped_literals_are_read_as_rust_reads_them() {
    let raw = Tok::Literal {
        text: format!("r#\"{IL}\"#"),
        line: 7,
        column: 5,
        file: "src/lib.rs".into(),
        span: 1,
    };
    let escaped = Tok::Literal {
        text: format!("{IL:?}"),
        line: 7,
        column: 5,
        file: "src/lib.rs".into(),
        span: 1,
    };
    assert_eq!(expand(&[raw]).code, expand(&[escaped]).code);
    // Errors count lines from the literal's line.
    let bad = Tok::Literal {
        text: "r\"FUNCTION_BLOCK F\nVAR x : INT; END_VAR\n    LD y\nEND_FUNCTION_BLOCK\n\"".into(),
        line: 10,
        column: 20,
        file: "src/lib.rs".into(),
        span: 6,
    };
    let e = expand(&[bad]);
    assert_eq!(e.errors[0].1, 6);
    // `LD y` is IL line 3, column 8: Rust line 12, column 8 (a later line
    // of a raw string starts at column 1).
    assert!(
        e.errors[0].0.contains("--> src/lib.rs:12:8\n"),
        "{}",
        e.errors[0].0
    );
    assert!(
        e.errors[0]
            .0
            .contains("IL line 3, column 8 of the il! input"),
        "{}",
        e.errors[0].0
    );
    assert!(e.code.contains("struct F"), "stubs: {}", e.code);
    // On the literal's first line the IL starts after `r"` (2 characters
    // from column 20): `INTT`, IL column 26, is Rust column 47.
    let first = Tok::Literal {
        text: "r\"FUNCTION_BLOCK F VAR x : INTT; END_VAR END_FUNCTION_BLOCK\"".into(),
        line: 4,
        column: 20,
        file: "src/lib.rs".into(),
        span: 2,
    };
    let e = expand(&[first]);
    assert!(
        e.errors[0].0.contains("--> src/lib.rs:4:47\n"),
        "{}",
        e.errors[0].0
    );
}

#[test]
fn an_input_over_16_mib_is_refused_with_its_code() {
    let mut il = String::from("PROGRAM P\nVAR x : INT; END_VAR\n");
    while il.len() <= super::MAX_MACRO_INPUT / 2 {
        il.push_str("    LD x\n    ST x\n");
    }
    // Two files of 8 MiB each: the limit is on the call, not per file.
    let dir = std::env::temp_dir().join(format!("il-expand-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (a, b) = (dir.join("a.il"), dir.join("b.il"));
    std::fs::write(&a, format!("{il}END_PROGRAM\n")).unwrap();
    std::fs::write(
        &b,
        format!("{}END_PROGRAM\n", il.replace("PROGRAM P", "PROGRAM Q")),
    )
    .unwrap();
    let (a, b) = (a.display().to_string(), b.display().to_string());
    let files = Tok::Group {
        open: '[',
        inner: vec![s(&a), p(','), s(&b)],
        span: 4,
    };
    let out = expand(&[id("files"), p('='), files]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(out.errors[0].0.contains("IL0035"), "{}", out.errors[0].0);
    assert!(out.code.is_empty(), "nothing is compiled");
}

#[test]
fn std_option_selects_the_standard() {
    let il = "PROGRAM P\nVAR s : SINT; i : INT; END_VAR\n    LD s\n    ST i\nEND_PROGRAM\n";
    let plain = expand(&[s(il)]);
    assert!(plain.errors.is_empty(), "{}", text(&plain));
    let iec2013 = expand(&[s(il), p(','), id("std"), p('='), s("iec2013")]);
    assert_eq!(iec2013.code, plain.code);
    let strict = expand(&[
        s(il),
        p(','),
        id("serde"),
        p(','),
        id("std"),
        p('='),
        s("IEC2003"),
    ]);
    let msg = &strict.errors[0].0;
    assert!(msg.contains("IL0302"), "{msg}");
    assert!(msg.contains("implicit conversion SINT → INT is a 3rd-edition feature"));
    let bad = expand(&[s(il), p(','), id("std"), p('='), s("iec1993")]);
    assert!(
        bad.errors[0].0.contains("unknown standard `iec1993`"),
        "{}",
        text(&bad)
    );
}

/// A program instance left out of the stubs (its global is missing) shifts
/// the positions VAR_CONFIG and VAR_ACCESS name instances by: the paths into
/// it go, the others follow their instance (a fuzzed input indexed past the
/// end, in `emit::config_vars::place`).
#[test]
fn stubs_without_an_unbound_instance_keep_the_paths_into_the_others() {
    let il = "PROGRAM Uses\nVAR_EXTERNAL g : INT; END_VAR\nVAR a : INT; END_VAR\n    LD g\n    ST a\nEND_PROGRAM\n\
PROGRAM Plain\nVAR b : INT; END_VAR\n    LD b\n    ST b\nEND_PROGRAM\n\
CONFIGURATION C\nRESOURCE R ON PLC\n    PROGRAM P1 : Uses;\n    PROGRAM P2 : Plain;\nEND_RESOURCE\n\
VAR_CONFIG\n    R.P1.a : INT := 1;\n    R.P2.b : INT := 7;\nEND_VAR\n\
VAR_ACCESS\n    A : R.P1.a : INT READ_WRITE;\n    B : R.P2.b : INT READ_WRITE;\nEND_VAR\nEND_CONFIGURATION\n";
    let e = expand(&[s(il)]);
    let t = text(&e);
    assert!(t.contains("no global") || t.contains("`g`"), "{t}");
    assert!(!t.contains("internal"), "{t}");
    syn::parse_file(&e.code).unwrap_or_else(|err| panic!("{err}\n{t}"));
    let code: String = e.code.split_whitespace().collect();
    assert!(
        code.contains("fnaccess_B(&self)->i16{::core::clone::Clone::clone(&self.R.P2.b)}"),
        "{t}"
    );
    assert!(code.contains("__s.R.P2.b=7i16;"), "{t}");
    assert!(!code.contains("access_A") && !code.contains("P1"), "{t}");
}

/// `il!(file = ...)` knows XML by its text: a PLCopen project named `.il` is
/// imported (with the `plcopen` feature; without it, IL0210 names the
/// feature), another tool's XML is one IL0202.
#[test]
fn a_file_is_xml_by_its_text() {
    let dir = std::env::temp_dir().join(format!("il-expand-xml-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let project = "\u{feff}<?xml version=\"1.0\"?>\n<project><types><pous>\
        <pou name=\"Blink\" pouType=\"functionBlock\"><interface><localVars>\
        <variable name=\"lamp\"><type><BOOL/></type></variable></localVars></interface>\
        <body><IL><p><![CDATA[LD lamp\nSTN lamp]]></p></IL></body></pou></pous></types></project>\n";
    let (il, tcpou) = (dir.join("blink.il"), dir.join("Main.TcPOU"));
    std::fs::write(&il, project).unwrap();
    std::fs::write(&tcpou, "<?xml version=\"1.0\"?>\n<TcPlcObject/>\n").unwrap();
    let file = |f: &std::path::Path| expand(&[id("file"), p('='), s(&f.display().to_string())]);
    let (imported, other) = (file(&il), file(&tcpou));
    let _ = std::fs::remove_dir_all(&dir);
    if cfg!(feature = "plcopen") {
        assert!(imported.errors.is_empty(), "{}", text(&imported));
        assert!(
            imported.code.contains("pub struct Blink"),
            "{}",
            text(&imported)
        );
        assert_eq!(other.errors.len(), 1, "{}", text(&other));
        assert!(other.errors[0].0.contains("IL0202"), "{}", text(&other));
        assert!(
            other.errors[0].0.contains("`<TcPlcObject>`"),
            "{}",
            text(&other)
        );
    } else {
        for e in [&imported, &other] {
            assert_eq!(e.errors.len(), 1, "{}", text(e));
            assert!(e.errors[0].0.contains("IL0210"), "{}", text(e));
            assert!(e.errors[0].0.contains("`plcopen` feature"), "{}", text(e));
        }
    }
}

/// `encoding = "..."` reads a file that is not UTF-8 in that encoding; an
/// unknown name is refused at its literal, and bytes invalid in the named
/// encoding are an error with the IL line and column.
#[test]
#[cfg(feature = "encodings")]
fn files_in_a_named_encoding() {
    let dir = std::env::temp_dir().join(format!("il-expand-enc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("nasos.exp");
    // "Пуск" in Windows-1251, in a comment and a STRING literal.
    std::fs::write(
        &path,
        b"PROGRAM Nasos\nVAR t : STRING := '\xCF\xF3\xF1\xEA'; END_VAR\n    LD t (* \xCF\xF3\xF1\xEA *)\n    ST t\nEND_PROGRAM\n",
    )
    .unwrap();
    let file = path.display().to_string();
    let call = |enc: &str| {
        expand(&[
            id("file"),
            p('='),
            s(&file),
            p(','),
            id("encoding"),
            p('='),
            Tok::string(enc, 5),
        ])
    };
    let out = call("windows-1251");
    assert!(out.errors.is_empty(), "{}", text(&out));
    assert!(
        out.code.contains(r#"from_str_truncating("Пуск")"#),
        "{}",
        out.code
    );
    // Without a name it is read as Windows-1252 (il! shows no warnings).
    let out = expand(&[id("file"), p('='), s(&file)]);
    assert!(out.errors.is_empty(), "{}", text(&out));
    assert!(
        out.code.contains(r#"from_str_truncating("Ïóñê")"#),
        "{}",
        out.code
    );
    let out = call("cp-1251");
    assert_eq!(out.errors.len(), 1, "{}", text(&out));
    assert!(
        out.errors[0].0.starts_with("unknown encoding `cp-1251`"),
        "{}",
        text(&out)
    );
    assert_eq!(out.errors[0].1, 5, "the error is at the name");
    let out = call("utf-8");
    assert!(out.errors[0].0.contains("IL0040"), "{}", text(&out));
    assert!(
        out.errors[0].0.contains("nasos.exp:2:20\n"),
        "{}",
        text(&out)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `il!` as users get it by default, without code pages: a file in one is an
/// error that names the feature, and so is naming one.
#[test]
#[cfg(not(feature = "encodings"))]
fn without_code_pages_a_file_in_one_is_an_error_naming_the_feature() {
    let dir = std::env::temp_dir().join(format!("il-expand-noenc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("nasos.il");
    std::fs::write(
        &path,
        b"PROGRAM Nasos\nVAR t : BOOL; END_VAR\n    LD t (* \xCF\xF3\xF1\xEA *)\n    ST t\nEND_PROGRAM\n",
    )
    .unwrap();
    let file = path.display().to_string();
    let out = expand(&[id("file"), p('='), s(&file)]);
    assert_eq!(out.errors.len(), 1, "{}", text(&out));
    let msg = &out.errors[0].0;
    assert!(msg.contains("IL0040"), "{msg}");
    assert!(msg.contains("nasos.il:3:13\n"), "{msg}");
    assert!(msg.contains("`encodings` feature"), "{msg}");
    let out = expand(&[
        id("file"),
        p('='),
        s(&file),
        p(','),
        id("encoding"),
        p('='),
        Tok::string("windows-1251", 5),
    ]);
    assert_eq!(out.errors.len(), 1, "{}", text(&out));
    assert!(
        out.errors[0].0.contains("`encodings` feature"),
        "{}",
        text(&out)
    );
    assert_eq!(out.errors[0].1, 5, "the error is at the name");
    let _ = std::fs::remove_dir_all(&dir);
}
