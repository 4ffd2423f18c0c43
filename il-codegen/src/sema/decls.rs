//! Declarations: POU interfaces, variable types, initial values, literals.

use super::codes::*;
use super::ir::{Const, Field, Init, Loc, TypeDef, Var};
use super::types::{DEFAULT_STRING_LEN, Elem, Ty};
use super::{Cx, stdfb, suggest};
use crate::ast::{
    self, ConstExpr, Initializer, LitKind, Literal, Operand, PouKind, Span, TypeSpec,
};
use std::collections::{HashMap, HashSet};

/// The interfaces of every POU of the unit, by upper-case name.
pub(crate) struct Env {
    pub pous: HashMap<String, PouSig>,
    pub types: TypeTables,
    /// Checked configurations, with the index of the declaring file.
    pub configs: Vec<(usize, super::ir::ConfigDef)>,
    /// Bytes of each user FB (`FB:NAME`) and STRUCT (`S:NAME`), for the
    /// large-array rules (see `size.rs`).
    pub sizes: super::size::Sizes,
}

/// Resolved user types.
#[derive(Default)]
pub(crate) struct TypeTables {
    /// STRUCT key → its fields.
    pub structs: HashMap<String, Vec<Field>>,
    /// Enumeration key → (name as declared, values).
    pub enums: HashMap<String, (String, Vec<String>)>,
    /// Items to emit, with the index of the declaring file.
    pub defs: Vec<(usize, TypeDef)>,
}

impl TypeTables {
    /// The enumeration that has a value `name`, if exactly one has.
    pub fn enum_of_value(&self, name: &str) -> Option<(String, String)> {
        let mut found = self.enums.values().filter_map(|(ty, vals)| {
            vals.iter()
                .find(|v| v.eq_ignore_ascii_case(name))
                .map(|v| (ty.clone(), v.clone()))
        });
        let first = found.next()?;
        found.next().is_none().then_some(first)
    }
}

/// Every name a declaration can refer to, across all files.
pub(crate) struct Names<'u> {
    /// POU key → (name as declared, kind).
    pub pous: HashMap<String, (String, PouKind)>,
    /// User type key → its declaration.
    pub types: HashMap<String, &'u ast::TypeDecl>,
    depth: std::cell::Cell<u32>,
}

impl Names<'_> {
    /// A user type by key: `Some(Some(ty))` when resolved, `Some(None)` after
    /// an error, `None` when no user type has that name.
    fn user_type(&self, cx: &mut Cx, key: &str, span: Span) -> Option<Option<Ty>> {
        let decl = self.types.get(key)?;
        Some(match &decl.spec {
            TypeSpec::Struct { .. } => Some(Ty::Struct(decl.name.name.clone())),
            TypeSpec::Enum { .. } => Some(Ty::Enum(decl.name.name.clone())),
            spec => {
                // An alias or a subrange: the type it names (aliases may chain).
                if self.depth.get() > 32 {
                    cx.err(
                        RECURSION,
                        span,
                        format!("type `{}` is defined in terms of itself", decl.name),
                    );
                    return Some(None);
                }
                self.depth.set(self.depth.get() + 1);
                let t = resolve_type(cx, self, spec);
                self.depth.set(self.depth.get() - 1);
                t
            }
        })
    }

    /// Subrange bounds of a type spec (inline or through aliases).
    pub fn range_of(&self, spec: &TypeSpec) -> Option<(i128, i128)> {
        self.range_depth(spec, 0)
    }

    fn range_depth(&self, spec: &TypeSpec, depth: u32) -> Option<(i128, i128)> {
        match spec {
            TypeSpec::Subrange { range, .. } => match (&range.lo, &range.hi) {
                (
                    ConstExpr::Lit(Literal {
                        kind: LitKind::Int(lo),
                        ..
                    }),
                    ConstExpr::Lit(Literal {
                        kind: LitKind::Int(hi),
                        ..
                    }),
                ) => Some((*lo, *hi)),
                _ => None,
            },
            TypeSpec::Named(id) if depth < 32 => self
                .types
                .get(&id.key())
                .and_then(|d| self.range_depth(&d.spec, depth + 1)),
            _ => None,
        }
    }

    /// The initial value a named type gives its variables (`TYPE T : INT := 5`).
    pub fn default_init(&self, spec: &TypeSpec) -> Option<&Initializer> {
        let mut spec = spec;
        for _ in 0..32 {
            let TypeSpec::Named(id) = spec else {
                return None;
            };
            let decl = self.types.get(&id.key())?;
            if let Some(i) = &decl.init {
                return Some(i);
            }
            spec = &decl.spec;
        }
        None
    }
}

pub(crate) struct PouSig {
    pub kind: PouKind,
    pub name: String,
    pub vars: Vec<Var>,
    /// Upper-case name → index into `vars`.
    pub index: HashMap<String, usize>,
    pub ret: Option<Ty>,
    /// Index of the source file that declares it.
    pub file: usize,
    /// Variables whose declaration had an error (their uses are not reported).
    pub poisoned: HashSet<String>,
    /// The POU's name where it is declared (a duplicate has another span).
    pub span: Span,
}

