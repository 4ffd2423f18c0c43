//! The emitter: checked IR → Rust text (see `text.rs`, which also keeps
//! IL-derived text from becoming code).
//!
//! Everything here is total: the checker has already refused whatever could
//! not compile. Generated code never panics: integer arithmetic wraps,
//! DIV/MOD by zero yields 0 and records a fault in the cycle context, array
//! accesses go through `get` and record a fault when out of range.

mod access;
mod complement;
mod config_vars;
mod configuration;
mod flow;
mod io;
mod names;
mod tasks;
pub(crate) mod text;
mod values;
mod visit;
mod writeback;

use crate::ast::{PouKind, VarKind};
use crate::ir::types::Ty;
use crate::ir::{CheckedPou, Program, Storage};
use text::{Out, doc, each, str_lit, tail, user_doc};

pub use names::{item_ident, local_ident, rust_ident};

/// How to emit.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// Put `__il_line!(N);` markers before the code of each IL line; the file
    /// writer turns them into `// N: <IL text>` comments.
    pub line_markers: bool,
    /// Derive `serde::Serialize`/`Deserialize` on the generated user types,
    /// FB/PROGRAM structs and RETAIN snapshots (the user's crate depends on
    /// `serde` and enables `il-std`'s `serde` feature).
    pub serde: bool,
}

/// `#[derive(Serialize, Deserialize)]` when serde is on.
pub(crate) fn serde_derive(opts: Options) -> &'static str {
    if opts.serde {
        "#[derive(::serde::Serialize, ::serde::Deserialize)]"
    } else {
        ""
    }
}

/// For a field of type `t`: serde covers arrays up to 32 elements itself;
/// a longer (outermost) dimension goes through `il_std::serde_array`.
pub(crate) fn serde_field(t: &Ty, opts: Options) -> String {
    match t {
        Ty::Array(a) if opts.serde && a.dims.first().is_some_and(|(lo, hi)| hi - lo + 1 > 32) => {
            "#[serde(with = \"::il_std::serde_array\")]".to_string()
        }
        _ => String::new(),
    }
}

/// The Rust type of a field: a heap field (an array over 64 KiB, see
/// `sema/heap_arrays.rs`) is `Box<[Row]>`.
pub(crate) fn field_ty(v: &crate::ir::Var) -> String {
    if v.heap {
        let row = rust_ty(&v.ty.row());
        format!("::il_std::heap::Box<[{row}]>")
    } else {
        rust_ty(&v.ty)
    }
}

/// [`serde_field`] for a field: a heap field is a sequence of exactly its
/// declared length.
pub(crate) fn serde_var(v: &crate::ir::Var, opts: Options) -> String {
    match &v.ty {
        Ty::Array(a) if v.heap && opts.serde => {
            let n = a.dims.first().map_or(0, |(lo, hi)| hi - lo + 1);
            let de = str_lit(&format!(
                "::il_std::heap::serde_len::deserialize::<_, _, {n}>"
            ));
            format!(
                "#[serde(serialize_with = \"::il_std::heap::serde_len::serialize\", deserialize_with = {de})]"
            )
        }
        t => serde_field(t, opts),
    }
}

/// Emit every POU of a checked program: Rust text, laid out.
pub fn program(p: &Program, opts: Options) -> String {
    program_marked(p, opts).0
}

/// [`program`], and where each `__il_line!(` marker starts in the text.
pub(crate) fn program_marked(p: &Program, opts: Options) -> (String, Vec<usize>) {
    let mut out = Out::new();
    // At most a marker per statement: sized once (a vector doubling beside
    // the text's buffer raised the peak RSS of `ilc emit` by 8 MiB).
    out.reserve_markers(p.pous.iter().map(|pou| pou.body.len()).sum());
    for t in &p.types {
        emit_type(&mut out, t, opts);
    }
    for pou in &p.pous {
        emit_pou(&mut out, pou, opts);
    }
    for c in &p.configs {
        configuration::emit_config(&mut out, c, opts);
    }
    out.finish_marked()
}

