//! The IL text of one `.EXP` file's objects, given what the project knows
//! ([`Facts`]): copied byte for byte where CODESYS's text is IL already,
//! generated (and mapped to the object it stands for) where it is not.

use std::ops::Range;

use super::actions;
use super::decls::{self, Block};
use super::facts::Facts;
use super::scan::{Scanner, Tok, for_lexer};
use super::{Import, Language, Object, ObjectKind, codes};
use crate::ast::{PouKind, Span};
use crate::diag::Diagnostic;
use crate::plcopen::map::Writer;

/// Words that only Structured Text has (IL jumps with `JMP`, returns with
/// `RET`, and has no statements).
const ST_KEYWORDS: &[&str] = &[
    "IF",
    "THEN",
    "ELSIF",
    "ELSE",
    "END_IF",
    "CASE",
    "END_CASE",
    "FOR",
    "TO",
    "BY",
    "DO",
    "END_FOR",
    "WHILE",
    "END_WHILE",
    "REPEAT",
    "UNTIL",
    "END_REPEAT",
    "EXIT",
    "RETURN",
];

/// The language of a body: CODESYS marks graphical bodies (`_CFC_BODY`,
/// `_FBD_BODY`, `_LD_BODY`) and writes IL and ST as they are. A text body
/// is ST when it has what only ST has, outside parentheses (where an IL
/// call's `CAL f(a := 1)` puts its `:=`): a statement's `;`, an assignment's
/// `:=`, or a control keyword (`IF`, `FOR`, `RETURN` ...). Otherwise it is
/// IL, whatever its first word: an IL body may start with a label, an
/// operator, or a user function used as one (`Scale 10`). An empty body
/// is IL.
pub(super) fn language(text: &str, body: Range<usize>, nested: bool) -> Language {
    let mut toks = Scanner::new(text, body, nested)
        .filter(|(t, _)| !matches!(t, Tok::Comment { .. } | Tok::Pragma))
        .peekable();
    let Some((tok, r)) = toks.peek().cloned() else {
        return Language::Il;
    };
    let word = text[r].to_ascii_uppercase();
    if tok == Tok::Word {
        if word.starts_with("_CFC") {
            return Language::Cfc;
        }
        if word.starts_with("_FBD") {
            return Language::Fbd;
        }
        if word.starts_with("_LD") {
            return Language::Ld;
        }
        if word.starts_with("_SFC")
            || ["INITIAL_STEP", "STEP", "TRANSITION"].contains(&word.as_str())
        {
            return Language::Sfc;
        }
    }
    let mut depth = 0i32;
    for (t, r) in toks {
        let s = &text[r.clone()];
        match (t, s) {
            (Tok::Punct, "(") => depth += 1,
            (Tok::Punct, ")") => depth -= 1,
            (Tok::Punct, ";") if depth <= 0 => return Language::St,
            (Tok::Punct, ":") if depth <= 0 && text[r.end..].starts_with('=') => {
                return Language::St;
            }
            (Tok::Word, w)
                if depth <= 0 && ST_KEYWORDS.iter().any(|k| k.eq_ignore_ascii_case(w)) =>
            {
                return Language::St;
            }
            _ => {}
        }
    }
    Language::Il
}

/// Text edits of a copied range: `(range, replacement)`, in order.
type Edits = Vec<(Range<usize>, String)>;

/// Copy `range` of the EXP text into `w`, with `edits` generated in place.
fn copy_edited(
    w: &mut Writer,
    text: &str,
    range: Range<usize>,
    nested: bool,
    decl: bool,
    mut edits: Edits,
) {
    edits.sort_by_key(|(r, _)| (r.start, r.end));
    let lexed = for_lexer(text, range.clone(), nested, decl);
    let base = range.start;
    let mut at = range.start;
    for (r, s) in edits {
        if r.start < at || r.end > range.end {
            continue;
        }
        w.copy(&lexed[at - base..r.start - base], at);
        w.gen_at(&s, r.clone());
        at = r.end;
    }
    w.copy(&lexed[at - base..], at);
}