impl PouSig {
    pub fn var(&self, name: &str) -> Option<(usize, &Var)> {
        // Called for every variable reference: upper-case short names on
        // the stack instead of allocating a String per lookup.
        let mut buf = [0u8; 64];
        let i = match buf.get_mut(..name.len()) {
            Some(b) => {
                b.copy_from_slice(name.as_bytes());
                b.make_ascii_uppercase();
                *self.index.get(std::str::from_utf8(b).ok()?)?
            }
            None => *self.index.get(&name.to_ascii_uppercase())?,
        };
        Some((i, &self.vars[i]))
    }
    /// Inputs in declaration order (what a non-formal call fills).
    pub fn inputs(&self) -> impl Iterator<Item = (usize, &Var)> {
        self.vars
            .iter()
            .enumerate()
            .filter(|(_, v)| v.kind == ast::VarKind::Input)
    }
}

impl Env {
    pub fn pou(&self, name: &str) -> Option<&PouSig> {
        self.pous.get(&name.to_ascii_uppercase())
    }
}

pub(crate) fn collect(cxs: &mut [Cx], units: &[&ast::CompilationUnit]) -> Env {
    let mut env = Env {
        pous: HashMap::new(),
        types: TypeTables::default(),
        configs: Vec::new(),
        sizes: Default::default(),
    };
    let mut seen: HashMap<String, (usize, Span)> = HashMap::new();
    let pous: Vec<(usize, &ast::Pou)> = units
        .iter()
        .enumerate()
        .flat_map(|(f, u)| {
            u.items.iter().filter_map(move |i| match i {
                ast::Item::Pou(p) => Some((f, p)),
                _ => None,
            })
        })
        .collect();
    for (f, p) in &pous {
        let key = p.name.key();
        if let Some((pf, prev)) = seen.get(&key).copied() {
            let other = cxs[pf].file.name.clone();
            let d = cxs[*f].err(
                DUPLICATE_DECL,
                p.name.span,
                format!("`{}` is declared twice", p.name),
            );
            if pf == *f {
                d.add_secondary(prev, "first declared here");
            } else {
                d.add_note(format!("first declared in {other}"));
            }
        } else {
            seen.insert(key.clone(), (*f, p.name.span));
            if stdfb::lookup(&key).is_some() || super::stdfn::is_std(&key) {
                cxs[*f].err(
                    DUPLICATE_DECL,
                    p.name.span,
                    format!("`{}` is the name of a standard block or function", p.name),
                );
            }
        }
    }
    // Every POU and user type by upper-case key, across all files.
    let mut types: HashMap<String, &ast::TypeDecl> = HashMap::new();
    let mut type_file: Vec<(usize, &ast::TypeDecl)> = Vec::new();
    for (f, unit) in units.iter().enumerate() {
        for item in &unit.items {
            let ast::Item::Types(decls) = item else {
                continue;
            };
            for d in decls {
                let key = d.name.key();
                check_ident(&mut cxs[f], &d.name);
                if types.contains_key(&key)
                    || seen.contains_key(&key)
                    || Elem::from_name(&key).is_some()
                    || stdfb::lookup(&key).is_some()
                {
                    cxs[f].err(
                        DUPLICATE_DECL,
                        d.name.span,
                        format!("`{}` is already the name of a type or POU", d.name),
                    );
                    continue;
                }
                types.insert(key, d);
                type_file.push((f, d));
            }
        }
    }
    let fb_names = Names {
        pous: pous
            .iter()
            .map(|(_, p)| (p.name.key(), (p.name.name.clone(), p.kind)))
            .collect(),
        types,
        depth: std::cell::Cell::new(0),
    };
    // Enumerations first (struct fields and initial values refer to them).
    for (f, d) in &type_file {
        if let TypeSpec::Enum { values, .. } = &d.spec {
            let mut vals = Vec::new();
            let mut seen_vals: HashSet<String> = HashSet::new();
            for v in values {
                check_ident(&mut cxs[*f], &v.name);
                if !seen_vals.insert(v.name.key()) {
                    cxs[*f].err(
                        DUPLICATE_DECL,
                        v.name.span,
                        format!("`{}` appears twice in `{}`", v.name, d.name),
                    );
                    continue;
                }
                let disc = match &v.value {
                    None => None,
                    Some(Literal {
                        kind: LitKind::Int(n),
                        ..
                    }) if i64::try_from(*n).is_ok() => Some(*n),
                    Some(l) => {
                        cxs[*f].err(
                            BAD_INIT,
                            l.span,
                            "an enumeration value must be a (64-bit) integer",
                        );
                        None
                    }
                };
                vals.push((v.name.name.clone(), disc));
            }
            let default = match &d.init {
                Some(Initializer::Simple(Operand::Var(v))) => {
                    vals.iter().position(|(n, _)| v.base.is(n)).unwrap_or(0)
                }
                _ => 0,
            };
            env.types.enums.insert(
                d.name.key(),
                (
                    d.name.name.clone(),
                    vals.iter().map(|(n, _)| n.clone()).collect(),
                ),
            );
            env.types.defs.push((
                *f,
                TypeDef::Enum {
                    name: d.name.name.clone(),
                    values: vals,
                    default,
                },
            ));
        }
    }
    for (f, d) in &type_file {
        if let TypeSpec::Struct { fields, .. } = &d.spec {
            let mut out: Vec<Field> = Vec::new();
            for decl in fields {
                let Some(ty) = resolve_type(&mut cxs[*f], &fb_names, &decl.ty) else {
                    continue;
                };
                if matches!(ty, Ty::Fb(_)) {
                    cxs[*f].err(
                        BAD_OPERATOR_TYPE,
                        decl.ty.span(),
                        "a STRUCT field cannot be a function block instance",
                    );
                    continue;
                }
                let range = fb_names.range_of(&decl.ty);
                let init = decl
                    .init
                    .as_ref()
                    .or_else(|| fb_names.default_init(&decl.ty));
                let init = init.and_then(|i| init_value(&mut cxs[*f], &env.types, i, &ty, range));
                for n in &decl.names {
                    check_ident(&mut cxs[*f], n);
                    if out.iter().any(|o| n.is(&o.name)) {
                        cxs[*f].err(
                            DUPLICATE_DECL,
                            n.span,
                            format!("field `{n}` is declared twice"),
                        );
                        continue;
                    }
                    out.push(Field {
                        name: n.name.clone(),
                        ty: ty.clone(),
                        init: init.clone(),
                        range,
                    });
                }
            }
            env.types.structs.insert(d.name.key(), out.clone());
            env.types.defs.push((
                *f,
                TypeDef::Struct {
                    name: d.name.name.clone(),
                    fields: out,
                },
            ));
        }
    }
    // A STRUCT that contains itself has no finite size.
    for (f, d) in &type_file {
        if matches!(d.spec, TypeSpec::Struct { .. })
            && struct_contains(&env.types, &d.name.key(), &d.name.key(), 0)
        {
            cxs[*f].err(
                RECURSION,
                d.name.span,
                format!("STRUCT `{}` contains itself", d.name),
            );
        }
    }
    for (f, p) in &pous {
        if env.pous.contains_key(&p.name.key()) {
            continue;
        }
        let mut sig = pou_sig(&mut cxs[*f], &fb_names, &env.types, p);
        sig.file = *f;
        env.pous.insert(p.name.key(), sig);
    }
    env.configs = super::config::collect(cxs, units, &fb_names, &mut env);
    super::config::check_fb_externals(cxs, &pous, &env);
    env
}

