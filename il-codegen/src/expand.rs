//! The `il!` macro's expansion, on proc_macro2 types so that it is testable
//! here; `il-macros` only converts the token streams.
//!
//! Forms: `il!(r#"...IL..."#)`, `il!(file = "plc/motor.il")` and
//! `il!(files = ["plc/types.il", "plc/tank.xml"])` (relative to the crate
//! being compiled; the files are tracked so edits rebuild; `.xml` files are
//! PLCopen projects), each optionally followed by `, serde` to derive
//! serde's traits on the generated types. One call is one program: its
//! POUs see each other's TYPEs and FBs, and no other call's.

use crate::diag::{SourceFile, has_errors, render::render_short_in};
use crate::pipeline::Program;
use crate::{emit, sema, syntax};
use proc_macro2::{Span, TokenStream};
use quote::{quote, quote_spanned};

enum Input {
    Inline(syn::LitStr),
    /// `file = "a.il"` or `files = ["a.il", "b.xml"]`: one program.
    Files(Vec<syn::LitStr>),
}

/// What may follow the IL: `, serde` and `, std = "iec2003"`.
#[derive(Clone, Copy, Default)]
struct Flags {
    serde: bool,
    standard: crate::Standard,
}

fn parse_flags(ps: syn::parse::ParseStream) -> syn::Result<Flags> {
    let mut flags = Flags::default();
    while ps.parse::<Option<syn::Token![,]>>()?.is_some() {
        if ps.is_empty() {
            break;
        }
        let flag: syn::Ident = ps.parse()?;
        if flag == "serde" {
            flags.serde = true;
        } else if flag == "std" {
            let _: syn::Token![=] = ps.parse()?;
            let name: syn::LitStr = ps.parse()?;
            flags.standard = crate::Standard::from_name(&name.value()).ok_or_else(|| {
                syn::Error::new(
                    name.span(),
                    format!(
                        "unknown standard `{}`: use `std = \"iec2003\"` (2nd edition, strict) or `std = \"iec2013\"` (the default)",
                        name.value()
                    ),
                )
            })?;
        } else {
            return Err(syn::Error::new(flag.span(), USAGE));
        }
    }
    if !ps.is_empty() {
        return Err(ps.error(USAGE));
    }
    Ok(flags)
}

/// The most IL one `il!` call takes (IL0035): beyond it, build.rs.
const MAX_MACRO_INPUT: usize = 16 << 20;

const USAGE: &str = "il! takes Instruction List as a string, `il!(r#\"...IL...\"#)`, or files relative to the crate, `il!(file = \"plc/motor.il\")` or `il!(files = [\"plc/types.il\", \"plc/tank.il\"])` (one program: a POU may use the TYPEs and FBs of every file), optionally followed by `, serde` and `, std = \"iec2003\"`";

fn parse_input(tokens: TokenStream) -> syn::Result<(Input, Flags)> {
    syn::parse::Parser::parse2(
        |ps: syn::parse::ParseStream| {
            if ps.peek(syn::LitStr) {
                let lit: syn::LitStr = ps.parse()?;
                return Ok((Input::Inline(lit), parse_flags(ps)?));
            }
            let kw: syn::Ident = ps.parse()?;
            let _: syn::Token![=] = ps.parse()?;
            let files = if kw == "file" {
                vec![ps.parse::<syn::LitStr>()?]
            } else if kw == "files" {
                let list;
                syn::bracketed!(list in ps);
                let lits = list.parse_terminated(|p| p.parse::<syn::LitStr>(), syn::Token![,])?;
                let lits: Vec<syn::LitStr> = lits.into_iter().collect();
                if lits.is_empty() {
                    return Err(syn::Error::new(kw.span(), "`files = [...]` lists no file"));
                }
                for (i, l) in lits.iter().enumerate() {
                    if lits[..i].iter().any(|o| o.value() == l.value()) {
                        return Err(syn::Error::new(
                            l.span(),
                            format!("`{}` is listed twice", l.value()),
                        ));
                    }
                }
                lits
            } else {
                return Err(syn::Error::new(kw.span(), USAGE));
            };
            Ok((Input::Files(files), parse_flags(ps)?))
        },
        tokens,
    )
}

