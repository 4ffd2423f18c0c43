//! LogicLab / Arduino PLC IDE projects (`.plcprj`) through the public API:
//! the project written for these tests (`tests/logiclab/project.plcprj`),
//! small projects for each rule, and bad input with located errors.

use std::path::{Path, PathBuf};

use il_codegen::diag::{Severity, SourceFile};
use il_codegen::{EmitOptions, Input, Program};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn project_file() -> SourceFile {
    let text = std::fs::read_to_string(root().join("tests/logiclab/project.plcprj"))
        .expect("tests/logiclab/project.plcprj");
    SourceFile::new("project.plcprj", text)
}

fn check(file: SourceFile) -> il_codegen::Checked {
    Program::new().source(file).check()
}

/// (code, severity, line, column) of every diagnostic.
fn located(c: &il_codegen::Checked) -> Vec<(&'static str, Severity, usize, usize)> {
    let src = c.inputs()[0].source();
    c.diagnostics()[0]
        .iter()
        .map(|d| {
            let (l, col) = src.line_col(d.span.lo);
            (d.code, d.severity, l, col)
        })
        .collect()
}

/// A project whose `<main>` holds `main` and whose one library holds `lib`.
fn project(main: &str, lib: &str) -> SourceFile {
    SourceFile::new(
        "t.plcprj",
        format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<plcProject version=\"2.11\">\n<sources>\n<main>\n{main}\n</main>\n<libraries>\n<lib name=\"C:\\libs\\Lib.plclib\" fullXml=\"true\" link=\"true\">\n{lib}\n</lib>\n</libraries>\n</sources>\n</plcProject>\n"
        ),
    )
}

const IL_PROGRAM: &str = "<programs><program name=\"Main\"><vars><localVars><var name=\"x\" type=\"INT\"/></localVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tLD\t1\n\tST\tx\n]]></sourceCode></program></programs>";

#[test]
fn the_project_checks_with_one_warning_per_thing_not_compiled_as_written() {
    let c = check(project_file());
    assert!(matches!(c.inputs()[0], Input::PlcOpen(_)));
    assert_eq!(
        located(&c),
        [
            ("IL0424", Severity::Warning, 29, 7),
            ("IL0420", Severity::Warning, 108, 26),
            ("IL0423", Severity::Warning, 225, 4),
            ("IL0425", Severity::Warning, 252, 20),
        ],
        "{}",
        c.render(false)
    );
    let msgs: Vec<&str> = c.diagnostics()[0]
        .iter()
        .map(|d| d.message.as_str())
        .collect();
    assert!(
        msgs[1].contains("`Scale` is in Structured Text (ST)"),
        "{msgs:?}"
    );
    assert!(
        msgs[2].starts_with("1 function block(s) of library `MyLib.plclib` that the project uses have standard blocks' names: `TON`"),
        "{msgs:?}"
    );
    assert!(
        msgs[3].contains("`sysTimer` is no global of the project"),
        "{msgs:?}"
    );
    let files = c.emit(EmitOptions::default()).expect("no errors: emitted");
    let rust = &files[0].text;
    // The ST block is host-provided; the unused EMBEDDED function of the
    // library is not written at all (it would ask the crate for a body).
    assert!(rust.contains("Host `FUNCTION_BLOCK` `Scale`"), "{rust}");
    assert!(!rust.contains("sysLog"), "{rust}");
    // The library's IL blocks the project uses are compiled, its TON under
    // another name than the standard block's.
    assert!(rust.contains("pub struct EdgeCounter"), "{rust}");
    assert!(rust.contains("pub struct TON_LogicLab"), "{rust}");
}

