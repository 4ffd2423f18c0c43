//! CODESYS 2.3 `.EXP` import through the public API: the project written
//! for these tests (`tests/exp/project.EXP`, Windows-1252), a project of
//! several files, bad input with located errors, and the real OWEN project
//! of `../shared/corpus/exp` (skipped, visibly, without it).

use std::path::{Path, PathBuf};

use il_codegen::diag::{Diagnostic, Severity, SourceFile};
use il_codegen::exp::{Import, Language, ObjectKind};
use il_codegen::read::{Encoding, decode};
use il_codegen::{EmitOptions, Input, Program};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn project_file() -> SourceFile {
    let bytes = std::fs::read(root().join("tests/exp/project.EXP")).expect("tests/exp/project.EXP");
    decode(
        "project.EXP",
        bytes,
        Encoding::from_label("windows-1252").unwrap(),
    )
}

fn check(files: Vec<SourceFile>) -> il_codegen::Checked {
    files
        .into_iter()
        .fold(Program::new(), Program::source)
        .check()
}

/// (code, severity, line, column) of every diagnostic of input `i`.
fn located(c: &il_codegen::Checked, i: usize) -> Vec<(&'static str, Severity, usize, usize)> {
    let src = c.inputs()[i].source();
    c.diagnostics()[i]
        .iter()
        .map(|d: &Diagnostic| {
            let (l, col) = src.line_col(d.span.lo);
            (d.code, d.severity, l, col)
        })
        .collect()
}

#[test]
fn the_project_checks_with_one_warning_for_its_st_block() {
    let c = check(vec![project_file()]);
    assert!(matches!(c.inputs()[0], Input::Exp(_)));
    assert_eq!(
        located(&c, 0),
        [("IL0401", Severity::Warning, 80, 1)],
        "{}",
        c.render(false)
    );
    let d = &c.diagnostics()[0][0];
    assert!(
        d.message.contains("`Scale` is in Structured Text"),
        "{}",
        d.message
    );
    let ir = c.ir().expect("no errors");
    let names: Vec<&str> = ir[0].pous.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["Twice", "Counter", "Scale", "PLC_PRG"]);
    let scale = &ir[0].pous[2];
    assert!(scale.host);
    // The interface only: BLINK (a library block) was a local of the ST body.
    let vars: Vec<&str> = scale.vars.iter().map(|v| v.name.as_str()).collect();
    assert_eq!(vars, ["i", "o"]);
    // PLC_PRG names the globals `total` (VAR_EXTERNAL) and `lamp` (at
    // %QX0.0), and the constants LIMIT_N and SLOTS (local constants).
    let prg = &ir[0].pous[3];
    let buffer = prg.vars.iter().find(|v| v.name == "buffer").unwrap();
    assert_eq!(buffer.ty.to_string(), "ARRAY[1..4] OF INT");
    let cfg = &ir[0].configs[0];
    assert_eq!(cfg.name, "Project");
    let globals: Vec<&str> = cfg.globals.iter().map(|v| v.name.as_str()).collect();
    // (Constants first: the bounds of the others may name them.)
    assert_eq!(globals, ["LIMIT_N", "SLOTS", "start", "lamp", "total"]);
    assert_eq!(cfg.resources[0].programs[0].program, "PLC_PRG");
    assert_eq!(cfg.resources[0].programs[0].task, None);
}

#[test]
fn the_objects_their_folders_and_languages() {
    let i = Import::new(project_file());
    let kinds: Vec<(&ObjectKind, &str, &str, Language)> = i
        .objects()
        .iter()
        .map(|o| (&o.kind, o.name.as_str(), o.path.as_str(), o.language))
        .collect();
    use il_codegen::ast::PouKind::*;
    assert_eq!(
        kinds,
        [
            (&ObjectKind::Types, "eMode", "", Language::Il),
            (&ObjectKind::Globals, "Globals", "", Language::Il),
            (&ObjectKind::Pou(Function), "Twice", "\\/Util", Language::Il),
            (
                &ObjectKind::Pou(FunctionBlock),
                "Counter",
                "\\/Util",
                Language::Il
            ),
            (&ObjectKind::Pou(FunctionBlock), "Scale", "", Language::St),
            (&ObjectKind::Pou(Program), "PLC_PRG", "", Language::Il),
        ]
    );
}

