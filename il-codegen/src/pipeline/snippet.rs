//! A bare instruction list (`ilc check --snippet`), like the standard's own
//! Table 51 (`START: LD %IX1 / ANDN %MX5 / ST %QX2`): compiled as the body of
//! a PROGRAM named after the file. Only direct addresses and literals have a
//! meaning without declarations, so the names it uses are listed in one
//! error instead of one "unknown variable" per use.

use crate::ast::Span;
use crate::diag::{Diagnostic, SourceFile};
use crate::sema::codes::UNKNOWN_NAME;
use crate::syntax::code::SNIPPET;

/// The file as written and the PROGRAM wrapped around it.
#[derive(Clone, Debug)]
pub struct Snippet {
    /// The file the user wrote.
    pub file: SourceFile,
    /// `PROGRAM name` + the file + `END_PROGRAM`: what is compiled.
    pub il: SourceFile,
    /// Bytes of the first line added before the file.
    prefix: u32,
    /// Problems of the snippet as a whole (a POU declared in it).
    diagnostics: Vec<Diagnostic>,
    /// The names it uses that would need a declaration.
    names: Vec<(String, Span)>,
}

/// Words that start a declaration: a file with one is not a bare list.
const POU_WORDS: [&str; 5] = [
    "PROGRAM",
    "FUNCTION_BLOCK",
    "FUNCTION",
    "TYPE",
    "CONFIGURATION",
];

impl Snippet {
    /// Wraps `file` in a PROGRAM named after the file's stem.
    pub fn new(file: SourceFile) -> Snippet {
        let mut diagnostics = Vec::new();
        if let Some((at, word)) = pou_word(&file.text) {
            diagnostics.push(
                Diagnostic::error(
                    SNIPPET,
                    Span::new(at, at + word.len()),
                    format!(
                        "`--snippet` takes a bare instruction list, but this file declares a {word}"
                    ),
                )
                .with_label("a declaration")
                .with_help("check the file without `--snippet`"),
            );
        }
        let head = format!("PROGRAM {}\n", program_name(&file.name));
        let il = SourceFile::new(
            file.name.clone(),
            format!("{head}{}\nEND_PROGRAM\n", file.text),
        );
        let mut s = Snippet {
            prefix: head.len() as u32,
            file,
            il,
            diagnostics,
            names: Vec::new(),
        };
        s.names = s.undeclared();
        s
    }

    /// The names the list uses (not direct addresses, literals or labels),
    /// each once, with its first place in the file: none has a declaration.
    /// From the syntax tree, since the checker stops looking at operands
    /// after the first error on a path.
    fn undeclared(&self) -> Vec<(String, Span)> {
        let (unit, _) = crate::syntax::parse(&self.il);
        let mut names: Vec<(String, Span)> = Vec::new();
        for item in &unit.items {
            let crate::ast::Item::Pou(p) = item else {
                continue;
            };
            for st in &p.body {
                let crate::ast::Stmt::Instr(i) = st else {
                    continue;
                };
                i.each_operand(&mut |o| {
                    if let crate::ast::Operand::Var(v) = o
                        && !names.iter().any(|(n, _)| v.base.is(n))
                    {
                        names.push((v.base.name.to_string(), self.to_file(v.base.span)));
                    }
                });
            }
        }
        names
    }

    /// The PROGRAM's name.
    pub fn program(&self) -> String {
        program_name(&self.file.name)
    }

    /// IL line `n` of the wrapped text as a line of the file (0: added).
    pub fn line_of(&self, n: usize) -> usize {
        n.saturating_sub(1)
    }

    /// The diagnostics of the wrapped text in the user's file; the names that
    /// need a declaration become one error.
    pub fn finish(&self, diags: Vec<Diagnostic>) -> Vec<Diagnostic> {
        let mut out = self.diagnostics.clone();
        let names = &self.names;
        for mut d in diags {
            // "Unknown variable", once per name and path: one error below.
            if d.code == UNKNOWN_NAME && !names.is_empty() {
                continue;
            }
            d.span = self.to_file(d.span);
            for f in &mut d.fixes {
                for (s, _) in &mut f.edits {
                    *s = self.to_file(*s);
                }
            }
            for (s, _) in &mut d.secondary {
                *s = self.to_file(*s);
            }
            out.push(d);
        }
        if let Some((_, first)) = names.first() {
            let list: Vec<String> = names.iter().map(|(n, _)| format!("`{n}`")).collect();
            let mut d = Diagnostic::error(
                SNIPPET,
                *first,
                format!(
                    "a bare instruction list has no declarations; these names need one: {}",
                    list.join(", ")
                ),
            )
            .with_label("not a direct address or a literal")
            .with_help(format!(
                "use direct addresses (`%IX0.1`, `%QW2`), or declare them: `PROGRAM {}` / `VAR {} : BOOL; END_VAR` before the list and `END_PROGRAM` after it",
                self.program(),
                names[0].0
            ));
            for (_, s) in names.iter().skip(1) {
                d.secondary.push((*s, String::new()));
            }
            out.push(d);
        }
        out
    }

    /// A span of the wrapped text in the file (the added lines map to its
    /// start and end).
    pub fn to_file(&self, s: Span) -> Span {
        let len = self.file.text.len();
        let f = |o: u32| (o.saturating_sub(self.prefix) as usize).min(len);
        Span::new(f(s.lo), f(s.hi))
    }
}

/// The first word of the text outside comments, when it starts a POU.
fn pou_word(text: &str) -> Option<(usize, &'static str)> {
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            c if c.is_ascii_whitespace() => i += 1,
            b'(' if b.get(i + 1) == Some(&b'*') => {
                i = text[i + 2..].find("*)").map_or(b.len(), |e| i + 2 + e + 2)
            }
            b'{' => i = text[i..].find('}').map_or(b.len(), |e| i + e + 1),
            _ => break,
        }
    }
    let end = text[i..]
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(text.len(), |e| i + e);
    let word = &text[i..end];
    POU_WORDS
        .iter()
        .find(|w| w.eq_ignore_ascii_case(word))
        .map(|w| (i, *w))
}

/// The file's stem as an IEC identifier (`table51.il` → `table51`,
/// `2-fan.il` → `P_2_fan`, standard input → `Snippet`).
fn program_name(path: &str) -> String {
    let stem = std::path::Path::new(path)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("");
    let mut name: String = stem
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    // Single `_` only, and none at the ends.
    while name.contains("__") {
        name = name.replace("__", "_");
    }
    let name = name.trim_matches('_');
    match name.chars().next() {
        None => "Snippet".into(),
        Some(c) if c.is_ascii_digit() => format!("P_{name}"),
        _ => name.chars().take(200).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_come_from_the_file() {
        assert_eq!(program_name("plc/table51.il"), "table51");
        assert_eq!(program_name("2-fan.il"), "P_2_fan");
        assert_eq!(program_name("-"), "Snippet");
        assert_eq!(program_name("a  b__c.il"), "a_b_c");
    }

    #[test]
    fn a_pou_header_is_found_after_comments_and_pragmas() {
        assert_eq!(pou_word("(* x *) {p}\n program P"), Some((13, "PROGRAM")));
        assert_eq!(pou_word("LD %IX1"), None);
        assert_eq!(pou_word("(* open"), None);
    }
}
