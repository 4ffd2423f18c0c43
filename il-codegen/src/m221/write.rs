//! The IL text of an M221 project: one PROGRAM per POU of the master task,
//! its rungs translated in order (a rung with an error is left out whole,
//! with its diagnostic), and one CONFIGURATION `M221` that declares every
//! object the programs use as a global and runs the programs in the order
//! of the POUs, every scan.

use std::collections::{BTreeSet, HashSet};
use std::ops::Range;

use super::codes::{SYSTEM_OBJECT, UNSUPPORTED};
use super::objects::{Global, Objects};
use super::read::{self, Pou as XmlPou, Project, span};
use super::rung::{Locals, Pou, Rung, SCAN_END, bad, label_name};
use crate::diag::Diagnostic;
use crate::plcopen::PouInfo;
use crate::plcopen::map::Writer;
use crate::plcopen::translate::Translation;

pub(crate) fn translate(doc: &roxmltree::Document, xml: &str) -> Translation {
    let mut diags = Vec::new();
    let root = doc.root_element();
    let p = read::read(root, xml, &mut diags);
    if let Some(r) = &p.subroutines {
        diags.push(
            Diagnostic::error(
                UNSUPPORTED,
                span(&(r.start..r.start + "<Subroutines>".len())),
                "the project's `<Subroutines>` are not all `<ProgramOrganizationUnits>` with a `<SectionNumber>` or a name `SRn` (one each), the layout the import reads",
            )
            .with_label("not compiled")
            .with_note("no subroutine of the project is compiled; a `CAL SRn` is an error"),
        );
    }
    write(&p, root.range(), diags)
}

/// The IL text of a project read from an `.smbp` or a text listing;
/// `root` is the range the configuration stands for.
pub(super) fn write(p: &Project, root: Range<usize>, mut diags: Vec<Diagnostic>) -> Translation {
    let mut objs = Objects::default();
    let mut w = Writer::default();
    let mut pous = Vec::new();
    let mut programs: Vec<(String, String, Range<usize>)> = Vec::new();
    let mut taken = HashSet::new();
    // `END`/`ENDC`/`ENDCN` end the scan: a flag the first POU clears and
    // every POU tests first.
    let ends = p
        .pous
        .iter()
        .flat_map(|x| &x.rungs)
        .flat_map(|r| &r.lines)
        .any(|l| {
            let w = l.text.split_whitespace().next().unwrap_or("");
            ["END", "ENDC", "ENDCN"]
                .iter()
                .any(|e| w.eq_ignore_ascii_case(e))
        });
    if ends {
        objs.globals.insert(
            SCAN_END.to_string(),
            Global {
                decl: "BOOL".into(),
                ty: "BOOL".into(),
                constant: false,
                system: false,
                at: root.start..root.start + 1,
            },
        );
    }
    // First pass: which globals and locals each body needs; a POU that
    // calls a subroutine declares the globals the subroutine uses too.
    let mut firsts: Vec<Locals> = p
        .pous
        .iter()
        .map(|pou| {
            body(
                p,
                &mut objs,
                &mut Writer::default(),
                &mut Vec::new(),
                pou,
                ends,
            )
        })
        .collect();
    called_globals(p, &mut firsts);
    // The system bits the controller sets: one `M221_SYS` the first POU
    // runs at the start of every scan, its outputs copied into the bits.
    let sys: Vec<u32> = objs.sys_bits.iter().copied().collect();
    if !sys.is_empty() {
        objs.globals.insert(
            SYS.to_string(),
            Global {
                decl: "M221_SYS".into(),
                ty: "M221_SYS".into(),
                constant: false,
                system: false,
                at: root.start..root.start + 1,
            },
        );
    }
    let mut k = 0;
    for (pou, mut locals) in p.pous.iter().zip(firsts) {
        if ends {
            locals.used.insert(SCAN_END.to_string());
        }
        let first = pou.sr.is_none() && k == 0;
        if first && !sys.is_empty() {
            locals.used.insert(SYS.to_string());
            locals.used.extend(sys.iter().map(|n| format!("S{n}")));
        }
        let at = pou.at.start..pou.at.start + 1;
        let (ty, kind) = match pou.sr {
            Some(n) => (format!("SUB_SR{n}"), "FUNCTION_BLOCK"),
            None => (
                unique(format!("POU_{}", ident(&pou.name)), &mut taken),
                "PROGRAM",
            ),
        };
        w.gen_at(&format!("{kind} {ty}\n"), at.clone());
        externals(&mut w, &objs, &locals, at.clone());
        own_vars(&mut w, &locals, at.clone());
        if first && !sys.is_empty() {
            w.gen_at(&format!("    CAL {SYS}\n"), at.clone());
            for n in &sys {
                w.gen_at(&format!("    LD {SYS}.S{n}\n    ST S{n}\n"), at.clone());
            }
        }
        if first && ends {
            w.gen_at(&format!("    LD FALSE\n    ST {SCAN_END}\n"), at.clone());
        } else if pou.sr.is_none() && ends {
            w.gen_at(&format!("    LD {SCAN_END}\n    RETC\n"), at.clone());
        }
        body(p, &mut objs, &mut w, &mut diags, pou, ends);
        w.gen_at(&format!("END_{kind}\n\n"), at.clone());
        pous.push(PouInfo {
            name: pou.name.clone(),
            kind,
            language: "IL".into(),
            translated: true,
        });
        if pou.sr.is_some() {
            continue;
        }
        k += 1;
        let mut inst = ident(&pou.name);
        if objs.globals.contains_key(&inst) || inst.eq_ignore_ascii_case(&ty) {
            inst.push_str("_1");
        }
        programs.push((unique(inst, &mut taken), ty, at));
    }
    configuration(&mut w, &objs, &programs, root);
    for (name, g) in &objs.globals {
        if g.system {
            diags.push(
                Diagnostic::warning(
                    SYSTEM_OBJECT,
                    span(&g.at),
                    format!("system object: `{name}` is a global the host sets, its controller behaviour is not simulated"),
                )
                .with_label("set by the host"),
            );
        }
    }
    let (text, map) = w.finish();
    Translation {
        text,
        map,
        diags,
        pous,
        folders: Vec::new(),
        globals: HashSet::new(),
    }
}