#[test]
fn generated_rust_calls_the_crates_body_of_the_st_block() {
    let c = check(vec![project_file()]);
    let files = c.files(EmitOptions::default()).expect("compiles");
    let rs = &files[0];
    let squeezed: String = rs.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        squeezed.contains("const _: fn(&mut Scale, &mut ::il_std::Cycle) = Scale;"),
        "{rs}"
    );
    assert!(squeezed.contains("Scale(self, __ctx);"), "{rs}");
    // The IL lines are shown with their EXP line numbers.
    assert!(rs.contains("// 62: LD inc"), "{rs}");
}

const GVL: &str = "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @GLOBAL_VARIABLE_LIST := 'G' *)\n(* @PATH := '' *)\nVAR_GLOBAL\n\tcount : INT;\nEND_VAR\nVAR_GLOBAL CONSTANT\n\tN : INT := 2;\nEND_VAR\n(* @OBJECT_END := 'G' *)\n";

const FB: &str = "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @PATH := '' *)\nFUNCTION_BLOCK Inc\nVAR_OUTPUT\n\tq : BOOL;\nEND_VAR\n(* @END_DECLARATION := '0' *)\nLD count\nADD 1\nST count\nGE N\nST q\nEND_FUNCTION_BLOCK\n";

const PRG: &str = "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @PATH := '' *)\nPROGRAM Main\nVAR\n\tinc : Inc;\nEND_VAR\n(* @END_DECLARATION := '0' *)\nCAL inc\nEND_PROGRAM\n";

const TASKS: &str = "\nRESOURCE\n\nTASK Fast (PRIORITY := 1, INTERVAL := T#20ms);\nMain();\n{Additional_info : 1,0,0,0,1,4294967295}\nEND_TASK\n{event_task : 'start','Called when program starts','',''}\nEND_RESOURCE\n";

#[test]
fn several_files_form_one_project() {
    let files = vec![
        SourceFile::new("G.EXP", GVL),
        SourceFile::new("Inc.EXP", FB),
        SourceFile::new("Main.EXP", PRG),
        SourceFile::new("Task configuration.EXP", TASKS),
    ];
    let c = check(files);
    assert!(!c.has_errors(), "{}", c.render(false));
    let ir = c.ir().unwrap();
    // The configuration is written with the task configuration.
    let cfg = &ir[3].configs[0];
    let r = &cfg.resources[0];
    assert_eq!(r.tasks[0].name, "Fast");
    assert_eq!(r.programs[0].name, "Main");
    assert_eq!(r.programs[0].task, Some(0));
    // Inc uses the global `count` (VAR_EXTERNAL, passed down by Main).
    let inc = &ir[1].pous[0];
    assert!(inc.vars.iter().any(|v| v.name == "count"));
    // The interpreter runs it: count counts, q rises at N.
    let m = il_interp_free_check(&c);
    assert!(m, "configuration emitted");
}

/// The configuration's Rust is emitted (the interpreter is another crate's
/// test: il-cli's `exp` runs the project).
fn il_interp_free_check(c: &il_codegen::Checked) -> bool {
    let files = c.files(EmitOptions::default()).unwrap();
    files[3].contains("pub struct Project")
}

#[test]
fn an_object_exported_twice_is_read_once_and_a_different_one_is_an_error() {
    let twice = check(vec![
        SourceFile::new("a.EXP", FB),
        SourceFile::new("b.EXP", FB),
        SourceFile::new("g.EXP", GVL),
    ]);
    assert!(!twice.has_errors(), "{}", twice.render(false));
    let other = FB.replace("ADD 1", "ADD 2");
    let c = check(vec![
        SourceFile::new("a.EXP", FB),
        SourceFile::new("b.EXP", other),
        SourceFile::new("g.EXP", GVL),
    ]);
    assert_eq!(
        located(&c, 1),
        [("IL0406", Severity::Error, 3, 1)],
        "{}",
        c.render(false)
    );
    assert!(c.diagnostics()[1][0].notes[0].contains("`a.EXP`, line 3"));
}

