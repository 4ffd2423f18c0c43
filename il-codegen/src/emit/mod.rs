//! The emitter: checked IR → Rust tokens.
//!
//! Everything here is total: the checker has already refused whatever could
//! not compile. Generated code never panics: integer arithmetic wraps,
//! DIV/MOD by zero yields 0 and records a fault in the cycle context, array
//! accesses go through `get` and record a fault when out of range.

mod access;
mod config_vars;
mod configuration;
mod flow;
mod io;
mod names;
mod partly;
mod tasks;
mod values;
mod visit;

use crate::ast::{PouKind, VarKind};
use crate::sema::ir::{CheckedPou, Program, Storage};
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
    /// Derive `serde::Serialize`/`Deserialize` on the generated user types,
    /// FB/PROGRAM structs and RETAIN snapshots (the user's crate depends on
    /// `serde` and enables `il-std`'s `serde` feature).
    pub serde: bool,
}

/// `#[derive(Serialize, Deserialize)]` when serde is on.
pub(crate) fn serde_derive(opts: Options) -> TokenStream {
    if opts.serde {
        quote!(#[derive(::serde::Serialize, ::serde::Deserialize)])
    } else {
        quote!()
    }
}

/// For a field of type `t`: serde covers arrays up to 32 elements itself;
/// a longer (outermost) dimension goes through `il_std::serde_array`.
pub(crate) fn serde_field(t: &Ty, opts: Options) -> TokenStream {
    match t {
        Ty::Array { dims, .. }
            if opts.serde && dims.first().is_some_and(|(lo, hi)| hi - lo + 1 > 32) =>
        {
            quote!(#[serde(with = "::il_std::serde_array")])
        }
        _ => quote!(),
    }
}

/// The Rust type of a field: a heap field (an array over 64 KiB, see
/// `sema/size.rs`) is `Box<[Row]>`.
pub(crate) fn field_ty(v: &crate::sema::ir::Var) -> TokenStream {
    if v.heap {
        let row = rust_ty(&crate::sema::size::row(&v.ty));
        quote!(::il_std::heap::Box<[#row]>)
    } else {
        rust_ty(&v.ty)
    }
}

/// [`serde_field`] for a field: a heap field is a sequence of exactly its
/// declared length.
pub(crate) fn serde_var(v: &crate::sema::ir::Var, opts: Options) -> TokenStream {
    match &v.ty {
        Ty::Array { dims, .. } if v.heap && opts.serde => {
            let n = dims.first().map_or(0, |(lo, hi)| hi - lo + 1);
            let de = format!("::il_std::heap::serde_len::deserialize::<_, _, {n}>");
            quote!(#[serde(serialize_with = "::il_std::heap::serde_len::serialize", deserialize_with = #de)])
        }
        t => serde_field(t, opts),
    }
}

/// Emit every POU of a checked program.
pub fn program(p: &Program, opts: Options) -> TokenStream {
    // Streams are moved into the result, never interpolated: `quote!`'s
    // `#stream` copies every token (and, in proc-macro2's fallback, every
    // identifier's string), which for large POUs dominated emit time.
    let mut out = TokenStream::new();
    out.extend(p.types.iter().map(|t| emit_type(t, opts)));
    out.extend(p.pous.iter().map(|pou| emit_pou(pou, opts)));
    out.extend(
        p.configs
            .iter()
            .map(|c| configuration::emit_config(c, opts)),
    );
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

/// Emits one checked POU (the checked IR's `CheckedPou`; not the AST's
/// `ast::Pou`).
struct PouEmitter<'a> {
    pou: &'a CheckedPou,
    opts: Options,
}

impl PouEmitter<'_> {
    /// Whether variable `i` is a field of `self` (FB/PROGRAM memory).
    fn field(&self, i: usize) -> bool {
        self.pou.vars[i].storage == Storage::Instance
    }

    /// Whether variable `i` (an elementary value in `self`) is copied into a
    /// local for the duration of the call and written back at its end, so
    /// that it can live in a register: nothing else can see `self` meanwhile.
    fn cached(&self, i: usize) -> bool {
        let v = &self.pou.vars[i];
        self.field(i) && v.edge.is_none() && matches!(v.ty, Ty::Elem(_))
    }

    fn has_cached(&self) -> bool {
        (0..self.pou.vars.len()).any(|i| self.cached(i))
    }
}

fn emit_pou(pou: &CheckedPou, opts: Options) -> TokenStream {
    let p = PouEmitter { pou, opts };
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
    // FUNCTION inputs and outputs are parameters, FB memory is in `self`.
    let temp_locals = pou.vars.iter().filter(|v| v.storage == Storage::Temp);
    let temp_locals = temp_locals.map(|v| {
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
    let allow = quote!(#[allow(dead_code, non_snake_case, unused_mut, unused_variables, unused_assignments, unreachable_code, unused_labels, unused_parens,
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
            let inouts = inout_params(pou);
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
                pub fn #name(__ctx: &mut ::il_std::Cycle, #(#params,)* #(#inouts,)* #(#outs,)*) -> #ret_ty #block
            }
        }
        PouKind::FunctionBlock | PouKind::Program => {
            let fields: Vec<_> = pou
                .vars
                .iter()
                .enumerate()
                .filter(|(i, _)| p.field(*i))
                .map(|(_, v)| v)
                .collect();
            let decls = fields.iter().map(|v| {
                let id = rust_ident(&v.name);
                let ty = field_ty(v);
                let vdoc = if v.heap {
                    format!(
                        " {} (IL line {}); over 64 KiB, so on the heap: the elements of its first dimension",
                        v.kind.keyword(),
                        v.line
                    )
                } else {
                    format!(" {} (IL line {})", v.kind.keyword(), v.line)
                };
                let sf = serde_var(v, opts);
                quote!(#[doc = #vdoc] #sf pub #id: #ty,)
            });
            let inits = fields.iter().map(|v| {
                let id = rust_ident(&v.name);
                let init = if v.heap {
                    values::heap_init_value(&v.ty, v.init.as_ref())
                } else {
                    values::init_value(&v.ty, v.init.as_ref())
                };
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
            let addresses = io::addresses(pou);
            let io_accessors = io::accessors(&pou.vars);
            let method_doc = if pou.kind == PouKind::Program {
                " Run one scan."
            } else {
                " Call the block once."
            };
            let inouts = inout_params(pou);
            let externals: Vec<_> = pou
                .vars
                .iter()
                .filter(|v| v.storage == Storage::External)
                .collect();
            let ext_id = names::ext_ident(&pou.name);
            let (ext_item, ext_param) = if externals.is_empty() {
                (quote!(), quote!())
            } else {
                let fields = externals.iter().map(|v| {
                    let id = rust_ident(&v.name);
                    let ty = rust_ty(&v.ty);
                    if v.constant {
                        let vdoc = format!(" VAR_EXTERNAL CONSTANT (IL line {})", v.line);
                        quote!(#[doc = #vdoc] pub #id: &'a #ty,)
                    } else {
                        let vdoc = format!(" VAR_EXTERNAL (IL line {})", v.line);
                        quote!(#[doc = #vdoc] pub #id: &'a mut #ty,)
                    }
                });
                let edoc = format!(
                    " The globals `{}` uses (its VAR_EXTERNALs), passed to every call.",
                    pou.name
                );
                (
                    quote! {
                        #[doc = #edoc]
                        #[allow(dead_code, non_snake_case, non_camel_case_types)]
                        pub struct #ext_id<'a> { #(#fields)* }
                    },
                    quote!(mut __ext: #ext_id<'_>),
                )
            };
            let retain = retain_items(pou, opts);
            let visit = visit::pou(&name, &fields);
            let serde = serde_derive(opts);
            // The generic trait fits blocks called with the context alone.
            let trait_impl = (inouts.is_empty() && externals.is_empty()).then(|| {
                quote! {
                    impl ::il_std::FunctionBlock for #name {
                        fn call(&mut self, ctx: &mut ::il_std::Cycle) {
                            #name::call(self, ctx)
                        }
                    }
                }
            });
            quote! {
                #[doc = #doc]
                #[derive(Clone, Debug, PartialEq)]
                #serde
                #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all)]
                pub struct #name {
                    #(#decls)*
                    #(#mem_decls)*
                }

                #[allow(dead_code, clippy::all)]
                impl ::core::default::Default for #name {
                    fn default() -> Self {
                        Self { #(#inits)* #(#mem_inits)* }
                    }
                }

                #[allow(dead_code, clippy::all)]
                impl #name {
                    /// The located variables and direct addresses this POU
                    /// reads or writes in `Cycle::io`, for binding I/O.
                    pub const ADDRESSES: &'static [::il_std::Located] = &[#(#addresses),*];
                    #io_accessors

                    #[doc = #method_doc]
                    #allow
                    pub fn call(&mut self, __ctx: &mut ::il_std::Cycle, #(#inouts,)* #ext_param) #block
                }

                #trait_impl
                #visit
                #ext_item
                #retain
            }
        }
    }
}

/// The RETAIN snapshot type of an FB/PROGRAM, with `retain()` and `restore()`.
fn retain_items(pou: &CheckedPou, opts: Options) -> TokenStream {
    use crate::sema::ir::Retained;
    if pou.retained.is_empty() {
        return quote!();
    }
    let name = item_ident(&pou.name);
    let st = names::retain_ident(&pou.name);
    let mut fields = Vec::new();
    let mut takes = Vec::new();
    let mut puts = Vec::new();
    for (i, how) in &pou.retained {
        let v = &pou.vars[*i];
        let id = rust_ident(&v.name);
        match how {
            Retained::Whole => {
                let ty = field_ty(v);
                let doc = format!(" {} RETAIN (IL line {})", v.kind.keyword(), v.line);
                let sf = serde_var(v, opts);
                fields.push(quote!(#[doc = #doc] #sf pub #id: #ty,));
                takes.push(quote!(#id: ::core::clone::Clone::clone(&self.#id),));
                puts.push(quote!(self.#id = ::core::clone::Clone::clone(&s.#id);));
            }
            Retained::Nested => {
                // The snapshot of each instance, arrays mapped element-wise.
                let snap = |t: &Ty| {
                    t.rust(&|fb| {
                        let r = names::retain_ident(fb);
                        quote!(#r)
                    })
                };
                let ty = if v.heap {
                    let row = snap(&crate::sema::size::row(&v.ty));
                    quote!(::il_std::heap::Box<[#row]>)
                } else {
                    snap(&v.ty)
                };
                let doc = format!(" The RETAIN variables of `{}` (IL line {})", v.name, v.line);
                let sf = serde_var(v, opts);
                fields.push(quote!(#[doc = #doc] #sf pub #id: #ty,));
                let mut depth = 0;
                let mut t = &v.ty;
                while let Ty::Array { elem, dims, .. } = t {
                    depth += dims.len();
                    t = elem;
                }
                let mut take = quote!(__x.retain());
                let mut put = quote!(__d.restore(__s););
                for k in (0..depth).rev() {
                    // The first dimension of a heap field is a boxed slice.
                    take = if v.heap && k == 0 {
                        quote!(__x.iter().map(|__x| #take).collect())
                    } else {
                        quote!(__x.each_ref().map(|__x| #take))
                    };
                    put = quote!(for (__d, __s) in __d.iter_mut().zip(__s.iter()) { #put });
                }
                takes.push(quote!(#id: { let __x = &self.#id; #take },));
                puts.push(quote!({ let (__d, __s) = (&mut self.#id, &s.#id); #put }));
            }
        }
    }
    let doc = format!(
        " The RETAIN variables of `{}` (and of the blocks it holds): what a host saves before power-off and restores at a warm start.",
        pou.name
    );
    snapshot_item(&name, &st, &doc, (fields, takes, puts), opts)
}

/// A RETAIN snapshot struct `st` and `retain()`/`restore()` on `owner`, from
/// the fields, their `retain()` initialisers and their `restore()` statements.
pub(crate) fn snapshot_item(
    owner: &proc_macro2::Ident,
    st: &proc_macro2::Ident,
    doc: &str,
    (fields, takes, puts): (Vec<TokenStream>, Vec<TokenStream>, Vec<TokenStream>),
    opts: Options,
) -> TokenStream {
    let serde = serde_derive(opts);
    quote! {
        #[doc = #doc]
        #[derive(Clone, Debug, PartialEq)]
        #serde
        #[allow(dead_code, non_snake_case, non_camel_case_types)]
        pub struct #st { #(#fields)* }

        #[allow(dead_code, clippy::all)]
        impl #owner {
            /// A snapshot of the RETAIN variables.
            pub fn retain(&self) -> #st {
                #st { #(#takes)* }
            }
            /// Puts a snapshot back (a warm start); other variables keep their values.
            pub fn restore(&mut self, s: &#st) {
                #(#puts)*
            }
        }
    }
}

/// `__v_x: &mut T` for every VAR_IN_OUT, in declaration order.
fn inout_params(pou: &CheckedPou) -> Vec<TokenStream> {
    pou.vars
        .iter()
        .filter(|v| v.kind == VarKind::InOut)
        .map(|v| {
            let id = local_ident(&v.name);
            let ty = rust_ty(&v.ty);
            quote!(#id: &mut #ty)
        })
        .collect()
}

/// A user STRUCT or enumeration as a Rust item the host can use directly.
fn emit_type(t: &crate::sema::ir::TypeDef, opts: Options) -> TokenStream {
    let serde = serde_derive(opts);
    use crate::sema::ir::TypeDef;
    match t {
        TypeDef::Struct { name, fields } => {
            let id = item_ident(name);
            let doc = format!(" IEC 61131-3 STRUCT `{name}`, generated from Instruction List.");
            let decls = fields.iter().map(|f| {
                let fid = rust_ident(&f.name);
                let ty = rust_ty(&f.ty);
                let sf = serde_field(&f.ty, opts);
                quote!(#sf pub #fid: #ty,)
            });
            let inits = fields.iter().map(|f| {
                let fid = rust_ident(&f.name);
                let v = values::init_value(&f.ty, f.init.as_ref());
                quote!(#fid: #v,)
            });
            let visit = visit::strukt(name, fields);
            quote! {
                #[doc = #doc]
                #[derive(Clone, Copy, Debug, PartialEq)]
                #serde
                #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all)]
                pub struct #id { #(#decls)* }

                #[allow(dead_code, clippy::all)]
                impl ::core::default::Default for #id {
                    fn default() -> Self {
                        Self { #(#inits)* }
                    }
                }

                #visit
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
            let visit = visit::enumeration(name, values);
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
                #serde
                #[allow(dead_code, non_camel_case_types, clippy::all)]
                pub enum #id { #(#vals)* }

                #visit
            }
        }
    }
}
