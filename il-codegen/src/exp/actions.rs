//! CODESYS actions in IL: `ACTION Reset: ... END_ACTION` after a FUNCTION_BLOCK
//! or PROGRAM is code on the POU's own variables, run by `CAL inst.Reset`
//! (from a POU that holds an instance) or `CAL Reset` (in the POU itself).
//!
//! IL has no second entry into a block, so each action `A` becomes part of
//! its POU, said in IEC terms:
//! - a BOOL input `A` selects it: `CAL inst.A` is `CAL inst(A := TRUE)`;
//! - the body starts with `LD A` / `JMPC A_ACTION` for each action, then
//!   runs the POU's own body and `RET`s; at `A_ACTION:` the action clears
//!   its input and runs its code (labels renamed `label_A`), then `RET`s;
//! - `CAL A` inside the POU itself runs the action's code in place (with
//!   `CALC`/`CALCN`, behind a jump), since a block cannot call itself.
//!
//! So the generated Rust has the input `A` as a field: a host runs an
//! action with `fb.A = true; fb.call(ctx)`.

use std::collections::HashMap;
use std::ops::Range;

use super::decls;
use super::facts::Facts;
use super::scan::{Scanner, Tok, for_lexer, line_firsts};
use super::{Language, Object};

/// Text edits of a copied range: `(range, replacement)`.
pub(super) type Edits = Vec<(Range<usize>, String)>;

/// The IL actions of `o` (those in other languages are not compiled).
pub(super) fn il_actions(o: &Object) -> impl Iterator<Item = &super::Action> {
    o.actions.iter().filter(|a| a.language == Language::Il)
}

/// The VAR_INPUT block that selects `o`'s actions ("" when it has none).
pub(super) fn selector_block(o: &Object) -> String {
    let mut s = String::new();
    for a in il_actions(o) {
        s.push_str(&format!("\t{} : BOOL;\n", a.name));
    }
    if s.is_empty() {
        return s;
    }
    format!("VAR_INPUT\n{s}END_VAR\n")
}

/// Upper-case instance name → upper-case type name, for `o`'s variables.
fn instances(text: &str, o: &Object) -> HashMap<String, String> {
    let mut out = HashMap::new();
    for b in decls::blocks(text, o.decl.clone(), o.nested) {
        for d in &b.decls {
            let ty = text[d.ty.clone()].trim().to_ascii_uppercase();
            for (n, _) in &d.names {
                out.insert(n.to_ascii_uppercase(), ty.clone());
            }
        }
    }
    out
}

/// Labels of `range` (defined or jumped to) renamed `label_suffix`.
pub(super) fn label_edits(text: &str, range: Range<usize>, nested: bool, suffix: &str) -> Edits {
    let from = range.start;
    let toks: Vec<(Tok, Range<usize>)> = Scanner::new(text, range, nested)
        .filter(|(t, _)| !matches!(t, Tok::Comment { .. } | Tok::Pragma))
        .collect();
    let firsts = line_firsts(text, from, &toks);
    let mut out = Vec::new();
    for (k, (t, r)) in toks.iter().enumerate() {
        if *t != Tok::Word {
            continue;
        }
        let next_colon = toks.get(k + 1).is_some_and(|(t, c)| {
            *t == Tok::Punct && &text[c.clone()] == ":" && !text[c.end..].starts_with('=')
        });
        let after_jump = k > 0
            && toks[k - 1].0 == Tok::Word
            && text[toks[k - 1].1.clone()]
                .to_ascii_uppercase()
                .starts_with("JMP");
        if (next_colon && firsts[k]) || after_jump {
            out.push((r.clone(), format!("{}_{suffix}", &text[r.clone()])));
        }
    }
    out
}

/// The text of action `a` of `o` in place of a `CAL`, labels renamed with
/// `suffix` so that two calls do not define a label twice.
fn inline(text: &str, o: &Object, a: &super::Action, suffix: &str) -> String {
    let lexed = for_lexer(text, a.body.clone(), o.nested, false);
    let mut edits = label_edits(text, a.body.clone(), o.nested, suffix);
    edits.sort_by_key(|(r, _)| r.start);
    let base = a.body.start;
    let mut out = String::new();
    let mut at = a.body.start;
    for (r, s) in edits {
        out.push_str(&lexed[at - base..r.start - base]);
        out.push_str(&s);
        at = r.end;
    }
    out.push_str(&lexed[at - base..]);
    out
}

