//! The `il!` macro's expansion, on proc_macro2 types so that it is testable
//! here; `il-macros` only converts the token streams.
//!
//! Forms: `il!(r#"...IL..."#)` and `il!(file = "plc/motor.il")` (relative to
//! the crate being compiled; the file is tracked so edits rebuild).

use crate::compile::compile;
use crate::diag::{SourceFile, has_errors, render::render_short};
use crate::{emit, sema, syntax};
use proc_macro2::{Span, TokenStream};
use quote::{quote, quote_spanned};

enum Input {
    Inline(syn::LitStr),
    File(syn::LitStr),
}

fn parse_input(tokens: TokenStream) -> syn::Result<Input> {
    syn::parse::Parser::parse2(
        |ps: syn::parse::ParseStream| {
            if ps.peek(syn::LitStr) {
                let lit: syn::LitStr = ps.parse()?;
                let _: Option<syn::Token![,]> = ps.parse()?;
                return Ok(Input::Inline(lit));
            }
            let kw: syn::Ident = ps.parse()?;
            if kw != "file" {
                return Err(syn::Error::new(
                    kw.span(),
                    "expected a string of IL (`il!(r#\"...\"#)`) or `file = \"path.il\"`",
                ));
            }
            let _: syn::Token![=] = ps.parse()?;
            let lit: syn::LitStr = ps.parse()?;
            let _: Option<syn::Token![,]> = ps.parse()?;
            Ok(Input::File(lit))
        },
        tokens,
    )
}

/// Expand `il!(...)`: the generated items, or `compile_error!`s (one per
/// diagnostic, with the IL line, column and snippet) plus stubs of the POUs
/// so that one mistake does not cascade into errors in the user's code.
pub fn expand(tokens: TokenStream) -> TokenStream {
    let (file, lit_span, track) = match parse_input(tokens) {
        Err(e) => return e.to_compile_error(),
        Ok(Input::Inline(lit)) => (
            SourceFile::new("il! input", lit.value()),
            lit.span(),
            quote!(),
        ),
        Ok(Input::File(lit)) => {
            let rel = lit.value();
            let base = std::env::var_os("CARGO_MANIFEST_DIR")
                .map(std::path::PathBuf::from)
                .unwrap_or_default();
            let path = base.join(&rel);
            match std::fs::read_to_string(&path) {
                Ok(text) => {
                    let abs = path.display().to_string();
                    // include_bytes! makes cargo rebuild when the file changes.
                    (
                        SourceFile::new(rel, text),
                        lit.span(),
                        quote!(
                            const _: &[u8] = include_bytes!(#abs);
                        ),
                    )
                }
                Err(e) => {
                    let msg = format!("cannot read IL file `{}`: {e}", path.display());
                    return quote_spanned!(lit.span()=> ::core::compile_error!(#msg););
                }
            }
        }
    };
    match compile(&file, emit::Options::default()) {
        Ok(c) => {
            let items = c.tokens;
            quote!(#track #items)
        }
        Err(diags) => {
            let errors = diags.iter().filter(|d| d.is_error()).map(|d| {
                let msg = render_short(&file, d);
                quote_spanned!(lit_span=> ::core::compile_error!(#msg);)
            });
            let stubs = stubs(&file);
            quote!(#track #(#errors)* #stubs)
        }
    }
}

/// Items with the interfaces of every POU that could be checked, and empty
/// bodies; emitted only next to `compile_error!`s.
fn stubs(file: &SourceFile) -> TokenStream {
    let (unit, diags) = syntax::parse(file);
    if has_errors(&diags) && unit.items.is_empty() {
        return TokenStream::new();
    }
    let (mut program, _) = sema::check(file, &unit);
    for p in &mut program.pous {
        p.body.clear();
        p.cr_types.clear();
        p.save_types.clear();
        p.label_count = 0;
    }
    let _ = Span::call_site();
    emit::program(&program, emit::Options::default())
}