/// The edits that put the value of an integer constant in place of its
/// name inside `[ ... ]` (array bounds): CODESYS allows
/// `ARRAY [1..MAX_PUMPS] OF BOOL`, the IL checker wants literal bounds.
fn bound_edits(text: &str, range: Range<usize>, nested: bool, facts: &Facts) -> Edits {
    let mut out = Vec::new();
    let mut depth = 0i32;
    for (t, r) in Scanner::new(text, range, nested) {
        match (t, &text[r.clone()]) {
            (Tok::Punct, "[") => depth += 1,
            (Tok::Punct, "]") => depth -= 1,
            (Tok::Word, w) if depth > 0 => {
                if let Some(v) = facts.constant_value(w) {
                    out.push((r, v.to_string()));
                }
            }
            _ => {}
        }
    }
    out
}

/// CODESYS's forms in declarations: an array's initial values without
/// brackets (`:= 3, 1, 2`) get them, and a name spelt like the IEC keyword
/// `ON` (CODESYS does not reserve it) becomes `ON_x` (`on` → `on_x`).
fn decl_edits(text: &str, range: Range<usize>, nested: bool, facts: &Facts) -> Edits {
    let mut out = bound_edits(text, range.clone(), nested, facts);
    for (t, r) in Scanner::new(text, range.clone(), nested) {
        if t == Tok::Word && text[r.clone()].eq_ignore_ascii_case("ON") {
            out.push((r.clone(), format!("{}_x", &text[r])));
        }
    }
    for b in decls::blocks(text, range, nested) {
        for d in &b.decls {
            let Some(init) = &d.init else { continue };
            let is_array = text[d.ty.clone()]
                .trim_start()
                .get(..5)
                .is_some_and(|w| w.eq_ignore_ascii_case("ARRAY"));
            let v = text[init.clone()].trim_start();
            if is_array && !v.starts_with('[') && top_level_comma(v) {
                out.push((init.start..init.start, "[".into()));
                out.push((init.end..init.end, "]".into()));
            }
        }
    }
    out
}

fn top_level_comma(v: &str) -> bool {
    let mut depth = 0i32;
    v.chars().any(|c| {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            _ => {}
        }
        c == ',' && depth == 0
    })
}

/// IL ranges of globals declared in another file, each with its note.
pub(super) type Foreign = Vec<(Range<usize>, String)>;

/// Write the IL text of `imp`'s objects (the import numbered `me` of the
/// project).
pub(super) fn write(imp: &Import, me: usize, facts: &Facts) -> (Writer, Vec<Diagnostic>, Foreign) {
    let text = &imp.exp.text;
    let mut w = Writer::default();
    let mut diags = Vec::new();
    for (k, o) in imp.objects.iter().enumerate() {
        if imp.left_out[k] {
            continue;
        }
        match &o.kind {
            ObjectKind::Pou(kind) if o.end.is_some() => {
                write_pou(&mut w, text, o, *kind, facts, &mut diags);
            }
            ObjectKind::Types if o.end.is_some() => {
                let mut edits = decl_edits(text, o.decl.clone(), o.nested, facts);
                edits.extend(type_semicolons(text, o));
                copy_edited(&mut w, text, o.decl.clone(), o.nested, true, edits);
                w.gen_at("\n", o.decl.end..o.decl.end);
            }
            _ => {}
        }
    }
    let mut foreign = Vec::new();
    if facts.holder == Some(me) {
        super::config::write_config(&mut w, imp, me, facts, &mut foreign);
    }
    (w, diags, foreign)
}

/// A `;` after the last declaration of a TYPE where CODESYS leaves it out
/// (`END_STRUCT` right before `END_TYPE`).
fn type_semicolons(text: &str, o: &Object) -> Edits {
    let toks: Vec<(Tok, Range<usize>)> = Scanner::new(text, o.decl.clone(), o.nested)
        .filter(|(t, _)| !matches!(t, Tok::Comment { .. } | Tok::Pragma))
        .collect();
    let mut out = Vec::new();
    for pair in toks.windows(2) {
        let (prev, next) = (&pair[0], &pair[1]);
        if next.0 == Tok::Word
            && text[next.1.clone()].eq_ignore_ascii_case("END_TYPE")
            && &text[prev.1.clone()] != ";"
            && !text[prev.1.clone()].eq_ignore_ascii_case("END_TYPE")
        {
            out.push((prev.1.end..prev.1.end, ";".to_string()));
        }
    }
    out
}

/// Whether a VAR block is part of a POU's interface.
fn is_interface(b: &Block) -> bool {
    matches!(b.kind.as_str(), "VAR_INPUT" | "VAR_OUTPUT" | "VAR_IN_OUT")
}

