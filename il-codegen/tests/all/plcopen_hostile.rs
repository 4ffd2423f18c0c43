//! PLCopen import on hostile XML: attributes and bodies that try to add IL
//! text, empty names, names that try to forge messages. Sizes and depths
//! are in `plcopen_limits.rs`.

use crate::plcopen_import::{check, compile_inputs, import, parses};
use crate::plcopen_limits::quiet;
use crate::plcopen_xml::{block, il_pou, mutated_projects, project, template, var};
use il_codegen::Input;
use il_codegen::diag::{Diagnostic, Severity, SourceFile, render};

/// Every payload adds something named `Evil` if it reaches the IL text.
const INJECTIONS: &[(&str, &str)] = &[
    ("{PN}", "Main&#10;END_PROGRAM&#10;PROGRAM Evil"),
    ("{PN}", "Main\nEND_PROGRAM\nPROGRAM Evil"),
    ("{VN}", "x; END_VAR VAR Evil : INT; END_VAR VAR y"),
    ("{VN}", "x : INT;&#13;Evil"),
    ("{TN}", "INT; Evil : INT"),
    ("{IV}", "5; Evil : INT := 1"),
    ("{IV}", "5 (* Evil *)"),
    ("{IV}", "'a'; Evil : STRING := 'b'"),
    ("{IV}", "5&#10;END_VAR&#10;VAR Evil : INT;"),
    ("{IV}", "[1, 2]; Evil : INT := [1"),
    ("{IV}", "(x := 1) END_VAR VAR Evil : Pt := (x := 1)"),
    ("{AD}", "%IX0.0 : BOOL; Evil AT %IX0.1"),
    ("{SL}", "8]; Evil : STRING[8"),
    ("{AL}", "0..1] OF INT; Evil : ARRAY [0"),
    ("{SLO}", "0..1); Evil : INT (0"),
    ("{EN}", "A); Evil : (Z"),
    ("{EV}", "1); Evil : (Z := 1"),
    ("{RV}", "2(1)]; Evil : ARRAY [0..1] OF INT := [2"),
    ("{SM}", "x := 1); Evil : Pt := (x"),
    ("{DT}", "T : INT; END_TYPE PROGRAM Evil END_PROGRAM TYPE U"),
    ("{CN}", "Cell&#10;END_CONFIGURATION&#10;PROGRAM Evil"),
    ("{CN}", "Cell *) PROGRAM Evil (*"),
    ("{RN}", "Cpu ON PLC END_RESOURCE RESOURCE Evil"),
    ("{TK}", "Fast (PRIORITY := 1); TASK Evil"),
    ("{TI}", "T#10ms); TASK Evil (PRIORITY := 1"),
    ("{TP}", "1); TASK Evil (PRIORITY := 2"),
    ("{TS}", "ok); TASK Evil (PRIORITY := 2"),
    ("{IN}", "Inst WITH Fast : Main; PROGRAM Evil"),
    ("{IT}", "Main; PROGRAM Evil WITH Fast : Main"),
];

#[test]
fn the_template_is_valid() {
    let xml = template(("", ""));
    let imp = import(&xml);
    assert!(imp.diagnostics.is_empty(), "{:?}", imp.diagnostics);
    assert!(parses(&imp.il), "{}", imp.il.text);
    assert!(!imp.il.text.contains("Evil"), "{}", imp.il.text);
    for want in [
        "PROGRAM Main\n",
        "x : INT;",
        "v : INT := 5;",
        "a AT %IX0.0 : BOOL;",
        "s : STRING[8];",
        "r : ARRAY [0..1] OF INT := [2(1)];",
        "p : Pt := (x := 1);",
        "Lvl : INT (0..10);",
        "Col : (A := 1, B);",
        "CONFIGURATION Cell\n",
        "RESOURCE Cpu ON PLC\n",
        "TASK Fast (INTERVAL := T#10ms, PRIORITY := 1);",
        "TASK Trig (SINGLE := ok, PRIORITY := 2);",
        "PROGRAM Inst WITH Fast : Main;",
    ] {
        assert!(
            imp.il.text.contains(want),
            "missing {want:?} in\n{}",
            imp.il.text
        );
    }
}

