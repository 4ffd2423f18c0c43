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

pub use names::{item_ident, local_ident, rust_ident};

/// How to emit.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// Put `__il_line!(N);` markers before the code of each IL line; the file
    /// writer turns them into `// N: <IL text>` comments after formatting.
    pub line_markers: bool,
}

/// Emit every POU of a checked program.
pub fn program(p: &Program, opts: Options) -> TokenStream {
    // Streams are moved into the result, never interpolated: `quote!`'s
    // `#stream` copies every token (and, in proc-macro2's fallback, every
    // identifier's string), which for large POUs dominated emit time.
    let mut out = TokenStream::new();
    out.extend(p.types.iter().map(emit_type));
    out.extend(p.pous.iter().map(|pou| emit_pou(pou, opts)));
    out
}

/// `{ tokens }` as one token tree: interpolating it clones a reference to
/// the inner stream, not the tokens.
pub(crate) fn braced(tokens: TokenStream) -> proc_macro2::Group {
    proc_macro2::Group::new(proc_macro2::Delimiter::Brace, tokens)
}

/// The Rust type of an IEC type; user FBs are items beside the generated code.
pub(crate) fn rust_ty(t: &Ty) -> TokenStream {
    t.rust(&|name| {
        if is_std_fb(name) {
            let id = format_ident!("{}", name);
            quote!(::il_std::#id)
        } else {
            let id = item_ident(name);
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
        let v = &self.pou.vars[i];
        self.pou.kind != PouKind::Function && v.kind != VarKind::Temp && v.location.is_none()
    }

    /// Whether variable `i` (an elementary value in `self`) is copied into a
    /// local for the duration of the call and written back at its end, so
    /// that it can live in a register: nothing else can see `self` meanwhile.
    fn cached(&self, i: usize) -> bool {
        let v = &self.pou.vars[i];
        self.in_self(i) && v.edge.is_none() && matches!(v.ty, Ty::Elem(_))
    }

    fn has_cached(&self) -> bool {
        (0..self.pou.vars.len()).any(|i| self.cached(i))
    }
}

fn emit_pou(pou: &CheckedPou, opts: Options) -> TokenStream {
    let p = Pou { pou, opts };
    let name = item_ident(&pou.name);
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
        // FUNCTION inputs and outputs are parameters, FB memory is in `self`.
        let param =
            pou.kind == PouKind::Function && matches!(v.kind, VarKind::Input | VarKind::Output);
        !(p.in_self(*i) || param)
    });
    let temp_locals = temp_locals.map(|(_, v)| {
        let id = local_ident(&v.name);
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
    let allow = quote!(#[allow(non_snake_case, unused_mut, unused_variables, unused_assignments, unreachable_code, unused_labels,
        unused_comparisons, clippy::all)]);

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
                    let id = local_ident(&v.name);
                    let ty = rust_ty(&v.ty);
                    quote!(mut #id: #ty)
                });
            let outs = pou
                .vars
                .iter()
                .filter(|v| v.kind == VarKind::Output)
                .map(|v| {
                    let id = local_ident(&v.name);
                    let ty = rust_ty(&v.ty);
                    quote!(#id: &mut #ty)
                });
            // Outputs start from their initial values on every call.
            let out_inits = pou
                .vars
                .iter()
                .filter(|v| v.kind == VarKind::Output)
                .map(|v| {
                    let id = local_ident(&v.name);
                    let init = values::init_value(&v.ty, v.init.as_ref());
                    quote!(*#id = #init;)
                });
            let mut inner = quote! {
                let mut __ret: #ret_ty = #ret_default;
                #(#out_inits)*
                #locals
            };
            inner.extend(body);
            inner.extend(quote!(__ret));
            let block = braced(inner);
            quote! {
                #[doc = #doc]
                #allow
                pub fn #name(__ctx: &mut ::il_std::Cycle, #(#params,)* #(#outs,)*) -> #ret_ty #block
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
            // R_EDGE/F_EDGE inputs: private memory, and the edge computed on
            // entry (F_EDGE follows F_TRIG: Q := NOT CLK AND NOT M; M := NOT CLK).
            let edges: Vec<_> = fields
                .iter()
                .filter_map(|v| v.edge.map(|e| (*v, e)))
                .collect();
            let mem_decls = edges.iter().map(|(v, _)| {
                let m = rust_ident(&format!("__edge_memory_{}", v.name));
                quote!(#m: bool,)
            });
            let mem_inits = edges.iter().map(|(v, _)| {
                let m = rust_ident(&format!("__edge_memory_{}", v.name));
                quote!(#m: false,)
            });
            let edge_lets = edges.iter().map(|(v, e)| {
                let m = rust_ident(&format!("__edge_memory_{}", v.name));
                let x = rust_ident(&v.name);
                let l = rust_ident(&format!("__edge_{}", v.name));
                match e {
                    crate::ast::Edge::Rising => {
                        quote!(let #l: bool = self.#x && !self.#m; self.#m = self.#x;)
                    }
                    crate::ast::Edge::Falling => {
                        quote!(let #l: bool = !self.#x && !self.#m; self.#m = !self.#x;)
                    }
                }
            });
            let cached: Vec<_> = (0..pou.vars.len())
                .filter(|i| p.cached(*i))
                .map(|i| &pou.vars[i])
                .collect();
            let loads = cached.iter().map(|v| {
                let (id, l) = (rust_ident(&v.name), names::cache_ident(&v.name));
                let ty = rust_ty(&v.ty);
                quote!(let mut #l: #ty = self.#id;)
            });
            let stores = cached.iter().map(|v| {
                let (id, l) = (rust_ident(&v.name), names::cache_ident(&v.name));
                quote!(self.#id = #l;)
            });
            // RET leaves the labelled block, so the values are written back.
            let body = if cached.is_empty() {
                body
            } else {
                let mut t = quote!('__body:);
                t.extend([proc_macro2::TokenTree::Group(proc_macro2::Group::new(
                    proc_macro2::Delimiter::Brace,
                    body,
                ))]);
                t.extend(quote!(#(#stores)*));
                t
            };
            let mut inner = quote!(#(#edge_lets)* #(#loads)* #locals);
            inner.extend(body);
            let block = braced(inner);
            let addresses = addresses(pou);
            let method_doc = if pou.kind == PouKind::Program {
                " Run one scan."
            } else {
                " Call the block once."
            };
            quote! {
                #[doc = #doc]
                #[derive(Clone, Debug, PartialEq)]
                #[allow(non_snake_case, non_camel_case_types, clippy::all)]
                pub struct #name {
                    #(#decls)*
                    #(#mem_decls)*
                }

                #[allow(clippy::all)]
                impl ::core::default::Default for #name {
                    fn default() -> Self {
                        Self { #(#inits)* #(#mem_inits)* }
                    }
                }

                impl #name {
                    /// The located variables and direct addresses this POU
                    /// reads or writes in `Cycle::io`, for binding I/O.
                    pub const ADDRESSES: &'static [::il_std::Located] = &[#(#addresses),*];

                    #[doc = #method_doc]
                    #allow
                    pub fn call(&mut self, __ctx: &mut ::il_std::Cycle) #block
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

fn addresses(pou: &CheckedPou) -> Vec<TokenStream> {
    let located = pou
        .vars
        .iter()
        .filter_map(|v| v.location.as_ref().map(|l| (v.name.as_str(), l)));
    let direct = pou.addresses.iter().map(|l| (l.text.as_str(), l));
    located
        .chain(direct)
        .map(|(name, l)| {
            let area = match l.area {
                crate::ast::Area::Input => quote!(::il_std::Area::Input),
                crate::ast::Area::Output => quote!(::il_std::Area::Output),
                crate::ast::Area::Memory => quote!(::il_std::Area::Memory),
            };
            let (text, byte, ty) = (&l.text, l.byte, l.elem.name());
            let bit = match l.bit {
                Some(b) => quote!(::core::option::Option::Some(#b)),
                None => quote!(::core::option::Option::None),
            };
            quote!(::il_std::Located { name: #name, address: #text, area: #area, byte: #byte, bit: #bit, ty: #ty })
        })
        .collect()
}

/// A user STRUCT or enumeration as a Rust item the host can use directly.
fn emit_type(t: &crate::sema::ir::TypeDef) -> TokenStream {
    use crate::sema::ir::TypeDef;
    match t {
        TypeDef::Struct { name, fields } => {
            let id = item_ident(name);
            let doc = format!(" IEC 61131-3 STRUCT `{name}`, generated from Instruction List.");
            let decls = fields.iter().map(|f| {
                let fid = rust_ident(&f.name);
                let ty = rust_ty(&f.ty);
                quote!(pub #fid: #ty,)
            });
            let inits = fields.iter().map(|f| {
                let fid = rust_ident(&f.name);
                let v = values::init_value(&f.ty, f.init.as_ref());
                quote!(#fid: #v,)
            });
            quote! {
                #[doc = #doc]
                #[derive(Clone, Copy, Debug, PartialEq)]
                #[allow(non_snake_case, non_camel_case_types, clippy::all)]
                pub struct #id { #(#decls)* }

                #[allow(clippy::all)]
                impl ::core::default::Default for #id {
                    fn default() -> Self {
                        Self { #(#inits)* }
                    }
                }
            }
        }
        TypeDef::Enum {
            name,
            values,
            default,
        } => {
            let id = item_ident(name);
            let doc =
                format!(" IEC 61131-3 enumeration `{name}`, generated from Instruction List.");
            let vals = values.iter().enumerate().map(|(i, (v, disc))| {
                let vid = rust_ident(v);
                let d = disc.map(|n| {
                    let lit = proc_macro2::Literal::i64_unsuffixed(n as i64);
                    quote!(= #lit)
                });
                let def = (i == *default).then(|| quote!(#[default]));
                quote!(#def #vid #d,)
            });
            quote! {
                #[doc = #doc]
                #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
                #[allow(non_camel_case_types, clippy::all)]
                pub enum #id { #(#vals)* }
            }
        }
    }
}
