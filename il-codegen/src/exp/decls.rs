//! The VAR blocks of an object's declarations, read far enough to know
//! each block's kind and extent and each variable's name, address, type
//! and initial value as text: what the project needs to declare globals in
//! the generated CONFIGURATION, give POUs their VAR_EXTERNALs and keep only
//! the interface of a POU that is not IL. The IL parser reads the text
//! itself afterwards and reports what is wrong in it.

use std::ops::Range;

use super::scan::{Scanner, Tok};

/// `VAR_GLOBAL CONSTANT ... END_VAR`
#[derive(Clone, Debug)]
pub(super) struct Block {
    /// `VAR_INPUT`, `VAR_GLOBAL` ... as written.
    pub kind: String,
    /// `CONSTANT`, `RETAIN`, `PERSISTENT` ...
    pub constant: bool,
    pub retain: bool,
    /// From the keyword to the end of `END_VAR` (to the end of the text
    /// when `END_VAR` is missing).
    pub range: Range<usize>,
    pub decls: Vec<Decl>,
}

/// `a, b AT %IX0.0 : BOOL := TRUE;`
#[derive(Clone, Debug)]
pub(super) struct Decl {
    pub names: Vec<(String, Range<usize>)>,
    pub at: Option<Range<usize>>,
    pub ty: Range<usize>,
    pub init: Option<Range<usize>>,
    /// From the first name to the `;`.
    pub range: Range<usize>,
}

fn is(text: &str, r: &Range<usize>, w: &str) -> bool {
    text[r.clone()].eq_ignore_ascii_case(w)
}

/// Every VAR block of `text[range]`.
pub(super) fn blocks(text: &str, range: Range<usize>, nested: bool) -> Vec<Block> {
    let toks: Vec<(Tok, Range<usize>)> = Scanner::new(text, range.clone(), nested)
        .filter(|(t, _)| !matches!(t, Tok::Comment { .. } | Tok::Pragma))
        .collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let (t, r) = &toks[i];
        let word = &text[r.clone()];
        let is_var = *t == Tok::Word
            && (word.eq_ignore_ascii_case("VAR")
                || word.len() > 4 && word[..4].eq_ignore_ascii_case("VAR_"));
        if !is_var {
            i += 1;
            continue;
        }
        let mut b = Block {
            kind: word.to_ascii_uppercase(),
            constant: false,
            retain: false,
            range: r.start..range.end,
            decls: Vec::new(),
        };
        i += 1;
        while let Some((Tok::Word, q)) = toks.get(i) {
            match text[q.clone()].to_ascii_uppercase().as_str() {
                "CONSTANT" => b.constant = true,
                "RETAIN" | "PERSISTENT" => b.retain = true,
                "NON_RETAIN" => {}
                _ => break,
            }
            i += 1;
        }
        // Declarations up to END_VAR.
        while i < toks.len() {
            let (t, r) = &toks[i];
            if *t == Tok::Word && is(text, r, "END_VAR") {
                b.range.end = r.end;
                i += 1;
                break;
            }
            let (d, next) = decl(text, &toks, i);
            if let Some(d) = d {
                b.decls.push(d);
            }
            i = next.max(i + 1);
        }
        out.push(b);
    }
    out
}

/// One declaration from token `i`; the index after its `;`.
fn decl(text: &str, toks: &[(Tok, Range<usize>)], mut i: usize) -> (Option<Decl>, usize) {
    let start = toks[i].1.start;
    let mut names = Vec::new();
    let punct = |k: usize, c: &str| {
        toks.get(k)
            .is_some_and(|(t, r)| *t == Tok::Punct && &text[r.clone()] == c)
    };
    let end_var = |k: usize| {
        toks.get(k)
            .is_some_and(|(t, r)| *t == Tok::Word && is(text, r, "END_VAR"))
    };
    loop {
        match toks.get(i) {
            Some((Tok::Word, r)) if !is(text, r, "AT") && !is(text, r, "END_VAR") => {
                names.push((text[r.clone()].to_string(), r.clone()));
                i += 1;
            }
            _ => return (None, skip_to_semicolon(text, toks, i)),
        }
        if punct(i, ",") {
            i += 1;
            continue;
        }
        break;
    }
    let mut at = None;
    if let Some((Tok::Word, r)) = toks.get(i)
        && is(text, r, "AT")
    {
        at = toks.get(i + 1).map(|(_, r)| r.clone());
        i += 2;
    }
    if !punct(i, ":") || punct(i + 1, "=") {
        return (None, skip_to_semicolon(text, toks, i));
    }
    i += 1;
    let ty_start = i;
    let mut depth = 0i32;
    let mut init = None;
    let mut ty_end = i;
    while i < toks.len() && !end_var(i) {
        let (t, r) = &toks[i];
        let c = if *t == Tok::Punct {
            &text[r.clone()]
        } else {
            ""
        };
        match c {
            "(" | "[" => depth += 1,
            ")" | "]" => depth -= 1,
            ":" if depth <= 0 && punct(i + 1, "=") && init.is_none() => {
                ty_end = i;
                init = Some(i + 2);
            }
            ";" if depth <= 0 => break,
            _ => {}
        }
        i += 1;
    }
    if init.is_none() {
        ty_end = i;
    }
    let span = |a: usize, b: usize| -> Range<usize> {
        if a < b && b <= toks.len() {
            toks[a].1.start..toks[b - 1].1.end
        } else {
            let at = toks.get(a).map_or(start, |t| t.1.start);
            at..at
        }
    };
    let ty = span(ty_start, ty_end);
    let init = init.map(|k| span(k, i));
    let end = toks.get(i).map_or(start, |t| t.1.end);
    let next = if punct(i, ";") { i + 1 } else { i };
    (
        Some(Decl {
            names,
            at,
            ty,
            init,
            range: start..end,
        }),
        next,
    )
}

fn skip_to_semicolon(text: &str, toks: &[(Tok, Range<usize>)], mut i: usize) -> usize {
    while let Some((t, r)) = toks.get(i) {
        if *t == Tok::Word && is(text, r, "END_VAR") {
            return i;
        }
        i += 1;
        if *t == Tok::Punct && &text[r.clone()] == ";" {
            return i;
        }
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_and_declarations() {
        let t = "VAR_GLOBAL CONSTANT\n N : USINT := 3; (* n *)\nEND_VAR\nVAR_GLOBAL RETAIN\n a, b AT %IX0.0 : ARRAY [1..N] OF BOOL;\n s : STRING(20) := 'x;y';\nEND_VAR";
        let b = blocks(t, 0..t.len(), true);
        assert_eq!(b.len(), 2);
        assert!(b[0].constant && !b[0].retain);
        let d = &b[0].decls[0];
        assert_eq!(d.names[0].0, "N");
        assert_eq!(&t[d.ty.clone()], "USINT");
        assert_eq!(&t[d.init.clone().unwrap()], "3");
        assert!(b[1].retain);
        let d = &b[1].decls[0];
        assert_eq!(d.names.len(), 2);
        assert_eq!(&t[d.at.clone().unwrap()], "%IX0.0");
        assert_eq!(&t[d.ty.clone()], "ARRAY [1..N] OF BOOL");
        let d = &b[1].decls[1];
        assert_eq!(&t[d.ty.clone()], "STRING(20)");
        assert_eq!(&t[d.init.clone().unwrap()], "'x;y'");
        assert!(t[b[1].range.clone()].ends_with("END_VAR"));
    }
}
