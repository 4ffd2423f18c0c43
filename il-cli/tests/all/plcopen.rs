//! `ilc check`, `ilc emit` and `ilc run` on PLCopen TC6 XML files (known by
//! their text, whatever their name): diagnostics in XML lines, JSON output,
//! exit status; other XML is one error.

use il_testkit::json;

use std::path::PathBuf;
use std::process::{Command, Output};

use json::get;

const PROJECT: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <types>
    <dataTypes/>
    <pous>
      <pou name="Blink" pouType="program">
        <interface>
          <inputVars><variable name="run"><type><BOOL/></type></variable></inputVars>
          <outputVars><variable name="lamp"><type><BOOL/></type></variable></outputVars>
        </interface>
        <body>
          <IL>
            <xhtml:p><![CDATA[LD run
ANDN lamp
ST lamp
]]></xhtml:p>
          </IL>
        </body>
      </pou>
      <pou name="Doc" pouType="program">
        <body><ST><xhtml:p>x := 1;</xhtml:p></ST></body>
      </pou>
    </pous>
  </types>
</project>
"#;

fn ilc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(args)
        .env_remove("NO_COLOR")
        .output()
        .expect("run ilc")
}

fn temp(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ilc-plcopen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn check_accepts_the_il_pou_and_names_the_st_one() {
    let p = temp("blink.xml", PROJECT);
    let o = ilc(&["check", "--color", "never", p.to_str().unwrap()]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(
        err.contains(
            "warning[IL0203]: POU `Doc` is not translated: its body is Structured Text (ST)"
        ),
        "{err}"
    );
    assert!(err.contains("blink.xml:20:18"), "{err}");
    assert!(
        err.contains(r#"<pou name="Doc" pouType="program">"#),
        "{err}"
    );
}

#[test]
fn errors_point_at_xml_lines_in_human_and_json_output() {
    let p = temp("bad.xml", &PROJECT.replace("ANDN lamp", "ANDN lmap"));
    let path = p.to_str().unwrap();
    let o = ilc(&["check", "--color", "never", path]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("error[IL0101]"), "{err}");
    assert!(err.contains("bad.xml:14:6"), "{err}");
    assert!(err.contains("14 | ANDN lmap"), "{err}");

    let o = ilc(&["check", "--message-format", "json", path]);
    assert_eq!(o.status.code(), Some(1));
    let out = String::from_utf8(o.stdout).unwrap();
    let errors: Vec<json::Value> = out
        .lines()
        .map(json::parse)
        .filter(|j| get(j, "severity") == "error")
        .collect();
    assert_eq!(errors.len(), 1, "{out}");
    let e = &errors[0];
    assert_eq!(get(e, "file"), path);
    assert_eq!(get(e, "code"), "IL0101");
    assert_eq!(get(e, "line"), 14);
    assert_eq!(get(e, "column"), 6);
    assert_eq!(get(e, "end_column"), 10);
}

#[test]
fn malformed_xml_is_an_error_with_line_and_column() {
    let p = temp("broken.xml", &PROJECT.replace("</xhtml:p>", ""));
    let o = ilc(&["check", "--color", "never", p.to_str().unwrap()]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("error[IL0201]: malformed XML"), "{err}");
    assert!(err.contains("broken.xml:17:11"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    let o = ilc(&["emit", "--color", "never", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.is_empty());
}

#[test]
fn emit_writes_a_file_named_after_the_xml_stem_with_xml_line_comments() {
    let p = temp("blink_emit.xml", PROJECT);
    let dir = p.parent().unwrap().join("out");
    let o = ilc(&[
        "emit",
        "--color",
        "never",
        "-o",
        dir.to_str().unwrap(),
        p.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let code = std::fs::read_to_string(dir.join("blink_emit.rs")).unwrap();
    assert!(code.contains("pub struct Blink"), "{code}");
    assert!(code.contains("// 13: LD run"), "{code}");
    assert!(code.contains("// 15: ST lamp"), "{code}");
    assert!(code.contains("/// `VAR_INPUT` (XML line 8)"), "{code}");
    assert!(stderr(&o).contains("IL0203"), "warnings are shown");
}

#[test]
fn run_simulates_an_il_program_of_the_project() {
    let p = temp("blink_run.xml", PROJECT);
    let o = ilc(&[
        "run",
        p.to_str().unwrap(),
        "--program",
        "Blink",
        "--cycles",
        "4",
        "--set",
        "run=TRUE",
        "--color",
        "never",
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}{out}", stderr(&o));
    assert!(out.contains("lamp"), "{out}");
}

#[test]
fn the_corpus_project_checks_with_warnings_only() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/corpus/beremiz_beremiz_first_steps_plc.xml"
    );
    if !std::path::Path::new(path).is_file() {
        eprintln!("SKIPPED: ../shared/corpus/beremiz_beremiz_first_steps_plc.xml not found");
        return;
    }
    let o = ilc(&["check", "--color", "never", path]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert_eq!(err.matches("warning[IL0203]").count(), 6, "{err}");
    assert!(err.contains("warning: 7 warnings emitted"), "{err}");
    let o = ilc(&["emit", "--color", "never", path]);
    let code = String::from_utf8_lossy(&o.stdout);
    assert!(code.contains("pub struct CounterIL"), "{code}");
    assert!(code.contains("// 943: LD Reset"), "{code}");
}

/// The JSON diagnostics of `ilc check` of `path`, and its exit status.
fn check_json(args: &[&str]) -> (Option<i32>, Vec<serde_json::Value>) {
    let mut all = vec!["check", "--message-format", "json"];
    all.extend(args);
    let o = ilc(&all);
    let out = String::from_utf8(o.stdout).unwrap();
    (o.status.code(), out.lines().map(json::parse).collect())
}

#[test]
fn xml_of_another_tool_is_one_error_naming_its_root() {
    // A TwinCAT 3 POU: UTF-8 with a byte order mark, its own root (an M221
    // `.smbp`, `<ProjectDescriptor>`, has an import of its own: m221.rs).
    let tcpou = "\u{feff}<?xml version=\"1.0\" encoding=\"utf-8\"?>\n\
        <TcPlcObject Version=\"1.1.0.1\">\n\
        <POU Name=\"Main\"><Declaration><![CDATA[PROGRAM Main]]></Declaration></POU>\n\
        </TcPlcObject>\n";
    let p = temp("Main.TcPOU", tcpou);
    let path = p.to_str().unwrap();
    let (code, diags) = check_json(&[path]);
    assert_eq!(code, Some(1));
    assert_eq!(diags.len(), 1, "{diags:?}");
    let d = &diags[0];
    assert_eq!(get(d, "code"), &serde_json::Value::from("IL0202"));
    assert_eq!(get(d, "file"), &serde_json::Value::from(path));
    assert_eq!(get(d, "line"), &serde_json::json!(2.0 as u64));
    assert_eq!(get(d, "column"), &serde_json::json!(1.0 as u64));
    let serde_json::Value::String(msg) = get(d, "message") else {
        panic!("{d:?}")
    };
    assert!(msg.contains("`<TcPlcObject>` (no namespace)"), "{msg}");
    let serde_json::Value::String(rendered) = get(d, "rendered") else {
        panic!("{d:?}")
    };
    assert!(rendered.contains("PLCopen TC6 XML projects"), "{rendered}");
    // A namespace is named; another schema's `<project>` is no PLCopen one.
    for (name, xml, want) in [
        (
            "Main.TcPOU",
            "<?xml version=\"1.0\"?>\n<TcPlcObject xmlns=\"urn:beckhoff\"/>\n",
            "`<TcPlcObject>` in namespace `urn:beckhoff`",
        ),
        (
            "pom.xml",
            "<project xmlns=\"http://maven.apache.org/POM/4.0.0\"/>",
            "`<project>` in namespace `http://maven.apache.org/POM/4.0.0`",
        ),
    ] {
        let p = temp(name, xml);
        let (code, diags) = check_json(&[p.to_str().unwrap()]);
        assert_eq!(code, Some(1));
        assert_eq!(diags.len(), 1, "{diags:?}");
        let serde_json::Value::String(msg) = get(&diags[0], "message") else {
            panic!("{diags:?}")
        };
        assert!(msg.contains(want), "{msg}");
    }
}

#[test]
fn a_plcopen_project_under_any_name_is_imported() {
    let variants = [
        ("blink_named.il", PROJECT.to_string()),
        ("blink_named.txt", PROJECT.to_string()),
        ("blink_bom.plcprj", format!("\u{feff}{PROJECT}")),
        // Blank lines before the declaration (which XML itself refuses).
        ("blink_blank.il", format!("\u{feff}\r\n  \n{PROJECT}")),
        (
            "blink_nodecl.il",
            PROJECT.split_once('\n').unwrap().1.to_string(),
        ),
    ];
    for (name, text) in &variants {
        let p = temp(name, text);
        let path = p.to_str().unwrap();
        let (code, diags) = check_json(&[path]);
        assert_eq!(code, Some(0), "{name}: {diags:?}");
        assert_eq!(diags.len(), 1, "{name}: {diags:?}");
        assert_eq!(
            get(&diags[0], "code"),
            &serde_json::Value::from("IL0203"),
            "{name}"
        );
        // The XML's own lines, shifted by what stands before the declaration.
        let shift = text.matches('\n').count() as f64 - PROJECT.matches('\n').count() as f64;
        assert_eq!(
            get(&diags[0], "line"),
            &serde_json::json!((20.0 + shift) as u64),
            "{name}"
        );
        let o = ilc(&[
            "run",
            path,
            "--program",
            "Blink",
            "--cycles",
            "2",
            "--set",
            "run=TRUE",
        ]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", stderr(&o));
    }
    // `emit` names the output after the stem, whatever the extension.
    let p = temp("blink_named.txt", PROJECT);
    let dir = p.parent().unwrap().join("out_txt");
    let o = ilc(&["emit", "-o", dir.to_str().unwrap(), p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let code = std::fs::read_to_string(dir.join("blink_named.rs")).unwrap();
    assert!(code.contains("// 13: LD run"), "{code}");
    // `--snippet` and standard input read XML as XML too.
    let (code, diags) = check_json(&["--snippet", p.to_str().unwrap()]);
    assert_eq!((code, diags.len()), (Some(0), 1), "{diags:?}");
    let mut child = Command::new(env!("CARGO_BIN_EXE_ilc"))
        .args(["check", "--color", "never", "-"])
        .stdin(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write;
    child
        .stdin
        .take()
        .unwrap()
        .write_all(PROJECT.as_bytes())
        .unwrap();
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("warning[IL0203]"), "{}", stderr(&o));
}

/// A PLCopen project whose IL body divides by zero on XML line 16.
const RATIO: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <types>
    <dataTypes/>
    <pous>
      <pou name="Ratio" pouType="program">
        <interface>
          <inputVars><variable name="d"><type><INT/></type></variable></inputVars>
          <outputVars><variable name="q"><type><INT/></type></variable></outputVars>
        </interface>
        <body>
          <IL>
            <xhtml:p><![CDATA[
(* the ratio *)
LD 100
DIV d
ST q
]]></xhtml:p>
          </IL>
        </body>
      </pou>
    </pous>
  </types>
</project>
"#;

#[test]
fn run_reports_a_fault_at_the_xml_line_of_the_il_body() {
    let line = RATIO.lines().position(|l| l == "DIV d").unwrap() + 1;
    assert_eq!(line, 16);
    let p = temp("ratio.xml", RATIO);
    let path = p.to_str().unwrap();
    let o = ilc(&["run", path, "--cycles", "2", "--set", "d=4@2"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    // Scan 1 divides by zero; scan 2 by 4.
    assert!(
        err.contains(&format!(
            "warning: cycle 1: fault DivisionByZero in Ratio at {path}:16\n"
        )),
        "{err}"
    );
    assert!(!err.contains("cycle 2: fault"), "{err}");
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.lines().nth(2).is_some_and(|l| l.ends_with(" 25")),
        "{out}"
    );
}

/// A scan that never ends (the interpreter's limit of instructions per
/// scan) is an error placed at the XML line of the IL body too.
#[test]
fn run_places_an_endless_scan_at_the_xml_line() {
    let xml = RATIO.replace(
        "\n(* the ratio *)\nLD 100\nDIV d\nST q\n",
        "\ntop: LD q\nADD 1\nST q\nJMP top\n",
    );
    let body: Vec<usize> = xml
        .lines()
        .enumerate()
        .filter(|(_, l)| ["top: LD q", "ADD 1", "ST q", "JMP top"].contains(l))
        .map(|(k, _)| k + 1)
        .collect();
    assert_eq!(body, [14, 15, 16, 17]);
    let p = temp("spin.xml", &xml);
    let path = p.to_str().unwrap();
    let o = ilc(&["run", path, "--cycles", "1"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    let at = err
        .split_once(&format!("{path}:"))
        .and_then(|(_, rest)| rest.split(':').next())
        .and_then(|l| l.parse::<usize>().ok());
    assert!(at.is_some_and(|l| body.contains(&l)), "{err}");
    assert!(err.contains("in Ratio: more than"), "{err}");
}