#[test]
fn bad_input_gets_located_errors_and_the_other_objects_are_checked() {
    // A truncated FB, an unknown header, a mismatched END_, stray text, and
    // an IL error in a sound object after them.
    let text = "(* @NESTEDCOMMENTS := 'Yes' *)\n\
FUNCTION_BLOCK Cut\nVAR_INPUT a : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD a\n\
(* @NESTEDCOMMENTS := 'Yes' *)\n(* @COLOUR := 'red' *)\n\
FUNCTION_BLOCK Wrong\nVAR_INPUT a : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD a\nEND_PROGRAM\n\
LD stray\n\
PROGRAM Sound\nVAR x : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD y\nST x\nEND_PROGRAM\n\
FUNCTION_BLOCK Open\nVAR_INPUT a : INT; END_VAR\n";
    let c = check(vec![SourceFile::new("bad.EXP", text)]);
    let got = located(&c, 0);
    let codes: Vec<(&str, usize, usize)> =
        got.iter().map(|(c, _, l, col)| (*c, *l, *col)).collect();
    assert_eq!(
        codes,
        [
            ("IL0404", 2, 1),  // Cut ends before END_FUNCTION_BLOCK
            ("IL0402", 7, 1),  // @COLOUR
            ("IL0405", 12, 1), // END_PROGRAM ends a FUNCTION_BLOCK
            ("IL0403", 13, 1), // LD stray
            ("IL0101", 17, 4), // `y` in Sound is still checked
            ("IL0404", 20, 1), // Open: the file ends
        ],
        "{}",
        c.render(false)
    );
    assert!(got.iter().all(|(_, s, _, _)| *s == Severity::Error));
}

#[test]
fn exp_is_known_by_name_or_by_its_headers() {
    use il_codegen::exp::is_exp;
    assert!(is_exp("A.EXP", ""));
    assert!(is_exp("a.exp", "PROGRAM p END_PROGRAM"));
    assert!(is_exp("a.txt", "\r\n(* @NESTEDCOMMENTS := 'Yes' *)\r\n"));
    assert!(is_exp("a", "(* @PATH := '' *)"));
    assert!(!is_exp("a.il", "(* a comment *) PROGRAM p END_PROGRAM"));
    assert!(!is_exp("a.il", ""));
}

/// Every `.EXP` of the OWEN project as one program, in Windows-1251.
#[test]
fn the_owen_project_reads_as_one_project_without_a_false_error() {
    let dir = root().join("../shared/corpus/exp/kaapyth0n_OWEN");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        eprintln!(
            "SKIPPED: {} not found: the OWEN .EXP project is not checked",
            dir.display()
        );
        return;
    };
    let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    paths.sort();
    assert_eq!(paths.len(), 89);
    let enc = Encoding::from_label("windows-1251").unwrap();
    let files: Vec<SourceFile> = paths
        .iter()
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            decode(&name, std::fs::read(p).unwrap(), enc)
        })
        .collect();
    let c = check(files);
    assert!(!c.has_errors(), "{}", c.render(false));
    let ir = c.ir().unwrap();
    // TYPEs (structures and an alias), the global lists and the task
    // configuration compile.
    let exps: Vec<&Import> = c
        .inputs()
        .iter()
        .filter_map(|i| match i {
            Input::Exp(e) => Some(&**e),
            _ => None,
        })
        .collect();
    let type_objects = exps
        .iter()
        .flat_map(|e| e.objects())
        .filter(|o| o.kind == ObjectKind::Types)
        .count();
    assert_eq!(type_objects, 16);
    // (Aliases such as `TYPE tUZSpeed : REAL;` are no Rust item.)
    let types: usize = ir.iter().map(|p| p.types.len()).sum();
    assert!(types >= 11, "{types} types");
    let cfgs: Vec<_> = ir.iter().flat_map(|p| &p.configs).collect();
    assert_eq!(cfgs.len(), 1);
    let tasks: Vec<&str> = cfgs[0].resources[0]
        .tasks
        .iter()
        .map(|t| t.name.as_str())
        .collect();
    assert_eq!(tasks, ["TaskFreewheeling", "Task200ms", "Task1Sec"]);
    let programs: Vec<&str> = cfgs[0].resources[0]
        .programs
        .iter()
        .map(|p| p.program.as_str())
        .collect();
    assert_eq!(
        programs,
        ["PLC_PRG", "GetInputs", "ModbusControl", "SetOutputs"]
    );
    assert!(cfgs[0].globals.len() > 100, "{}", cfgs[0].globals.len());
    // Every POU is ST: each is an interface, with one warning.
    let pous: Vec<_> = ir.iter().flat_map(|p| &p.pous).collect();
    assert!(pous.len() >= 40 && pous.iter().all(|p| p.host));
    let not_il = c
        .diagnostics()
        .iter()
        .flatten()
        .filter(|d| d.code == "IL0401")
        .count();
    assert_eq!(not_il, pous.len());
    // Libraries, the PLC configuration, the workspace ... are skipped.
    let skipped = exps
        .iter()
        .flat_map(|e| e.objects())
        .filter(|o| matches!(o.kind, ObjectKind::Skipped(_)))
        .count();
    assert!(skipped >= 15, "{skipped}");
}