/// The Rust type of an IEC type; user FBs are items beside the generated code.
pub(crate) fn rust_ty(t: &Ty) -> String {
    t.rust(&|name| {
        if is_std_fb(name) {
            format!("::il_std::{}", rust_ident(name))
        } else {
            item_ident(name)
        }
    })
}

fn is_std_fb(name: &str) -> bool {
    il_std::signature::lookup_fb(name).is_some()
}

/// Emits one checked POU (the checked IR's `CheckedPou`; not the AST's
/// `ast::Pou`).
struct PouEmitter<'a> {
    pou: &'a CheckedPou,
    opts: Options,
    /// Per variable: the body reads its complement (see `complement.rs`).
    complemented: Vec<bool>,
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

/// The `allow` list of generated function bodies.
const ALLOW_BODY: &str = "#[allow(dead_code, non_snake_case, unused_mut, unused_variables, unused_assignments, unreachable_code, unused_labels, unused_parens, unused_comparisons, clippy::all, clippy::pedantic)]";

impl PouEmitter<'_> {
    /// `let mut` for the CR, saved-value and VAR_TEMP locals.
    fn locals(&self, o: &mut Out) {
        let pou = self.pou;
        for t in &pou.cr_types {
            let (id, ty, d) = (values::cr_ident(t), rust_ty(t), values::default_value(t));
            o.code(&format!("let mut {id}: {ty} = {d};"));
        }
        for (i, t) in pou.save_types.iter().enumerate() {
            let (ty, d) = (rust_ty(t), values::default_value(t));
            o.code(&format!("let mut __save_{i}: {ty} = {d};"));
        }
        // FUNCTION inputs and outputs are parameters, FB memory is in `self`.
        for v in pou.vars.iter().filter(|v| v.storage == Storage::Temp) {
            let id = local_ident(&v.name);
            let ty = rust_ty(&v.ty);
            let init = values::init_value(&v.ty, v.init.as_ref());
            o.code(&format!("let mut {id}: {ty} = {init};"));
        }
    }
}