pub(crate) fn pou_sig(cx: &mut Cx, fb_names: &Names, types: &TypeTables, p: &ast::Pou) -> PouSig {
    check_ident(cx, &p.name);
    let mut sig = PouSig {
        kind: p.kind,
        name: p.name.name.clone(),
        vars: Vec::new(),
        index: HashMap::new(),
        ret: None,
        file: 0,
        poisoned: HashSet::new(),
        span: p.name.span,
    };
    if p.kind == PouKind::Function {
        sig.ret = p
            .return_type
            .as_ref()
            .and_then(|t| resolve_type(cx, fb_names, t));
        if let Some(Ty::Fb(_)) = sig.ret {
            cx.err(
                BAD_OPERATOR_TYPE,
                p.name.span,
                "a FUNCTION cannot return a function block",
            );
            sig.ret = None;
        }
    }
    let mut spans: HashMap<String, Span> = HashMap::new();
    for block in &p.var_blocks {
        // Every declared name is poisoned: uses of a name whose declaration
        // is refused below stay silent (the lookup finds real variables first).
        for decl in &block.decls {
            sig.poisoned.extend(decl.names.iter().map(|n| n.key()));
        }
        let refused = match (p.kind, block.kind) {
            (_, ast::VarKind::Global) => Some((
                BAD_SECTION,
                "VAR_GLOBAL belongs in a CONFIGURATION or RESOURCE: declare the variable there and use it here through VAR_EXTERNAL",
            )),
            (PouKind::Function, ast::VarKind::External) => Some((
                BAD_SECTION,
                "a FUNCTION cannot use globals (VAR_EXTERNAL): pass the value as an input or a VAR_IN_OUT",
            )),
            (PouKind::Program, ast::VarKind::InOut) => Some((
                UNSUPPORTED,
                "VAR_IN_OUT of a PROGRAM is not supported: share the variable through VAR_GLOBAL/VAR_EXTERNAL",
            )),
            _ => None,
        };
        if let Some((code, msg)) = refused {
            cx.err(code, block.span, msg);
            continue;
        }
        let by_ref = matches!(block.kind, ast::VarKind::InOut | ast::VarKind::External);
        if by_ref && block.retain == ast::Retain::Retain {
            cx.err(
                BAD_SECTION,
                block.span,
                format!(
                    "{} cannot be RETAIN: the variable it refers to decides",
                    block.kind.keyword()
                ),
            );
        }
        for decl in &block.decls {
            if by_ref && (decl.init.is_some() || decl.location.is_some()) {
                cx.err(
                    BAD_SECTION,
                    decl.span,
                    format!(
                        "a {} refers to a variable declared elsewhere: it takes no initial value and no address",
                        block.kind.keyword()
                    ),
                );
                continue;
            }
            if decl.edge.is_some()
                && (p.kind == PouKind::Function || block.kind != ast::VarKind::Input)
            {
                cx.err(BAD_OPERATOR_TYPE, decl.span, "R_EDGE and F_EDGE apply to VAR_INPUTs of a FUNCTION_BLOCK or PROGRAM (a FUNCTION has no memory)");
                continue;
            }
            let Some(ty) = resolve_type(cx, fb_names, &decl.ty) else {
                // Already reported; uses of these names stay silent.
                sig.poisoned.extend(decl.names.iter().map(|n| n.key()));
                continue;
            };
            if p.kind == PouKind::Function && matches!(ty, Ty::Fb(_)) {
                cx.err(
                    BAD_OPERATOR_TYPE,
                    decl.ty.span(),
                    "a FUNCTION cannot hold function block instances (it has no memory)",
                );
                continue;
            }
            let location = match &decl.location {
                None => None,
                Some(_) if p.kind == PouKind::Function => {
                    cx.err(
                        BAD_ADDRESS,
                        decl.span,
                        "a FUNCTION cannot have located variables (AT %...)",
                    );
                    continue;
                }
                Some(a) => match resolve_addr(cx, a, Some(&ty)) {
                    Some(l) => Some(l),
                    None => {
                        sig.poisoned.extend(decl.names.iter().map(|n| n.key()));
                        continue;
                    }
                },
            };
            if location.is_some() && decl.init.is_some() {
                cx.warn(BAD_INIT, decl.span, "the initial value of a located variable is not applied: the host owns the process image");
            }
            let range = fb_names.range_of(&decl.ty);
            let init = decl
                .init
                .as_ref()
                .or_else(|| fb_names.default_init(&decl.ty));
            let init = init.and_then(|i| init_value(cx, types, i, &ty, range));
            for name in &decl.names {
                check_ident(cx, name);
                let key = name.key();
                let clash = p.kind == PouKind::Function
                    && (key == p.name.key() || key == "ENO" || key == "EN");
                if let Some(prev) = spans.get(&key) {
                    cx.err(
                        DUPLICATE_DECL,
                        name.span,
                        format!("`{name}` is declared twice"),
                    )
                    .add_secondary(*prev, "first declared here");
                    continue;
                }
                if clash {
                    cx.err(
                        DUPLICATE_DECL,
                        name.span,
                        format!("`{name}` is reserved in a FUNCTION (its result, EN or ENO)"),
                    );
                    continue;
                }
                spans.insert(key.clone(), name.span);
                sig.index.insert(key, sig.vars.len());
                sig.vars.push(Var {
                    name: name.name.clone(),
                    location: location.clone(),
                    edge: decl.edge,
                    range,
                    kind: block.kind,
                    ty: ty.clone(),
                    init: init.clone(),
                    constant: block.constant,
                    retain: block.retain == ast::Retain::Retain,
                    heap: false,
                    line: cx.line(name.span),
                });
            }
        }
    }
    if p.kind == PouKind::Function && mentions(&p.body, "ENO") {
        // ENO exists on every function; it is an output (TRUE on entry) of
        // those whose body sets it.
        sig.index.insert("ENO".into(), sig.vars.len());
        sig.vars.push(Var {
            name: "ENO".into(),
            location: None,
            edge: None,
            range: None,
            kind: ast::VarKind::Output,
            ty: Ty::BOOL,
            init: Some(Init::Const(Const::Bool(true))),
            constant: false,
            retain: false,
            heap: false,
            line: cx.line(p.name.span),
        });
    }
    sig
}

