//! Without the `plcopen` feature an XML source (and an M221 listing) is one
//! error that says how to turn the feature on; without `exp`, a CODESYS
//! export is (as `il!` builds the compiler; CI: `cargo test -p il-codegen
//! --no-default-features --test all not_built`).

use il_codegen::Program;
use il_codegen::diag::SourceFile;
#[cfg(not(feature = "plcopen"))]
use il_codegen::plcopen::codes::NOT_BUILT;

#[cfg(not(feature = "plcopen"))]
#[test]
fn an_xml_source_is_one_error_that_names_the_feature() {
    // Known by its text too: not 200 IL errors about `<`.
    let other = SourceFile::new(
        "plc/cell.plcprj",
        "\u{feff}\n<?xml version=\"1.0\"?><project/>".to_string(),
    );
    let checked = Program::new().source(other).check();
    let d = &checked.diagnostics()[0];
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code, NOT_BUILT);
    assert!(d[0].message.contains("plc/cell.plcprj"), "{d:?}");
    let xml = SourceFile::new(
        "plc/cell.xml",
        "<?xml version=\"1.0\"?><project/>".to_string(),
    );
    let checked = Program::new().source(xml).check();
    let diags: Vec<_> = checked
        .reports()
        .flat_map(|(_, d)| d.iter().cloned())
        .collect();
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0].code, NOT_BUILT);
    assert!(
        diags[0].message.contains("plc/cell.xml"),
        "{}",
        diags[0].message
    );
    assert!(
        diags[0]
            .notes
            .iter()
            .any(|n| n.contains("`plcopen` feature")),
        "{:?}",
        diags[0].notes
    );
    assert!(checked.emit(Default::default()).is_none());
}

#[cfg(not(feature = "plcopen"))]
#[test]
fn an_m221_listing_is_one_error_that_names_the_feature() {
    // The M221 translation is the `plcopen` feature's.
    let listing = SourceFile::new("plc/cell.il", "LD %I0.0\nST %Q0.0\n".to_string());
    let checked = Program::new()
        .input(il_codegen::Dialect::M221.input(listing))
        .check();
    let diags: Vec<_> = checked
        .reports()
        .flat_map(|(_, d)| d.iter().cloned())
        .collect();
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0].code, NOT_BUILT);
    assert!(
        diags[0]
            .message
            .contains("an M221 listing (`--dialect m221`)"),
        "{}",
        diags[0].message
    );
    assert!(
        diags[0]
            .notes
            .iter()
            .any(|n| n.contains("`plcopen` feature")),
        "{:?}",
        diags[0].notes
    );
}

#[cfg(not(feature = "exp"))]
#[test]
fn an_export_is_one_error_that_names_the_feature() {
    let exp = SourceFile::new(
        "project.EXP",
        "(* @NESTEDCOMMENTS := 'Yes' *)\nPROGRAM P\nVAR x : INT; END_VAR\nLD 1\nST x\nEND_PROGRAM\n",
    );
    let checked = Program::new().source(exp).check();
    let diags: Vec<_> = checked
        .reports()
        .flat_map(|(_, d)| d.iter().cloned())
        .collect();
    // One error at the file's start, not the IL checker's view of the export.
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!((diags[0].code, diags[0].span.lo), ("IL0410", 0));
    assert!(
        diags[0].message.contains("project.EXP"),
        "{}",
        diags[0].message
    );
    assert!(
        diags[0]
            .notes
            .iter()
            .any(|n| n.contains("features = [\"exp\"]")),
        "{:?}",
        diags[0].notes
    );
    assert!(checked.emit(Default::default()).is_none());
}