fn emit_pou(o: &mut Out, pou: &CheckedPou, opts: Options) {
    let mut p = PouEmitter {
        pou,
        opts,
        complemented: Vec::new(),
    };
    p.complemented = complement::complemented(pou, p.has_fenced_rungs());
    let name = item_ident(&pou.name);
    let pdoc = user_doc(pou.doc.as_deref())
        + &doc(&format!(
            " IEC 61131-3 {} `{}`, generated from Instruction List.",
            pou.kind.keyword(),
            pou.name
        ));
    match pou.kind {
        PouKind::Function if pou.host => emit_host_check(o, pou),
        PouKind::Function => {
            let ret_ty = fn_ret_ty(pou);
            let ret_default = pou
                .ret
                .as_ref()
                .map(values::default_value)
                .unwrap_or_else(|| "false".to_string());
            let params = tail(fn_params(pou).into_iter().map(|(v, ty)| {
                let m = if v.kind == VarKind::Input { "mut " } else { "" };
                format!("{m}{}: {ty}", local_ident(&v.name))
            }));
            o.code(&format!(
                "{pdoc}{ALLOW_BODY} pub fn {name}(__ctx: &mut ::il_std::Cycle{params}) -> {ret_ty} {{ let mut __ret: {ret_ty} = {ret_default};"
            ));
            // Outputs start from their initial values on every call.
            for v in pou.vars.iter().filter(|v| v.kind == VarKind::Output) {
                let id = local_ident(&v.name);
                let init = values::init_value(&v.ty, v.init.as_ref());
                o.code(&format!("*{id} = {init};"));
            }
            p.locals(o);
            p.body(o);
            o.code("__ret }");
        }
        PouKind::FunctionBlock | PouKind::Program => {
            let fields: Vec<_> = pou
                .vars
                .iter()
                .enumerate()
                .filter(|(i, _)| p.field(*i))
                .map(|(_, v)| v)
                .collect();
            let mut decls = String::new();
            let mut inits = String::new();
            for v in &fields {
                let id = rust_ident(&v.name);
                let vdoc = if v.heap {
                    format!(
                        " `{}` (IL line {}); over 64 KiB, so on the heap: the elements of its first dimension",
                        v.kind.keyword(),
                        v.line
                    )
                } else {
                    format!(" `{}` (IL line {})", v.kind.keyword(), v.line)
                };
                decls.push_str(&format!(
                    "{}{}{} pub {id}: {},",
                    user_doc(v.doc.as_deref()),
                    doc(&vdoc),
                    serde_var(v, opts),
                    field_ty(v)
                ));
                let init = if v.heap {
                    values::heap_init_value(&v.ty, v.init.as_ref())
                } else {
                    values::init_value(&v.ty, v.init.as_ref())
                };
                inits.push_str(&format!("{id}: {init},"));
            }
            // R_EDGE/F_EDGE inputs: private memory, and the edge computed on
            // entry (F_EDGE follows F_TRIG: Q := NOT CLK AND NOT M; M := NOT CLK).
            let mut edge_lets = String::new();
            for v in &fields {
                let Some(e) = v.edge else { continue };
                let m = rust_ident(&format!("__edge_memory_{}", v.name));
                let x = rust_ident(&v.name);
                let l = rust_ident(&format!("__edge_{}", v.name));
                decls.push_str(&format!("{m}: bool,"));
                inits.push_str(&format!("{m}: false,"));
                edge_lets.push_str(&match e {
                    crate::ast::Edge::Rising => {
                        format!("let {l}: bool = self.{x} && !self.{m}; self.{m} = self.{x};")
                    }
                    crate::ast::Edge::Falling => {
                        format!("let {l}: bool = !self.{x} && !self.{m}; self.{m} = !self.{x};")
                    }
                });
            }
            let cached: Vec<_> = (0..pou.vars.len())
                .filter(|i| p.cached(*i))
                .map(|i| &pou.vars[i])
                .collect();
            let serde = serde_derive(opts);
            o.code(&format!(
                "{pdoc}#[derive(Clone, Debug, PartialEq)] {serde} #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all, clippy::pedantic)] pub struct {name} {{ {decls} }}"
            ));
            o.code(&format!(
                "#[allow(dead_code, clippy::all, clippy::pedantic)] impl ::core::default::Default for {name} {{ fn default() -> Self {{ Self {{ {inits} }} }} }}"
            ));
            let addresses = each(io::addresses(pou), ", ");
            let io_accessors = io::accessors(&pou.vars);
            let method_doc = if pou.kind == PouKind::Program {
                " Run one scan."
            } else {
                " Call the block once."
            };
            let inouts = tail(inout_params(pou));
            let externals: Vec<_> = pou
                .vars
                .iter()
                .filter(|v| v.storage == Storage::External)
                .collect();
            let ext_id = names::ext_ident(&pou.name);
            let ext_param = if externals.is_empty() {
                String::new()
            } else {
                format!(", mut __ext: {ext_id}<'_>")
            };
            o.code(&format!(
                "#[allow(dead_code, clippy::all, clippy::pedantic)] impl {name} {{ \
                 /// The located variables and direct addresses this POU\n\
                 /// reads or writes in `Cycle::io`, for binding I/O.\n\
                 pub const ADDRESSES: &'static [::il_std::Located] = &[\n{addresses}]; {io_accessors} \
                 {}{ALLOW_BODY} pub fn call(&mut self, __ctx: &mut ::il_std::Cycle{inouts}{ext_param}) {{ {edge_lets}",
                doc(method_doc)
            ));
            for v in &cached {
                let (id, l) = (rust_ident(&v.name), names::cache_ident(&v.name));
                o.code(&format!("let mut {l}: {} = self.{id};", rust_ty(&v.ty)));
            }
            if pou.host {
                // A host block (`{extern}`, or a CODESYS POU whose body is
                // not IL): the crate's `fn Name(&mut Name, &mut Cycle,
                // in-outs...)`, a value beside the struct of that name.
                let args = tail(
                    pou.vars
                        .iter()
                        .filter(|v| v.kind == VarKind::InOut)
                        .map(|v| local_ident(&v.name)),
                );
                o.code(&format!("{name}(self, __ctx{args});"));
            } else if cached.is_empty() {
                p.complements(o);
                p.locals(o);
                p.body(o);
            } else {
                p.complements(o);
                p.locals(o);
                // RET leaves the labelled block, so the values are written back.
                o.code("'__body: {");
                let at_end = p.body(o);
                o.code("}");
                p.write_back(o, &at_end);
            }
            o.code("} }");
            if pou.host {
                emit_host_block_check(o, pou);
            }
            // The generic trait fits blocks called with the context alone.
            if inouts.is_empty() && externals.is_empty() {
                o.code(&format!(
                    "impl ::il_std::FunctionBlock for {name} {{ fn call(&mut self, ctx: &mut ::il_std::Cycle) {{ {name}::call(self, ctx); }} }}"
                ));
            }
            visit::pou(o, &name, &fields);
            if !externals.is_empty() {
                let mut efields = String::new();
                for v in &externals {
                    let id = rust_ident(&v.name);
                    let ty = rust_ty(&v.ty);
                    if v.constant {
                        let vdoc = doc(&format!(" `VAR_EXTERNAL CONSTANT` (IL line {})", v.line));
                        efields.push_str(&format!("{vdoc}pub {id}: &'a {ty},"));
                    } else {
                        let vdoc = doc(&format!(" `VAR_EXTERNAL` (IL line {})", v.line));
                        efields.push_str(&format!("{vdoc}pub {id}: &'a mut {ty},"));
                    }
                }
                let edoc = doc(&format!(
                    " The globals `{}` uses (its `VAR_EXTERNAL` variables), passed to every call.",
                    pou.name
                ));
                o.code(&format!(
                    "{edoc}#[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all, clippy::pedantic)] pub struct {ext_id}<'a> {{ {efields} }}"
                ));
            }
            retain_items(o, pou, opts);
        }
    }
}

