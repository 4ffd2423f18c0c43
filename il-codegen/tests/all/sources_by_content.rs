//! XML is known by its text, not its name: through the pipeline
//! (`Program::source`, `Input::by_content`) and the build-script `Builder`,
//! a PLCopen project under any name is imported, and another tool's XML is
//! one error (IL0202) that names its root.

use il_codegen::diag::{Diagnostic, SourceFile};
use il_codegen::{Builder, Input, Program};
use std::path::PathBuf;

const PROJECT: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <types><pous>
    <pou name="Blink" pouType="program">
      <interface>
        <localVars><variable name="lamp"><type><BOOL/></type></variable></localVars>
      </interface>
      <body><IL><p><![CDATA[LD lamp
STN lamp]]></p></IL></body>
    </pou>
  </pous></types>
</project>
"#;

const OTHER: &str = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  <POU Name=\"Main\">\n  <Declaration>LD %I0.0 ; &lt;x&gt;</Declaration></POU>\n</TcPlcObject>\n";

fn diagnostics(name: &str, text: &str) -> (Input, Vec<Diagnostic>) {
    let checked = Program::new().source(SourceFile::new(name, text)).check();
    let d = checked.diagnostics()[0].clone();
    let input = checked.inputs()[0].clone();
    (input, d)
}

#[test]
fn a_plcopen_project_is_imported_under_any_name_and_with_any_lead() {
    let no_decl = PROJECT.split_once('\n').unwrap().1;
    for (name, text) in [
        ("blink.il", PROJECT.to_string()),
        ("blink.txt", PROJECT.to_string()),
        ("blink", PROJECT.to_string()),
        // A SourceFile made by a program keeps its byte order mark.
        ("blink.plcprj", format!("\u{feff}{PROJECT}")),
        // Blank space before the declaration, which XML itself refuses.
        ("blink.il", format!("\n\t \r\n{PROJECT}")),
        ("blink.il", format!("\u{feff} \n{PROJECT}")),
        ("blink.il", no_decl.to_string()),
        ("blink.il", format!("\n\n{no_decl}")),
    ] {
        let (input, d) = diagnostics(name, &text);
        assert!(matches!(input, Input::PlcOpen(_)), "{name}: {text:?}");
        assert_eq!(d, [], "{name}: {text:?}");
        let checked = Program::new()
            .source(SourceFile::new(name, text.clone()))
            .check();
        let files = checked.files(Default::default()).unwrap();
        assert!(files[0].contains("pub struct Blink"), "{name}");
        // The comments quote the file's own lines.
        let line = text.lines().position(|l| l.contains("STN lamp")).unwrap() + 1;
        assert!(
            files[0].contains(&format!("// {line}: STN lamp")),
            "{name}: {text:?}\n{}",
            files[0]
        );
    }
}

#[test]
fn an_error_in_the_il_points_into_the_file_after_blank_lines() {
    let text = format!("\n\n{}", PROJECT.replace("STN lamp", "STN lmap"));
    let (input, d) = diagnostics("blink.il", &text);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code, "IL0101");
    assert_eq!(input.source().snippet(d[0].span), "lmap");
    assert_eq!(input.source().line_col(d[0].span.lo), (11, 5));
    // A malformed project after blank lines: the parser's one error, at the
    // file's line.
    let text = format!("\n\n{}", PROJECT.replace("</p>", ""));
    let (input, d) = diagnostics("blink.il", &text);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code, "IL0201");
    assert_eq!(input.source().line_col(d[0].span.lo).0, 11);
}

