//! The PLCopen XML the import tests are written in: a project around data
//! types, POUs and configurations, POUs with an IL body, variable blocks,
//! and the hostile template (every attribute that reaches the IL text a
//! placeholder) with random edits of it.
//!
//! Plain text and std only: the importer's own unit test (the one that reads
//! the lexer's tokens, `src/plcopen/tests.rs`) includes this file too.

pub const HEAD: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="t"/>
"#;

/// A project with `data_types` inside `<dataTypes>`, `pous` inside
/// `<pous>` and `instances` inside `<instances><configurations>`.
pub fn project(data_types: &str, pous: &str, configurations: &str) -> String {
    format!(
        "{HEAD}  <types>\n    <dataTypes>\n{data_types}    </dataTypes>\n    <pous>\n{pous}    </pous>\n  </types>\n  <instances>\n    <configurations>\n{configurations}    </configurations>\n  </instances>\n</project>\n"
    )
}

/// A POU with an IL body given as CDATA.
pub fn il_pou(name: &str, kind: &str, interface: &str, body: &str) -> String {
    format!(
        "      <pou name=\"{name}\" pouType=\"{kind}\">\n        <interface>\n{interface}        </interface>\n        <body>\n          <IL>\n            <xhtml:p><![CDATA[{body}]]></xhtml:p>\n          </IL>\n        </body>\n      </pou>\n"
    )
}

pub fn var(name: &str, ty: &str) -> String {
    format!("            <variable name=\"{name}\"><type>{ty}</type></variable>\n")
}

pub fn var_init(name: &str, ty: &str, init: &str) -> String {
    format!(
        "            <variable name=\"{name}\"><type>{ty}</type><initialValue>{init}</initialValue></variable>\n"
    )
}

pub fn block(kind: &str, attrs: &str, vars: &str) -> String {
    format!("          <{kind}{attrs}>\n{vars}          </{kind}>\n")
}

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
pub fn template(set: (&str, &str)) -> String {
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

/// What the random edits of [`mutated_projects`] write: quotes, markup,
/// keywords, comment openers, entities.
const PIECES: &[&str] = &[
    "\"",
    "'",
    "<",
    ">",
    "&#10;",
    ";",
    "(*",
    "*)",
    "END_VAR",
    "</a>",
    "<a b='1'>",
    "]",
    "[",
    "(",
    ")",
    ":=",
    "é",
    "\u{202e}",
    "%IX",
    "T#",
    "#",
    "$",
    "''",
    "/>",
    "<!--",
    "-->",
    "<![CDATA[",
    "]]>",
    "xmlns:q='u' ",
    " x='1'",
    "&amp;",
    "&",
    "",
    "&#10;END_PROGRAM&#10;PROGRAM Evil&#10;",
    "\nEND_PROGRAM\nPROGRAM Evil\n",
    "END_TYPE",
    "END_CONFIGURATION",
];

/// `n` random edits of the template (one to four pieces of [`PIECES`], each
/// over up to five characters), the same every run: a fixed LCG.
pub fn mutated_projects(n: usize) -> impl Iterator<Item = String> {
    let base = template(("", ""));
    let mut seed: u64 = 0x9876_5431;
    let mut rnd = move |n: usize| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 33) as usize) % n.max(1)
    };
    (0..n).map(move |_| {
        let mut x = base.clone();
        for _ in 0..(1 + rnd(4)) {
            let mut at = rnd(x.len());
            while !x.is_char_boundary(at) {
                at -= 1;
            }
            let mut end = (at + rnd(6)).min(x.len());
            while !x.is_char_boundary(end) {
                end -= 1;
            }
            x.replace_range(at..end.max(at), PIECES[rnd(PIECES.len())]);
        }
        x
    })
}