#[test]
fn diagnostics_of_the_il_point_into_the_xml_body() {
    let main = IL_PROGRAM.replace("ST\tx", "ST\ty");
    let c = check(project(&main, ""));
    let d = c.diagnostics()[0]
        .iter()
        .find(|d| d.code == "IL0101")
        .unwrap_or_else(|| panic!("{}", c.render(false)));
    let src = c.inputs()[0].source();
    assert_eq!(src.snippet(d.span), "y");
    assert_eq!(src.line_col(d.span.lo), (7, 5));
}

#[test]
fn a_library_used_for_a_non_il_block_gets_one_warning_and_an_unused_one_none() {
    let main = "<programs><program name=\"Main\"><vars><localVars><var name=\"c\" type=\"Clock\"/><var name=\"q\" type=\"BOOL\"/></localVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tCAL\tc(period := 5)\n\tLD\tc.out\n\tST\tq\n\tLD\t3\n\tFwAbs\n\tST\tc.period\n]]></sourceCode></program></programs>";
    let lib = "<functions><function name=\"FwAbs\"><returnValue>INT</returnValue><vars><inputVars><var name=\"v\" type=\"INT\"/></inputVars></vars><sourceCode type=\"EMBEDDED\"/></function><function name=\"FwUnused\"><returnValue>INT</returnValue><sourceCode type=\"EMBEDDED\"/></function></functions><functionBlocks><functionBlock name=\"Clock\"><vars><inputVars><var name=\"period\" type=\"INT\"/></inputVars><outputVars><var name=\"out\" type=\"BOOL\"/></outputVars><localVars><var name=\"n\" type=\"INT\"/></localVars></vars><sourceCode type=\"ST\"><![CDATA[out := TRUE;]]></sourceCode></functionBlock></functionBlocks>";
    let c = check(project(main, lib));
    let d = &c.diagnostics()[0];
    assert_eq!(d.len(), 1, "{}", c.render(false));
    assert_eq!(d[0].code, "IL0420");
    assert_eq!(
        d[0].message,
        "2 POU(s) of library `Lib.plclib` that the project uses are not in IL: `FwAbs`, `Clock`; their interfaces are compiled, their bodies are host-provided"
    );
    assert!(!c.has_errors());
}

#[test]
fn globals_are_seen_without_var_external_and_constants_become_local_constants() {
    let main = "<globalVars><group name=\"G\"><var name=\"g\" type=\"INT\"/></group></globalVars><constantVars><group name=\"K\"><const name=\"K1\" type=\"INT\"><initValue>7</initValue></const></group></constantVars><functions><function name=\"F\"><returnValue>INT</returnValue><vars><inputVars><var name=\"a\" type=\"INT\"/></inputVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tLD\ta\n\tADD\tK1\n\tST\tF\n]]></sourceCode></function></functions><programs><program name=\"Main\"><vars/><sourceCode type=\"IL\"><![CDATA[\n\tLD\tg\n\tF\n\tST\tg\n]]></sourceCode></program></programs>";
    let c = check(project(main, ""));
    assert!(c.diagnostics()[0].is_empty(), "{}", c.render(false));
    let Input::PlcOpen(imp) = &c.inputs()[0] else {
        panic!("XML import")
    };
    let il = &imp.il.text;
    assert!(il.contains("VAR_EXTERNAL\n\tg : INT;\nEND_VAR"), "{il}");
    assert!(
        il.contains("VAR CONSTANT\n\tK1 : INT := 7;\nEND_VAR"),
        "{il}"
    );
    assert!(il.contains("CONFIGURATION Project\nVAR_GLOBAL\n\tg : INT;\nEND_VAR\nVAR_GLOBAL CONSTANT\n\tK1 : INT := 7;\nEND_VAR\nEND_CONFIGURATION"), "{il}");
}

#[test]
fn a_plclib_on_its_own_is_read_as_a_library() {
    let text = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n<plcLibrary schemaVersion=\"2.8\">\n<lib version=\"1.0.0\" name=\"L\" fullXml=\"true\">\n{IL_PROGRAM}\n</lib>\n</plcLibrary>\n"
    );
    let c = check(SourceFile::new("L.plclib", text));
    assert!(c.diagnostics()[0].is_empty(), "{}", c.render(false));
    assert_eq!(
        c.emit(EmitOptions::default()).expect("emitted")[0].pous,
        ["Main"]
    );
}

