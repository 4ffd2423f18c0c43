//! The `.EXP` files of one program read as one CODESYS project: objects
//! exported twice are read once (two different objects of one name are an
//! error at the second), the global variable lists and the task
//! configuration become one CONFIGURATION, and IL POUs get the
//! declarations IEC needs for the globals they name ([`Facts`]).

use std::collections::{BTreeSet, HashMap, HashSet};
use std::ops::Range;

use super::decls;
use super::facts::{Facts, Global};
use super::scan::{Scanner, Tok, for_lexer};
use super::{Import, Language, ObjectKind, codes};
use crate::ast::{PouKind, Span};
use crate::diag::Diagnostic;

/// The text of an object for comparing two of one name: its code, without
/// headers and blank space at the ends.
fn object_text(imp: &Import, k: usize) -> &str {
    let o = &imp.objects[k];
    imp.exp.text[o.keyword.start..o.span.end.max(o.keyword.start)].trim()
}

/// Read the `.EXP` inputs of a program together and write their IL text.
pub(crate) fn assemble(imports: &mut [&mut Import]) {
    for imp in imports.iter_mut() {
        imp.diagnostics = imp.split_diags.clone();
        imp.left_out = vec![false; imp.objects.len()];
    }
    duplicates(imports);
    let mut facts = Facts::default();
    collect_globals(imports, &mut facts);
    super::config::collect_tasks(imports, &mut facts);
    called_programs(imports, &mut facts);
    collect_needs(imports, &mut facts);
    facts.holder = facts.tasks.as_ref().map(|t| t.0).or_else(|| {
        let with_prg = imports.iter().position(|i| {
            i.objects.iter().any(|o| {
                o.kind == ObjectKind::Pou(PouKind::Program)
                    && o.name.eq_ignore_ascii_case("PLC_PRG")
            })
        });
        with_prg.or_else(|| facts.globals.first().map(|g| g.import))
    });
    let library_pous = library_pous(imports);
    for (me, imp) in imports.iter_mut().enumerate() {
        imp.library_pous = library_pous.clone();
        let (w, diags, foreign) = super::write::write(imp, me, &facts);
        imp.foreign = foreign;
        imp.globals = facts
            .globals
            .iter()
            .filter(|g| !g.constant)
            .map(|g| g.name.to_ascii_uppercase())
            .collect();
        let (text, map) = w.finish();
        imp.il = crate::diag::SourceFile::new(imp.exp.name.clone(), text);
        imp.map = map;
        imp.diagnostics.extend(diags);
    }
}

/// The IL PROGRAMs another IL POU calls (`CAL P`, `CALC P.Reset`, `CAL
/// P(x := 1)`, where `P` is no variable of the caller), each with a global
/// instance of its name in the project's globals.
fn called_programs(imports: &[&mut Import], facts: &mut Facts) {
    let mut programs: HashMap<String, (usize, usize)> = HashMap::new();
    for (i, imp) in imports.iter().enumerate() {
        for (k, o) in imp.objects.iter().enumerate() {
            if o.kind == ObjectKind::Pou(PouKind::Program)
                && o.language == Language::Il
                && !imp.left_out[k]
                && o.end.is_some()
            {
                programs
                    .entry(o.name.to_ascii_uppercase())
                    .or_insert((i, k));
            }
        }
    }
    for imp in imports.iter() {
        for (k, o) in imp.objects.iter().enumerate() {
            if !matches!(o.kind, ObjectKind::Pou(_))
                || o.language != Language::Il
                || imp.left_out[k]
            {
                continue;
            }
            let bodies = o
                .body
                .iter()
                .cloned()
                .chain(super::actions::il_actions(o).map(|a| a.body.clone()));
            for body in bodies {
                for target in super::actions::cal_targets(&imp.exp.text, body, o) {
                    if programs.contains_key(&target) && !target.eq_ignore_ascii_case(&o.name) {
                        facts.called.insert(target);
                    }
                }
            }
        }
    }
    let mut called: Vec<&String> = facts.called.iter().collect();
    called.sort();
    for name in called {
        let (i, k) = programs[name];
        let o = &imports[i].objects[k];
        facts.globals.push(Global {
            name: o.name.clone(),
            at: None,
            ty: o.name.clone(),
            init: None,
            constant: false,
            retain: false,
            import: i,
            range: o.keyword.clone(),
            file: imports[i].exp.name.clone(),
            line: imports[i].exp.line_of(o.keyword.start as u32),
        });
    }
}

