//! The CONFIGURATION a CODESYS project becomes: its global variable lists'
//! globals, its task configuration's tasks and the programs they call (or,
//! without one, `PLC_PRG` on every cycle).

use std::ops::Range;

use super::facts::{Facts, Task};
use super::scan::{Scanner, Tok, for_lexer, line_firsts};
use super::{Import, ObjectKind};
use crate::ast::PouKind;
use crate::plcopen::map::Writer;

/// The name of the CONFIGURATION made of a project's global lists and task
/// configuration.
pub(super) const CONFIG_NAME: &str = "Project";

pub(super) fn collect_tasks(imports: &[&mut Import], facts: &mut Facts) {
    facts.plc_prg = imports.iter().any(|i| {
        i.objects.iter().enumerate().any(|(k, o)| {
            !i.left_out[k]
                && o.kind == ObjectKind::Pou(PouKind::Program)
                && o.name.eq_ignore_ascii_case("PLC_PRG")
        })
    });
    for (i, imp) in imports.iter().enumerate() {
        for (k, o) in imp.objects.iter().enumerate() {
            if o.kind != ObjectKind::Tasks || imp.left_out[k] || o.end.is_none() {
                continue;
            }
            let text = &imp.exp.text;
            let toks: Vec<(Tok, Range<usize>)> = Scanner::new(text, o.decl.clone(), o.nested)
                .filter(|(t, _)| !matches!(t, Tok::Comment { .. } | Tok::Pragma))
                .collect();
            let firsts = line_firsts(text, o.decl.start, &toks);
            let mut tasks: Vec<Task> = Vec::new();
            let mut j = 0;
            while j < toks.len() {
                let (t, r) = &toks[j];
                let w = &text[r.clone()];
                let semi = (j..toks.len())
                    .find(|&n| toks[n].0 == Tok::Punct && &text[toks[n].1.clone()] == ";");
                if *t == Tok::Word && w.eq_ignore_ascii_case("TASK") && firsts[j] {
                    let name = toks.get(j + 1).map(|t| text[t.1.clone()].to_string());
                    if let (Some(name), Some(s)) = (name, semi) {
                        tasks.push(Task {
                            decl: r.start..toks[s].1.end,
                            name,
                            programs: Vec::new(),
                        });
                        j = s + 1;
                        continue;
                    }
                }
                // `Prog();` or `Prog(a := b);` inside a TASK.
                if *t == Tok::Word
                    && firsts[j]
                    && toks.get(j + 1).is_some_and(|n| &text[n.1.clone()] == "(")
                    && let (Some(task), Some(s)) = (tasks.last_mut(), semi)
                {
                    let close = toks[s].1.start;
                    let open = toks[j + 1].1.end;
                    let args = text[open..close].trim().trim_end_matches(')').trim();
                    task.programs
                        .push((w.to_string(), args.to_string(), r.start..toks[s].1.end));
                    j = s + 1;
                    continue;
                }
                j += 1;
            }
            if facts.tasks.is_none() {
                facts.tasks = Some((i, k, tasks));
            }
        }
    }
}