#[test]
fn a_diagnostic_names_the_folder_and_the_file_of_a_global() {
    // A global of another file is declared in the CONFIGURATION, which the
    // file of the task configuration holds: the note says where it is.
    let gvl = GVL.replace("count : INT;", "count : NOSUCHTYPE;");
    let c = check(vec![
        SourceFile::new("G.EXP", gvl),
        SourceFile::new("Task configuration.EXP", TASKS),
        SourceFile::new("Main.EXP", PRG.replace("\tinc : Inc;\n", "")),
    ]);
    let d: Vec<&Diagnostic> = c.diagnostics().iter().flatten().collect();
    let unknown = d.iter().find(|d| d.code == "IL0105").expect("unknown type");
    assert!(
        unknown
            .notes
            .iter()
            .any(|n| n.contains("`count` is declared in `G.EXP`, line 5")),
        "{:?}",
        unknown.notes
    );
    // `@PATH := '\/Util'`: the folder is named.
    let text = FB
        .replace("(* @PATH := '' *)", "(* @PATH := '\\/Util' *)")
        .replace("LD count", "LD nothing");
    let c = check(vec![
        SourceFile::new("Inc.EXP", text),
        SourceFile::new("G.EXP", GVL),
    ]);
    let d = &c.diagnostics()[0][0];
    assert_eq!(d.code, "IL0101", "{}", c.render(false));
    assert!(
        d.notes
            .contains(&"in the project's folder `/Util`".to_string()),
        "{:?}",
        d.notes
    );
}

#[test]
fn actions_run_in_place_inside_their_own_pou() {
    // `CAL Twice` inside the block runs the action's code where it stands;
    // CALC behind a jump. Labels of the action are renamed per call.
    let fb = "FUNCTION_BLOCK Acc\nVAR_INPUT go : BOOL; END_VAR\nVAR_OUTPUT n : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nCAL Bump\nLD go\nCALC Bump\nEND_FUNCTION_BLOCK\n\nACTION Bump:\nLD n\nADD 1\nST n\nJMP out\nout:\nEND_ACTION\n";
    let prg = "PROGRAM Main\nVAR a : Acc; END_VAR\n(* @END_DECLARATION := '0' *)\nCAL a(go := TRUE)\nCAL a.Bump\nEND_PROGRAM\n";
    let c = check(vec![
        SourceFile::new("Acc.EXP", fb),
        SourceFile::new("Main.EXP", prg),
    ]);
    assert!(!c.has_errors(), "{}", c.render(false));
    let ir = c.ir().unwrap();
    let acc = &ir[0].pous[0];
    // The action's selector is an input of the block.
    assert!(acc.vars.iter().any(|v| v.name == "Bump"));
    let Input::Exp(e) = &c.inputs()[0] else {
        panic!()
    };
    assert!(e.il.text.contains("out_Bump1:"), "{}", e.il.text);
    assert!(e.il.text.contains("JMPCN Bump_skip2"), "{}", e.il.text);
    let Input::Exp(m) = &c.inputs()[1] else {
        panic!()
    };
    assert!(m.il.text.contains("CAL a(Bump := TRUE)"), "{}", m.il.text);
    // An ACTION after a FUNCTION is an error at its keyword.
    let f = "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD a\nST F\nEND_FUNCTION\nACTION A:\nLD 1\nEND_ACTION\n";
    let c = check(vec![SourceFile::new("F.EXP", f)]);
    assert_eq!(located(&c, 0), [("IL0407", Severity::Error, 7, 1)]);
}

