//! PLCopen import on hostile XML: attributes that try to add IL text, empty
//! names, deep nesting, and sizes that must cost linear work.

use super::tests::{check, import, project};
use super::*;
use crate::diag::render::render;
use crate::input::Input;

/// The placeholders of [`template`] and their valid values.
const DEFAULTS: &[(&str, &str)] = &[
    ("{DT}", "Lvl"),
    ("{SLO}", "0"),
    ("{EN}", "A"),
    ("{EV}", "1"),
    ("{PN}", "Main"),
    ("{VN}", "x"),
    ("{TN}", "Lvl"),
    ("{IV}", "5"),
    ("{AD}", "%IX0.0"),
    ("{SL}", "8"),
    ("{AL}", "0"),
    ("{RV}", "2"),
    ("{SM}", "x"),
    ("{CN}", "Cell"),
    ("{RN}", "Cpu"),
    ("{TK}", "Fast"),
    ("{TI}", "T#10ms"),
    ("{TP}", "1"),
    ("{TS}", "ok"),
    ("{IN}", "Inst"),
    ("{IT}", "Main"),
];

/// A project in which every attribute that reaches the IL text is a
/// placeholder; `set` replaces one of them (raw XML attribute text).
fn template(set: (&str, &str)) -> String {
    let types = r#"      <dataType name="{DT}"><baseType><subrangeSigned><range lower="{SLO}" upper="10"/><baseType><INT/></baseType></subrangeSigned></baseType></dataType>
      <dataType name="Col"><baseType><enum><values><value name="{EN}" value="{EV}"/><value name="B"/></values></enum></baseType></dataType>
      <dataType name="Pt"><baseType><struct><variable name="x"><type><INT/></type></variable></struct></baseType>
        <documentation><xhtml:p>END_TYPE PROGRAM Evil END_PROGRAM</xhtml:p></documentation></dataType>
"#;
    let pou = r#"      <pou name="{PN}" pouType="program">
        <interface>
          <localVars>
            <variable name="{VN}"><type><INT/></type></variable>
            <variable name="d"><type><derived name="{TN}"/></type></variable>
            <variable name="v"><type><INT/></type><initialValue><simpleValue value="{IV}">; Evil : INT;</simpleValue></initialValue></variable>
            <variable name="a" address="{AD}"><type><BOOL/></type></variable>
            <variable name="s"><type><string length="{SL}"/></type></variable>
            <variable name="r"><type><array><dimension lower="{AL}" upper="1"/><baseType><INT/></baseType></array></type><initialValue><arrayValue><value repetitionValue="{RV}"><simpleValue value="1"/></value></arrayValue></initialValue></variable>
            <variable name="p"><type><derived name="Pt"/></type><initialValue><structValue><value member="{SM}"><simpleValue value="1"/></value></structValue></initialValue></variable>
            <variable name="ok"><type><BOOL/></type>
              <documentation><xhtml:p>END_VAR VAR Evil : INT; END_VAR</xhtml:p></documentation></variable>
          </localVars>
        </interface>
        <body><IL><xhtml:p><![CDATA[LD ok
ST ok
]]></xhtml:p></IL></body>
        <documentation><xhtml:p>END_PROGRAM PROGRAM Evil</xhtml:p></documentation>
      </pou>
"#;
    let cfg = r#"      <configuration name="{CN}">
        <resource name="{RN}">
          <task name="{TK}" interval="{TI}" priority="{TP}"><pouInstance name="{IN}" typeName="{IT}"/></task>
          <task name="Trig" single="{TS}" priority="2"/>
          <globalVars><variable name="ok"><type><BOOL/></type></variable></globalVars>
        </resource>
      </configuration>
"#;
    let mut xml = project(types, pou, cfg);
    for (k, v) in DEFAULTS {
        xml = xml.replace(k, if *k == set.0 { set.1 } else { v });
    }
    xml
}

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

fn parses(il: &SourceFile) -> bool {
    !crate::diag::has_errors(&crate::syntax::parse(il).1)
}

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
            assert_eq!(d.severity, crate::diag::Severity::Error);
        }
        // Nothing invalid is compiled either.
        let input = Input::plcopen(SourceFile::new("p.xml", xml.as_str()));
        assert!(crate::input::compile_inputs(&[input]).is_err(), "{key}");
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

/// The stack the deep-nesting tests run on: 1 MiB, a quarter of the 4 MiB
/// build scripts and test threads get by default here (debug build).
const SMALL_STACK: usize = 1 << 20;