/// Whether any operand of the body names `name`.
fn mentions(body: &[ast::Stmt], name: &str) -> bool {
    let op = |o: &Operand| matches!(o, Operand::Var(v) if v.base.is(name));
    body.iter().any(|s| match s {
        ast::Stmt::Instr(i) => match &i.kind {
            ast::InstrKind::Load { operand, .. } | ast::InstrKind::Expr { operand, .. } => {
                op(operand)
            }
            ast::InstrKind::Store { target, .. }
            | ast::InstrKind::Set { target }
            | ast::InstrKind::Reset { target } => op(target),
            ast::InstrKind::Deferred { first, body, .. } => {
                first.as_ref().is_some_and(op) || mentions(body, name)
            }
            ast::InstrKind::FnCall {
                args: ast::CallArgs::NonFormal(l),
                ..
            } => l.iter().any(op),
            _ => false,
        },
        ast::Stmt::Label(_) => false,
    })
}

/// Resolve a direct address, checking it against the process image and,
/// for a located variable, against its declared type.
pub(crate) fn resolve_addr(
    cx: &mut Cx,
    a: &ast::DirectAddress,
    declared: Option<&Ty>,
) -> Option<Loc> {
    use ast::{AddrSize, Area};
    let text = cx.file.snippet(a.span).to_string();
    if a.partial {
        cx.err(
            UNSUPPORTED,
            a.span,
            "partly specified addresses (%I*, %Q*) are not supported yet",
        );
        return None;
    }
    let (width, default) = match a.size {
        AddrSize::Default | AddrSize::X => (0, Elem::BOOL),
        AddrSize::B => (1, Elem::BYTE),
        AddrSize::W => (2, Elem::WORD),
        AddrSize::D => (4, Elem::DWORD),
        AddrSize::L => (8, Elem::LWORD),
    };
    let (byte, bit) = match (width, a.path.as_slice()) {
        (0, [n]) => ((*n / 8) as usize, Some((*n % 8) as u8)),
        (0, [b, n]) if *n < 8 => (*b as usize, Some(*n as u8)),
        (0, [_, n]) => {
            cx.err(
                BAD_ADDRESS,
                a.span,
                format!("bit {n} does not exist: a byte has bits 0 to 7"),
            );
            return None;
        }
        (w, [n]) => ((*n as usize).saturating_mul(w), None),
        _ => {
            cx.err(BAD_ADDRESS, a.span, format!("`{text}`: only `%IXbyte.bit`, `%IXbit` and `%IBn`/`%IWn`/`%IDn`/`%ILn` addresses are supported"));
            return None;
        }
    };
    let (cap, area_name) = match a.area {
        Area::Input => (il_std::INPUT_BYTES, "inputs"),
        Area::Output => (il_std::OUTPUT_BYTES, "outputs"),
        Area::Memory => (il_std::MEMORY_BYTES, "memory"),
    };
    if byte.saturating_add(width.max(1)) > cap {
        cx.err(
            BAD_ADDRESS,
            a.span,
            format!("`{text}` is outside the process image ({cap} bytes of {area_name})"),
        );
        return None;
    }
    let elem = match declared {
        None => default,
        Some(Ty::Elem(e)) => {
            let fits = match width {
                0 => *e == Elem::BOOL,
                1 => matches!(e, Elem::BYTE | Elem::SINT | Elem::USINT),
                2 => matches!(e, Elem::WORD | Elem::INT | Elem::UINT),
                4 => matches!(e, Elem::DWORD | Elem::DINT | Elem::UDINT | Elem::REAL),
                _ => matches!(e, Elem::LWORD | Elem::LINT | Elem::ULINT | Elem::LREAL),
            };
            if !fits {
                let what = match width {
                    0 => "a bit (BOOL)",
                    1 => "a byte (BYTE, SINT, USINT)",
                    2 => "a word (WORD, INT, UINT)",
                    4 => "a double word (DWORD, DINT, UDINT, REAL)",
                    _ => "a long word (LWORD, LINT, ULINT, LREAL)",
                };
                cx.err(
                    BAD_ADDRESS,
                    a.span,
                    format!("`{text}` is {what}; it cannot hold {}", e.name()),
                );
                return None;
            }
            *e
        }
        Some(t) => {
            cx.err(
                BAD_ADDRESS,
                a.span,
                format!("a {t} cannot be located at a direct address"),
            );
            return None;
        }
    };
    Some(Loc {
        area: a.area,
        byte,
        bit,
        elem,
        text,
    })
}