/// The RETAIN snapshot type of an FB/PROGRAM, with `retain()` and `restore()`.
fn retain_items(o: &mut Out, pou: &CheckedPou, opts: Options) {
    use crate::ir::Retained;
    if pou.retained.is_empty() {
        return;
    }
    let name = item_ident(&pou.name);
    let st = names::retain_ident(&pou.name);
    let mut fields = String::new();
    let mut takes = String::new();
    let mut puts = String::new();
    for (i, how) in &pou.retained {
        let v = &pou.vars[*i];
        let id = rust_ident(&v.name);
        match how {
            Retained::Whole => {
                let ty = field_ty(v);
                let d = doc(&format!(
                    " `{} RETAIN` (IL line {})",
                    v.kind.keyword(),
                    v.line
                ));
                let sf = serde_var(v, opts);
                fields.push_str(&format!("{d}{sf} pub {id}: {ty},"));
                takes.push_str(&format!("{id}: ::core::clone::Clone::clone(&self.{id}),"));
                puts.push_str(&format!(
                    "self.{id} = ::core::clone::Clone::clone(&s.{id});"
                ));
            }
            Retained::Nested => {
                // The snapshot of each instance, arrays mapped element-wise.
                let snap = |t: &Ty| t.rust(&names::retain_ident);
                let ty = if v.heap {
                    let row = snap(&v.ty.row());
                    format!("::il_std::heap::Box<[{row}]>")
                } else {
                    snap(&v.ty)
                };
                let d = doc(&format!(
                    " The `RETAIN` variables of `{}` (IL line {})",
                    v.name, v.line
                ));
                let sf = serde_var(v, opts);
                fields.push_str(&format!("{d}{sf} pub {id}: {ty},"));
                let mut depth = 0;
                let mut t = &v.ty;
                while let Ty::Array(a) = t {
                    depth += a.dims.len();
                    t = &a.elem;
                }
                let mut take = "__x.retain()".to_string();
                let mut put = "__d.restore(__s);".to_string();
                for k in (0..depth).rev() {
                    // The first dimension of a heap field is a boxed slice.
                    take = if v.heap && k == 0 {
                        format!("__x.iter().map(|__x| {take}).collect()")
                    } else {
                        format!("__x.each_ref().map(|__x| {take})")
                    };
                    put = format!("for (__d, __s) in __d.iter_mut().zip(__s.iter()) {{ {put} }}");
                }
                takes.push_str(&format!("{id}: {{ let __x = &self.{id}; {take} }},"));
                puts.push_str(&format!(
                    "{{ let (__d, __s) = (&mut self.{id}, &s.{id}); {put} }}"
                ));
            }
        }
    }
    let d = format!(
        " The RETAIN variables of `{}` (and of the blocks it holds): what a host saves before power-off and restores at a warm start.",
        pou.name
    );
    snapshot_item(o, &name, &st, &d, (fields, takes, puts), opts)
}