/// The instance of il-std's `M221_SYS` that computes the system bits.
const SYS: &str = "SYSTEM_BITS";

/// Translate the rungs of `pou` into `w`; the locals they need.
fn body(
    p: &Project,
    objs: &mut Objects,
    w: &mut Writer,
    diags: &mut Vec<Diagnostic>,
    pou: &XmlPou,
    ends: bool,
) -> Locals {
    let mut t = Pou {
        p,
        objs,
        w,
        diags,
        locals: Locals::default(),
        sr: pou.sr.is_some(),
        ends,
    };
    for r in &pou.rungs {
        let mark = t.w.mark();
        let at = r.at.start..r.at.start + 1;
        t.w.gen_at(&format!("(* rung {} *)\n", r.number), at.clone());
        let mut rung = Rung::default();
        let mut failed = None;
        if let Some(l) = &r.label {
            let name = label_name(l.text.trim()).map(|n| format!("{n}:"));
            match name {
                Some(n) => t.w.gen_at(&format!("{n}\n"), l.xml(0..l.text.len())),
                None => {
                    failed = Some(*bad(
                        l,
                        0..l.text.len(),
                        format!("`{}` is not a label (`%L1` ... `%L63`)", l.text.trim()),
                    ))
                }
            }
        }
        for line in r.lines.iter().filter(|_| failed.is_none()) {
            let res = t.line(&mut rung, line);
            for n in t.objs.touched.drain(..) {
                t.locals.used.insert(n);
            }
            if let Err(d) = res {
                failed = Some(*d);
                break;
            }
        }
        if failed.is_none()
            && let Some(last) = r.lines.last()
        {
            let whole = 0..last.text.len();
            let open = if !rung.parens.is_empty() {
                Some("an `AND(` or `OR(` without its `)`")
            } else if rung.blk.is_some() {
                Some("a `BLK` without its `END_BLK`")
            } else if rung.stack > 0 {
                Some("an `MPS` without its `MPP`")
            } else {
                None
            };
            if let Some(what) = open {
                failed = Some(*bad(last, whole, format!("the rung ends with {what}")));
            }
        }
        match failed {
            Some(mut d) => {
                t.w.rollback(mark);
                d.notes.push(format!(
                    "rung {} of POU `{}` is left out",
                    r.number, pou.name
                ));
                t.diags.push(d);
            }
            None => t.flush(&mut rung, false, at),
        }
    }
    t.locals
}