/// The POUs the project's library references list (`LIBRARY Util.lib ...
/// NumOfPOUs: 24 / BLINK: 2048 / ... / NumOfGVLs`), by upper-case name,
/// with the library's file name: a POU that names one the compiler does
/// not have is told where it comes from.
fn library_pous(imports: &[&mut Import]) -> HashMap<String, String> {
    let mut out = HashMap::new();
    for imp in imports {
        for o in &imp.objects {
            if o.kind != ObjectKind::Skipped("a library reference") {
                continue;
            }
            let lib = o.name.split_whitespace().next().unwrap_or("").to_string();
            let text = imp.exp.text.get(o.span.clone()).unwrap_or("");
            let mut in_pous = false;
            for line in text.lines() {
                crate::step_counter::add(1);
                let Some((name, count)) = line.split_once(':') else {
                    continue;
                };
                let name = name.trim();
                if name.eq_ignore_ascii_case("NumOfPOUs") {
                    in_pous = true;
                } else if name.eq_ignore_ascii_case("NumOfGVLs") {
                    in_pous = false;
                } else if in_pous
                    && !name.is_empty()
                    && !name.contains(char::is_whitespace)
                    && count.trim().chars().all(|c| c.is_ascii_digit())
                {
                    out.entry(name.to_ascii_uppercase())
                        .or_insert_with(|| lib.clone());
                }
            }
        }
    }
    out
}

/// Objects of one name: the same text is read once, another text is an
/// error at the second.
fn duplicates(imports: &mut [&mut Import]) {
    let mut seen: HashMap<(u8, String), (usize, usize)> = HashMap::new();
    for i in 0..imports.len() {
        for k in 0..imports[i].objects.len() {
            let o = &imports[i].objects[k];
            let class = match o.kind {
                ObjectKind::Pou(_) => 0,
                ObjectKind::Types => 1,
                ObjectKind::Globals => 2,
                ObjectKind::Tasks => 3,
                ObjectKind::Skipped(_) => continue,
            };
            let key = (class, o.name.to_ascii_uppercase());
            let Some(&(fi, fk)) = seen.get(&key) else {
                seen.insert(key, (i, k));
                continue;
            };
            let same = object_text(imports[fi], fk) == object_text(imports[i], k);
            imports[i].left_out[k] = true;
            if same {
                continue;
            }
            let first = &imports[fi];
            let line = first.exp.line_of(first.objects[fk].keyword.start as u32);
            let o = &imports[i].objects[k];
            let d = Diagnostic::error(
                codes::DUPLICATE_OBJECT,
                Span::new(o.keyword.start, o.keyword.end),
                format!(
                    "{} `{}` is already an object of this project, with other text; this one is left out",
                    o.kind.describe(),
                    o.name
                ),
            )
            .with_label("second object of this name")
            .with_note(format!("the first is in `{}`, line {line}", first.exp.name));
            imports[i].diagnostics.push(d);
        }
    }
}

/// Replace integer constants inside `[ ... ]` of `text[range]`.
fn with_bounds(text: &str, range: Range<usize>, nested: bool, facts: &Facts) -> String {
    let lexed = for_lexer(text, range.clone(), nested, true);
    let mut out = String::new();
    let mut at = range.start;
    let mut depth = 0;
    for (t, r) in Scanner::new(text, range.clone(), nested) {
        match (t, &text[r.clone()]) {
            (Tok::Punct, "[") => depth += 1,
            (Tok::Punct, "]") => depth -= 1,
            (Tok::Word, w) if depth > 0 => {
                if let Some(v) = facts.constant_value(w) {
                    out.push_str(&lexed[at - range.start..r.start - range.start]);
                    out.push_str(v);
                    at = r.end;
                }
            }
            _ => {}
        }
    }
    out.push_str(&lexed[at - range.start..]);
    // A declaration's text on one line (comments inside it dropped).
    out.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The addresses the compiler binds: `%IX0.1`, `%IX7`, `%QW4`, `%MD2`,
/// `%I*`. CODESYS targets accept others: OWEN's `%IR3.0` for a REAL, and
/// hierarchical ones (`%IX1.0.3`, `%QW9.1.0`: module, channel ...).
fn iec_address(a: &str) -> bool {
    let up = a.to_ascii_uppercase();
    let Some(rest) = up.strip_prefix('%') else {
        return false;
    };
    let Some(rest) = rest.strip_prefix(['I', 'Q', 'M']) else {
        return false;
    };
    if rest == "*" {
        return true;
    }
    let (size, nums) = match rest.as_bytes().first() {
        Some(b'X' | b'B' | b'W' | b'D' | b'L') => (rest.as_bytes()[0], &rest[1..]),
        _ => (b'X', rest),
    };
    let parts: Vec<&str> = nums.split('.').collect();
    let numeric = parts
        .iter()
        .all(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()));
    numeric && (parts.len() == 1 || size == b'X' && parts.len() == 2)
}