/// A RETAIN snapshot struct `st` and `retain()`/`restore()` on `owner`, from
/// the fields, their `retain()` initialisers and their `restore()` statements.
pub(crate) fn snapshot_item(
    o: &mut Out,
    owner: &str,
    st: &str,
    d: &str,
    (fields, takes, puts): (String, String, String),
    opts: Options,
) {
    let serde = serde_derive(opts);
    o.code(&format!(
        "{}#[derive(Clone, Debug, PartialEq)] {serde} #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all, clippy::pedantic)] pub struct {st} {{ {fields} }}",
        doc(d)
    ));
    o.code(&format!(
        "#[allow(dead_code, clippy::all, clippy::pedantic)] impl {owner} {{ \
         /// A snapshot of the RETAIN variables.\n\
         pub fn retain(&self) -> {st} {{ {st} {{ {takes} }} }} \
         /// Puts a snapshot back (a warm start); other variables keep their values.\n\
         pub fn restore(&mut self, s: &{st}) {{ {puts} }} }}"
    ));
}

/// `__v_x: &mut T` for every VAR_IN_OUT, in declaration order.
/// A host FUNCTION (`{extern}`) is the crate's own Rust function, called
/// like a generated one. What is emitted is a check of its signature, so a
/// missing or mistyped function is a rustc error that names it here.
fn emit_host_check(o: &mut Out, pou: &CheckedPou) {
    let name = item_ident(&pou.name);
    let ret_ty = fn_ret_ty(pou);
    let params = fn_params(pou);
    let types = tail(params.iter().map(|(_, ty)| ty));
    let named = tail(
        params
            .iter()
            .map(|(v, ty)| format!("{}: {ty}", rust_ident(&v.name))),
    );
    let d = doc(&format!(
        " Host `FUNCTION` `{}` (`{{extern}}`): not generated. The crate provides `fn {name}(ctx: &mut ::il_std::Cycle{named}) -> {ret_ty}` beside this code; this constant checks that it exists with that signature.",
        pou.name
    ));
    o.code(&format!(
        "{d} const _: fn(&mut ::il_std::Cycle{types}) -> {ret_ty} = {name};"
    ));
}

/// A host FUNCTION_BLOCK or PROGRAM: the crate provides `fn Name(&mut
/// Name, &mut Cycle, in-outs...)`; this constant checks its signature, so
/// a missing or mistyped one is a rustc error that names it here.
fn emit_host_block_check(o: &mut Out, pou: &CheckedPou) {
    let name = item_ident(&pou.name);
    let inouts: Vec<String> = pou
        .vars
        .iter()
        .filter(|v| v.kind == VarKind::InOut)
        .map(|v| format!("&mut {}", rust_ty(&v.ty)))
        .collect();
    let types = tail(inouts.iter());
    let d = doc(&format!(
        " Host `{}` `{}`: its body is not generated. The crate provides `fn {name}(this: &mut {name}, ctx: &mut ::il_std::Cycle{types})` beside this code, which runs one call on the struct's fields; this constant checks that it exists with that signature.",
        pou.kind.keyword(),
        pou.name
    ));
    o.code(&format!(
        "{d} const _: fn(&mut {name}, &mut ::il_std::Cycle{types}) = {name};"
    ));
}