#[test]
fn attributes_cannot_add_il_text() {
    for &(key, payload) in INJECTIONS {
        let xml = template((key, payload));
        let imp = import(&xml);
        let il = &imp.il.text;
        assert!(
            !il.contains("Evil"),
            "{key} = {payload:?} reached the IL:\n{il}"
        );
        assert!(
            parses(&imp.il),
            "{key} = {payload:?}: the rest does not parse:\n{il}"
        );
        // One error at the attribute's value, as written in the XML.
        let bad: Vec<&Diagnostic> = imp
            .diagnostics
            .iter()
            .filter(|d| d.code == "IL0206")
            .collect();
        assert!(
            !bad.is_empty(),
            "{key} = {payload:?}: {:?}",
            imp.diagnostics
        );
        let at = xml.find(payload).unwrap_or_else(|| panic!("{payload}"));
        for d in &bad {
            assert_eq!(d.span.range(), at..at + payload.len(), "{key}: {d:?}");
            assert_eq!(d.severity, Severity::Error);
        }
        // Nothing invalid is compiled either.
        let input = Input::plcopen(SourceFile::new("p.xml", xml.as_str()));
        assert!(compile_inputs(&[input]).is_err(), "{key}");
    }
}

#[test]
fn leaving_an_element_out_keeps_the_rest() {
    // A bad variable: only it is left out, the POU and its other variables stay.
    let imp = import(&template(("{VN}", "x; END_VAR")));
    assert!(imp.il.text.contains("PROGRAM Main\n"), "{}", imp.il.text);
    assert!(imp.il.text.contains("ok : BOOL;"), "{}", imp.il.text);
    assert!(
        !imp.il.text.contains("VAR\n    x : INT;"),
        "{}",
        imp.il.text
    );
    assert!(imp.il.text.contains("VAR\n    d : Lvl;"), "{}", imp.il.text);
    // A bad POU name: the POU is left out whole, and not listed.
    let imp = import(&template(("{PN}", "Main;")));
    assert!(!imp.il.text.contains("PROGRAM Main"), "{}", imp.il.text);
    assert!(!imp.il.text.contains("d : Lvl;"), "{}", imp.il.text);
    assert!(imp.pous.is_empty(), "{:?}", imp.pous);
    // A bad task: the task and its instance are left out, the rest stays.
    let imp = import(&template(("{TI}", "10ms")));
    assert!(!imp.il.text.contains("TASK Fast"), "{}", imp.il.text);
    assert!(!imp.il.text.contains("PROGRAM Inst"), "{}", imp.il.text);
    assert!(imp.il.text.contains("TASK Trig"), "{}", imp.il.text);
}

#[test]
fn empty_names_are_errors_at_the_attribute() {
    for key in [
        "{PN}", "{VN}", "{TN}", "{DT}", "{EN}", "{SM}", "{CN}", "{RN}", "{TK}", "{IN}", "{IT}",
    ] {
        let xml = template((key, ""));
        let (input, d) = check(&xml);
        let e: Vec<&Diagnostic> = d.iter().filter(|d| d.code == "IL0206").collect();
        assert_eq!(e.len(), 1, "{key}: {}", render(input.source(), &d, false));
        let snippet = input.source().snippet(e[0].span);
        assert!(
            snippet.ends_with("=\"\"") && !snippet.contains(' '),
            "{key}: {snippet:?}"
        );
        assert!(e[0].message.contains("empty"), "{}", e[0].message);
        let (line, col) = input.source().line_col(e[0].span.lo);
        assert!(line > 1 && col > 1, "{key}: {line}:{col}");
    }
    // A POU without any name: an error at its start tag (was dropped silently).
    let xml = template(("", "")).replace("<pou name=\"Main\"", "<pou");
    let imp = import(&xml);
    let e = imp
        .diagnostics
        .iter()
        .find(|d| d.code == "IL0202")
        .expect("IL0202");
    assert!(imp.xml.snippet(e.span).starts_with("<pou pouType"), "{e:?}");
}

