//! The `il!` macro's expansion, here so that it is testable; `il-macros`
//! only turns the call's tokens into [`Tok`]s and the result back into
//! tokens.
//!
//! Forms: `il!(r#"...IL..."#)`, `il!(file = "plc/motor.il")` and
//! `il!(files = ["plc/types.il", "plc/tank.xml"])` (relative to the crate
//! being compiled; the files are tracked so edits rebuild; XML files, by
//! their text or a `.xml` name, are PLCopen projects), each optionally followed by `, serde` to derive
//! serde's traits on the generated types. One call is one program: its
//! POUs see each other's TYPEs and FBs, and no other call's.

mod input;
mod literal;

pub use input::{CALL_SITE, SpanId, Tok};

use crate::diag::{SourceFile, has_errors, render::render_short_in};
use crate::pipeline::Program;
use crate::{emit, sema, syntax};
pub use input::RustPlace;
use input::{Input, Refusal};

/// The most IL one `il!` call takes (IL0035): beyond it, build.rs.
const MAX_MACRO_INPUT: usize = 16 << 20;

/// What `il!` expands to: Rust source text, and errors, each to become a
/// `compile_error!` at its span.
#[derive(Debug, Default)]
pub struct Expansion {
    /// The generated items (with stubs of the POUs when there are errors,
    /// so that one mistake does not cascade into the user's code).
    pub code: String,
    /// Messages with the IL line, column and snippet, and where to put them.
    pub errors: Vec<(String, SpanId)>,
}

impl Expansion {
    fn error(msg: String, span: SpanId) -> Expansion {
        Expansion {
            code: String::new(),
            errors: vec![(msg, span)],
        }
    }
}

impl From<Refusal> for Expansion {
    fn from(r: Refusal) -> Expansion {
        Expansion::error(r.msg, r.span)
    }
}

/// Expand `il!(...)`: the generated items, or one error per diagnostic
/// (with the IL line, column and snippet) plus stubs of the POUs.
pub fn expand(tokens: &[Tok]) -> Expansion {
    // A bug in the compiler must still reach the user as a message that says
    // what happened, not as "proc macro panicked" with nothing else.
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| expand_inner(tokens))) {
        Ok(t) => t,
        Err(e) => {
            let what = e
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| e.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            let msg = format!(
                "internal error in the IL compiler (please report it with the IL source): {what}"
            );
            Expansion::error(msg, CALL_SITE)
        }
    }
}

fn expand_inner(tokens: &[Tok]) -> Expansion {
    let mut place = None;
    let (input, flags) = match input::parse(tokens) {
        Ok(x) => x,
        Err(r) => return r.into(),
    };
    let opts = emit::Options {
        serde: flags.serde,
        ..Default::default()
    };
    // Each source with the literal its errors point at.
    let mut sources: Vec<(SourceFile, SpanId)> = Vec::new();
    let mut track = String::new();
    match input {
        Input::Inline(lit) => {
            // The IL's line 1 is the rest of the line where the string starts
            // (none when the compiler does not report locations).
            place = lit.place;
            sources.push((SourceFile::new("il! input", lit.value), lit.span));
        }
        Input::Files(lits) => {
            let base = std::env::var_os("CARGO_MANIFEST_DIR")
                .map(std::path::PathBuf::from)
                .unwrap_or_default();
            let mut unreadable = Expansion::default();
            for lit in lits {
                let path = base.join(&lit.value);
                match crate::read::read_source(&path, &lit.value, flags.encoding) {
                    Ok(file) => {
                        // include_bytes! makes cargo rebuild when the file changes.
                        let abs = path.display().to_string();
                        track.push_str(&format!("const _: &[u8] = include_bytes!({abs:?});\n"));
                        sources.push((file, lit.span));
                    }
                    Err(e) => {
                        let msg =
                            format!("cannot read source file `{}`: {}", path.display(), e.reason);
                        unreadable.errors.push((msg, lit.span));
                    }
                }
            }
            if !unreadable.errors.is_empty() {
                return unreadable;
            }
        }
    }
    let total: usize = sources.iter().map(|(f, _)| f.text.len()).sum();
    if total > MAX_MACRO_INPUT {
        let msg = format!(
            "{}: il! takes at most 16 MiB of IL, this call has {} MiB: compile it with il_codegen::Builder in build.rs",
            crate::syntax::code::MACRO_TOO_LARGE,
            total.div_ceil(1 << 20)
        );
        return Expansion::error(msg, sources.first().map_or(CALL_SITE, |s| s.1));
    }
    let checked = sources
        .iter()
        .fold(Program::new().standard(flags.standard), |p, (f, _)| {
            p.input(flags.dialect.input(f.clone()))
        })
        .check();
    let mut out = Expansion {
        code: track,
        errors: Vec::new(),
    };
    if let Some(emitted) = checked.emit(opts) {
        for e in emitted {
            out.code.push_str(&e.text);
            out.code.push('\n');
        }
        return out;
    }
    for ((input, diags), (_, span)) in checked.reports().zip(&sources) {
        for d in diags.iter().filter(|d| d.is_error()) {
            // A file's message names it on its arrow line, as rustc would.
            let msg = render_short_in(input.source(), d, place.as_ref());
            out.errors.push((msg, *span));
        }
    }
    let files: Vec<&SourceFile> = checked.inputs().iter().map(|i| i.il_text()).collect();
    out.code.push_str(&stubs(&files, opts, flags.standard));
    out
}

