//! Without the `plcopen` feature an XML source is one error that says how to
//! turn the feature on (the binary needs `build`: `cargo test -p il-codegen
//! --no-default-features --features build --test all not_built`).

use il_codegen::Program;
use il_codegen::diag::SourceFile;
use il_codegen::plcopen::codes::NOT_BUILT;

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
