//! Without the `plcopen` feature an XML source (and an M221 listing) is one
//! error that says how to turn the feature on; without `exp`, a CODESYS
//! export is (as `il!` builds the compiler; CI: `cargo test -p il-codegen
//! --no-default-features --test all not_built`).

#![allow(dead_code)] // with both features on, no test here uses the helper

use il_codegen::diag::{Diagnostic, SourceFile};
use il_codegen::{Checked, Input, Program};

/// The one diagnostic of `input`, at the file's start, with `code`, a
/// message naming `name` and a note naming `feature`; nothing emitted.
fn the_one_error(input: Input, code: &str, name: &str, feature: &str) -> Diagnostic {
    let checked: Checked = Program::new().input(input).check();
    let diags: Vec<_> = (checked.reports())
        .flat_map(|(_, d)| d.iter().cloned())
        .collect();
    // Not the IL checker's view of the text: 200 errors about `<`.
    let [d] = &diags[..] else { panic!("{diags:?}") };
    assert_eq!((d.code, d.span.lo), (code, 0), "{d:?}");
    assert!(d.message.contains(name), "{}", d.message);
    let wanted = format!("features = [\"{feature}\"]");
    assert!(d.notes.iter().any(|n| n.contains(&wanted)), "{:?}", d.notes);
    assert!(checked.emit(Default::default()).is_none());
    d.clone()
}

#[cfg(not(feature = "plcopen"))]
#[test]
fn an_xml_source_is_one_error_that_names_the_feature() {
    // Known by its text, whatever its name, and by a `.xml` name.
    let other = SourceFile::new(
        "plc/cell.plcprj",
        "\u{feff}\n<?xml version=\"1.0\"?><project/>",
    );
    the_one_error(
        Input::by_content(other),
        "IL0210",
        "plc/cell.plcprj",
        "plcopen",
    );
    let xml = SourceFile::new("plc/cell.xml", "<?xml version=\"1.0\"?><project/>");
    the_one_error(Input::by_content(xml), "IL0210", "plc/cell.xml", "plcopen");
}

#[cfg(not(feature = "plcopen"))]
#[test]
fn an_m221_listing_is_one_error_that_names_the_feature() {
    // The M221 translation is the `plcopen` feature's.
    let listing = SourceFile::new("plc/cell.il", "LD %I0.0\nST %Q0.0\n");
    let input = il_codegen::Dialect::M221.input(listing);
    let d = the_one_error(input, "IL0210", "plc/cell.il", "plcopen");
    assert!(
        d.message.contains("an M221 listing (`--dialect m221`)"),
        "{}",
        d.message
    );
}

#[cfg(not(feature = "exp"))]
#[test]
fn an_export_is_one_error_that_names_the_feature() {
    let exp = SourceFile::new(
        "project.EXP",
        "(* @NESTEDCOMMENTS := 'Yes' *)\nPROGRAM P\nVAR x : INT; END_VAR\nLD 1\nST x\nEND_PROGRAM\n",
    );
    the_one_error(Input::by_content(exp), "IL0410", "project.EXP", "exp");
}
