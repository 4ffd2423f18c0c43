//! Grammar actions: building AST nodes, and the checks that give clearer
//! messages after parsing than a syntax error would.

use lalrpop_util::ErrorRecovery;

use super::code;
use super::lexer::{LexError, Tok};
use crate::ast::*;
use crate::diag::Diagnostic;

/// State shared with the grammar's actions.
#[derive(Default)]
pub struct Ctx {
    pub errors: Vec<ErrorRecovery<usize, Tok, LexError>>,
    pub diags: Vec<Diagnostic>,
    /// The statements of the open POU and of its open parenthesised groups,
    /// pushed by each line as it is reduced: a group takes the tail from its
    /// start on at its `)`, the POU the rest at its end. One growing vector
    /// instead of a vector per line, copied into the body at the end (the
    /// lines, the list of them and the body were alive at once).
    pub stmts: Vec<Stmt>,
    /// What the elements of the open POU decided so far.
    elems: Elems,
}

/// The checks of a POU's element order, made as each element is reduced
/// (see [`elem`]).
#[derive(Default)]
struct Elems {
    var_blocks: Vec<VarBlock>,
    begin: Option<Span>,
    end: Option<Span>,
    reported_late_decl: bool,
    /// The first element's span, for code outside any POU.
    first: Option<Span>,
    /// Held back until the POU ends, to keep the order the messages had
    /// when the checks ran there.
    diags: Vec<Diagnostic>,
}

pub fn sp(lo: usize, hi: usize) -> Span {
    Span::new(lo, hi)
}

/// One element of a POU: declarations, instruction lines, KAS-IDE markers.
pub enum Elem {
    Vars(VarBlock),
    /// A line: how many statements it pushed onto [`Ctx::stmts`].
    Stmts(usize),
    BeginIl(Span),
    EndIl(Span),
}

/// Each variant is small: the parser's stack entry is as large as its
/// largest symbol (see [`unbox`]), so a `Task` is boxed.
pub enum CfgElem {
    Vars(VarBlock),
    VarConfig(Vec<ConfigVar>, Span),
    VarAccess(Vec<AccessVar>, Span),
    Resource(Resource),
    Task(Box<Task>),
    Program(ProgramInstance),
    Error,
}

/// The items of a list whose nonterminal is boxed. lalrpop keeps every
/// symbol on its stack in one enum, as large as the largest nonterminal, and
/// moves one on every shift and reduce: declarations, type specs, POUs and
/// the other rare, large results are boxed in the grammar so that the entry
/// is sized by an instruction (the common symbol) instead of a `VarDecl`.
pub fn unbox<T>(v: Vec<Box<T>>) -> Vec<T> {
    v.into_iter().map(|b| *b).collect()
}

/// One line: its label and instruction go onto [`Ctx::stmts`]; returns
/// how many.
pub fn line(ctx: &mut Ctx, label: Option<Ident>, instr: Option<Instr>) -> usize {
    let n = ctx.stmts.len();
    ctx.stmts.extend(label.map(Stmt::Label));
    ctx.stmts.extend(instr.map(Stmt::Instr));
    ctx.stmts.len() - n
}

/// The statements of a parenthesised group, pushed since its first line
/// (`start`), as one exactly sized list.
pub fn group(ctx: &mut Ctx, start: usize) -> Vec<Stmt> {
    ctx.stmts.split_off(start)
}

pub fn instr(kind: InstrKind, lo: usize, op_hi: usize, hi: usize) -> Instr {
    Instr {
        kind,
        op_span: sp(lo, op_hi),
        span: sp(lo, hi),
    }
}

pub fn bit_access(ctx: &mut Ctx, l: Literal) -> Accessor {
    match l.kind {
        LitKind::Int(n) if (0..=63).contains(&n.get()) && l.type_prefix.is_none() => {
            Accessor::Part {
                size: AddrSize::Default,
                index: n.get() as u32,
                span: l.span,
            }
        }
        _ => {
            ctx.diags.push(
                Diagnostic::error(
                    code::SYNTAX,
                    l.span,
                    "expected a field name or a bit number (0 to 63) after `.`",
                )
                .with_label("not a field or bit"),
            );
            Accessor::Part {
                size: AddrSize::Default,
                index: 0,
                span: l.span,
            }
        }
    }
}