#[test]
fn bad_projects_get_located_errors_and_nothing_is_emitted() {
    let cases: &[(&str, &str, &str, &str)] = &[
        // (what, main, code, message part)
        (
            "a body that ends its POU",
            "<programs><program name=\"Main\"><vars/><sourceCode type=\"IL\"><![CDATA[\n\tLD\t1\nEND_PROGRAM\nPROGRAM Evil\n]]></sourceCode></program></programs>",
            "IL0209",
            "reaches outside its POU",
        ),
        (
            "a name that is no identifier",
            "<programs><program name=\"Main\"><vars><localVars><var name=\"x; END_VAR\" type=\"INT\"/></localVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tLD\t1\n]]></sourceCode></program></programs>",
            "IL0422",
            "is not an IEC identifier",
        ),
        (
            "an array of no element",
            "<globalVars><group name=\"G\"><var name=\"a\" type=\"INT\" dim0=\"0\"/></group></globalVars>",
            "IL0422",
            "is not a positive number",
        ),
        (
            "a FUNCTION without result",
            "<functions><function name=\"F\"><vars/><sourceCode type=\"IL\"><![CDATA[\n\tLD\t1\n]]></sourceCode></function></functions>",
            "IL0421",
            "has no valid `<returnValue>`",
        ),
        (
            "an initial value that is code",
            "<globalVars><group name=\"G\"><var name=\"a\" type=\"INT\"><initValue>1; END_VAR</initValue></var></group></globalVars>",
            "IL0422",
            "the initial value",
        ),
        (
            "an enumeration without elements",
            "<enums><enum name=\"E\"><elements/></enum></enums>",
            "IL0421",
            "has no elements",
        ),
        (
            "a task interval that is no duration",
            "<resources><resource name=\"R\"><task name=\"Fast\" interval=\"10 ms\" priority=\"0\" type=\"cyclic\"/></resource></resources><tasks><task name=\"Fast\"><program>Main</program></task></tasks>{IL}",
            "IL0422",
            "which is not a duration",
        ),
        (
            "a name with a bidirectional control",
            "<programs><program name=\"Ma\u{202E}in\"><vars/><sourceCode type=\"IL\"><![CDATA[\n\tLD\t1\n]]></sourceCode></program></programs>",
            "IL0422",
            "control character U+202E",
        ),
        (
            "a task name that is code",
            "<resources><resource name=\"R\"><task name=\"Fast(); END_RESOURCE\" interval=\"t#10ms\" priority=\"0\" type=\"cyclic\"/></resource></resources><tasks><task name=\"Fast(); END_RESOURCE\"><program>Main</program></task></tasks>{IL}",
            "IL0422",
            "is not an IEC identifier",
        ),
    ];
    for (what, main, code, part) in cases {
        let main = main.replace("{IL}", IL_PROGRAM);
        let c = check(project(&main, ""));
        let src = c.inputs()[0].source();
        let d = c.diagnostics()[0]
            .iter()
            .find(|d| d.code == *code && d.is_error())
            .unwrap_or_else(|| panic!("{what}: {}", c.render(false)));
        assert!(d.message.contains(part), "{what}: {}", d.message);
        assert!(
            d.span.lo > 0 && (d.span.hi as usize) <= src.text.len(),
            "{what}"
        );
        assert!(c.emit(EmitOptions::default()).is_none(), "{what}");
    }
}