/// The CONFIGURATION: the project's globals, its tasks and the programs
/// they run (or `PLC_PRG` on every cycle).
///
/// A global of another file is mapped to the configuration's anchor here;
/// `foreign` gets its IL range and a note naming where it is declared.
pub(super) fn write_config(
    w: &mut Writer,
    imp: &Import,
    me: usize,
    facts: &Facts,
    foreign: &mut Vec<(Range<usize>, String)>,
) {
    let tasks = facts.tasks.as_ref().filter(|t| t.0 == me);
    let anchor = tasks
        .map(|t| imp.objects[t.1].keyword.clone())
        .or_else(|| {
            imp.objects
                .iter()
                .find(|o| o.name.eq_ignore_ascii_case("PLC_PRG") || o.kind == ObjectKind::Globals)
                .map(|o| o.keyword.clone())
        })
        .unwrap_or(0..0);
    if facts.globals.is_empty() && tasks.is_none() && !facts.plc_prg {
        return;
    }
    // The PROGRAMs that run a called program's global instance.
    let scheduled: Vec<(String, Range<usize>)> = match tasks {
        Some((_, _, tasks)) => tasks
            .iter()
            .flat_map(|t| &t.programs)
            .filter(|(p, _, _)| facts.is_called(p))
            .map(|(p, _, r)| (p.clone(), r.clone()))
            .collect(),
        None if facts.plc_prg && facts.is_called("PLC_PRG") => {
            vec![("PLC_PRG".to_string(), anchor.clone())]
        }
        None => Vec::new(),
    };
    for (p, r) in &scheduled {
        // The instance, and the globals the block uses (IEC: who holds an
        // instance declares them too).
        let mut externals = format!("\t{p} : {p};\n");
        for g in facts.needed_by(p).filter(|g| !g.constant) {
            externals.push_str(&format!("\t{} : {};\n", g.name, g.ty));
        }
        w.gen_at(
            &format!(
                "\nPROGRAM {}\nVAR_EXTERNAL\n{externals}END_VAR\nCAL {p}\nEND_PROGRAM\n",
                run_name(p)
            ),
            r.clone(),
        );
    }
    w.gen_at(&format!("\nCONFIGURATION {CONFIG_NAME}\n"), anchor.clone());
    let mut open: Option<(bool, bool)> = None;
    for g in &facts.globals {
        let at = if g.import == me {
            g.range.clone()
        } else {
            anchor.clone()
        };
        if open != Some((g.constant, g.retain)) {
            if open.is_some() {
                w.gen_at("END_VAR\n", at.clone());
            }
            let mut head = "VAR_GLOBAL".to_string();
            if g.constant {
                head.push_str(" CONSTANT");
            }
            if g.retain {
                head.push_str(" RETAIN");
            }
            head.push('\n');
            w.gen_at(&head, at.clone());
            open = Some((g.constant, g.retain));
        }
        let mut line = format!("\t{}", g.name);
        if let Some(a) = &g.at {
            line.push_str(&format!(" AT {a}"));
        }
        line.push_str(&format!(" : {}", g.ty));
        if let Some(i) = &g.init {
            line.push_str(&format!(" := {i}"));
        }
        line.push_str(";\n");
        let start = w.text.len();
        w.gen_at(&line, at);
        if g.import != me {
            foreign.push((
                start..w.text.len(),
                format!(
                    "`{}` is declared in `{}`, line {} (a global variable list of this project)",
                    g.name, g.file, g.line
                ),
            ));
        }
    }
    if open.is_some() {
        w.gen_at("END_VAR\n", anchor.clone());
    }
    match tasks {
        Some((_, _, tasks)) => {
            w.gen_at("RESOURCE PLC ON PLC\n", anchor.clone());
            for t in tasks {
                w.copy(
                    &for_lexer(&imp.exp.text, t.decl.clone(), true, false),
                    t.decl.start,
                );
                w.gen_at("\n", t.decl.end..t.decl.end);
            }
            for t in tasks {
                for (p, args, r) in &t.programs {
                    let args = if args.is_empty() {
                        String::new()
                    } else {
                        format!("({args})")
                    };
                    let ty = if facts.is_called(p) {
                        run_name(p)
                    } else {
                        p.clone()
                    };
                    w.gen_at(
                        &format!("PROGRAM {p} WITH {} : {ty}{args};\n", t.name),
                        r.clone(),
                    );
                }
            }
            w.gen_at("END_RESOURCE\n", anchor.clone());
        }
        None if facts.plc_prg => {
            let ty = if facts.is_called("PLC_PRG") {
                run_name("PLC_PRG")
            } else {
                "PLC_PRG".to_string()
            };
            w.gen_at(&format!("PROGRAM PLC_PRG : {ty};\n"), anchor.clone());
        }
        None => {}
    }
    w.gen_at("END_CONFIGURATION\n", anchor);
}

/// The PROGRAM that runs the global instance of called program `p` from a
/// task: `p_RUN` (`pRUN` after a trailing `_`: IEC names have no `__`).
fn run_name(p: &str) -> String {
    if p.ends_with('_') {
        format!("{p}RUN")
    } else {
        format!("{p}_RUN")
    }
}
