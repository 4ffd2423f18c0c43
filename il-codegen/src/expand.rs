//! The `il!` macro's expansion, on proc_macro2 types so that it is testable
//! here; `il-macros` only converts the token streams.
//!
//! Forms: `il!(r#"...IL..."#)` and `il!(file = "plc/motor.il")` (relative to
//! the crate being compiled; the file is tracked so edits rebuild), either
//! followed by `, serde` to derive serde's traits on the generated types.

use crate::diag::{SourceFile, has_errors, render::render_short_in};
use crate::pipeline::Program;
use crate::{emit, sema, syntax};
use proc_macro2::{Span, TokenStream};
use quote::{quote, quote_spanned};

enum Input {
    Inline(syn::LitStr),
    File(syn::LitStr),
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

const USAGE: &str = "il! takes Instruction List as a string, `il!(r#\"...IL...\"#)`, or a file relative to the crate, `il!(file = \"plc/motor.il\")`, optionally followed by `, serde` and `, std = \"iec2003\"`";

fn parse_input(tokens: TokenStream) -> syn::Result<(Input, Flags)> {
    syn::parse::Parser::parse2(
        |ps: syn::parse::ParseStream| {
            if ps.peek(syn::LitStr) {
                let lit: syn::LitStr = ps.parse()?;
                return Ok((Input::Inline(lit), parse_flags(ps)?));
            }
            let kw: syn::Ident = ps.parse()?;
            if kw != "file" {
                return Err(syn::Error::new(kw.span(), USAGE));
            }
            let _: syn::Token![=] = ps.parse()?;
            let lit: syn::LitStr = ps.parse()?;
            Ok((Input::File(lit), parse_flags(ps)?))
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
    let (file, lit_span, track) = match input {
        Input::Inline(lit) => {
            // The IL's line 1 is the rest of the line where the string starts
            // (0 when the compiler does not report locations).
            let line = lit.span().start().line;
            first_line = (line > 0).then_some(line);
            (
                SourceFile::new("il! input", lit.value()),
                lit.span(),
                quote!(),
            )
        }
        Input::File(lit) => {
            let rel = lit.value();
            let base = std::env::var_os("CARGO_MANIFEST_DIR")
                .map(std::path::PathBuf::from)
                .unwrap_or_default();
            let path = base.join(&rel);
            match crate::read::read_source(&path, &rel) {
                Ok(file) => {
                    let abs = path.display().to_string();
                    // include_bytes! makes cargo rebuild when the file changes.
                    (
                        file,
                        lit.span(),
                        quote!(
                            const _: &[u8] = include_bytes!(#abs);
                        ),
                    )
                }
                Err(e) => {
                    let msg = format!("cannot read IL file `{}`: {}", path.display(), e.reason);
                    return quote_spanned!(lit.span()=> ::core::compile_error!(#msg););
                }
            }
        }
    };
    let checked = Program::new().standard(flags.standard).il(file).check();
    if let Some(mut emitted) = checked.emit(opts) {
        let items = emitted.pop().map(|e| e.tokens).unwrap_or_default();
        return quote!(#track #items);
    }
    let file = checked.inputs()[0].source();
    let errors = checked.diagnostics()[0]
        .iter()
        .filter(|d| d.is_error())
        .map(|d| {
            let msg = render_short_in(file, d, first_line);
            quote_spanned!(lit_span=> ::core::compile_error!(#msg);)
        });
    let stubs = stubs(file, opts);
    quote!(#track #(#errors)* #stubs)
}

/// Items with the interfaces of every POU that could be checked, and empty
/// bodies; emitted only next to `compile_error!`s.
fn stubs(file: &SourceFile, opts: emit::Options) -> TokenStream {
    let (unit, diags) = syntax::parse(file);
    if has_errors(&diags) && unit.items.is_empty() {
        return TokenStream::new();
    }
    let (mut program, diags) = sema::check(file, &unit);
    // A FUNCTION_BLOCK that contains itself cannot be a Rust struct at all.
    if diags.iter().any(|d| d.code == sema::codes::RECURSION) {
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
    let _ = Span::call_site();
    emit::program(&program, opts)
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
