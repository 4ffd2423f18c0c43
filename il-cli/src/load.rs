//! The one loader of what `ilc run` and `ilc debug` run: the files (IL,
//! PLCopen XML, CODESYS `.EXP`, folders of them, expanded by the caller)
//! read in `--encoding`, checked together as one program, joined, and the
//! PROGRAM, FUNCTION_BLOCK or CONFIGURATION to run chosen as `ilc run`
//! chooses it.

use il_codegen::ir::{PouKind, Program};

use crate::input::Front;
use crate::source_map::SourceMap;

/// What to load and run.
pub struct Request<'a> {
    pub files: &'a [String],
    pub front: Front,
    /// The POU to run (`--program`, launch `pou`).
    pub program: Option<&'a str>,
    /// The CONFIGURATION to run (`--config`, launch `configuration`).
    pub config: Option<&'a str>,
    /// How the two options are named in messages: (`--program`, `--config`).
    pub names: (&'a str, &'a str),
    /// ANSI colours in the rendered diagnostics.
    pub color: bool,
}

/// What runs.
#[derive(Clone, Debug, PartialEq)]
pub enum Chosen {
    /// A PROGRAM or FUNCTION_BLOCK alone.
    Pou(String),
    /// A CONFIGURATION with its tasks.
    Config(String),
}

/// The checked program (the files joined), where its lines are, and what runs.
pub struct Loaded {
    pub prog: Program,
    pub map: SourceMap,
    pub chosen: Chosen,
    /// A Modicon M221 program (`.smbp`, `--dialect m221`): `%` names are
    /// its objects (`%I0.3`, `%MW1`), [`il_codegen::m221::il_name`].
    pub m221: bool,
}

/// The checked programs of several files as one.
fn join(many: &[Program]) -> Program {
    let mut out = Program {
        file: many.first().map(|p| p.file.clone()).unwrap_or_default(),
        ..Default::default()
    };
    for p in many {
        out.types.extend(p.types.iter().cloned());
        out.pous.extend(p.pous.iter().cloned());
        out.configs.extend(p.configs.iter().cloned());
    }
    out
}

/// Load `r`: the rendered diagnostics (warnings too, also when it fails),
/// and the program or why it cannot run.
pub fn load(r: &Request) -> (String, Result<Loaded, String>) {
    let files = match r
        .files
        .iter()
        .map(|f| r.front.read(f))
        .collect::<Result<Vec<_>, _>>()
    {
        Ok(f) => f,
        Err(e) => return (String::new(), Err(e)),
    };
    if files.is_empty() {
        return (String::new(), Err("no source file to run".into()));
    }
    let checked = r.front.program(files).check();
    let mut rendered = checked.render(r.color);
    let loaded = choose(r, &checked);
    if let (Ok(l), None) = (&loaded, r.program) {
        rendered.push_str(&alone_note(l, r.names.1));
    }
    (rendered, loaded)
}

/// A PROGRAM chosen to run alone in a program that has a CONFIGURATION:
/// its VAR_EXTERNALs start at their types' defaults, not at the globals'
/// initial values, which the user is told (with the option that runs the
/// configuration) rather than left to find in the values.
fn alone_note(l: &Loaded, c_opt: &str) -> String {
    let (Chosen::Pou(name), [config]) = (&l.chosen, l.prog.configs.as_slice()) else {
        return String::new();
    };
    let Some(pou) = l
        .prog
        .pous
        .iter()
        .find(|p| p.name.eq_ignore_ascii_case(name))
    else {
        return String::new();
    };
    let externals: Vec<&str> = (pou.vars.iter())
        .filter(|v| v.kind == il_codegen::ast::VarKind::External)
        .map(|v| v.name.as_str())
        .collect();
    if externals.is_empty() {
        return String::new();
    }
    format!(
        "note: PROGRAM `{name}` runs alone: its VAR_EXTERNALs ({}) start at their types' \
         defaults, not at the initial values of CONFIGURATION `{c}`'s globals; \
         {c_opt} {c} runs the configuration as the PLC does\n",
        externals.join(", "),
        c = config.name,
    )
}

fn choose(r: &Request, checked: &il_codegen::Checked) -> Result<Loaded, String> {
    let file = r.files.join("`, `");
    let Some(progs) = checked.ir() else {
        return Err(format!("`{file}` has errors; nothing was run"));
    };
    // Several files are one program: the interpreter finds POUs, types and
    // configurations by name, so their checked programs are joined.
    let prog = match progs {
        [one] => one.clone(),
        many => join(many),
    };
    let (p_opt, c_opt) = r.names;
    if r.program.is_some() && r.config.is_some() {
        return Err(format!("give {p_opt} or {c_opt}, not both"));
    }
    let programs: Vec<&str> = prog
        .pous
        .iter()
        .filter(|p| p.kind == PouKind::Program)
        .map(|p| p.name.as_str())
        .collect();
    // A CONFIGURATION is run when named, or when no program is named and
    // the only CONFIGURATION is the one thing to run (a file with one
    // PROGRAM runs that program, as it did before configurations could
    // run). A CODESYS project with a task configuration runs it, as the PLC
    // does, and so does an M221 project.
    let exp_tasks = checked.inputs().iter().any(|i| match i {
        il_codegen::Input::Exp(e) => e
            .objects()
            .iter()
            .any(|ob| ob.kind == il_codegen::exp::ObjectKind::Tasks),
        // A Modicon M221 project runs its POUs, in order, as one task.
        il_codegen::Input::PlcOpen(i) => i.is_m221(),
        _ => false,
    });
    let m221 = checked.inputs().iter().any(|i| match i {
        il_codegen::Input::PlcOpen(i) => i.is_m221(),
        _ => false,
    });
    let chosen = match (r.config, r.program, prog.configs.as_slice()) {
        (Some(c), _, _) => Chosen::Config(c.to_string()),
        (None, None, [one]) if programs.len() != 1 || exp_tasks => Chosen::Config(one.name.clone()),
        (None, Some(p), _) => Chosen::Pou(p.to_string()),
        (None, None, _) => match programs.as_slice() {
            [one] => Chosen::Pou(one.to_string()),
            [] => {
                return Err(format!(
                    "`{file}` has no PROGRAM; name a FUNCTION_BLOCK with {p_opt}"
                ));
            }
            many => {
                let configs: Vec<&str> = prog.configs.iter().map(|c| c.name.as_str()).collect();
                let also = if configs.is_empty() {
                    String::new()
                } else {
                    format!(", or a CONFIGURATION ({}) with {c_opt}", configs.join(", "))
                };
                return Err(format!(
                    "`{file}` has several PROGRAMs ({}); choose one with {p_opt}{also}",
                    many.join(", ")
                ));
            }
        },
    };
    Ok(Loaded {
        prog,
        map: SourceMap::of(checked),
        chosen,
        m221,
    })
}

/// The name to look up for one the user wrote: in an M221 program an
/// object as the program writes it (`%I0.3`, `%C0.V`) is the import's
/// global (`I0_3`, `C0.V`); anything else is looked up as written.
pub fn program_name(name: &str, m221: bool) -> std::borrow::Cow<'_, str> {
    // A bit of a word (`%MW4:X3`) is no variable the run can name.
    if m221 && name.to_ascii_uppercase().contains(":X") {
        return std::borrow::Cow::Borrowed(name);
    }
    match m221.then(|| il_codegen::m221::il_name(name)).flatten() {
        Some(il) => std::borrow::Cow::Owned(il),
        None => std::borrow::Cow::Borrowed(name),
    }
}