pub fn repeat(ctx: &mut Ctx, n: Literal, i: Initializer) -> (Option<Literal>, Initializer) {
    if !matches!(n.kind, LitKind::Int(k) if k.get() >= 0) || n.type_prefix.is_some() {
        ctx.diags.push(
            Diagnostic::error(
                code::DECL_SYNTAX,
                n.span,
                "a repeat count in an array initial value must be a plain integer, e.g. `3(0)`",
            )
            .with_label("not a repeat count"),
        );
    }
    (Some(n), i)
}

pub fn var_block(
    ctx: &mut Ctx,
    kind: VarKind,
    quals: Vec<(Tok, Span)>,
    decls: Vec<Option<Box<VarDecl>>>,
    _closed: bool,
    span: Span,
) -> VarBlock {
    let mut constant = false;
    let mut retain = Retain::Unspecified;
    for (q, s) in quals {
        let dup = match q {
            Tok::Constant => std::mem::replace(&mut constant, true),
            Tok::Retain | Tok::NonRetain => {
                let r = if q == Tok::Retain {
                    Retain::Retain
                } else {
                    Retain::NonRetain
                };
                std::mem::replace(&mut retain, r) != Retain::Unspecified
            }
            _ => false,
        };
        if dup {
            ctx.diags.push(
                Diagnostic::error(
                    code::DECL_SYNTAX,
                    s,
                    "this qualifier is repeated or conflicts with an earlier one",
                )
                .with_label("repeated qualifier"),
            );
        }
    }
    // Exactly sized: collected through `flatten`, a block of one
    // declaration reserved room for four (a third of the memory of a
    // program of many small POUs).
    let mut out = Vec::with_capacity(decls.iter().flatten().count());
    out.extend(decls.into_iter().flatten().map(|d| *d));
    VarBlock {
        kind,
        constant,
        retain,
        decls: out,
        span,
    }
}

/// Check a body: labels, jumps, CAL and RET inside parentheses.
fn check_parens(ctx: &mut Ctx, body: &[Stmt], inside: bool) {
    for s in body {
        match s {
            Stmt::Label(l) if inside => ctx.diags.push(
                Diagnostic::error(
                    code::IN_PARENS,
                    l.span,
                    format!("a label is not allowed inside parentheses (`{}:`)", l.name),
                )
                .with_label("label inside ( )")
                .with_help("move the label before the operator that opens the parenthesis"),
            ),
            Stmt::Label(_) => {}
            Stmt::Instr(i) => match &i.kind {
                InstrKind::Deferred { body, .. } => check_parens(ctx, body, true),
                InstrKind::Jump { .. } | InstrKind::Call { .. } | InstrKind::Return { .. }
                    if inside =>
                {
                    let what = match i.kind {
                        InstrKind::Jump { .. } => "a jump",
                        InstrKind::Call { .. } => "CAL",
                        _ => "RET",
                    };
                    ctx.diags.push(
                        Diagnostic::error(code::IN_PARENS, i.op_span, format!("{what} is not allowed inside parentheses"))
                            .with_label("inside ( )")
                            .with_note("between `OP(` and `)` only loads, stores and operators that compute a value may appear"),
                    );
                }
                _ => {}
            },
        }
    }
}

/// The first element of a POU. It starts afresh, keeping only this line's
/// statements: error recovery drops the symbols of what it abandons, not
/// what their lines pushed onto [`Ctx::stmts`].
pub fn first_elem(ctx: &mut Ctx, e: Elem) {
    let keep = match e {
        Elem::Stmts(n) => n,
        _ => 0,
    };
    ctx.stmts.drain(..ctx.stmts.len() - keep);
    ctx.elems = Elems::default();
    elem(ctx, e);
}