#[test]
fn other_xml_is_one_error_that_names_its_root() {
    for name in ["Main.TcPOU", "Main.il", "Main.xml"] {
        let (input, d) = diagnostics(name, OTHER);
        assert_eq!(d.len(), 1, "{name}: {d:?}");
        assert_eq!(d[0].code, "IL0202");
        assert!(
            d[0].message
                .contains("its root element is `<TcPlcObject>` (no namespace)"),
            "{}",
            d[0].message
        );
        assert!(
            input
                .source()
                .snippet(d[0].span)
                .starts_with("<TcPlcObject"),
            "{d:?}"
        );
        assert!(
            d[0].notes.iter().any(|n| n.contains("PLCopen TC6 XML")),
            "{:?}",
            d[0].notes
        );
    }
    // A namespaced root is named with its namespace, also when it is
    // another schema's `<project>`.
    let (_, d) = diagnostics(
        "pom.xml",
        "<project xmlns=\"http://maven.apache.org/POM/4.0.0\"><modelVersion/></project>",
    );
    assert_eq!(d.len(), 1, "{d:?}");
    assert!(
        d[0].message
            .contains("`<project>` in namespace `http://maven.apache.org/POM/4.0.0`"),
        "{}",
        d[0].message
    );
    // PLCopen's older namespaces are PLCopen's.
    let tc6_0200 = PROJECT.replace("tc6_0201", "tc6_0200");
    assert_eq!(diagnostics("a.xml", &tc6_0200).1, []);
}

#[test]
fn il_text_stays_il_and_a_xml_name_stays_xml() {
    let il = "PROGRAM P\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_PROGRAM\n";
    for name in ["p.il", "p.smbp", "p.txt"] {
        let (input, d) = diagnostics(name, il);
        assert!(matches!(input, Input::Il(_)), "{name}");
        assert_eq!(d, [], "{name}");
    }
    // Named `.xml` but not XML: the XML parser's one error, not the IL
    // parser's many.
    let (input, d) = diagnostics("p.xml", il);
    assert!(matches!(input, Input::PlcOpen(_)));
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code, "IL0201");
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("il-by-content-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn builder_file_reads_xml_by_its_text() {
    let dir = temp("builder");
    std::fs::write(dir.join("blink.il"), format!("\u{feff}{PROJECT}")).unwrap();
    std::fs::write(
        dir.join("main.txt"),
        "PROGRAM Main\nVAR t : TON; END_VAR\n    CAL t\nEND_PROGRAM\n",
    )
    .unwrap();
    let written = Builder::new()
        .file(dir.join("blink.il"))
        .file(dir.join("main.txt"))
        .out_dir(dir.join("out"))
        .cargo_directives(false)
        .compile()
        .unwrap_or_else(|e| panic!("{e}"));
    let code = std::fs::read_to_string(&written[0]).unwrap();
    assert!(code.contains("pub struct Blink"), "{code}");
    assert!(written[1].ends_with("main.rs"), "{written:?}");
    assert!(code.contains("// 9: STN lamp"), "{code}");

    std::fs::write(dir.join("Main.TcPOU"), format!("\u{feff}{OTHER}")).unwrap();
    let e = Builder::new()
        .file(dir.join("Main.TcPOU"))
        .out_dir(dir.join("out2"))
        .cargo_directives(false)
        .compile()
        .unwrap_err()
        .to_string();
    assert_eq!(e.matches("error[").count(), 1, "{e}");
    assert!(e.contains("error[IL0202]"), "{e}");
    assert!(e.contains("`<TcPlcObject>`"), "{e}");
    assert!(e.contains("Main.TcPOU:2:1"), "{e}");
    assert!(!dir.join("out2").join("Main.rs").exists());

    // UTF-16 (here by its byte order mark) is read for XML as for IL.
    let utf16: Vec<u8> = [0xFF, 0xFE]
        .into_iter()
        .chain(PROJECT.encode_utf16().flat_map(u16::to_le_bytes))
        .collect();
    std::fs::write(dir.join("wide.xml"), utf16).unwrap();
    let written = Builder::new()
        .file(dir.join("wide.xml"))
        .out_dir(dir.join("out3"))
        .cargo_directives(false)
        .compile()
        .unwrap_or_else(|e| panic!("{e}"));
    let code = std::fs::read_to_string(&written[0]).unwrap();
    assert!(code.contains("pub struct Blink"), "{code}");
    let _ = std::fs::remove_dir_all(&dir);
}