fn is_int_literal(s: &str) -> bool {
    let v = s.rsplit('#').next().unwrap_or(s);
    !v.is_empty() && v.bytes().all(|b| b.is_ascii_digit() || b == b'_') && !s.contains("T#")
}

fn collect_globals(imports: &mut [&mut Import], facts: &mut Facts) {
    let mut by_key: HashMap<String, usize> = HashMap::new();
    // Constants first: bounds of other globals name them.
    for pass in [true, false] {
        for (i, imp) in imports.iter_mut().enumerate() {
            let mut diags = Vec::new();
            for (k, o) in imp.objects.iter().enumerate() {
                if o.kind != ObjectKind::Globals || imp.left_out[k] {
                    continue;
                }
                let text = &imp.exp.text;
                for b in decls::blocks(text, o.decl.clone(), o.nested) {
                    if b.kind != "VAR_GLOBAL" {
                        if !pass {
                            let r = b.range.start..b.range.start + b.kind.len();
                            diags.push(
                                Diagnostic::warning(
                                    codes::NOT_GLOBALS,
                                    Span::new(r.start, r.end),
                                    format!(
                                        "{} in global variable list `{}` is not compiled: only its VAR_GLOBAL blocks are",
                                        b.kind, o.name
                                    ),
                                )
                                .with_label("left out"),
                            );
                        }
                        continue;
                    }
                    if b.constant != pass {
                        continue;
                    }
                    for d in &b.decls {
                        let ty = with_bounds(text, d.ty.clone(), o.nested, facts);
                        let init = d
                            .init
                            .clone()
                            .map(|r| with_bounds(text, r, o.nested, facts));
                        for (name, nr) in &d.names {
                            let key = name.to_ascii_uppercase();
                            if let Some(&prev) = by_key.get(&key) {
                                let p: &Global = &facts.globals[prev];
                                if p.ty != ty || p.init != init || p.constant != b.constant {
                                    diags.push(
                                        Diagnostic::error(
                                            codes::DUPLICATE_OBJECT,
                                            Span::new(nr.start, nr.end),
                                            format!(
                                                "global `{name}` is already declared in another global variable list, as {}",
                                                p.ty
                                            ),
                                        )
                                        .with_label("declared twice"),
                                    );
                                }
                                continue;
                            }
                            if b.constant
                                && let Some(v) = init.as_deref().filter(|v| is_int_literal(v))
                            {
                                facts.constants.insert(key.clone(), v.to_string());
                            }
                            let mut at = d.at.clone().map(|r| text[r].to_string());
                            if let Some(a) = at.as_deref().filter(|a| !iec_address(a)) {
                                diags.push(
                                    Diagnostic::warning(
                                        codes::NOT_IEC_ADDRESS,
                                        Span::new(nr.start, nr.end),
                                        format!(
                                            "`{name}` is at `{a}`, an address the compiler does not bind: it is compiled as a global without an address"
                                        ),
                                    )
                                    .with_label("address left out")
                                    .with_help("the compiler binds `%IXbyte.bit`, `%IXbit` and `%IBn`/`%IWn`/`%IDn`/`%ILn` (and %Q, %M)"),
                                );
                                at = None;
                            }
                            by_key.insert(key, facts.globals.len());
                            facts.globals.push(Global {
                                name: name.clone(),
                                at,
                                ty: ty.clone(),
                                init: init.clone(),
                                constant: b.constant,
                                retain: b.retain,
                                import: i,
                                range: d.range.clone(),
                                file: imp.exp.name.clone(),
                                line: imp.exp.line_of(d.range.start as u32),
                            });
                        }
                    }
                }
            }
            imp.diagnostics.extend(diags);
        }
    }
}