#[test]
fn what_is_not_translated_is_a_located_warning() {
    let main = format!(
        "<resources><resource name=\"R\"><task name=\"Ev\" type=\"event\" priority=\"0\"/><task name=\"Fast\" interval=\"t#10ms\" priority=\"0\" type=\"cyclic\"/></resource></resources><tasks><task name=\"Ev\"><program>Main</program></task><task name=\"Fast\"><program>Nowhere</program></task></tasks>{IL_PROGRAM}<macros><macro name=\"M\"/></macros>"
    );
    let text = project(&main, "").text.replace(
        "fullXml=\"true\" link=\"true\">",
        "fullXml=\"false\" link=\"true\"><![CDATA[FUNCTION F : INT END_FUNCTION]]>",
    );
    let c = check(SourceFile::new("t.plcprj", text));
    let codes: Vec<&str> = c.diagnostics()[0].iter().map(|d| d.code).collect();
    assert_eq!(codes, ["IL0426"; 4], "{}", c.render(false));
    assert!(!c.has_errors());
}

#[test]
fn a_logiclab_3_project_says_how_to_save_it() {
    let text = "<?xml version=\"1.0\" encoding=\"UTF-16\"?>\n<plcProject>\n<sources>\n<main><![CDATA[PROGRAM Main\nEND_PROGRAM]]></main>\n</sources>\n</plcProject>\n";
    let c = check(SourceFile::new("old.ppjs", text));
    assert_eq!(
        located(&c),
        [("IL0421", Severity::Error, 4, 1)],
        "{}",
        c.render(false)
    );
    assert!(
        c.diagnostics()[0][0]
            .help
            .as_deref()
            .unwrap_or("")
            .contains(".plcprj")
    );
}

#[test]
fn mangled_projects_never_panic() {
    // Every cut of the test project, and its second half spliced into its
    // first: diagnostics inside the file, never a panic.
    let text = project_file().text;
    let bounds: Vec<usize> = (0..=text.len())
        .filter(|&k| text.is_char_boundary(k))
        .step_by(41)
        .collect();
    for &k in &bounds {
        for t in [
            text[..k].to_string(),
            format!("{}{}", &text[..k], &text[k / 2..]),
        ] {
            let c = check(SourceFile::new("cut.plcprj", t));
            for (input, diags) in c.reports() {
                for d in diags {
                    assert!(d.span.hi as usize <= input.source().text.len(), "{d:?}");
                }
            }
            if k < text.len() && c.has_errors() {
                assert!(c.emit(EmitOptions::default()).is_none());
            }
        }
    }
}

#[test]
fn what_logiclab_excludes_from_the_build_is_left_out() {
    // The excluded POU, type and group would not compile: they are not read.
    let main = format!(
        "<globalVars><group name=\"Off\" excludeFromBuild=\"TRUE\"><var name=\"bad\" type=\"NoSuchType\"/></group></globalVars><structs><struct name=\"S\" excludeFromBuild=\"TRUE\"><vars><var name=\"m\" type=\"NoSuchType\"/></vars></struct></structs>{}",
        IL_PROGRAM.replace(
            "</programs>",
            "<program name=\"Old\" excludeFromBuild=\"TRUE\"><vars/><sourceCode type=\"IL\"><![CDATA[\n\tLD\tnowhere\n]]></sourceCode></program></programs>"
        )
    );
    let c = check(project(&main, ""));
    assert!(c.diagnostics()[0].is_empty(), "{}", c.render(false));
    assert_eq!(
        c.emit(EmitOptions::default()).expect("emitted")[0].pous,
        ["Main"]
    );
}

#[test]
fn methods_of_a_block_are_a_warning() {
    let main = "<functionBlocks><functionBlock name=\"Fb\"><vars><inputVars><var name=\"a\" type=\"INT\"/></inputVars></vars><methods><method name=\"Reset\"/></methods><sourceCode type=\"IL\"><![CDATA[\n\tLD\ta\n]]></sourceCode></functionBlock></functionBlocks>";
    let c = check(project(main, ""));
    assert_eq!(
        located(&c),
        [("IL0426", Severity::Warning, 5, 104)],
        "{}",
        c.render(false)
    );
}