/// Run the whole import and check of `xml` on [`SMALL_STACK`]; the
/// diagnostics, or a failure if the thread died.
fn on_small_stack(xml: String) -> (String, Vec<Diagnostic>) {
    std::thread::Builder::new()
        .stack_size(SMALL_STACK)
        .spawn(move || {
            let (input, d) = check(&xml);
            let _ = crate::input::compile_inputs(std::slice::from_ref(&input));
            (xml, d)
        })
        .expect("spawn")
        .join()
        .expect("the import ran out of stack or panicked")
}

/// `n` levels of `open` around `inner`, closed by `close`, one level a line.
fn nest(n: usize, open: &str, inner: &str, close: &str) -> String {
    let mut s = String::with_capacity(n * (open.len() + close.len() + 2) + inner.len());
    for _ in 0..n {
        s.push_str(open);
        s.push('\n');
    }
    s.push_str(inner);
    for _ in 0..n {
        s.push_str(close);
    }
    s
}

fn in_var(ty: &str, init: &str) -> String {
    let init = if init.is_empty() {
        String::new()
    } else {
        format!("<initialValue>{init}</initialValue>")
    };
    let iface = format!(
        "        <interface><localVars>\n<variable name=\"deep\"><type>{ty}</type>{init}</variable>\n<variable name=\"ok\"><type><BOOL/></type></variable>\n        </localVars></interface>\n"
    );
    project(
        "",
        &format!(
            "      <pou name=\"P\" pouType=\"program\">\n{iface}        <body><IL><xhtml:p>LD ok\nST ok\n</xhtml:p></IL></body>\n      </pou>\n"
        ),
        "",
    )
}

#[test]
fn deep_nesting_is_an_error_not_a_stack_overflow() {
    const ARRAY: &str = r#"<array><dimension lower="0" upper="1"/><baseType>"#;
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "array",
            in_var(&nest(20_000, ARRAY, "<INT/>", "</baseType></array>"), ""),
            "<baseType>",
        ),
        (
            "subrange",
            in_var(
                &nest(
                    20_000,
                    r#"<subrangeSigned><range lower="0" upper="1"/><baseType>"#,
                    "<INT/>",
                    "</baseType></subrangeSigned>",
                ),
                "",
            ),
            "<baseType>",
        ),
        (
            "struct",
            in_var(
                &nest(
                    20_000,
                    r#"<struct><variable name="m"><type>"#,
                    "<INT/>",
                    "</type></variable></struct>",
                ),
                "",
            ),
            "<type>",
        ),
        (
            "arrayValue",
            in_var(
                "<derived name=\"T\"/>",
                &nest(
                    40_000,
                    "<arrayValue><value>",
                    "<simpleValue value=\"1\"/>",
                    "</value></arrayValue>",
                ),
            ),
            "<value>",
        ),
        (
            "structValue",
            in_var(
                "<derived name=\"T\"/>",
                &nest(
                    40_000,
                    r#"<structValue><value member="m">"#,
                    "<simpleValue value=\"1\"/>",
                    "</value></structValue>",
                ),
            ),
            "<value member",
        ),
        (
            "dataType",
            project(
                &format!(
                    "<dataType name=\"T\"><baseType>{}</baseType></dataType>\n",
                    nest(20_000, ARRAY, "<INT/>", "</baseType></array>")
                ),
                "",
                "",
            ),
            "<baseType>",
        ),
    ];
    for (what, xml, tag) in cases {
        let (xml, d) = on_small_stack(xml);
        let deep: Vec<&Diagnostic> = d.iter().filter(|d| d.code == "IL0207").collect();
        assert_eq!(
            deep.len(),
            1,
            "{what}: {:?}",
            d.iter().map(|d| d.code).collect::<Vec<_>>()
        );
        // At the start tag of the element MAX_DEPTH levels down (the first
        // one counts as level 0), on its own line.
        let lo = deep[0].span.lo as usize;
        assert!(
            xml[lo..].starts_with(tag.trim_end_matches(" member")),
            "{what}: {}",
            &xml[lo..lo + 20]
        );
        let before = xml[..lo].matches(tag).count();
        assert!(
            (translate::MAX_DEPTH - 1..=translate::MAX_DEPTH).contains(&before),
            "{what}: {before} levels before the error"
        );
        let (line, col) = SourceFile::new("x", xml.as_str()).line_col(lo as u32);
        assert!(
            line > translate::MAX_DEPTH && col >= 1,
            "{what}: {line}:{col}"
        );
    }
}