/// A FUNCTION's Rust result type (a FUNCTION without one is refused; `bool`
/// keeps the stub of such a program compiling).
fn fn_ret_ty(pou: &CheckedPou) -> String {
    pou.ret
        .as_ref()
        .map(rust_ty)
        .unwrap_or_else(|| "bool".to_string())
}

/// A FUNCTION's parameters after `__ctx`, each with its Rust type: the
/// inputs by value, then the in-outs and the outputs as `&mut`, each in
/// declaration order (generated FUNCTIONs and host functions alike).
fn fn_params(pou: &CheckedPou) -> Vec<(&crate::ir::Var, String)> {
    let of = |k: VarKind| pou.vars.iter().filter(move |v| v.kind == k);
    of(VarKind::Input)
        .map(|v| (v, rust_ty(&v.ty)))
        .chain(
            of(VarKind::InOut)
                .chain(of(VarKind::Output))
                .map(|v| (v, format!("&mut {}", rust_ty(&v.ty)))),
        )
        .collect()
}

fn inout_params(pou: &CheckedPou) -> Vec<String> {
    pou.vars
        .iter()
        .filter(|v| v.kind == VarKind::InOut)
        .map(|v| format!("{}: &mut {}", local_ident(&v.name), rust_ty(&v.ty)))
        .collect()
}

/// A user STRUCT or enumeration as a Rust item the host can use directly.
fn emit_type(o: &mut Out, t: &crate::ir::TypeDef, opts: Options) {
    let serde = serde_derive(opts);
    use crate::ir::TypeDef;
    match t {
        TypeDef::Struct { name, fields } => {
            let id = item_ident(name);
            let d = doc(&format!(
                " IEC 61131-3 STRUCT `{name}`, generated from Instruction List."
            ));
            let mut decls = String::new();
            let mut inits = String::new();
            for f in fields {
                let fid = rust_ident(&f.name);
                let sf = serde_field(&f.ty, opts);
                // Documented from the declaration, so that a crate with
                // `#![warn(missing_docs)]` accepts the public field.
                let fdoc = doc(&format!(" `{}`: `{}` field of `{name}`.", f.name, f.ty));
                decls.push_str(&format!("{fdoc}{sf} pub {fid}: {},", rust_ty(&f.ty)));
                let v = values::init_value(&f.ty, f.init.as_ref());
                inits.push_str(&format!("{fid}: {v},"));
            }
            o.code(&format!(
                "{d}#[derive(Clone, Copy, Debug, PartialEq)] {serde} #[allow(dead_code, non_snake_case, non_camel_case_types, clippy::all, clippy::pedantic)] pub struct {id} {{ {decls} }} \
                 #[allow(dead_code, clippy::all, clippy::pedantic)] impl ::core::default::Default for {id} {{ fn default() -> Self {{ Self {{ {inits} }} }} }}"
            ));
            visit::strukt(o, name, fields);
        }
        TypeDef::Enum {
            name,
            values,
            default,
        } => {
            let id = item_ident(name);
            let d = doc(&format!(
                " IEC 61131-3 enumeration `{name}`, generated from Instruction List."
            ));
            let mut vals = String::new();
            for (i, (v, disc)) in values.iter().enumerate() {
                // Each value documented as IL writes it (`missing_docs`).
                vals.push_str(&doc(&format!(" `{name}#{v}`")));
                if i == *default {
                    vals.push_str("#[default] ");
                }
                vals.push_str(&rust_ident(v));
                if let Some(n) = disc {
                    vals.push_str(&format!(" = {}", *n as i64));
                }
                vals.push(',');
            }
            o.code(&format!(
                "{d}#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)] {serde} #[allow(dead_code, non_camel_case_types, clippy::all, clippy::pedantic)] pub enum {id} {{ {vals} }}"
            ));
            visit::enumeration(o, name, values);
        }
    }
}