/// Before the first element (of code outside any POU): nothing parsed yet.
pub fn start_elems(ctx: &mut Ctx) {
    ctx.elems = Elems::default();
    ctx.stmts.clear();
}

/// One more element of the open POU, checked against the ones before it.
pub fn elem(ctx: &mut Ctx, e: Elem) {
    // Called as each element is reduced: the body so far is `ctx.stmts`
    // (a line's statements are its tail).
    let st = &mut ctx.elems;
    match e {
        Elem::Vars(v) => {
            st.first.get_or_insert(v.span);
            if let (false, Some(first)) = (st.reported_late_decl, ctx.stmts.first().map(Stmt::span))
            {
                st.reported_late_decl = true;
                let kw = v.kind.keyword();
                st.diags.push(
                    Diagnostic::error(
                        code::DECL_AFTER_CODE,
                        sp(v.span.lo as usize, v.span.lo as usize + kw.len()),
                        "declarations must come before the instructions",
                    )
                    .with_label(format!("{kw} block after instructions"))
                    .with_secondary(first, "the instructions start here")
                    .with_help("move all VAR ... END_VAR blocks to the start of the POU"),
                );
            }
            st.var_blocks.push(v);
        }
        Elem::Stmts(n) => {
            let line_first = ctx.stmts.len() - n;
            if let Some(sspan) = ctx.stmts.get(line_first).map(Stmt::span) {
                st.first.get_or_insert(sspan);
                if let Some(e) = st.end {
                    st.diags.push(
                        Diagnostic::error(code::BEGIN_IL, sspan, "instructions after END_IL")
                            .with_secondary(e, "the body ended here")
                            .with_label("outside BEGIN_IL ... END_IL"),
                    );
                    st.end = None;
                }
            }
        }
        Elem::BeginIl(s) => {
            st.first.get_or_insert(s);
            if st.begin.is_some() {
                st.diags.push(
                    Diagnostic::error(code::BEGIN_IL, s, "a second BEGIN_IL")
                        .with_label("repeated"),
                );
            } else if !ctx.stmts.is_empty() {
                st.diags.push(
                    Diagnostic::error(
                        code::BEGIN_IL,
                        s,
                        "BEGIN_IL must come before the first instruction",
                    )
                    .with_label("too late"),
                );
            }
            st.begin = Some(s);
        }
        Elem::EndIl(s) => {
            st.first.get_or_insert(s);
            if st.begin.is_none() {
                st.diags.push(
                    Diagnostic::error(code::BEGIN_IL, s, "END_IL without BEGIN_IL")
                        .with_label("no BEGIN_IL before this"),
                );
            }
            st.end = Some(s);
        }
    }
}

struct Split {
    var_blocks: Vec<VarBlock>,
    body: Vec<Stmt>,
    begin_il: bool,
}

/// The end of a POU's elements: the checks of the whole, and its parts.
fn finish_elems(ctx: &mut Ctx) -> Split {
    let st = std::mem::take(&mut ctx.elems);
    let mut body = std::mem::take(&mut ctx.stmts);
    // Grown by doubling: up to half of it would stay unused in the tree.
    body.shrink_to_fit();
    ctx.diags.extend(st.diags);
    if let (Some(b), None) = (st.begin, st.end)
        && !ctx.diags.iter().any(|d| d.code == code::BEGIN_IL)
    {
        {
            ctx.diags.push(
                Diagnostic::error(code::BEGIN_IL, b, "missing END_IL")
                    .with_label("this BEGIN_IL is never closed"),
            );
        }
    }
    check_parens(ctx, &body, false);
    Split {
        var_blocks: st.var_blocks,
        body,
        begin_il: st.begin.is_some(),
    }
}

