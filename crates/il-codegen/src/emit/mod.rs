//! The emitter: checked IR → Rust tokens.
//!
//! Everything here is total: the checker has already refused whatever could
//! not compile. Generated code never panics: integer arithmetic wraps,
//! DIV/MOD by zero yields 0 and records a fault in the cycle context, array
//! accesses go through `get` and record a fault when out of range.

mod flow;
mod names;
mod values;

use crate::ast::{PouKind, VarKind};
use crate::sema::ir::{CheckedPou, Program};
use crate::sema::types::Ty;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

pub use names::rust_ident;

/// How to emit.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// Put `__il_line!(N);` markers before the code of each IL line; the file
    /// writer turns them into `// N: <IL text>` comments after formatting.
    pub line_markers: bool,
}

/// Emit every POU of a checked program.
pub fn program(p: &Program, opts: Options) -> TokenStream {
    let items = p.pous.iter().map(|pou| emit_pou(pou, opts));
    quote!(#(#items)*)
}

/// The Rust type of an IEC type; user FBs are items beside the generated code.
pub(crate) fn rust_ty(t: &Ty) -> TokenStream {
    t.rust(&|name| {
        if is_std_fb(name) {
            let id = format_ident!("{}", name);
            quote!(::il_std::#id)
        } else {
            let id = rust_ident(name);
            quote!(#id)
        }
    })
}

fn is_std_fb(name: &str) -> bool {
    crate::sema::is_std_fb(name)
}

struct Pou<'a> {
    pou: &'a CheckedPou,
    opts: Options,
}

impl Pou<'_> {
    /// Whether variable `i` lives in `self` (FB/PROGRAM memory) or is a local.
    fn in_self(&self, i: usize) -> bool {
        self.pou.kind != PouKind::Function && self.pou.vars[i].kind != VarKind::Temp
    }
}

fn emit_pou(pou: &CheckedPou, opts: Options) -> TokenStream {
    let p = Pou { pou, opts };
    let name = rust_ident(&pou.name);
    let body = p.body();
    let cr_locals = pou.cr_types.iter().map(|t| {
        let id = values::cr_ident(t);
        let ty = rust_ty(t);
        let d = values::default_value(t);
        quote!(let mut #id: #ty = #d;)
    });
    let save_locals = pou.save_types.iter().enumerate().map(|(i, t)| {
        let id = format_ident!("__save_{}", i);
        let ty = rust_ty(t);
        let d = values::default_value(t);
        quote!(let mut #id: #ty = #d;)
    });
    let temp_locals = pou.vars.iter().enumerate().filter(|(i, v)| {
        !p.in_self(*i)
            && !(pou.kind == PouKind::Function
                && matches!(v.kind, VarKind::Input | VarKind::Output))
    });
    let temp_locals = temp_locals.map(|(_, v)| {
        let id = rust_ident(&v.name);
        let ty = rust_ty(&v.ty);
        let init = values::init_value(&v.ty, v.init.as_ref());
        quote!(let mut #id: #ty = #init;)
    });
    let locals = quote!(#(#cr_locals)* #(#save_locals)* #(#temp_locals)*);
    let doc = format!(
        " IEC 61131-3 {} `{}`, generated from Instruction List.",
        pou.kind.keyword(),
        pou.name
    );
    let allow = quote!(#[allow(non_snake_case, unused_mut, unused_variables, unused_assignments, unreachable_code, unused_labels, clippy::all)]);

    match pou.kind {
        PouKind::Function => {
            let ret_ty = pou
                .ret
                .as_ref()
                .map(rust_ty)
                .unwrap_or_else(|| quote!(bool));
            let ret_default = pou
                .ret
                .as_ref()
                .map(values::default_value)
                .unwrap_or_else(|| quote!(false));
            let params = pou
                .vars
                .iter()
                .filter(|v| v.kind == VarKind::Input)
                .map(|v| {
                    let id = rust_ident(&v.name);
                    let ty = rust_ty(&v.ty);
                    quote!(mut #id: #ty)
                });
            let outs = pou
                .vars
                .iter()
                .filter(|v| v.kind == VarKind::Output)
                .map(|v| {
                    let id = rust_ident(&v.name);
                    let ty = rust_ty(&v.ty);
                    quote!(#id: &mut #ty)
                });
            quote! {
                #[doc = #doc]
                #allow
                pub fn #name(__ctx: &mut ::il_std::Cycle, #(#params,)* #(#outs,)*) -> #ret_ty {
                    let mut __ret: #ret_ty = #ret_default;
                    let mut __eno: bool = true;
                    #locals
                    #body
                    __ret
                }
            }
        }
        PouKind::FunctionBlock | PouKind::Program => {
            let fields: Vec<_> = pou
                .vars
                .iter()
                .enumerate()
                .filter(|(i, _)| p.in_self(*i))
                .map(|(_, v)| v)
                .collect();
            let decls = fields.iter().map(|v| {
                let id = rust_ident(&v.name);
                let ty = rust_ty(&v.ty);
                let vdoc = format!(" {} (IL line {})", v.kind.keyword(), v.line);
                quote!(#[doc = #vdoc] pub #id: #ty,)
            });
            let inits = fields.iter().map(|v| {
                let id = rust_ident(&v.name);
                let init = values::init_value(&v.ty, v.init.as_ref());
                quote!(#id: #init,)
            });
            let method_doc = if pou.kind == PouKind::Program {
                " Run one scan."
            } else {
                " Call the block once."
            };
            quote! {
                #[doc = #doc]
                #[derive(Clone, Debug, PartialEq)]
                #[allow(non_snake_case, non_camel_case_types)]
                pub struct #name {
                    #(#decls)*
                }

                impl ::core::default::Default for #name {
                    fn default() -> Self {
                        Self { #(#inits)* }
                    }
                }

                impl #name {
                    #[doc = #method_doc]
                    #allow
                    pub fn call(&mut self, __ctx: &mut ::il_std::Cycle) {
                        #locals
                        #body
                    }
                }

                impl ::il_std::FunctionBlock for #name {
                    fn call(&mut self, ctx: &mut ::il_std::Cycle) {
                        #name::call(self, ctx)
                    }
                }
            }
        }
    }
}
