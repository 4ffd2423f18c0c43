//! Projects in XML (PLCopen, LogicLab): diagnostics and answers in the
//! XML's own positions.

use super::*;

/// A PLCopen project: diagnostics and answers in the XML's own positions.
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
ST lampp
]]></xhtml:p>
          </IL>
        </body>
      </pou>
    </pous>
  </types>
</project>
"#;

#[test]
fn a_plcopen_project() {
    let dir = temp_dir("xml");
    let xml = uri(&dir.join("plc.xml"));
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": xml, "languageId": "xml", "version": 1, "text": PROJECT}}),
    );
    let diags = c.diagnostics_for(&xml);
    assert_eq!(diags.len(), 1, "{diags:?}");
    let (line, col) = find(PROJECT, "lampp", 0);
    assert_eq!(
        diags[0]["range"]["start"],
        json!({"line": line, "character": col})
    );
    // Hover and definition inside the IL body of the XML.
    let h = c.result("textDocument/hover", at(&xml, PROJECT, "ANDN lamp", 6));
    assert!(hover_text(&h).contains("lamp : BOOL"), "{h}");
    let h = c.result("textDocument/hover", at(&xml, PROJECT, "ANDN", 1));
    assert!(hover_text(&h).contains("CR after: `BOOL`"), "{h}");
    let fixed = PROJECT.replace("ST lampp", "ST lamp");
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": xml, "version": 2}, "contentChanges": [{"text": fixed}]}),
    );
    assert_eq!(c.diagnostics_for(&xml), Vec::<Value>::new());
    let d = c.result("textDocument/definition", at(&xml, &fixed, "ST lamp", 4));
    assert_eq!(d["uri"], xml);
    assert_eq!(
        d["range"]["start"]["line"],
        find(&fixed, "\"lamp\"", 0).0,
        "{d}"
    );
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A LogicLab / Arduino PLC IDE project: the same answers in its XML.
const LOGICLAB: &str = r#"<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<plcProject version="2.11">
  <sources>
    <main>
      <globalVars>
        <group name="IO">
          <var name="lamp" type="BOOL"/>
        </group>
      </globalVars>
      <programs>
        <program name="Blink">
          <vars>
            <inputVars>
              <var name="run" type="BOOL"/>
            </inputVars>
          </vars>
          <sourceCode type="IL">
            <![CDATA[
	LD	run
	ANDN	lamp
	ST	lampp
]]>
          </sourceCode>
        </program>
      </programs>
    </main>
  </sources>
</plcProject>
"#;

#[test]
fn a_logiclab_project() {
    let dir = temp_dir("plcprj");
    let prj = uri(&dir.join("Blink.plcprj"));
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": prj, "languageId": "xml", "version": 1, "text": LOGICLAB}}),
    );
    let diags = c.diagnostics_for(&prj);
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0]["code"], "IL0101");
    let (line, col) = find(LOGICLAB, "lampp", 0);
    assert_eq!(
        diags[0]["range"]["start"],
        json!({"line": line, "character": col})
    );
    // `lamp` is a global of the project's group, seen without VAR_EXTERNAL:
    // its definition is the group's `<var>`.
    let h = c.result("textDocument/hover", at(&prj, LOGICLAB, "ANDN\tlamp", 6));
    assert!(hover_text(&h).contains("lamp : BOOL"), "{h}");
    let d = c.result(
        "textDocument/definition",
        at(&prj, LOGICLAB, "ANDN\tlamp", 6),
    );
    assert_eq!(d["uri"], prj);
    assert_eq!(
        d["range"]["start"]["line"],
        find(LOGICLAB, "\"lamp\"", 0).0,
        "{d}"
    );
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