/// Names with `__` or a trailing `_` are not IEC identifiers, and the generated
/// code relies on that to keep its own names apart.
fn check_ident(cx: &mut Cx, id: &ast::Ident) {
    // The lexer already refuses `_` alone; this also covers names that reach
    // the checker some other way.
    if id.name.bytes().all(|b| b == b'_') {
        cx.err(
            BAD_IDENT,
            id.span,
            format!("`{id}` is not an IEC identifier (it needs a letter or a digit)"),
        );
    } else if id.name.contains("__") || id.name.ends_with('_') {
        cx.err(
            BAD_IDENT,
            id.span,
            format!("`{id}` is not an IEC identifier (no `__`, no trailing `_`)"),
        );
    }
}

fn struct_contains(t: &TypeTables, key: &str, target: &str, depth: u32) -> bool {
    let Some(fields) = t.structs.get(key) else {
        return false;
    };
    depth < 64
        && fields.iter().any(|f| {
            let mut ty = &f.ty;
            while let Ty::Array { elem, .. } = ty {
                ty = elem;
            }
            matches!(ty, Ty::Struct(n) if n.eq_ignore_ascii_case(target) || struct_contains(t, &n.to_ascii_uppercase(), target, depth + 1))
        })
}

pub(crate) fn resolve_type(cx: &mut Cx, fb_names: &Names, spec: &TypeSpec) -> Option<Ty> {
    match spec {
        TypeSpec::Named(id) => {
            if let Some(e) = Elem::from_name(&id.name) {
                return Some(Ty::Elem(e));
            }
            let key = id.key();
            match key.as_str() {
                "STRING" => {
                    return Some(Ty::Str {
                        wide: false,
                        len: DEFAULT_STRING_LEN,
                    });
                }
                "WSTRING" => {
                    return Some(Ty::Str {
                        wide: true,
                        len: DEFAULT_STRING_LEN,
                    });
                }
                _ => {}
            }
            if let Some(fb) = stdfb::lookup(&key) {
                return Some(Ty::Fb(fb.name.to_string()));
            }
            if let Some(t) = fb_names.user_type(cx, &key, id.span) {
                return t;
            }
            match fb_names.pous.get(&key) {
                Some((declared, PouKind::FunctionBlock)) => return Some(Ty::Fb(declared.clone())),
                Some((declared, kind)) => {
                    let why = if *kind == PouKind::Program {
                        "programs are instances of a CONFIGURATION's resources, not variables of a POU"
                    } else {
                        "a FUNCTION is called, not instantiated"
                    };
                    cx.err(
                        UNKNOWN_TYPE,
                        id.span,
                        format!("`{declared}` is a {}, not a type: {why}", kind.keyword()),
                    );
                    return None;
                }
                None => {}
            }
            let names = super::types::ALL_ELEMS.iter().map(|e| e.name()).chain([
                "TON", "TOF", "TP", "CTU", "CTD", "CTUD", "SR", "RS", "R_TRIG", "F_TRIG",
            ]);
            let d = cx
                .err(UNKNOWN_TYPE, id.span, format!("unknown type `{id}`"))
                .set_label("not an elementary type or function block");
            if let Some(s) = suggest(&id.name, names) {
                d.help = Some(format!("did you mean `{s}`?"));
            }
            None
        }
        TypeSpec::String { wide, len, span } => {
            let len = match len {
                None => DEFAULT_STRING_LEN,
                Some(ConstExpr::Lit(Literal {
                    kind: LitKind::Int(n),
                    ..
                })) if (1..=65535).contains(n) => *n as u32,
                Some(other) => {
                    cx.err(
                        BAD_INIT,
                        other.span(),
                        "a string length must be an integer literal from 1 to 65535",
                    );
                    let _ = span;
                    return None;
                }
            };
            Some(Ty::Str { wide: *wide, len })
        }
        TypeSpec::Array { dims, elem, .. } => {
            let elem = resolve_type(cx, fb_names, elem)?;
            let mut out = Vec::new();
            let mut total: i128 = 1;
            for d in dims {
                let (Some(lo), Some(hi)) = (const_int(cx, &d.lo), const_int(cx, &d.hi)) else {
                    return None;
                };
                if hi < lo {
                    cx.err(
                        BAD_INDEX,
                        d.span,
                        format!("array bounds {lo}..{hi} are empty"),
                    );
                    return None;
                }
                total = total.saturating_mul((hi - lo + 1) as i128);
                out.push((lo, hi));
            }
            if total > 1 << 24 {
                cx.err(
                    BAD_INDEX,
                    spec.span(),
                    "array too large (over 16 million elements)",
                );
                return None;
            }
            Some(Ty::Array {
                dims: out,
                elem: Box::new(elem),
            })
        }
        TypeSpec::Subrange { base, range, span } => {
            let e =
                Elem::from_name(&base.name).filter(|e| e.int_range().is_some() && *e != Elem::BOOL);
            let Some(e) = e else {
                cx.err(
                    BAD_INIT,
                    base.span,
                    format!("a subrange needs an integer base type, not `{base}`"),
                );
                return None;
            };
            let (Some(lo), Some(hi)) = (const_int(cx, &range.lo), const_int(cx, &range.hi)) else {
                return None;
            };
            let (min, max) = e.int_range().unwrap_or_default();
            if lo > hi || (lo as i128) < min || (hi as i128) > max {
                cx.err(
                    BAD_INIT,
                    *span,
                    format!("the subrange {lo}..{hi} is empty or outside {}", e.name()),
                );
                return None;
            }
            Some(Ty::Elem(e))
        }
        TypeSpec::Enum { span, .. } | TypeSpec::Struct { span, .. } => {
            cx.err(
                UNSUPPORTED,
                *span,
                "enumerations and structures are declared in TYPE ... END_TYPE and used by name",
            );
            None
        }
    }
}

