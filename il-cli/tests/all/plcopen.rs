//! `ilc check`, `ilc emit` and `ilc run` on PLCopen TC6 XML files (detected by
//! the `.xml` extension): diagnostics in XML lines, JSON output, exit status.

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
    assert!(code.contains("/// VAR_INPUT (XML line 8)"), "{code}");
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