#[test]
fn a_build_of_a_damaged_export_writes_nothing() {
    let dir = std::env::temp_dir().join(format!("il-exp-build-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("out")).unwrap();
    let good = dir.join("Inc.EXP");
    let bad = dir.join("Main.EXP");
    std::fs::write(&good, FB).unwrap();
    std::fs::write(dir.join("G.EXP"), GVL).unwrap();
    // Main is cut short: no END_PROGRAM.
    std::fs::write(&bad, PRG.replace("END_PROGRAM\n", "")).unwrap();
    let e = il_codegen::Builder::new()
        .file(&good)
        .file(dir.join("G.EXP"))
        .file(&bad)
        .out_dir(dir.join("out"))
        .compile()
        .unwrap_err();
    assert!(e.to_string().contains("IL0404"), "{e}");
    assert!(e.to_string().contains("Main.EXP:3:1"), "{e}");
    let written: Vec<_> = std::fs::read_dir(dir.join("out")).unwrap().collect();
    assert!(written.is_empty(), "{written:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn mangled_exports_never_panic() {
    // Every cut of the test project, and bytes of other objects spliced
    // in, go through the whole pipeline: diagnostics, never a panic.
    let text = project_file().text;
    let bounds: Vec<usize> = (0..=text.len())
        .filter(|&k| text.is_char_boundary(k))
        .step_by(13)
        .collect();
    for &k in &bounds {
        let cut = &text[..k];
        let c = check(vec![SourceFile::new("cut.EXP", cut)]);
        let _ = c.diagnostics();
        let spliced = format!("{}\nEND_ACTION\n(* @PATH := '' *)\n{}", cut, &text[k / 2..]);
        let c = check(vec![
            SourceFile::new("a.EXP", spliced),
            SourceFile::new("b.EXP", &text[k..]),
        ]);
        for (input, diags) in c.reports() {
            for d in diags {
                // Every span is inside its file.
                assert!(d.span.hi as usize <= input.source().text.len(), "{d:?}");
            }
        }
    }
}

#[test]
fn a_var_config_of_a_global_list_is_left_out_with_a_warning() {
    let text = "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @GLOBAL_VARIABLE_LIST := 'Variable_Configuration' *)\nVAR_CONFIG\n\tPLC_PRG.q AT %QX0.0 : BOOL;\nEND_VAR\n(* @OBJECT_END := 'Variable_Configuration' *)\n";
    let c = check(vec![SourceFile::new("VC.EXP", text)]);
    assert_eq!(located(&c, 0), [("IL0409", Severity::Warning, 3, 1)]);
}

#[test]
fn a_syntax_error_in_one_object_leaves_the_others_checked() {
    let text = "(* @NESTEDCOMMENTS := 'Yes' *)\nFUNCTION_BLOCK Broken\nVAR_INPUT a : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD a +\nEND_FUNCTION_BLOCK\n\
(* @NESTEDCOMMENTS := 'Yes' *)\nPROGRAM Sound\nVAR x : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD y\nST x\nEND_PROGRAM\n";
    let c = check(vec![SourceFile::new("two.EXP", text)]);
    let codes: Vec<(&str, usize)> = located(&c, 0).iter().map(|(c, _, l, _)| (*c, *l)).collect();
    assert_eq!(codes.len(), 2, "{}", c.render(false));
    assert_eq!(codes[0].1, 5, "{}", c.render(false));
    assert_eq!(codes[1], ("IL0101", 11), "{}", c.render(false));
}

#[test]
fn a_function_that_reads_a_global_gets_a_note() {
    let f = "FUNCTION Get : INT\nVAR_INPUT a : INT; END_VAR\n(* @END_DECLARATION := '0' *)\nLD count\nADD N\nST Get\nEND_FUNCTION\n";
    let c = check(vec![
        SourceFile::new("G.EXP", GVL),
        SourceFile::new("F.EXP", f),
    ]);
    let d = &c.diagnostics()[1];
    // N is CONSTANT: a local constant, fine in a FUNCTION; count is not.
    assert_eq!(d.len(), 1, "{}", c.render(false));
    assert_eq!(d[0].code, "IL0101");
    assert!(
        d[0].notes
            .iter()
            .any(|n| n.contains("`count` is a global of this project")),
        "{:?}",
        d[0].notes
    );
}