#[allow(clippy::too_many_arguments)]
pub fn pou(
    ctx: &mut Ctx,
    kind: PouKind,
    kw_span: Span,
    name: Option<Ident>,
    ret: Option<TypeSpec>,
    has_elems: bool,
    end: Option<(PouKind, Span)>,
    span: Span,
) -> Pou {
    let name = name.unwrap_or_else(|| Ident::new("", kw_span));
    // A result type the lexer had to make up (`FUNCTION f :` and nothing).
    let ret = ret.filter(|t| !matches!(t, TypeSpec::Named(n) if n.name.is_empty()));
    if !has_elems {
        start_elems(ctx);
    }
    let Split {
        var_blocks,
        body,
        begin_il,
    } = finish_elems(ctx);
    if !name.name.is_empty() {
        match (kind, &ret) {
            (PouKind::Function, None) => ctx.diags.push(
                Diagnostic::error(
                    code::RESULT_TYPE,
                    name.span,
                    format!("FUNCTION `{name}` needs a result type"),
                )
                .with_label("no result type")
                .with_help(format!(
                    "write `FUNCTION {name} : INT` (or the type it returns)"
                )),
            ),
            (PouKind::FunctionBlock | PouKind::Program, Some(t)) => ctx.diags.push(
                Diagnostic::error(
                    code::RESULT_TYPE,
                    t.span(),
                    format!("a {} has no result type", kind.keyword()),
                )
                .with_label("only a FUNCTION returns a value")
                .with_help("declare outputs in a VAR_OUTPUT block instead"),
            ),
            _ => {}
        }
    }
    let end_span = match end {
        Some((k, s)) => {
            if k != kind {
                ctx.diags.push(
                    Diagnostic::error(
                        code::MISSING_END,
                        s,
                        format!(
                            "END_{} does not close {} `{name}`",
                            k.keyword(),
                            kind.keyword()
                        ),
                    )
                    .with_label(format!("expected END_{}", kind.keyword()))
                    .with_secondary(kw_span, "opened here"),
                );
            }
            s
        }
        None => {
            let at = sp(span.hi as usize, span.hi as usize);
            let msg = if name.name.is_empty() {
                format!("missing END_{}", kind.keyword())
            } else {
                format!("missing END_{} for `{name}`", kind.keyword())
            };
            ctx.diags.push(
                Diagnostic::error(code::MISSING_END, at, msg)
                    .with_label(format!("END_{} expected here", kind.keyword()))
                    .with_secondary(kw_span.to(name.span), "this POU is not closed"),
            );
            at
        }
    };
    Pou {
        kind,
        name,
        return_type: ret,
        var_blocks,
        body,
        begin_il,
        span,
        end_span,
        host: None,
    }
}

/// Instructions outside any POU: reported, then dropped.
pub fn orphan(ctx: &mut Ctx, span: Span) {
    let at = ctx
        .elems
        .first
        .unwrap_or(sp(span.lo as usize, span.lo as usize));
    ctx.diags.push(
        Diagnostic::error(
            code::ORPHAN,
            at,
            "IL instructions must be inside a PROGRAM, FUNCTION or FUNCTION_BLOCK",
        )
        .with_label("outside any POU")
        .with_help("wrap them in `PROGRAM name` ... `END_PROGRAM`, with their VAR blocks first"),
    );
    let _ = finish_elems(ctx);
}

pub fn configuration(name: Ident, els: Vec<CfgElem>, span: Span) -> Configuration {
    let mut globals = Vec::new();
    let mut resources = Vec::new();
    let (mut var_config, mut var_access) = (Vec::new(), Vec::new());
    let mut loose = Resource {
        name: None,
        on: None,
        globals: Vec::new(),
        tasks: Vec::new(),
        programs: Vec::new(),
        span,
    };
    for e in els {
        match e {
            CfgElem::Vars(v) => globals.push(v),
            CfgElem::VarConfig(v, _) => var_config.extend(v),
            CfgElem::VarAccess(v, _) => var_access.extend(v),
            CfgElem::Resource(r) => resources.push(r),
            CfgElem::Task(t) => loose.tasks.push(*t),
            CfgElem::Program(p) => loose.programs.push(p),
            CfgElem::Error => {}
        }
    }
    if !loose.tasks.is_empty() || !loose.programs.is_empty() || resources.is_empty() {
        resources.insert(0, loose);
    }
    Configuration {
        name,
        globals,
        resources,
        var_config,
        var_access,
        span,
    }
}

