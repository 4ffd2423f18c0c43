//! Where the interpreter's IL lines are in the files the user wrote: each
//! POU is in one input (an IL file, a PLCopen XML project, a CODESYS
//! `.EXP`, a bare instruction list), and an input that is not IL was
//! translated to IL whose lines map back to the file's. `ilc run` (faults,
//! `--flow`) and `ilc debug` (breakpoints, frames) place lines through it.

use std::collections::HashMap;

use il_codegen::pipeline::{Checked, Input};

/// One input: its path as given, and its lines.
#[derive(Clone, Debug, Default)]
pub struct FileLines {
    /// The path as the user gave it (what diagnostics name).
    pub path: String,
    /// The user's line of each IL line (index 0 is line 1); `None`: the
    /// same (an IL file).
    map: Option<Vec<u32>>,
}

impl FileLines {
    /// The user's line of IL line `line`.
    pub fn get(&self, line: u32) -> u32 {
        match &self.map {
            None => line,
            Some(m) => m
                .get((line as usize).wrapping_sub(1))
                .copied()
                .unwrap_or(line),
        }
    }
}

/// The inputs of a checked program and the input of each POU.
#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    files: Vec<FileLines>,
    /// POU name in upper case → index into `files`.
    pous: HashMap<String, usize>,
    /// The inputs, for their span maps (an error's column).
    inputs: Vec<Input>,
}

impl SourceMap {
    /// The map of every input of a checked program.
    pub fn of(checked: &Checked) -> SourceMap {
        let mut files = Vec::new();
        let mut pous = HashMap::new();
        let irs = checked.partial_ir();
        for (k, input) in checked.inputs().iter().enumerate() {
            let lines = |v: Vec<usize>| Some(v.into_iter().map(|l| l as u32).collect());
            files.push(match input {
                Input::Il(f) => FileLines {
                    path: f.name.clone(),
                    map: None,
                },
                Input::PlcOpen(i) => FileLines {
                    path: i.xml.name.clone(),
                    map: lines(i.xml_lines()),
                },
                Input::Exp(i) => FileLines {
                    path: i.exp.name.clone(),
                    map: lines(i.exp_lines()),
                },
                Input::Snippet(s) => {
                    let n = s.il.text.lines().count() + 1;
                    FileLines {
                        path: s.file.name.clone(),
                        map: Some((1..=n).map(|k| s.line_of(k) as u32).collect()),
                    }
                }
            });
            for p in irs.get(k).map(|p| &p.pous[..]).unwrap_or_default() {
                // A name twice (a duplicate the import left out) keeps its first input.
                pous.entry(p.name.to_ascii_uppercase()).or_insert(k);
            }
        }
        SourceMap {
            files,
            pous,
            inputs: checked.inputs().to_vec(),
        }
    }

    /// The inputs, in the order given.
    pub fn files(&self) -> &[FileLines] {
        &self.files
    }

    /// The IL text input `k` became when it is not IL (an XML project, an
    /// export, a snippet): what `--flow` shows, numbered by its own lines.
    pub fn il_of(&self, k: usize) -> Option<&str> {
        match self.inputs.get(k)? {
            Input::Il(_) => None,
            other => Some(&other.il_text().text),
        }
    }

    /// The input that holds POU `pou`.
    pub fn file_of(&self, pou: &str) -> usize {
        self.pous
            .get(&pou.to_ascii_uppercase())
            .copied()
            .unwrap_or(0)
    }

    /// The path of the input that holds POU `pou`.
    pub fn path_of(&self, pou: &str) -> &str {
        self.files
            .get(self.file_of(pou))
            .map_or("", |f| f.path.as_str())
    }

    /// The user's line of IL line `line` of POU `pou`.
    pub fn line(&self, pou: &str, line: u32) -> u32 {
        self.files
            .get(self.file_of(pou))
            .map_or(line, |f| f.get(line))
    }

    /// `file:line:col` of IL line `line`, column `col` of POU `pou`, through
    /// the input's span map (the pipeline's, as its diagnostics are placed).
    pub fn locate(&self, pou: &str, line: u32, col: u32) -> String {
        let k = self.file_of(pou);
        let Some(input) = self.inputs.get(k) else {
            return format!("{}:{line}:{col}", self.path_of(pou));
        };
        let il = input.il_text();
        // The column counts characters: its byte in the line.
        let text = il.line_text(line as usize);
        let byte = text
            .char_indices()
            .nth((col as usize).saturating_sub(1))
            .map_or(text.len(), |(b, _)| b);
        let off = il.line_start(line as usize) + byte;
        let at = input.to_source(il_codegen::ast::Span::new(off, off));
        let (l, c) = input.source().line_col(at.lo);
        format!("{}:{l}:{c}", input.source().name)
    }

    /// A [`SourceMap::locate`] the interpreter calls for its errors.
    pub fn locator(&self) -> il_interp::Locate {
        let map = self.clone();
        std::sync::Arc::new(move |pou, line, col| map.locate(pou, line, col))
    }

    /// `file:line` of IL line `line` of POU `pou`, as a diagnostic names it.
    pub fn place(&self, pou: &str, line: u32) -> String {
        format!("{}:{}", self.path_of(pou), self.line(pou, line))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use il_codegen::SourceFile;

    /// An XML project's IL line and column are placed in the XML, as the
    /// pipeline places its diagnostics; an IL file's stay as they are.
    #[test]
    fn lines_and_columns_are_the_users_files() {
        let xml = "<?xml version=\"1.0\"?>\n\
<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n\
<types><dataTypes/><pous>\n\
<pou name=\"P\" pouType=\"program\">\n\
<interface><localVars><variable name=\"x\"><type><INT/></type></variable></localVars></interface>\n\
<body><IL><xhtml:p><![CDATA[\n\
LD 1\n\
  ADD x\n\
ST x\n\
]]></xhtml:p></IL></body></pou>\n\
</pous></types></project>\n";
        let il = "FUNCTION_BLOCK F\nVAR y : INT; END_VAR\n    LD y\n    ST y\nEND_FUNCTION_BLOCK\n";
        let checked = il_codegen::Program::new()
            .source(SourceFile::new("p.xml", xml))
            .source(SourceFile::new("f.il", il))
            .check();
        assert!(checked.ir().is_some(), "{}", checked.render(false));
        let map = SourceMap::of(&checked);
        let ir = &checked.ir().unwrap()[0];
        let add = ir.pous[0]
            .body
            .iter()
            .find(|s| s.line != ir.pous[0].body[0].line)
            .unwrap();
        // `ADD x` is on XML line 8 (its column is the one the pipeline's
        // span map gives: the import writes each IL line anew).
        assert_eq!(map.line("P", add.line), 8);
        let at = map.locate("P", add.line, add.col);
        assert!(at.starts_with("p.xml:8:"), "{at}");
        assert_eq!(map.path_of("f"), "f.il");
        assert_eq!(map.locate("F", 4, 5), "f.il:4:5");
        assert_eq!(map.place("F", 4), "f.il:4");
    }
}