/// Items with the interfaces of every POU that could be checked, and empty
/// bodies; emitted only next to `compile_error!`s.
fn stubs(files: &[&SourceFile], opts: emit::Options, standard: crate::Standard) -> String {
    let parsed: Vec<_> = files.iter().map(|f| syntax::parse(f)).collect();
    // Files whose syntax errors left no items have nothing to stub.
    let pairs: Vec<_> = files
        .iter()
        .zip(&parsed)
        .filter(|(_, (unit, diags))| !(has_errors(diags) && unit.items.is_empty()))
        .map(|(f, (unit, _))| (*f, unit))
        .collect();
    if pairs.is_empty() {
        return String::new();
    }
    let (programs, diags) = sema::check_all(&pairs, standard, false);
    let mut program = sema::ir::Program::default();
    for p in programs {
        program.types.extend(p.types);
        program.pous.extend(p.pous);
        program.configs.extend(p.configs);
    }
    // A FUNCTION_BLOCK that contains itself cannot be a Rust struct at all.
    if diags
        .iter()
        .flatten()
        .any(|d| d.code == sema::codes::RECURSION)
    {
        return String::new();
    }
    for p in &mut program.pous {
        p.body.clear();
        p.places.clear();
        p.cr_types.clear();
        p.save_types.clear();
        p.label_count = 0;
    }
    // A program instance whose globals could not all be bound would call
    // its program with a wrong argument: leave it out of the stub.
    let externals = |name: &str| {
        program.pous.iter().find(|p| p.name == name).map(|p| {
            p.vars
                .iter()
                .filter(|v| v.kind == crate::ast::VarKind::External && v.location.is_none())
                .count()
        })
    };
    let mut configs = std::mem::take(&mut program.configs);
    for c in &mut configs {
        // VAR_CONFIG and VAR_ACCESS name an instance by its position: each
        // instance's new position, `None` for one left out.
        let mut kept: Vec<Vec<Option<usize>>> = Vec::new();
        for r in &mut c.resources {
            let (mut at, mut n) = (Vec::new(), 0);
            r.programs.retain(|pi| {
                let bound = externals(&pi.program) == Some(pi.externals.len());
                at.push(bound.then_some(n));
                n += usize::from(bound);
                bound
            });
            kept.push(at);
        }
        let moved = |p: &mut sema::ir::InstancePath| match kept[p.resource][p.program] {
            Some(k) => {
                p.program = k;
                true
            }
            None => false,
        };
        c.var_config.retain_mut(|v| moved(&mut v.target));
        c.access.retain_mut(|a| match &mut a.target {
            sema::ir::AccessTarget::Instance(p) => moved(p),
            sema::ir::AccessTarget::Global { .. } => true,
        });
    }
    program.configs = configs;
    emit::program(&program, opts)
}

#[cfg(test)]
mod tests;