/// Nesting up to the limit still translates.
#[test]
fn nesting_up_to_the_limit_translates() {
    let ty = nest(
        translate::MAX_DEPTH - 1,
        r#"<array><dimension lower="0" upper="1"/><baseType>"#,
        "<INT/>",
        "</baseType></array>",
    );
    let imp = import(&in_var(&ty, ""));
    assert!(imp.diagnostics.is_empty(), "{:?}", imp.diagnostics);
    assert_eq!(
        imp.il.text.matches("ARRAY [0..1] OF").count(),
        translate::MAX_DEPTH - 1
    );
}

/// `n` attributes on the variable `deep`.
fn with_attributes(n: usize) -> String {
    let attrs: String = (0..n).map(|k| format!(" a{k}=\"1\"")).collect();
    in_var("<INT/>", "").replace(
        "<variable name=\"deep\"",
        &format!("<variable name=\"deep\"{attrs}"),
    )
}

/// The fastest of five runs of `f` (the minimum resists a busy machine).
fn fastest(f: impl Fn()) -> std::time::Duration {
    (0..5)
        .map(|_| {
            let t = std::time::Instant::now();
            f();
            t.elapsed()
        })
        .min()
        .expect("five runs")
}

#[test]
fn thousands_of_attributes_are_refused_in_linear_time() {
    // Was 4.4 s (release) at 30,000: roxmltree's duplicate check is quadratic.
    let xml = with_attributes(30_000);
    let imp = import(&xml);
    assert_eq!(imp.diagnostics.len(), 1, "{:?}", imp.diagnostics);
    let d = &imp.diagnostics[0];
    assert_eq!(d.code, "IL0208");
    assert_eq!(imp.xml.snippet(d.span), "<variable");
    assert_eq!(
        imp.xml.line_col(d.span.lo).0,
        xml[..xml.find("<variable name=\"deep\"").unwrap()]
            .lines()
            .count()
            + 1
    );
    // Work at n and 8n, measured in this run: linear is 8x, quadratic 64x.
    let small = with_attributes(30_000);
    let large = with_attributes(240_000);
    let t1 = fastest(|| drop(import(&small)));
    let t8 = fastest(|| drop(import(&large)));
    let ratio = t8.as_secs_f64() / t1.as_secs_f64().max(1e-9);
    assert!(
        ratio < 24.0,
        "8x the attributes took {ratio:.1}x the time ({t1:?} → {t8:?})"
    );
    // Up to the limit, the element is read as usual.
    let imp = import(&with_attributes(limits::MAX_ATTRIBUTES - 1));
    assert!(imp.diagnostics.is_empty(), "{:?}", imp.diagnostics);
}

/// `n` data types, each a structure whose member is of the next type.
fn struct_chain(n: usize) -> String {
    let mut types = String::new();
    for k in 0..n {
        types.push_str(&format!(
            "<dataType name=\"T{k}\"><baseType><struct><variable name=\"m\"><type><derived name=\"T{}\"/></type></variable></struct></baseType></dataType>\n",
            k + 1
        ));
    }
    types.push_str(&format!(
        "<dataType name=\"T{n}\"><baseType><INT/></baseType></dataType>\n"
    ));
    project(&types, "", "")
}

/// A POU whose IL body is `bytes` long, escaped (`&lt;`, `&amp;`) or not.
fn big_body(bytes: usize, escaped: bool) -> String {
    let line = if escaped {
        "LD ok (* a &lt; b &amp; c *)\nST ok\n"
    } else {
        "LD ok (* a b c *)\nST ok\n"
    };
    let body = line.repeat(bytes / line.len());
    let iface = super::tests::block("localVars", "", &super::tests::var("ok", "<BOOL/>"));
    let pou = format!(
        "      <pou name=\"P\" pouType=\"program\"><interface>{iface}</interface><body><IL><xhtml:p>{body}</xhtml:p></IL></body></pou>\n"
    );
    project("", &pou, "")
}

/// Time at n and 8n, measured in this run: linear is 8x, quadratic 64x.
fn assert_linear(what: &str, small: &str, large: &str, f: impl Fn(&str)) {
    let t1 = fastest(|| f(small));
    let t8 = fastest(|| f(large));
    let ratio = t8.as_secs_f64() / t1.as_secs_f64().max(1e-9);
    assert!(
        ratio < 24.0,
        "{what}: 8x the input took {ratio:.1}x the time ({t1:?} → {t8:?})"
    );
}

