//! Lines are the user's: the XML lines of a PLCopen project, the lines of a
//! bare instruction list (`snippet`), for breakpoints, frames and the flow.

use serde_json::json;

use super::{Dap, var};

/// A PLCopen project whose IL body is on XML lines 13 to 15.
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
    </pous>
  </types>
</project>
"#;

fn file(name: &str, text: &str) -> String {
    let d = std::env::temp_dir().join(format!("ilc-debug-src-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn a_plcopen_project_is_debugged_on_its_xml_lines() {
    let path = file("blink.xml", PROJECT);
    let mut d = Dap::start();
    d.launch(json!({"program": path, "cycles": 2, "set": ["run=TRUE@2"]}));
    let bps = d.breakpoints(&path, json!([{"line": 14}, {"line": 8}]));
    assert_eq!(
        (bps[0]["verified"].as_bool(), bps[0]["line"].as_u64()),
        (Some(true), Some(14))
    );
    // A declaration line moves to the first instruction's XML line.
    assert_eq!(bps[1]["line"], 13, "{bps:?}");
    d.breakpoints(&path, json!([{"line": 14, "condition": "run"}]));
    d.ok("configurationDone", json!({}));
    d.stopped();
    let (frame, line, _) = d.top();
    assert_eq!(line, 14);
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "scan").0, "2");
    assert_eq!(var(&cr, "CR"), ("TRUE", "BOOL"));
    let flow = d.ok("flow", json!({}));
    assert_eq!(
        super::without_source(&flow["lines"]),
        json!([{"pou": "Blink", "line": 13, "cr": "TRUE : BOOL"}])
    );
    assert_eq!(flow["lines"][0]["source"]["name"], "blink.xml");
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}

#[test]
fn a_snippet_is_debugged_on_its_own_lines() {
    let path = file(
        "table51.il",
        "(* Table 51 *)\nLD %IX0.0\nANDN %MX5.0\nST %QX0.0\n",
    );
    let mut d = Dap::start();
    d.launch(json!({"program": path, "snippet": true, "cycles": 1, "set": ["%IX0.0=TRUE"]}));
    let bps = d.breakpoints(&path, json!([{"line": 3}]));
    assert_eq!(
        (bps[0]["verified"].as_bool(), bps[0]["line"].as_u64()),
        (Some(true), Some(3))
    );
    d.ok("configurationDone", json!({}));
    d.stopped();
    let (frame, line, name) = d.top();
    assert_eq!((line, name.as_str()), (3, "table51"));
    let image = d.scope(frame, "Process image");
    assert_eq!(var(&image, "%IX0.0"), ("TRUE", "BOOL"));
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}

#[test]
fn an_m221_listing_is_debugged_on_its_own_lines() {
    // Launch field `dialect`: the listing's lines, into a subroutine. The
    // operation block (line 9) is several IL statements: one stop, and
    // `next` goes to the listing's next line.
    let path = file(
        "count.il",
        "LD %I0.0\nST %Q0.0\n\nLD %I0.1\nCAL SR1\n\nSR1:\nLD 1\n[ %MW0 := %MW0 + 1 ]\nRET\n",
    );
    let mut d = Dap::start();
    // `set`, `force` and `evaluate` name the objects as the listing does.
    d.launch(json!({
        "program": path, "dialect": "m221", "cycles": 2,
        "set": ["%I0.1=TRUE@2"], "force": {"%I0.0": true},
    }));
    let bps = d.breakpoints(&path, json!([{"line": 9}]));
    assert_eq!(
        (bps[0]["verified"].as_bool(), bps[0]["line"].as_u64()),
        (Some(true), Some(9))
    );
    d.ok("configurationDone", json!({}));
    d.stopped();
    let (frame, line, name) = d.top();
    assert_eq!((line, name.as_str()), (9, "count.SR1 (SUB_SR1)"));
    let cr = d.scope(frame, "Current result");
    assert_eq!(var(&cr, "scan").0, "2");
    // The forced input reached the output in this scan's first rung; the
    // subroutine has not counted yet.
    assert_eq!(d.eval(frame, "%Q0.0")["result"], "TRUE");
    assert_eq!(d.eval(frame, "%MW0")["result"], "0");
    d.ok("next", json!({"threadId": 1}));
    d.stopped();
    assert_eq!(d.top().1, 10);
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
}