fn const_int(cx: &mut Cx, c: &ConstExpr) -> Option<i64> {
    match c {
        ConstExpr::Lit(Literal {
            kind: LitKind::Int(n),
            ..
        }) if i64::try_from(*n).is_ok() => Some(*n as i64),
        other => {
            cx.err(
                UNSUPPORTED,
                other.span(),
                "array bounds must be integer literals",
            );
            None
        }
    }
}

pub(crate) fn init_value(
    cx: &mut Cx,
    types: &TypeTables,
    init: &Initializer,
    ty: &Ty,
    range: Option<(i128, i128)>,
) -> Option<Init> {
    match (init, ty) {
        (Initializer::Simple(Operand::Lit(lit)), Ty::Elem(_) | Ty::Str { .. }) => {
            match coerce(&lit_class(lit), ty) {
                Ok(Const::Int(v, e)) if range.is_some_and(|(lo, hi)| v < lo || v > hi) => {
                    let (lo, hi) = range.unwrap_or_default();
                    cx.err(
                        BAD_INIT,
                        lit.span,
                        format!("{v} is outside the subrange {lo}..{hi}"),
                    );
                    let _ = e;
                    None
                }
                Ok(c) => Some(Init::Const(c)),
                Err(msg) => {
                    cx.err(BAD_INIT, lit.span, msg);
                    None
                }
            }
        }
        (Initializer::Simple(o), Ty::Enum(name)) => {
            let value = match o {
                Operand::Lit(Literal {
                    kind: LitKind::Enum { ty: t, value },
                    ..
                }) if t.is(name) => value,
                Operand::Var(v) if v.path.is_empty() => &v.base,
                _ => {
                    cx.err(
                        BAD_INIT,
                        o.span(),
                        format!("expected a value of the enumeration {name}"),
                    );
                    return None;
                }
            };
            let vals = types
                .enums
                .get(&name.to_ascii_uppercase())
                .map(|(_, v)| v.clone())
                .unwrap_or_default();
            match vals.iter().find(|v| value.is(v)) {
                Some(v) => Some(Init::Const(Const::Enum {
                    ty: name.clone(),
                    value: v.clone(),
                })),
                None => {
                    cx.err(
                        BAD_INIT,
                        o.span(),
                        format!("`{value}` is not a value of {name} ({})", vals.join(", ")),
                    );
                    None
                }
            }
        }
        (Initializer::Struct { fields, .. }, Ty::Struct(name)) => {
            let defs = types
                .structs
                .get(&name.to_ascii_uppercase())
                .cloned()
                .unwrap_or_default();
            let mut out = Vec::new();
            for (fname, v) in fields {
                let Some(f) = defs.iter().find(|f| fname.is(&f.name)) else {
                    cx.err(
                        UNKNOWN_MEMBER,
                        fname.span,
                        format!("{name} has no field `{fname}`"),
                    );
                    continue;
                };
                if let Some(i) = init_value(cx, types, v, &f.ty, f.range) {
                    out.push((f.name.clone(), f.ty.clone(), i));
                }
            }
            Some(Init::Struct(out))
        }
        (Initializer::Array { elems, span }, Ty::Array { dims, elem }) => {
            let total: i64 = dims.iter().map(|(lo, hi)| hi - lo + 1).product();
            let mut out = Vec::new();
            // Each count is at most `total` (16 million): their sum over any
            // source text fits an i64.
            let mut len: i64 = 0;
            for (count, e) in elems {
                let n = match count {
                    None => 1,
                    Some(Literal {
                        kind: LitKind::Int(n),
                        ..
                    }) if (0..=total as i128).contains(n) => *n as i64,
                    Some(l) => {
                        cx.err(
                            BAD_INIT,
                            l.span,
                            "a repeat count must be a small non-negative integer",
                        );
                        return None;
                    }
                };
                let Some(Init::Const(c)) = init_value(cx, types, e, elem, None) else {
                    if !matches!(e, Initializer::Simple(Operand::Lit(_))) {
                        cx.err(UNSUPPORTED, e.span(), "array elements must be literals");
                    }
                    return None;
                };
                len += n;
                if n > 0 {
                    out.push((n as usize, c));
                }
            }
            if len > total {
                cx.err(
                    BAD_INIT,
                    *span,
                    format!("{len} initial values for an array of {total} elements"),
                );
                return None;
            }
            Some(Init::Array(out))
        }
        (Initializer::Struct { fields, .. }, Ty::Fb(fb)) => {
            let Some(std) = stdfb::lookup(fb) else {
                cx.err(
                    UNSUPPORTED,
                    init.span(),
                    "initial values of user FB instances are not supported yet",
                );
                return None;
            };
            let mut out = Vec::new();
            for (name, v) in fields {
                let Some((iec, e)) = std.inputs.iter().find(|(n, _)| name.is(n)) else {
                    cx.err(
                        UNKNOWN_MEMBER,
                        name.span,
                        format!("{fb} has no input `{name}`"),
                    );
                    continue;
                };
                if let Some(Init::Const(c)) = init_value(cx, types, v, &Ty::Elem(*e), None) {
                    out.push((iec.to_string(), c));
                }
            }
            Some(Init::Fields(out))
        }
        _ => {
            cx.err(
                BAD_INIT,
                init.span(),
                format!("this initial value does not fit type {ty}"),
            );
            None
        }
    }
}