pub fn resource(
    ctx: &mut Ctx,
    name: Ident,
    on: Option<Ident>,
    els: Vec<CfgElem>,
    span: Span,
) -> CfgElem {
    let mut r = Resource {
        name: Some(name),
        on,
        globals: Vec::new(),
        tasks: Vec::new(),
        programs: Vec::new(),
        span,
    };
    for e in els {
        match e {
            CfgElem::Vars(v) => r.globals.push(v),
            // Ed.2 B.1.7: access and instance-specific declarations are the
            // configuration's, after its resources.
            CfgElem::VarConfig(_, span) | CfgElem::VarAccess(_, span) => ctx.diags.push(
                Diagnostic::error(
                    code::CONFIG_SYNTAX,
                    span,
                    "VAR_CONFIG and VAR_ACCESS belong in the CONFIGURATION, not in a RESOURCE",
                )
                .with_label("inside a RESOURCE"),
            ),
            CfgElem::Task(t) => r.tasks.push(*t),
            CfgElem::Program(p) => r.programs.push(p),
            CfgElem::Resource(inner) => ctx.diags.push(
                Diagnostic::error(
                    code::CONFIG_SYNTAX,
                    inner.span,
                    "a RESOURCE cannot contain another RESOURCE",
                )
                .with_label("nested RESOURCE"),
            ),
            CfgElem::Error => {}
        }
    }
    CfgElem::Resource(r)
}

pub fn task(ctx: &mut Ctx, name: Ident, params: Vec<(Ident, Operand)>, span: Span) -> Task {
    let mut t = Task {
        name,
        single: None,
        interval: None,
        priority: None,
        span,
    };
    for (n, v) in params {
        let key = n.key();
        let dup = match key.as_str() {
            "SINGLE" => t.single.replace(v).is_some(),
            "INTERVAL" => t.interval.replace(v).is_some(),
            "PRIORITY" => match v {
                Operand::Lit(l) if matches!(l.kind, LitKind::Int(_)) => {
                    t.priority.replace(l).is_some()
                }
                other => {
                    ctx.diags.push(
                        Diagnostic::error(
                            code::CONFIG_SYNTAX,
                            other.span(),
                            "PRIORITY must be an integer, e.g. `PRIORITY := 1`",
                        )
                        .with_label("not an integer"),
                    );
                    false
                }
            },
            _ => {
                ctx.diags.push(
                    Diagnostic::error(
                        code::CONFIG_SYNTAX,
                        n.span,
                        format!("`{n}` is not a TASK parameter: use SINGLE, INTERVAL or PRIORITY"),
                    )
                    .with_label("unknown parameter"),
                );
                false
            }
        };
        if dup {
            ctx.diags.push(
                Diagnostic::error(code::CONFIG_SYNTAX, n.span, format!("`{n}` is given twice"))
                    .with_label("repeated"),
            );
        }
    }
    t
}

#[allow(clippy::too_many_arguments)]
pub fn program_instance(
    ctx: &mut Ctx,
    k: PouKind,
    kw_span: Span,
    retain: Option<Retain>,
    name: Ident,
    task: Option<Ident>,
    program: Ident,
    args: Option<Vec<ParamAssign>>,
    span: Span,
) -> ProgramInstance {
    if k != PouKind::Program {
        ctx.diags.push(
            Diagnostic::error(
                code::CONFIG_SYNTAX,
                kw_span,
                format!(
                    "a configuration runs PROGRAM instances, not a {}",
                    k.keyword()
                ),
            )
            .with_label("expected PROGRAM"),
        );
    }
    ProgramInstance {
        name,
        retain: retain.unwrap_or_default(),
        task,
        program,
        args: args.unwrap_or_default(),
        span,
    }
}