/// Add to each POU's globals those of the subroutines it calls, directly
/// or through another (IEC: a POU that holds or reaches a block instance
/// declares the globals the block uses).
fn called_globals(p: &Project, firsts: &mut [Locals]) {
    let sr_index = |n: u32| p.pous.iter().position(|x| x.sr == Some(n));
    for k in 0..firsts.len() {
        let mut seen = BTreeSet::new();
        let mut todo: Vec<u32> = firsts[k].calls.iter().copied().collect();
        let mut extra = BTreeSet::new();
        while let Some(n) = todo.pop() {
            if !seen.insert(n) {
                continue;
            }
            if let Some(j) = sr_index(n) {
                extra.extend(firsts[j].used.iter().cloned());
                todo.extend(firsts[j].calls.iter().copied());
            }
        }
        firsts[k].used.extend(extra);
    }
}

fn externals(w: &mut Writer, objs: &Objects, locals: &Locals, at: Range<usize>) {
    for constant in [false, true] {
        let names: Vec<_> = (locals.used.iter())
            .filter(|n| objs.globals.get(*n).is_some_and(|g| g.constant == constant))
            .collect();
        if names.is_empty() {
            continue;
        }
        let head = if constant {
            "VAR_EXTERNAL CONSTANT\n"
        } else {
            "VAR_EXTERNAL\n"
        };
        w.gen_at(head, at.clone());
        for n in names {
            let g = &objs.globals[n];
            w.gen_at(&format!("    {n} : {};\n", g.ty), g.at.clone());
        }
        w.gen_at("END_VAR\n", at.clone());
    }
}

fn own_vars(w: &mut Writer, l: &Locals, at: Range<usize>) {
    let mut vars: Vec<(String, &str)> = Vec::new();
    if l.cr {
        vars.push(("_cr".into(), "BOOL"));
    }
    for k in 1..=l.edges {
        vars.push((format!("_e{k}"), "BOOL"));
        vars.push((format!("_t{k}"), "BOOL"));
    }
    for k in 1..=l.stack {
        vars.push((format!("_s{k}"), "BOOL"));
    }
    vars.extend(l.temps.iter().map(|(n, t)| (n.clone(), *t)));
    if vars.is_empty() {
        return;
    }
    w.gen_at("VAR\n", at.clone());
    for (n, t) in vars {
        w.gen_at(&format!("    {n} : {t};\n"), at.clone());
    }
    w.gen_at("END_VAR\n", at);
}

fn configuration(
    w: &mut Writer,
    objs: &Objects,
    programs: &[(String, String, Range<usize>)],
    root: Range<usize>,
) {
    let at = root.start..root.start + 1;
    w.gen_at("CONFIGURATION M221\n", at.clone());
    for constant in [false, true] {
        let gs: Vec<_> = objs
            .globals
            .iter()
            .filter(|(_, g)| g.constant == constant)
            .collect();
        if gs.is_empty() {
            continue;
        }
        let head = if constant {
            "VAR_GLOBAL CONSTANT\n"
        } else {
            "VAR_GLOBAL\n"
        };
        w.gen_at(head, at.clone());
        for (n, g) in gs {
            let decl = if g.decl.starts_with("AT ") {
                format!("    {n} {};\n", g.decl)
            } else {
                format!("    {n} : {};\n", g.decl)
            };
            w.gen_at(&decl, g.at.clone());
        }
        w.gen_at("END_VAR\n", at.clone());
    }
    w.gen_at("RESOURCE Cpu ON PLC\n", at.clone());
    for (inst, ty, pat) in programs {
        w.gen_at(&format!("    PROGRAM {inst} : {ty};\n"), pat.clone());
    }
    w.gen_at("END_RESOURCE\nEND_CONFIGURATION\n", at);
}

/// An IEC identifier made of a name (`New POU` → `New_POU`).
fn ident(name: &str) -> String {
    let mut s = String::new();
    for c in name.chars() {
        if c.is_ascii_alphanumeric() {
            s.push(c);
        } else if !s.ends_with('_') && !s.is_empty() {
            s.push('_');
        }
    }
    while s.ends_with('_') {
        s.pop();
    }
    if s.is_empty() {
        s.push_str("POU");
    }
    if s.starts_with(|c: char| c.is_ascii_digit()) {
        s.insert(0, 'P');
    }
    s
}

fn unique(name: String, taken: &mut HashSet<String>) -> String {
    let mut n = name.clone();
    let mut k = 1;
    while !taken.insert(n.to_ascii_uppercase()) {
        k += 1;
        n = format!("{name}_{k}");
    }
    n
}