#[test]
fn chains_of_structure_types_check_in_linear_time() {
    let (small, large) = (struct_chain(250), struct_chain(2000));
    let (_, d) = check(&large);
    assert!(d.is_empty(), "{d:?}");
    assert_linear("structure chain", &small, &large, |x| drop(check(x)));
}

#[test]
fn a_big_body_imports_in_linear_time_and_space() {
    for escaped in [false, true] {
        let (small, large) = (big_body(64 << 10, escaped), big_body(512 << 10, escaped));
        let imp = import(&large);
        assert!(imp.diagnostics.is_empty(), "{:?}", imp.diagnostics);
        // The body is in the IL text once, not once per POU or per line.
        assert!(
            imp.il.text.len() < large.len(),
            "{} > {}",
            imp.il.text.len(),
            large.len()
        );
        assert_linear("body", &small, &large, |x| drop(import(x)));
    }
}

/// `n` POUs in ST and a configuration with `n` instances of an IL POU.
fn many_instances(n: usize) -> String {
    let mut pous: String = (0..n)
        .map(|k| {
            format!(
                "      <pou name=\"Main{k:05}\" pouType=\"program\"><body><ST><xhtml:p>x := 1;</xhtml:p></ST></body></pou>\n"
            )
        })
        .collect();
    pous.push_str(&super::tests::il_pou(
        "Main",
        "program",
        "",
        "LD TRUE\nRET\n",
    ));
    let instances: String = (0..n)
        .map(|k| format!("<pouInstance name=\"I{k}\" typeName=\"MainIL000\"/>\n"))
        .collect();
    let cfg = format!(
        "<configuration name=\"C\"><resource name=\"R\">{instances}</resource></configuration>\n"
    );
    project("", &pous, &cfg)
}

#[test]
fn instances_find_their_pou_in_linear_time() {
    // Names of one length that differ late: a scan compares each in full.
    let (small, large) = (many_instances(500), many_instances(4000));
    let imp = import(&large);
    assert_eq!(imp.il.text.matches(" : MainIL000;").count(), 4000);
    assert_linear("instances", &small, &large, |x| drop(import(x)));
}

#[test]
fn a_body_cannot_end_its_pou_or_swallow_the_next() {
    let iface = super::tests::block("localVars", "", &super::tests::var("ok", "<BOOL/>"));
    let good = super::tests::il_pou("Good", "program", &iface, "LD ok\nST ok\n");
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
        let bad = super::tests::il_pou("Bad", "program", &iface, body);
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
    let ext = super::tests::block(
        "externalVars",
        r#" constant="true""#,
        &super::tests::var("Limit", "<INT/>"),
    );
    let pous = super::tests::il_pou("A", "functionBlock", &ext, "LD Limit\nRET\n")
        + &super::tests::il_pou("B", "functionBlock", &ext, "LD Limit\nRET\n");
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

/// A body on one XML line (line breaks written as `&#10;`), `bytes` long.
fn one_line_body(bytes: usize) -> String {
    let body = "LD ok&#10;ST ok&#10;".repeat(bytes / 20);
    let iface = super::tests::block("localVars", "", &super::tests::var("ok", "<BOOL/>"));
    let pou = format!(
        "      <pou name=\"P\" pouType=\"program\"><interface>{iface}</interface><body><IL><xhtml:p>{body}</xhtml:p></IL></body></pou>\n"
    );
    project("", &pou, "")
}

#[test]
fn xml_lines_of_a_body_on_one_line_take_linear_time() {
    let (small, large) = (
        import(&one_line_body(32 << 10)),
        import(&one_line_body(256 << 10)),
    );
    let lines = large.xml_lines();
    let body_line = large
        .xml
        .line_of(large.xml.text.find("LD ok").unwrap() as u32);
    assert!(lines.iter().filter(|&&l| l == body_line).count() > 12000);
    let t1 = fastest(|| drop(small.xml_lines()));
    let t8 = fastest(|| drop(large.xml_lines()));
    let ratio = t8.as_secs_f64() / t1.as_secs_f64().max(1e-9);
    assert!(
        ratio < 24.0,
        "8x the body took {ratio:.1}x the time ({t1:?} → {t8:?})"
    );
}