/// Expand `il!(...)`: the generated items, or `compile_error!`s (one per
/// diagnostic, with the IL line, column and snippet) plus stubs of the POUs
/// so that one mistake does not cascade into errors in the user's code.
pub fn expand(tokens: TokenStream) -> TokenStream {
    // A bug in the compiler must still reach the user as a message that says
    // what happened, not as "proc macro panicked" with nothing else.
    let span = Span::call_site();
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
            quote_spanned!(span=> ::core::compile_error!(#msg);)
        }
    }
}

fn expand_inner(tokens: TokenStream) -> TokenStream {
    let mut first_line = None;
    let (input, flags) = match parse_input(tokens) {
        // syn's own messages ("expected identifier") say nothing about il!;
        // ours (an unknown standard) do.
        Err(e) if e.to_string().starts_with("unknown standard") => return e.to_compile_error(),
        Err(e) => return syn::Error::new(e.span(), USAGE).to_compile_error(),
        Ok(x) => x,
    };
    let opts = emit::Options {
        serde: flags.serde,
        ..Default::default()
    };
    // Each source with the literal its errors point at.
    let mut sources: Vec<(SourceFile, Span)> = Vec::new();
    let mut track = TokenStream::new();
    match input {
        Input::Inline(lit) => {
            // The IL's line 1 is the rest of the line where the string starts
            // (0 when the compiler does not report locations).
            let line = lit.span().start().line;
            first_line = (line > 0).then_some(line);
            sources.push((SourceFile::new("il! input", lit.value()), lit.span()));
        }
        Input::Files(lits) => {
            let base = std::env::var_os("CARGO_MANIFEST_DIR")
                .map(std::path::PathBuf::from)
                .unwrap_or_default();
            let mut unreadable = TokenStream::new();
            for lit in lits {
                let rel = lit.value();
                let path = base.join(&rel);
                match crate::read::read_source(&path, &rel) {
                    Ok(file) => {
                        let abs = path.display().to_string();
                        // include_bytes! makes cargo rebuild when the file changes.
                        track.extend(quote!(
                            const _: &[u8] = include_bytes!(#abs);
                        ));
                        sources.push((file, lit.span()));
                    }
                    Err(e) => {
                        let msg = format!("cannot read IL file `{}`: {}", path.display(), e.reason);
                        unreadable
                            .extend(quote_spanned!(lit.span()=> ::core::compile_error!(#msg);));
                    }
                }
            }
            if !unreadable.is_empty() {
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
        let span = sources.first().map_or_else(Span::call_site, |s| s.1);
        return quote_spanned!(span=> ::core::compile_error!(#msg););
    }
    let checked = sources
        .iter()
        .fold(Program::new().standard(flags.standard), |p, (f, _)| {
            p.source(f.clone())
        })
        .check();
    if let Some(emitted) = checked.emit(opts) {
        let mut items = track;
        let text: String = emitted.iter().map(|e| e.text.as_str()).collect();
        items.extend(tokens_of(&text));
        return items;
    }
    let mut errors = TokenStream::new();
    for ((input, diags), (_, span)) in checked.reports().zip(&sources) {
        for d in diags.iter().filter(|d| d.is_error()) {
            let mut msg = render_short_in(input.source(), d, first_line);
            // A file's message names it: with several, the line alone is ambiguous.
            if first_line.is_none() {
                msg = format!("{}: {msg}", input.source().name);
            }
            errors.extend(quote_spanned!(*span=> ::core::compile_error!(#msg);));
        }
    }
    let files: Vec<&SourceFile> = checked.inputs().iter().map(|i| i.il_text()).collect();
    let stubs = stubs(&files, opts, flags.standard);
    quote!(#track #errors #stubs)
}

/// Items with the interfaces of every POU that could be checked, and empty
/// bodies; emitted only next to `compile_error!`s.
fn stubs(files: &[&SourceFile], opts: emit::Options, standard: crate::Standard) -> TokenStream {
    let parsed: Vec<_> = files.iter().map(|f| syntax::parse(f)).collect();
    // Files whose syntax errors left no items have nothing to stub.
    let pairs: Vec<_> = files
        .iter()
        .zip(&parsed)
        .filter(|(_, (unit, diags))| !(has_errors(diags) && unit.items.is_empty()))
        .map(|(f, (unit, _))| (*f, unit))
        .collect();
    if pairs.is_empty() {
        return TokenStream::new();
    }
    let (programs, diags) = sema::check_all(&pairs, standard);
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
        return TokenStream::new();
    }
    for p in &mut program.pous {
        p.body.clear();
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
        for r in &mut c.resources {
            r.programs
                .retain(|pi| externals(&pi.program) == Some(pi.externals.len()));
        }
    }
    program.configs = configs;
    tokens_of(&emit::program(&program, opts))
}

/// The emitted Rust text as tokens (parsed once, here). Text that does not
/// parse is a bug of the emitter, never of the user's IL: it becomes a
/// `compile_error!` that says so, not a panic.
fn tokens_of(text: &str) -> TokenStream {
    match text.parse::<TokenStream>() {
        Ok(t) => t,
        Err(e) => {
            let msg = format!(
                "internal error in the IL compiler (please report it with the IL source): the generated Rust does not parse: {e}"
            );
            quote!(::core::compile_error!(#msg);)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::expand;
    use quote::quote;

    #[test]
    fn serde_flag_derives_and_unknown_flags_are_refused() {
        let il = "FUNCTION_BLOCK F\nVAR x : INT; END_VAR\n    LD x\n    ST x\nEND_FUNCTION_BLOCK\n";
        let plain = expand(quote!(#il)).to_string();
        assert!(!plain.contains("serde"), "{plain}");
        let with = expand(quote!(#il, serde)).to_string();
        assert!(with.contains(":: serde :: Serialize"), "{with}");
        let with_comma = expand(quote!(#il, serde,)).to_string();
        assert_eq!(with, with_comma);
        let bad = expand(quote!(#il, serdes)).to_string();
        assert!(
            bad.contains("compile_error") && bad.contains("serde"),
            "{bad}"
        );
        let trailing = expand(quote!(#il, )).to_string();
        assert_eq!(trailing, plain);
    }

    #[test]
    fn an_input_over_16_mib_is_refused_with_its_code() {
        let mut il = String::from("PROGRAM P\nVAR x : INT; END_VAR\n");
        while il.len() <= super::MAX_MACRO_INPUT / 2 {
            il.push_str("    LD x\n    ST x\n");
        }
        // Two files of 8 MiB each: the limit is on the call, not per file.
        let dir = std::env::temp_dir().join(format!("il-expand-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (a, b) = (dir.join("a.il"), dir.join("b.il"));
        std::fs::write(&a, format!("{il}END_PROGRAM\n")).unwrap();
        std::fs::write(
            &b,
            format!("{}END_PROGRAM\n", il.replace("PROGRAM P", "PROGRAM Q")),
        )
        .unwrap();
        let (a, b) = (a.display().to_string(), b.display().to_string());
        let out = expand(quote!(files = [#a, #b])).to_string();
        let _ = std::fs::remove_dir_all(&dir);
        assert!(
            out.contains("compile_error") && out.contains("IL0035"),
            "{}",
            &out[..200.min(out.len())]
        );
        assert!(!out.contains("struct"), "nothing is compiled");
    }

    #[test]
    fn std_option_selects_the_standard() {
        let il = "PROGRAM P\nVAR s : SINT; i : INT; END_VAR\n    LD s\n    ST i\nEND_PROGRAM\n";
        let plain = expand(quote!(#il)).to_string();
        assert!(!plain.contains("compile_error"), "{plain}");
        assert_eq!(expand(quote!(#il, std = "iec2013")).to_string(), plain);
        let strict = expand(quote!(#il, serde, std = "IEC2003")).to_string();
        assert!(
            strict.contains("compile_error") && strict.contains("IL0302"),
            "{strict}"
        );
        assert!(strict.contains("implicit conversion SINT → INT is a 3rd-edition feature"));
        let bad = expand(quote!(#il, std = "iec1993")).to_string();
        assert!(bad.contains("unknown standard `iec1993`"), "{bad}");
    }
}