#[test]
fn a_build_of_a_damaged_project_writes_nothing() {
    let dir = std::env::temp_dir().join(format!("il-logiclab-build-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("out")).unwrap();
    // The test project with one IL body that ends its POU early.
    let damaged = project_file()
        .text
        .replace("\tST\tBoots\n", "\tST\tBoots\nEND_PROGRAM\nPROGRAM Evil\n");
    let prj = dir.join("project.plcprj");
    std::fs::write(&prj, damaged).unwrap();
    let e = il_codegen::Builder::new()
        .file(&prj)
        .out_dir(dir.join("out"))
        .compile()
        .unwrap_err();
    assert!(e.to_string().contains("IL0209"), "{e}");
    assert!(e.to_string().contains("project.plcprj:180:1"), "{e}");
    let written: Vec<_> = std::fs::read_dir(dir.join("out")).unwrap().collect();
    assert!(written.is_empty(), "{written:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_block_of_a_standard_name_is_compiled_renamed_and_a_function_left_out() {
    let main = "<functions><function name=\"LIMIT\"><returnValue>INT</returnValue><vars><inputVars><var name=\"a\" type=\"INT\"/></inputVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tLD\ta\n\tST\tLIMIT\n]]></sourceCode></function></functions><functionBlocks><functionBlock name=\"R_TRIG\"><vars><inputVars><var name=\"clk\" type=\"BOOL\"/></inputVars><outputVars><var name=\"q\" type=\"BOOL\"/></outputVars><localVars><var name=\"m\" type=\"BOOL\"/></localVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tLD\tclk\n\tANDN\tm\n\tST\tq\n\tLD\tclk\n\tST\tm\n]]></sourceCode></functionBlock></functionBlocks><programs><program name=\"Main\"><vars><localVars><var name=\"e\" type=\"R_TRIG\"/><var name=\"x\" type=\"INT\"/></localVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tCAL\te(clk := TRUE)\n\tLD\t5\n\tLIMIT\t0, 3\n\tST\tx\n]]></sourceCode></program></programs>";
    let c = check(project(main, ""));
    let msgs: Vec<(&str, &str)> = c.diagnostics()[0]
        .iter()
        .map(|d| (d.code, d.message.as_str()))
        .collect();
    assert_eq!(
        msgs,
        [
            (
                "IL0423",
                "FUNCTION `LIMIT` of this project has the name of a standard function: il-std's is used instead"
            ),
            (
                "IL0423",
                "FUNCTION_BLOCK `R_TRIG` of this project has the name of a standard function block: compiled as `R_TRIG_LogicLab`, the type of the project's variables of type `R_TRIG`"
            ),
        ],
        "{}",
        c.render(false)
    );
    let files = c.emit(EmitOptions::default()).expect("emitted");
    assert!(
        files[0].text.contains("pub e: R_TRIG_LogicLab"),
        "{}",
        files[0].text
    );
}

#[test]
fn a_diagnostic_in_a_pou_of_a_folder_names_the_folder() {
    let main = IL_PROGRAM.replace("ST\tx", "ST\ty");
    let text = project(&main, "").text.replace(
        "</libraries>",
        "</libraries>\n<workspace><root name=\"t\"><Pou name=\"Other\"/><folder name=\"Lib\"><folder name=\"Time\"><Pou name=\"Main\"/></folder></folder></root></workspace>",
    );
    let c = check(SourceFile::new("t.plcprj", text));
    let d = &c.diagnostics()[0];
    assert_eq!(d.len(), 1, "{}", c.render(false));
    assert_eq!(d[0].notes, ["in the project's folder `Lib/Time`"]);
}

/// `n` IL blocks in a folder, each using its global and a library block,
/// `n` programs holding one each, run by a task, and one unknown name in
/// each program (a diagnostic with its folder's note).
fn many(n: usize) -> SourceFile {
    let mut globals = String::new();
    let mut fbs = String::new();
    let mut prgs = String::new();
    let mut runs = String::new();
    let mut tree = String::new();
    for k in 0..n {
        globals.push_str(&format!("<var name=\"g{k}\" type=\"INT\"/>"));
        fbs.push_str(&format!("<functionBlock name=\"Fb{k}\"><vars><localVars><var name=\"c\" type=\"Counter\"/></localVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tCAL\tc\n\tLD\tg{k}\n\tADD\t1\n\tST\tg{k}\n]]></sourceCode></functionBlock>"));
        prgs.push_str(&format!("<program name=\"P{k}\"><vars><localVars><var name=\"f\" type=\"Fb{k}\"/></localVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tCAL\tf\n\tLD\tnowhere{k}\n]]></sourceCode></program>"));
        runs.push_str(&format!("<program>P{k}</program>"));
        tree.push_str(&format!(
            "<folder name=\"F{k}\"><Pou name=\"P{k}\"/><Pou name=\"Fb{k}\"/></folder>"
        ));
    }
    let main = format!(
        "<resources><resource name=\"R\"><task name=\"Fast\" interval=\"t#10ms\" priority=\"0\" type=\"cyclic\"/></resource></resources><tasks><task name=\"Fast\">{runs}</task></tasks><globalVars><group name=\"G\">{globals}</group></globalVars><functionBlocks>{fbs}</functionBlocks><programs>{prgs}</programs>"
    );
    let lib = "<functionBlocks><functionBlock name=\"Counter\"><vars><outputVars><var name=\"n\" type=\"INT\"/></outputVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tLD\tn\n\tADD\t1\n\tST\tn\n]]></sourceCode></functionBlock></functionBlocks>";
    let text = project(&main, lib).text.replace(
        "</libraries>",
        &format!("</libraries><workspace><root name=\"t\">{tree}</root></workspace>"),
    );
    SourceFile::new("many.plcprj", text)
}

#[test]
fn a_project_of_many_pous_checks_in_linear_steps() {
    let _quiet = crate::plcopen_limits::quiet();
    let steps = |n: usize| {
        let file = many(n);
        let s0 = il_codegen::step_counter::steps();
        let c = check(file);
        let s = il_codegen::step_counter::steps() - s0;
        // One error per program (as many as a file shows), in its folder.
        let d = &c.diagnostics()[0];
        assert!(d.iter().filter(|d| d.code == "IL0101").count() >= n.min(100));
        assert!(
            d[0].notes
                .iter()
                .any(|n| n.starts_with("in the project's folder `F"))
        );
        s
    };
    let (s1, s8) = (steps(40), steps(320));
    let ratio = s8 as f64 / s1.max(1) as f64;
    println!("8x the POUs took {ratio:.1}x the steps ({s1} → {s8})");
    assert!(
        ratio < 12.0,
        "8x the POUs took {ratio:.1}x the steps ({s1} → {s8})"
    );
}

#[test]
fn a_function_naming_a_global_is_told_why_it_does_not_see_it() {
    let main = "<globalVars><group name=\"G\"><var name=\"g\" type=\"INT\"/></group></globalVars><functions><function name=\"F\"><returnValue>INT</returnValue><vars><inputVars><var name=\"a\" type=\"INT\"/></inputVars></vars><sourceCode type=\"IL\"><![CDATA[\n\tLD\tg\n\tST\tF\n]]></sourceCode></function></functions>";
    let c = check(project(main, ""));
    let d = &c.diagnostics()[0];
    assert_eq!(d.len(), 1, "{}", c.render(false));
    assert_eq!(d[0].code, "IL0101");
    assert!(
        d[0].notes[0].starts_with("`g` is a global of this project: a PROGRAM or FUNCTION_BLOCK sees it, a FUNCTION does not"),
        "{:?}",
        d[0].notes
    );
}
