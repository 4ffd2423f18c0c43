//! The import test that reads the lexer's tokens, which are no public API;
//! the other import tests are tests/all/plcopen_*.rs, in whose XML this one
//! is written too.

// The builders the other topics use as well.
#[allow(dead_code)]
#[path = "../../tests/all/plcopen_xml.rs"]
mod xml;

use super::Import;
use crate::diag::SourceFile;
use crate::syntax::lexer::{Tok, lex};

/// Random edits of the hostile template (quotes, markup, keywords, comment
/// openers, entities): the IL text holds exactly one END_ of a POU per POU
/// translated, so nothing added a POU or swallowed one. (That the same
/// edits never panic through the check is `tests/all/plcopen_hostile.rs`.)
#[test]
fn mutated_projects_keep_every_pou_whole() {
    for x in xml::mutated_projects(2000) {
        let imp = Import::new(SourceFile::new("project.xml", x.as_str()));
        let ends = lex(&imp.il.text)
            .0
            .iter()
            .filter(|(_, t, _)| matches!(t, Tok::EndPou(_)))
            .count();
        let translated = imp.pous.iter().filter(|p| p.translated).count();
        assert_eq!(ends, translated, "{x}\n---\n{}", imp.il.text);
    }
}