/// A literal before it meets a type.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum LitClass {
    Typed(Const),
    Int(i128),
    Real(f64, String),
    Str(String, bool),
    Unsupported(&'static str),
    /// A typed literal whose value does not fit its prefix (`SINT#300`).
    Invalid(String),
    /// A generic standard function applied to untyped literals only
    /// (`LD k / MUX 10, 20, 30`): like a literal, it gets its type from its
    /// first typed use, and its code is emitted then.
    Pending(Box<Pending>),
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Pending {
    pub key: String,
    pub args: Vec<(PendArg, Span)>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) enum PendArg {
    Typed(super::ir::Value, Ty),
    Lit(LitClass),
}

pub(crate) fn lit_class(lit: &Literal) -> LitClass {
    let untyped = match &lit.kind {
        LitKind::Int(v) => LitClass::Int(*v),
        LitKind::Real { value, text } => LitClass::Real(*value, text.clone()),
        LitKind::Bool(b) => LitClass::Typed(Const::Bool(*b)),
        LitKind::Time { nanos, long } => LitClass::Typed(Const::Time(
            *nanos,
            if *long { Elem::LTIME } else { Elem::TIME },
        )),
        LitKind::Date(d) => LitClass::Typed(Const::Time(*d, Elem::DATE)),
        LitKind::Tod(t) => LitClass::Typed(Const::Time(*t, Elem::TOD)),
        LitKind::Dt(t) => LitClass::Typed(Const::Time(*t, Elem::DT)),
        LitKind::String { value, wide } => LitClass::Str(value.clone(), *wide),
        LitKind::Enum { .. } => LitClass::Unsupported("enumeration literals are not supported yet"),
    };
    let Some(prefix) = &lit.type_prefix else {
        return untyped;
    };
    if prefix.is("STRING") || prefix.is("WSTRING") {
        return untyped;
    }
    match Elem::from_name(&prefix.name) {
        Some(e) => match coerce(&untyped, &Ty::Elem(e)) {
            Ok(c) => LitClass::Typed(c),
            Err(m) => LitClass::Invalid(m),
        },
        None => LitClass::Invalid(format!("`{prefix}#` is not an elementary type")),
    }
}

/// Give a literal a type, or say why it does not fit.
pub(crate) fn coerce(lit: &LitClass, ty: &Ty) -> Result<Const, String> {
    let mismatch = || {
        Err(format!(
            "expected a value of type {ty}, found {}",
            describe(lit)
        ))
    };
    match (lit, ty) {
        (LitClass::Typed(c), _) if c.ty() == *ty => Ok(c.clone()),
        (LitClass::Typed(Const::Str { value, wide, .. }), Ty::Str { wide: w, len })
            if wide == w =>
        {
            str_const(value, *wide, *len, ty)
        }
        (LitClass::Int(v), Ty::Elem(Elem::BOOL)) => match v {
            0 | 1 => Ok(Const::Bool(*v == 1)),
            _ => Err(format!("{v} is not a BOOL (only 0 and 1 are)")),
        },
        (LitClass::Int(v), Ty::Elem(e)) if e.int_range().is_some() => {
            let (lo, hi) = e.int_range().expect("checked");
            if (lo..=hi).contains(v) {
                Ok(Const::Int(*v, *e))
            } else {
                Err(format!("{v} does not fit in {} ({lo}..{hi})", e.name()))
            }
        }
        (LitClass::Int(v), Ty::Elem(e)) if e.is_real() => Ok(Const::Real(*v as f64, *e)),
        (LitClass::Real(v, text), Ty::Elem(e @ (Elem::REAL | Elem::LREAL))) => {
            let v = if *e == Elem::REAL {
                text.replace('_', "")
                    .parse::<f32>()
                    .map(f64::from)
                    .unwrap_or(*v)
            } else {
                *v
            };
            if v.is_finite() {
                Ok(Const::Real(v, *e))
            } else {
                Err(format!("{text} is out of range for {}", e.name()))
            }
        }
        (LitClass::Str(s, wide), Ty::Str { wide: w, len }) if wide == w => {
            str_const(s, *wide, *len, ty)
        }
        (LitClass::Unsupported(msg), _) => Err((*msg).to_string()),
        (LitClass::Invalid(msg), _) => Err(msg.clone()),
        (LitClass::Pending(p), _) => Err(format!("the result of {} has no type here", p.key)),
        _ => mismatch(),
    }
}

fn str_const(s: &str, wide: bool, len: u32, ty: &Ty) -> Result<Const, String> {
    let n = if wide {
        s.encode_utf16().count()
    } else {
        s.len()
    };
    if n > len as usize {
        return Err(format!("the string has {n} characters; {ty} holds {len}"));
    }
    Ok(Const::Str {
        value: s.to_string(),
        wide,
        len,
    })
}

pub(crate) fn describe(lit: &LitClass) -> String {
    match lit {
        LitClass::Typed(c) => format!("a {} literal", c.ty()),
        LitClass::Int(v) => format!("the integer literal {v}"),
        LitClass::Real(_, t) => format!("the real literal {t}"),
        LitClass::Str(..) => "a string literal".to_string(),
        LitClass::Unsupported(m) => (*m).to_string(),
        LitClass::Invalid(m) => m.clone(),
        LitClass::Pending(p) => format!("the result of {} on untyped literals", p.key),
    }
}

/// Refuse calls that lead back to the caller, and FBs that contain themselves.
pub(crate) fn check_recursion(cxs: &mut [Cx], env: &Env, units: &[&ast::CompilationUnit]) {
    // Edges: POU → POUs it calls (functions) or instantiates (FB types), with
    // the file and span of the reference.
    let mut edges: HashMap<String, Vec<(String, usize, Span)>> = HashMap::new();
    for (f, unit) in units.iter().enumerate() {
        for item in &unit.items {
            let ast::Item::Pou(p) = item else { continue };
            let me = p.name.key();
            let out = edges.entry(me.clone()).or_default();
            if let Some(sig) = env.pou(&me) {
                for v in &sig.vars {
                    if let Ty::Fb(t) = &v.ty
                        && env.pou(t).is_some()
                    {
                        out.push((t.to_ascii_uppercase(), f, p.name.span));
                    }
                }
            }
            let mut calls = Vec::new();
            collect_calls(&p.body, env, &mut calls);
            out.extend(calls.into_iter().map(|(k, s)| (k, f, s)));
        }
    }
    let mut reported = HashSet::new();
    let mut starts: Vec<&String> = edges.keys().collect();
    starts.sort();
    for start in starts {
        // Depth-first search for a path back to `start`.
        let mut stack = vec![(start.clone(), vec![start.clone()])];
        let mut visited = HashSet::new();
        while let Some((node, path)) = stack.pop() {
            for (next, f, span) in edges.get(&node).into_iter().flatten() {
                if next == start {
                    if reported.insert(start.clone()) {
                        let mut names: Vec<String> = path
                            .iter()
                            .map(|k| env.pou(k).map_or(k.clone(), |s| s.name.clone()))
                            .collect();
                        names.push(env.pou(start).map_or(start.clone(), |s| s.name.clone()));
                        cxs[*f].err(
                            RECURSION,
                            *span,
                            format!("recursion is not allowed: {}", names.join(" → ")),
                        );
                    }
                } else if visited.insert(next.clone()) {
                    let mut p = path.clone();
                    p.push(next.clone());
                    stack.push((next.clone(), p));
                }
            }
        }
    }
}

fn collect_calls(body: &[ast::Stmt], env: &Env, out: &mut Vec<(String, Span)>) {
    for s in body {
        let ast::Stmt::Instr(i) = s else { continue };
        match &i.kind {
            ast::InstrKind::FnCall { name, .. } if env.pou(&name.name).is_some() => {
                out.push((name.key(), name.span))
            }
            ast::InstrKind::Call {
                target: Operand::Var(v),
                ..
            } if v.path.is_empty()
                && env
                    .pou(&v.base.name)
                    .is_some_and(|s| s.kind == PouKind::Function) =>
            {
                out.push((v.base.key(), v.base.span));
            }
            ast::InstrKind::Deferred { body, .. } => collect_calls(body, env, out),
            _ => {}
        }
    }
}