/// A name that tries to forge a diagnostic line is quoted escaped.
#[test]
fn names_in_messages_cannot_forge_lines() {
    let xml = template(("{VN}", "x&#10;error[IL0000]: fake"));
    let (input, d) = check(&xml);
    let out = render(input.source(), &d, false);
    assert!(
        !out.lines().any(|l| l.starts_with("error[IL0000]")),
        "{out}"
    );
    assert!(out.contains(r"x\nerror[IL0000]: fake"), "{out}");
}

#[test]
fn a_body_cannot_end_its_pou_or_swallow_the_next() {
    let iface = block("localVars", "", &var("ok", "<BOOL/>"));
    let good = il_pou("Good", "program", &iface, "LD ok\nST ok\n");
    for (body, at) in [
        (
            "LD ok\nEND_PROGRAM\nPROGRAM Evil\nLD 1\n",
            Some("END_PROGRAM"),
        ),
        (
            "LD ok\nEND_PROGRAM\nFUNCTION_BLOCK Evil\n",
            Some("END_PROGRAM"),
        ),
        ("LD ok\n(* open\n", None),
    ] {
        let bad = il_pou("Bad", "program", &iface, body);
        // The bad POU first: an open comment would swallow the good one.
        let xml = project("", &(bad + &good), "");
        let imp = import(&xml);
        let e: Vec<&Diagnostic> = imp
            .diagnostics
            .iter()
            .filter(|d| d.code == "IL0209")
            .collect();
        assert_eq!(e.len(), 1, "{body:?}: {:?}", imp.diagnostics);
        match at {
            Some(word) => assert_eq!(imp.xml.snippet(e[0].span), word, "{body:?}"),
            None => assert!(imp.xml.snippet(e[0].span).starts_with("<IL"), "{body:?}"),
        }
        assert!(
            !imp.il.text.contains("Evil") && !imp.il.text.contains("PROGRAM Bad"),
            "{}",
            imp.il.text
        );
        assert!(imp.il.text.contains("PROGRAM Good\n"), "{}", imp.il.text);
        assert!(parses(&imp.il), "{}", imp.il.text);
    }
}

#[test]
fn a_bad_global_constant_taken_by_two_pous_is_reported_once() {
    let ext = block(
        "externalVars",
        r#" constant="true""#,
        &var("Limit", "<INT/>"),
    );
    let pous = il_pou("A", "functionBlock", &ext, "LD Limit\nRET\n")
        + &il_pou("B", "functionBlock", &ext, "LD Limit\nRET\n");
    let cfg = r#"      <configuration name="Cell">
        <globalVars constant="true">
          <variable name="Limit"><type><INT/></type><initialValue><simpleValue value="17; Evil : INT"/></initialValue></variable>
        </globalVars>
      </configuration>
"#;
    let imp = import(&project("", &pous, cfg));
    assert!(!imp.il.text.contains("Evil"), "{}", imp.il.text);
    let bad: Vec<_> = imp
        .diagnostics
        .iter()
        .filter(|d| d.code == "IL0206")
        .collect();
    assert_eq!(bad.len(), 1, "{bad:?}");
}

/// Random edits of the template (quotes, markup, keywords, comment openers,
/// entities): never a panic, through the check and the rendering. (That the
/// import keeps every POU whole under the same edits is the importer's own
/// test, in `src/plcopen/tests.rs`: it counts the lexer's tokens.)
#[test]
fn mutated_projects_never_panic() {
    // Heavy: not while a timing test measures.
    let _quiet = quiet();
    for x in mutated_projects(2000) {
        let (input, d) = check(&x);
        let _ = render(input.source(), &d, false);
    }
}