/// The words of `text[range]` that name a variable (not a member after `.`).
fn names_used(text: &str, range: Range<usize>, nested: bool, into: &mut HashSet<String>) {
    let mut after_dot = false;
    for (t, r) in Scanner::new(text, range, nested) {
        match t {
            Tok::Word if !after_dot => {
                into.insert(text[r.clone()].to_ascii_uppercase());
            }
            Tok::Comment { .. } | Tok::Pragma => continue,
            _ => {}
        }
        after_dot = t == Tok::Punct && &text[r.clone()] == ".";
    }
}

fn collect_needs(imports: &[&mut Import], facts: &mut Facts) {
    let keys: HashMap<String, usize> = facts
        .globals
        .iter()
        .enumerate()
        .map(|(k, g)| (g.name.to_ascii_uppercase(), k))
        .collect();
    let mut direct: HashMap<String, (PouKind, BTreeSet<usize>, Vec<String>)> = HashMap::new();
    for imp in imports {
        let text = &imp.exp.text;
        for (k, o) in imp.objects.iter().enumerate() {
            let ObjectKind::Pou(mut kind) = o.kind else {
                continue;
            };
            if kind == PouKind::Program && facts.is_called(&o.name) {
                kind = PouKind::FunctionBlock;
            }
            if imp.left_out[k] || o.language != Language::Il {
                continue;
            }
            let mut used = HashSet::new();
            names_used(text, o.decl.clone(), o.nested, &mut used);
            if let Some(b) = &o.body {
                names_used(text, b.clone(), o.nested, &mut used);
            }
            for a in super::actions::il_actions(o) {
                names_used(text, a.body.clone(), o.nested, &mut used);
            }
            if kind == PouKind::FunctionBlock {
                let names = super::actions::il_actions(o)
                    .map(|a| a.name.to_ascii_uppercase())
                    .collect::<Vec<_>>();
                if !names.is_empty() {
                    facts.actions.insert(o.name.to_ascii_uppercase(), names);
                }
            }
            let mut locals = HashSet::new();
            let mut instances = Vec::new();
            for b in decls::blocks(text, o.decl.clone(), o.nested) {
                for d in &b.decls {
                    for (n, _) in &d.names {
                        locals.insert(n.to_ascii_uppercase());
                    }
                    instances.push(text[d.ty.clone()].trim().to_ascii_uppercase());
                }
            }
            // A called program's global instance has its name: the POU
            // itself does not need it.
            locals.insert(o.name.to_ascii_uppercase());
            let needs: BTreeSet<usize> = used
                .iter()
                .filter(|u| !locals.contains(*u))
                .filter_map(|u| keys.get(u).copied())
                .collect();
            // The global instance of a called program is held through its
            // VAR_EXTERNAL: what that block needs, this POU declares too.
            instances.extend(
                needs
                    .iter()
                    .map(|&g| &facts.globals[g])
                    .filter(|g| facts.is_called(&g.name))
                    .map(|g| g.ty.to_ascii_uppercase()),
            );
            direct.insert(o.name.to_ascii_uppercase(), (kind, needs, instances));
        }
    }
    // A block that holds an instance of one that uses globals passes them
    // down, so it declares them too (IEC's rule, which the checker keeps).
    let mut needs: HashMap<String, BTreeSet<usize>> = direct
        .iter()
        .map(|(k, (_, n, _))| (k.clone(), n.clone()))
        .collect();
    for _ in 0..direct.len().min(64) {
        let mut changed = false;
        for (name, (kind, _, instances)) in &direct {
            if *kind == PouKind::Function {
                continue;
            }
            let mut add: BTreeSet<usize> = BTreeSet::new();
            for t in instances {
                if let Some((PouKind::FunctionBlock, _, _)) = direct.get(t)
                    && let Some(n) = needs.get(t)
                {
                    add.extend(n.iter().filter(|&&g| !facts.globals[g].constant));
                }
            }
            let mine = needs.entry(name.clone()).or_default();
            let before = mine.len();
            mine.extend(add);
            changed |= mine.len() != before;
        }
        if !changed {
            break;
        }
    }
    facts.needs = needs;
}