fn write_pou(
    w: &mut Writer,
    text: &str,
    o: &Object,
    kind: PouKind,
    facts: &Facts,
    diags: &mut Vec<Diagnostic>,
) {
    let end = o.end.clone().unwrap_or(o.decl.end..o.decl.end);
    let blocks = decls::blocks(text, o.decl.clone(), o.nested);
    let first_block = blocks.first().map_or(o.decl.end, |b| b.range.start);
    if o.language != Language::Il {
        diags.push(
            Diagnostic::warning(
                codes::NOT_IL,
                Import::span(&o.keyword),
                format!(
                    "{} `{}` is in {}: its interface is compiled, its body is not (host-provided)",
                    kind.keyword(),
                    o.name,
                    o.language.name()
                ),
            )
            .with_label("body not in IL")
            .with_note(
                "in generated Rust the crate supplies its body, as for an `{extern}` FUNCTION; `ilc run` runs its interface only",
            ),
        );
        w.gen_at("{extern} ", o.keyword.clone());
        let head = o.decl.start..first_block;
        copy_edited(w, text, head, o.nested, true, Vec::new());
        for b in blocks.iter().filter(|b| is_interface(b)) {
            let edits = decl_edits(text, b.range.clone(), o.nested, facts);
            copy_edited(w, text, b.range.clone(), o.nested, true, edits);
            w.gen_at("\n", b.range.end..b.range.end);
        }
        w.copy(&text[end.clone()], end.start);
        w.gen_at("\n", end.end..end.end);
        return;
    }
    let mut edits = decl_edits(text, o.decl.clone(), o.nested, facts);
    // A PROGRAM that other POUs call is a block with one global instance.
    let called = kind == PouKind::Program && facts.is_called(&o.name);
    let kind = if called {
        edits.push((o.keyword.clone(), "FUNCTION_BLOCK".to_string()));
        PouKind::FunctionBlock
    } else {
        kind
    };
    let mut implicit = facts.implicit_blocks(&o.name, kind);
    let acts: Vec<&super::Action> = match kind {
        PouKind::Function => Vec::new(),
        _ => actions::il_actions(o).collect(),
    };
    if !acts.is_empty() {
        implicit.push_str(&actions::selector_block(o));
    }
    if !implicit.is_empty() {
        edits.push((first_block..first_block, implicit));
    }
    copy_edited(w, text, o.decl.clone(), o.nested, true, edits);
    let mut counter = 0;
    if let Some(body) = &o.body {
        for a in &acts {
            w.gen_at(
                &format!("LD {0}\nJMPC {0}_ACTION\n", a.name),
                a.keyword.clone(),
            );
        }
        let edits = actions::call_edits(text, body.clone(), o, facts, &mut counter);
        copy_edited(w, text, body.clone(), o.nested, false, edits);
        if !acts.is_empty() {
            w.gen_at("\nRET\n", end.start..end.start);
        }
        for a in &acts {
            w.gen_at(
                &format!("{0}_ACTION:\nLD FALSE\nST {0}\n", a.name),
                a.keyword.clone(),
            );
            let mut edits = actions::label_edits(text, a.body.clone(), o.nested, &a.name);
            edits.extend(actions::call_edits(
                text,
                a.body.clone(),
                o,
                facts,
                &mut counter,
            ));
            copy_edited(w, text, a.body.clone(), o.nested, false, edits);
            w.gen_at("\nRET\n", a.end.clone());
        }
    }
    w.gen_at("\n", end.start..end.start);
    if called {
        w.gen_at("END_FUNCTION_BLOCK", end.clone());
    } else {
        w.copy(&text[end.clone()], end.start);
    }
    w.gen_at("\n", end.end..end.end);
    for a in &o.actions {
        let d = if kind == PouKind::Function {
            Diagnostic::error(
                codes::ACTION,
                Span::new(a.keyword.start, a.keyword.end),
                format!(
                    "FUNCTION `{}` has ACTION `{}`: a FUNCTION has no actions",
                    o.name, a.name
                ),
            )
            .with_label("ACTION of a FUNCTION")
        } else if a.language != Language::Il {
            Diagnostic::warning(
                codes::NOT_IL,
                Span::new(a.keyword.start, a.keyword.end),
                format!(
                    "ACTION `{}` of `{}` is in {}: it is not compiled",
                    a.name,
                    o.name,
                    a.language.name()
                ),
            )
            .with_label("action not in IL")
        } else {
            continue;
        };
        diags.push(d);
    }
}