/// The edits of an IL body `range` of `o` that turn action calls into IL:
/// `CAL inst.A` into `CAL inst(A := TRUE)` when `inst`'s block has action
/// `A`, and `CAL A` of `o`'s own action into the action's code.
pub(super) fn call_edits(
    text: &str,
    range: Range<usize>,
    o: &Object,
    facts: &Facts,
    counter: &mut usize,
) -> Edits {
    let from = range.start;
    let toks: Vec<(Tok, Range<usize>)> = Scanner::new(text, range, o.nested)
        .filter(|(t, _)| !matches!(t, Tok::Comment { .. } | Tok::Pragma))
        .collect();
    let firsts = line_firsts(text, from, &toks);
    let insts = instances(text, o);
    let mut out = Vec::new();
    let word = |k: usize| {
        toks.get(k)
            .filter(|(t, _)| *t == Tok::Word)
            .map(|(_, r)| &text[r.clone()])
    };
    let punct = |k: usize, c: &str| {
        toks.get(k)
            .is_some_and(|(t, r)| *t == Tok::Punct && &text[r.clone()] == c)
    };
    for k in 0..toks.len() {
        let Some(op) = word(k).map(str::to_ascii_uppercase) else {
            continue;
        };
        if !matches!(op.as_str(), "CAL" | "CALC" | "CALCN" | "CALNC") || !firsts[k] {
            continue;
        }
        let Some(target) = word(k + 1) else { continue };
        // `CAL inst.A`, nothing after it on the line.
        if punct(k + 2, ".")
            && let Some(action) = word(k + 3)
            && toks
                .get(k + 4)
                .is_none_or(|(_, r)| !same_line(text, toks[k].1.start, r.start))
            && let Some(ty) = insts
                .get(&target.to_ascii_uppercase())
                .cloned()
                .or_else(|| facts.is_called(target).then(|| target.to_ascii_uppercase()))
            && facts.has_action(&ty, action)
        {
            let r = toks[k + 1].1.start..toks[k + 3].1.end;
            out.push((r, format!("{target}({action} := TRUE)")));
            continue;
        }
        // `CAL A` of the POU's own action.
        let own = il_actions(o).find(|a| a.name.eq_ignore_ascii_case(target));
        if let Some(a) = own
            && !insts.contains_key(&target.to_ascii_uppercase())
            && toks
                .get(k + 2)
                .is_none_or(|(_, r)| !same_line(text, toks[k].1.start, r.start))
        {
            *counter += 1;
            let suffix = format!("{}{}", a.name, counter);
            let code = inline(text, o, a, &suffix);
            let skip = format!("{}_skip{}", a.name, counter);
            let text_of = match op.as_str() {
                "CAL" => format!("\n{code}\n"),
                "CALC" => format!("JMPCN {skip}\n{code}\n{skip}:\n"),
                _ => format!("JMPC {skip}\n{code}\n{skip}:\n"),
            };
            out.push((toks[k].1.start..toks[k + 1].1.end, text_of));
        }
    }
    out
}

/// The upper-case words that `CAL`, `CALC`, `CALCN` and `CALNC` at the
/// start of a line of `range` call, when they are no variable of `o`.
pub(super) fn cal_targets(text: &str, range: Range<usize>, o: &Object) -> Vec<String> {
    let from = range.start;
    let toks: Vec<(Tok, Range<usize>)> = Scanner::new(text, range, o.nested)
        .filter(|(t, _)| !matches!(t, Tok::Comment { .. } | Tok::Pragma))
        .collect();
    let firsts = line_firsts(text, from, &toks);
    let insts = instances(text, o);
    let mut out = Vec::new();
    for (k, (t, r)) in toks.iter().enumerate() {
        let op = text[r.clone()].to_ascii_uppercase();
        if *t != Tok::Word
            || !firsts[k]
            || !matches!(op.as_str(), "CAL" | "CALC" | "CALCN" | "CALNC")
        {
            continue;
        }
        if let Some((Tok::Word, n)) = toks.get(k + 1) {
            let name = text[n.clone()].to_ascii_uppercase();
            if !insts.contains_key(&name) {
                out.push(name);
            }
        }
    }
    out
}

fn same_line(text: &str, a: usize, b: usize) -> bool {
    !text[a..b].contains('\n')
}
