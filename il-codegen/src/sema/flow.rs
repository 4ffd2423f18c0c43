//! The body checker: walks the instruction list, proving the type of the
//! current result (CR) at every instruction, and lowers it to [`ir`].
//!
//! Labels make the CR's type a flow problem: the walk is repeated until the
//! CR state at every label is stable (a fixpoint), then run once more to
//! report diagnostics and build the IR with those states.

use super::codes::*;
use super::decls::{Env, LitClass, PendArg, Pending, PouSig, coerce, describe, lit_class};
use super::ir::{self, BinOp, CheckedPou, Const, Expr, Op, PathElem, Place, Root, Value};
use super::types::{Elem, Ty};
use super::{Cx, stdfb, stdfn, suggest};
use crate::ast::{
    self, Accessor, CallArgs, Cond, ExprOp, InstrKind, Operand, ParamKind, PouKind, Span, VarRef,
};
use std::collections::HashMap;

/// The CR at a point of the body.
#[derive(Clone, Debug, PartialEq)]
enum Cr {
    /// No path reaches here.
    Dead,
    Undef(Why),
    /// An untyped literal: it takes its type from its first typed use.
    Lit(LitClass, Span),
    Val(Ty),
}

#[derive(Clone, Debug, PartialEq)]
enum Why {
    Start,
    /// An error was reported for the instruction that set the CR; uses
    /// of it stay silent until the next load, so one mistake reports once.
    Error,
    AfterCal(u32),
    /// Paths into a label disagree; the text names them.
    Mixed(String),
}

/// The CR's class on one edge into a label (literal values erased).
#[derive(Clone, Debug, PartialEq)]
enum Class {
    /// An integer literal, with its value: it joins a typed path only if it fits.
    LitInt(i128),
    LitReal,
    LitStr(bool),
    Val(Ty),
    Undef(String),
    /// After an error: absorbs the join silently.
    Error,
}

/// A value the CR or an operand provides to an operation.
#[derive(Clone, Debug)]
enum Arg {
    Typed(Value, Ty),
    Lit(LitClass, Span),
}

pub(crate) fn check_pou(cx: &mut Cx, env: &Env, pou: &ast::Pou) -> Option<CheckedPou> {
    let sig = env.pou(&pou.name.name)?;
    if sig.kind != pou.kind || sig.name != pou.name.name {
        return None; // a duplicate, already reported
    }
    let mut labels = HashMap::new();
    let mut label_spans = Vec::new();
    for s in &pou.body {
        if let ast::Stmt::Label(id) = s {
            if let Some(&prev) = labels.get(&id.key()) {
                cx.err(
                    DUPLICATE_LABEL,
                    id.span,
                    format!("label `{id}` is defined twice"),
                )
                .add_secondary(label_spans[prev], "first defined here");
            } else {
                labels.insert(id.key(), label_spans.len());
                label_spans.push(id.span);
            }
        }
    }
    let n = label_spans.len();
    // Where each label stands in the body: edges from later statements are
    // backward edges, known only from the previous round.
    let mut label_pos = vec![0; n];
    for (i, s) in pou.body.iter().enumerate() {
        if let ast::Stmt::Label(id) = s
            && let Some(&l) = labels.get(&id.key())
            && label_pos[l] == 0
        {
            label_pos[l] = i;
        }
    }
    let mut w = Walk {
        cx,
        env,
        sig,
        labels,
        label_in: vec![Cr::Dead; n],
        edges: vec![Vec::new(); n],
        label_pos,
        pos: 0,
        back_prev: vec![Vec::new(); n],
        back_now: vec![Vec::new(); n],
        final_pass: false,
        out: Vec::new(),
        cr_types: Vec::new(),
        save_types: Vec::new(),
        jumped: vec![false; n],
        line: 0,
        addresses: Vec::new(),
    };
    // Fixpoint: the lattice per label is short (dead → literal → type → mixed),
    // so a few rounds settle it; the cap only guards against oscillation bugs.
    // Forward edges are used in the same round, so straight-line code with
    // any number of labels settles in two rounds; each round adds backward
    // edges, and the per-label lattice is short, so loops settle quickly too.
    let mut settled = false;
    for _ in 0..64 {
        w.edges.iter_mut().for_each(Vec::clear);
        w.back_now.iter_mut().for_each(Vec::clear);
        w.walk(&pou.body);
        let next: Vec<Cr> = w.edges.iter().map(|e| join(e)).collect();
        let same = next == w.label_in && w.back_now == w.back_prev;
        w.label_in = next;
        w.back_prev = w.back_now.clone();
        if same {
            settled = true;
            break;
        }
    }
    if !settled {
        // Never silently: report it rather than emit code from unsettled states.
        w.cx.err(UNSUPPORTED, pou.name.span, format!("the flow analysis of `{}` did not settle (too many nested loops); please report this", pou.name));
    }
    w.final_pass = true;
    w.edges.iter_mut().for_each(Vec::clear);
    w.out.clear();
    w.walk(&pou.body);
    for (i, used) in w.jumped.iter().enumerate() {
        if !used {
            let span = label_spans[i];
            let name =
                w.cx.file
                    .snippet(span)
                    .trim_end_matches(':')
                    .trim()
                    .to_string();
            w.cx.warn(
                UNUSED_LABEL,
                span,
                format!("label `{name}` is never jumped to"),
            );
        }
    }
    Some(CheckedPou {
        kind: pou.kind,
        name: sig.name.clone(),
        vars: sig.vars.clone(),
        ret: sig.ret.clone(),
        body: w.out,
        label_count: n,
        addresses: w.addresses,
        cr_types: w.cr_types,
        save_types: w.save_types,
        retained: super::config::retained(env, sig),
    })
}

/// The CR after a label, from the CR on every edge into it.
fn join(edges: &[(Span, Class, u32)]) -> Cr {
    let Some((_, first, _)) = edges.first() else {
        return Cr::Dead;
    };
    if edges.iter().any(|(_, c, _)| *c == Class::Error) {
        return Cr::Undef(Why::Error);
    }
    let mut ty: Option<Ty> = None;
    let mut lit: Option<Class> = None;
    let mut lits: Vec<&Class> = Vec::new();
    let mut bad = false;
    for (_, c, _) in edges {
        match c {
            Class::Val(t) => match &ty {
                None => ty = Some(t.clone()),
                Some(u) if u == t => {}
                Some(_) => bad = true,
            },
            Class::Undef(_) => bad = true,
            l => {
                // Literals of one kind join (their values may differ).
                match &lit {
                    None => lit = Some(l.clone()),
                    Some(m) if std::mem::discriminant(m) == std::mem::discriminant(l) => {}
                    Some(_) => bad = true,
                }
                lits.push(l);
            }
        }
    }
    if !bad {
        match (ty, lit) {
            (Some(t), None) => return Cr::Val(t),
            (Some(t), Some(_)) if lits.iter().all(|l| lit_fits(l, &t)) => return Cr::Val(t),
            (None, Some(Class::LitInt(_))) => return Cr::Val(Ty::Elem(Elem::DINT)),
            (None, Some(Class::LitReal)) => return Cr::Val(Ty::Elem(Elem::LREAL)),
            (None, Some(Class::LitStr(w))) => {
                return Cr::Val(Ty::Str {
                    wide: w,
                    len: super::types::DEFAULT_STRING_LEN,
                });
            }
            _ => {}
        }
    }
    let _ = first;
    let paths: Vec<String> = edges
        .iter()
        .map(|(_, c, line)| {
            let what = match c {
                Class::Val(t) => t.to_string(),
                Class::LitInt(v) => format!("the integer literal {v}"),
                Class::LitReal => "a real literal".into(),
                Class::LitStr(_) => "a string literal".into(),
                Class::Undef(why) => format!("undefined ({why})"),
                Class::Error => "an error".into(),
            };
            format!("{what} from line {line}")
        })
        .collect();
    Cr::Undef(Why::Mixed(paths.join(", ")))
}

fn lit_fits(c: &Class, t: &Ty) -> bool {
    match (c, t) {
        // BOOL takes 0 and 1 in a store, but a label joining an integer path
        // with a BOOL path is more likely a mistake: keep them apart.
        (Class::LitInt(v), Ty::Elem(e)) if *e != Elem::BOOL => {
            coerce(&LitClass::Int(*v), t).is_ok()
        }
        (Class::LitReal, Ty::Elem(e)) => e.is_real(),
        (Class::LitStr(w), Ty::Str { wide, .. }) => w == wide,
        _ => false,
    }
}

struct Walk<'a, 'c> {
    cx: &'a mut Cx<'c>,
    env: &'a Env,
    sig: &'a PouSig,
    labels: HashMap<String, usize>,
    /// CR after each label (from the previous round).
    label_in: Vec<Cr>,
    /// Edges into each label found in this round: (source span, class, line).
    edges: Vec<Vec<(Span, Class, u32)>>,
    /// Body index of each label.
    label_pos: Vec<usize>,
    /// Body index of the statement being walked.
    pos: usize,
    /// Backward edges found in the previous round / this round.
    back_prev: Vec<Vec<(Span, Class, u32)>>,
    back_now: Vec<Vec<(Span, Class, u32)>>,
    final_pass: bool,
    out: Vec<ir::Stmt>,
    cr_types: Vec<Ty>,
    save_types: Vec<Ty>,
    jumped: Vec<bool>,
    line: u32,
    addresses: Vec<ir::Loc>,
}

impl Walk<'_, '_> {
    fn err(
        &mut self,
        code: &'static str,
        span: Span,
        msg: impl Into<String>,
    ) -> Option<&mut crate::diag::Diagnostic> {
        if self.final_pass {
            Some(self.cx.err(code, span, msg))
        } else {
            None
        }
    }

    fn push(&mut self, op: Op) {
        if let Op::SetCr { ty, .. } = &op
            && !self.cr_types.contains(ty)
        {
            self.cr_types.push(ty.clone());
        }
        self.out.push(ir::Stmt {
            op,
            line: self.line,
        });
    }

    fn walk(&mut self, body: &[ast::Stmt]) {
        self.save_types.clear();
        let mut cr = Cr::Undef(Why::Start);
        let mut warned_dead = false;
        for (i, stmt) in body.iter().enumerate() {
            self.pos = i;
            match stmt {
                ast::Stmt::Label(id) => {
                    let Some(&l) = self.labels.get(&id.key()) else {
                        continue;
                    };
                    // The fall-through edge comes from the line before the label.
                    cr = self.settle_cr(cr);
                    if cr != Cr::Dead {
                        self.edge(l, &cr, id.span);
                    }
                    self.line = self.cx.line(id.span);
                    // This round's edges (all from before the label) plus the
                    // previous round's backward edges.
                    let mut into = self.edges[l].clone();
                    into.extend(self.back_prev[l].iter().cloned());
                    cr = match join(&into) {
                        Cr::Undef(Why::Mixed(paths)) => {
                            Cr::Undef(Why::Mixed(format!("{}\u{0}{paths}", id.name)))
                        }
                        other => other,
                    };
                    self.push(Op::Label(l));
                    warned_dead = false;
                }
                ast::Stmt::Instr(i) => {
                    self.line = self.cx.line(i.span);
                    if cr == Cr::Dead {
                        if !warned_dead && self.final_pass {
                            self.cx
                                .warn(UNREACHABLE, i.span, "this instruction can never run")
                                .set_label("no label leads here after the JMP or RET above");
                        }
                        warned_dead = true;
                        continue;
                    }
                    self.push(Op::Nop);
                    cr = self.instr(i, cr, false);
                }
            }
        }
    }

    /// Record an edge into label `l` with the current CR; on the final pass,
    /// give an untyped literal CR the label's type.
    fn edge(&mut self, l: usize, cr: &Cr, span: Span) {
        let class = match cr {
            Cr::Dead => return,
            Cr::Undef(Why::Start) => Class::Undef("no value loaded".into()),
            Cr::Undef(Why::Error) => Class::Error,
            Cr::Undef(Why::AfterCal(line)) => Class::Undef(format!("after CAL on line {line}")),
            // Only the label's name, not its own list of paths: that list
            // may hold the lists of earlier labels, and with a label repeated
            // (an error, but checked on) the text doubled at every join, to
            // gigabytes for a 600-byte input (found by fuzzing the `il!`
            // expansion, which checks sources with errors for its stubs).
            Cr::Undef(Why::Mixed(m)) => Class::Undef(match m.split_once('\u{0}') {
                Some((label, _)) => format!("the paths into `{label}` disagree"),
                None => m.clone(),
            }),
            Cr::Lit(LitClass::Int(v), _) => Class::LitInt(*v),
            Cr::Lit(LitClass::Real(..), _) => Class::LitReal,
            Cr::Lit(LitClass::Str(_, w), _) => Class::LitStr(*w),
            Cr::Lit(..) => Class::Undef("an invalid literal".into()),
            Cr::Val(t) => Class::Val(t.clone()),
        };
        if self.pos > self.label_pos[l] {
            self.back_now[l].push((span, class.clone(), self.line));
        }
        self.edges[l].push((span, class, self.line));
        if let (Cr::Lit(lit, lspan), Cr::Val(t)) = (cr, &self.label_in[l].clone())
            && !matches!(lit, LitClass::Pending(_))
        {
            match coerce(lit, t) {
                Ok(c) => self.push(Op::SetCr {
                    ty: t.clone(),
                    expr: Expr::Value(Value::Const(c)),
                }),
                Err(m) => {
                    let lspan = *lspan;
                    self.err(LITERAL_RANGE, lspan, m);
                }
            }
        }
    }

    /// One instruction. Deferred parentheses recurse (one level per nesting
    /// level, up to the parser's limit of 256), so the recursion path is kept
    /// to two small frames: this dispatcher and [`Walk::deferred`]. Every
    /// other instruction is checked in [`Walk::simple_instr`], whose frame is
    /// large in debug builds (tens of KiB); with it on the recursion path,
    /// 256 levels overflowed a 2 MiB thread (a debug `cargo test` thread)
    /// and aborted the process.
    fn instr(&mut self, i: &ast::Instr, cr: Cr, in_parens: bool) -> Cr {
        match &i.kind {
            InstrKind::Deferred {
                op,
                negate,
                first,
                body,
                close_span,
            } => self.deferred(i, cr, (*op, *negate), first.as_ref(), body, *close_span),
            _ => self.simple_instr(i, cr, in_parens),
        }
    }

    /// `OP( operand` / `OP(` ... `)`: see [`Walk::instr`].
    #[inline(never)]
    fn deferred(
        &mut self,
        i: &ast::Instr,
        cr: Cr,
        (op, negate): (ExprOp, bool),
        first: Option<&Operand>,
        body: &[ast::Stmt],
        close_span: Span,
    ) -> Cr {
        let span = i.span;
        // A pending call is emitted before the inner instructions,
        // which reuse the CR locals its arguments may read.
        let Some(lhs) = self.use_cr(&cr, span).and_then(|a| self.settle(a)) else {
            return Cr::Undef(Why::Error);
        };
        let lhs = match lhs {
            Arg::Typed(v, t) => {
                let slot = self.save_types.len();
                self.save_types.push(t.clone());
                self.push(Op::Save { slot, value: v });
                Arg::Typed(Value::Saved(slot, t.clone()), t)
            }
            lit => lit,
        };
        let mut inner = match first {
            Some(o) => self.load(false, o, span),
            None => Cr::Undef(Why::Start),
        };
        for s in body {
            match s {
                ast::Stmt::Label(id) => {
                    self.err(
                        IN_PARENS,
                        id.span,
                        "a label is not allowed inside parentheses",
                    );
                }
                ast::Stmt::Instr(ii) => inner = self.instr(ii, inner, true),
            }
        }
        let Some(rhs) = self.use_cr(&inner, close_span) else {
            return Cr::Undef(Why::Error);
        };
        self.binary(op, negate, lhs, rhs, i.op_span)
    }

    /// Every instruction but deferred parentheses (see [`Walk::instr`]).
    #[inline(never)]
    fn simple_instr(&mut self, i: &ast::Instr, cr: Cr, in_parens: bool) -> Cr {
        let span = i.span;
        match &i.kind {
            InstrKind::Load { negate, operand } => {
                if !negate && let Some(inst) = self.fb_operand(operand, &["CTD", "CTUD"]) {
                    return self.fb_input(inst, "LD", cr, span);
                }
                self.load(*negate, operand, span)
            }
            InstrKind::Store { negate, target } => {
                let Some(place) = self.place_of(target, true) else {
                    return cr;
                };
                let Some(arg) = self.use_cr(&cr, span) else {
                    return cr;
                };
                let dest = format!("`{}`", self.cx.file.snippet(target.span()));
                let Some(value) = self.fit_to(arg, &place.ty, span, &dest) else {
                    return cr;
                };
                if *negate && !place.ty.is_logic() {
                    self.err(
                        BAD_OPERATOR_TYPE,
                        i.op_span,
                        format!("STN needs BOOL or a bit string, not {}", place.ty),
                    );
                    return cr;
                }
                if let (Some((lo, hi)), Value::Const(Const::Int(v, _))) = (place.range, &value)
                    && (*v < lo || *v > hi)
                {
                    self.err(
                        LITERAL_RANGE,
                        span,
                        format!(
                            "{v} is outside the subrange {lo}..{hi} of `{}`",
                            self.cx.file.snippet(target.span())
                        ),
                    );
                    return cr;
                }
                self.push(Op::Store {
                    place,
                    value,
                    negate: *negate,
                });
                cr
            }
            InstrKind::Set { target } | InstrKind::Reset { target } => {
                let set = matches!(i.kind, InstrKind::Set { .. });
                let fbs: &[&str] = if set {
                    &["RS"]
                } else {
                    &[
                        "SR",
                        "CTU",
                        "CTUD",
                        "CTU_DINT",
                        "CTU_LINT",
                        "CTU_UDINT",
                        "CTU_ULINT",
                        "CTUD_DINT",
                        "CTUD_LINT",
                        "CTUD_UDINT",
                        "CTUD_ULINT",
                    ]
                };
                if let Some(inst) = self.fb_operand(target, fbs) {
                    return self.fb_input(inst, if set { "S" } else { "R" }, cr, span);
                }
                if let Some(inst) = self.fb_operand(target, &[]) {
                    let which = if set { "S" } else { "R" };
                    self.err(
                        BAD_INPUT_OP,
                        target.span(),
                        format!(
                            "`{which}` is not an input operator of {} (an instance of {})",
                            self.cx.file.snippet(target.span()),
                            inst.ty
                        ),
                    );
                    return cr;
                }
                let Some(place) = self.place_of(target, true) else {
                    return cr;
                };
                if !place.ty.is_bool() {
                    self.err(
                        BAD_OPERATOR_TYPE,
                        target.span(),
                        format!("S and R set or reset a BOOL; this is {}", place.ty),
                    );
                    return cr;
                }
                let Some(cond) = self.cond_value(&cr, span) else {
                    return cr;
                };
                self.push(Op::SetIf {
                    place,
                    value: set,
                    cond,
                });
                Cr::Val(Ty::BOOL)
            }
            InstrKind::Not => {
                let Some(arg) = self.use_cr(&cr, span).and_then(|a| self.settle(a)) else {
                    return cr;
                };
                match arg {
                    Arg::Typed(v, t) if t.is_logic() => {
                        self.push(Op::SetCr {
                            ty: t.clone(),
                            expr: Expr::Not(v),
                        });
                        Cr::Val(t)
                    }
                    Arg::Typed(_, t) => {
                        self.err(
                            BAD_OPERATOR_TYPE,
                            i.op_span,
                            format!("NOT needs a BOOL or bit-string current result; it is {t}"),
                        );
                        Cr::Val(t)
                    }
                    Arg::Lit(l, _) => {
                        self.err(
                            BAD_OPERATOR_TYPE,
                            i.op_span,
                            format!(
                                "NOT of {}: give the literal a type (BOOL#1, WORD#16#FF)",
                                describe(&l)
                            ),
                        );
                        cr
                    }
                }
            }
            InstrKind::Expr {
                op,
                negate,
                operand,
            } => {
                let Some(lhs) = self.use_cr(&cr, span) else {
                    return Cr::Undef(Why::Error);
                };
                let Some(rhs) = self.operand(operand) else {
                    return Cr::Undef(Why::Error);
                };
                self.binary(*op, *negate, lhs, rhs, i.op_span)
            }
            // Handled by `instr`.
            InstrKind::Deferred { .. } => cr,
            InstrKind::Jump { cond, label } => {
                if in_parens {
                    self.err(IN_PARENS, span, "a jump is not allowed inside parentheses");
                    return cr;
                }
                let Some(&l) = self.labels.get(&label.key()) else {
                    // In label order: `suggest` keeps the first of equally
                    // close names, and a hash map's order changes from run
                    // to run (fuzzing found `l0` suggesting `L2` or `L3`).
                    let mut labels: Vec<(&String, &usize)> = self.labels.iter().collect();
                    labels.sort_by_key(|&(_, &i)| i);
                    let names: Vec<String> = labels.into_iter().map(|(n, _)| n.clone()).collect();
                    let hint = suggest(&label.name, names.iter().map(String::as_str))
                        .map(|s| format!("did you mean `{s}`?"));
                    if let Some(d) = self.err(
                        UNKNOWN_LABEL,
                        label.span,
                        format!("no label `{label}` in {}", self.sig.name),
                    ) {
                        d.help = hint;
                    }
                    return if *cond == Cond::Always { Cr::Dead } else { cr };
                };
                self.jumped[l] = true;
                match cond {
                    Cond::Always => {
                        let cr = self.settle_cr(cr);
                        self.edge(l, &cr, span);
                        self.push(Op::Jump {
                            label: l,
                            cond: None,
                        });
                        Cr::Dead
                    }
                    c => {
                        let Some(v) = self.cond_value(&cr, span) else {
                            return cr;
                        };
                        let after = Cr::Val(Ty::BOOL);
                        self.edge(l, &after, span);
                        self.push(Op::Jump {
                            label: l,
                            cond: Some((v, *c == Cond::IfTrue)),
                        });
                        after
                    }
                }
            }
            InstrKind::Return { cond } => {
                if in_parens {
                    self.err(IN_PARENS, span, "RET is not allowed inside parentheses");
                    return cr;
                }
                match cond {
                    Cond::Always => {
                        self.push(Op::Return { cond: None });
                        Cr::Dead
                    }
                    c => {
                        let Some(v) = self.cond_value(&cr, span) else {
                            return cr;
                        };
                        self.push(Op::Return {
                            cond: Some((v, *c == Cond::IfTrue)),
                        });
                        Cr::Val(Ty::BOOL)
                    }
                }
            }
            InstrKind::Call { cond, target, args } => {
                if in_parens {
                    self.err(IN_PARENS, span, "CAL is not allowed inside parentheses");
                    return cr;
                }
                // CAL of a FUNCTION with a formal list (3rd edition, STACK_INT).
                if let Operand::Var(v) = target
                    && v.path.is_empty()
                    && self.sig.var(&v.base.name).is_none()
                    && self.is_function(&v.base.name)
                {
                    if *cond != Cond::Always {
                        self.err(
                            UNSUPPORTED,
                            i.op_span,
                            "CALC/CALCN of a FUNCTION is not supported; use JMPCN around it",
                        );
                        return cr;
                    }
                    let args = args.clone().unwrap_or(CallArgs::Formal(Vec::new()));
                    return self.fn_call(&v.base, &args, cr, span, true);
                }
                let Some(inst) = self.place_of(target, false) else {
                    return Cr::Undef(Why::AfterCal(self.line));
                };
                let Ty::Fb(fb) = inst.ty.clone() else {
                    self.err(
                        NOT_AN_FB,
                        target.span(),
                        format!(
                            "CAL needs a function block instance; `{}` is {}",
                            self.cx.file.snippet(target.span()),
                            inst.ty
                        ),
                    );
                    return Cr::Undef(Why::AfterCal(self.line));
                };
                let cond_v = match cond {
                    Cond::Always => None,
                    c => match self.cond_value(&cr, span) {
                        Some(v) => Some((v, *c == Cond::IfTrue)),
                        None => return Cr::Undef(Why::AfterCal(self.line)),
                    },
                };
                let (inouts_decl, externals) = self.fb_refs(&fb);
                let (inputs, outputs, inouts) = match args {
                    None => (Vec::new(), Vec::new(), Vec::new()),
                    Some(a) => self.fb_args(&fb, a, target.span()),
                };
                if inouts.len() != inouts_decl.len() {
                    if let Some(CallArgs::Formal(_)) | None = args {
                        // Only the names not written at all (a bad binding was reported).
                        let written = |n: &str| match args {
                            Some(CallArgs::Formal(list)) => list.iter().any(|p| p.name.is(n)),
                            _ => false,
                        };
                        let missing: Vec<&str> = inouts_decl
                            .iter()
                            .filter(|(n, _)| !written(n))
                            .map(|(n, _)| n.as_str())
                            .collect();
                        if !missing.is_empty() {
                            self.err(
                                BAD_IN_OUT,
                                span,
                                format!(
                                    "{fb} has VAR_IN_OUT {}: every call binds it (`CAL inst({} := variable)`)",
                                    missing.iter().map(|m| format!("`{m}`")).collect::<Vec<_>>().join(", "),
                                    missing[0]
                                ),
                            );
                        }
                    }
                    return Cr::Undef(Why::AfterCal(self.line));
                }
                // In declaration order.
                let inouts = inouts_decl
                    .iter()
                    .filter_map(|(n, _)| {
                        inouts
                            .iter()
                            .find(|(m, _)| m.eq_ignore_ascii_case(n))
                            .map(|(_, p)| p.clone())
                    })
                    .collect();
                self.push(Op::CallFb {
                    inst,
                    inputs,
                    outputs,
                    inouts,
                    externals,
                    cond: cond_v,
                });
                Cr::Undef(Why::AfterCal(self.line))
            }
            InstrKind::FnCall { name, args } => self.fn_call(name, args, cr, span, false),
            InstrKind::FbInput { op, instance } => {
                let Some(inst) = self.place_of(instance, false) else {
                    return cr;
                };
                self.fb_input(inst, op.input_name(), cr, span)
            }
        }
    }

    fn load(&mut self, negate: bool, operand: &Operand, span: Span) -> Cr {
        let Some(arg) = self.operand(operand) else {
            return Cr::Undef(Why::Error);
        };
        match arg {
            Arg::Lit(l, s) if !negate => Cr::Lit(l, s),
            Arg::Lit(l, s) => {
                self.err(
                    BAD_OPERATOR_TYPE,
                    s,
                    format!(
                        "LDN of {}: give the literal a type (BOOL#1, WORD#16#FF)",
                        describe(&l)
                    ),
                );
                Cr::Undef(Why::Error)
            }
            Arg::Typed(_, Ty::Fb(f)) => {
                self.err(BAD_OPERATOR_TYPE, operand.span(), format!("cannot load a function block instance ({f}); load one of its outputs, e.g. `.Q`"));
                let _ = span;
                Cr::Undef(Why::Error)
            }
            Arg::Typed(v, t) => {
                if negate && !t.is_logic() {
                    self.err(
                        BAD_OPERATOR_TYPE,
                        operand.span(),
                        format!("LDN needs BOOL or a bit string; this is {t}"),
                    );
                    return Cr::Val(t);
                }
                let expr = if negate { Expr::Not(v) } else { Expr::Value(v) };
                self.push(Op::SetCr {
                    ty: t.clone(),
                    expr,
                });
                Cr::Val(t)
            }
        }
    }

    /// The CR as an argument, or a diagnostic saying why there is none.
    fn use_cr(&mut self, cr: &Cr, span: Span) -> Option<Arg> {
        match cr {
            Cr::Dead => None,
            Cr::Undef(Why::Error) => None,
            Cr::Undef(Why::Start) => {
                if let Some(d) = self.err(CR_UNDEFINED, span, "there is no current result here") {
                    d.label = "this uses the current result".into();
                    d.help = Some("load a value first, e.g. `LD x`".into());
                }
                None
            }
            Cr::Undef(Why::AfterCal(line)) => {
                let line = *line;
                if let Some(d) = self.err(
                    CR_UNDEFINED,
                    span,
                    format!("the current result is undefined after the CAL on line {line}"),
                ) {
                    d.help =
                        Some("load a value first, e.g. an output of the block: `LD inst.Q`".into());
                }
                None
            }
            Cr::Undef(Why::Mixed(text)) => {
                // "label\0paths" (the label's name is added where it is known).
                let (label, paths) = text.split_once('\u{0}').unwrap_or(("above", text));
                let label = if label == "above" {
                    "the label above".to_string()
                } else {
                    format!("`{label}`")
                };
                let paths = paths.to_string();
                if let Some(d) = self.err(
                    CR_DISAGREES,
                    span,
                    format!("the current result has different types on the paths into {label}"),
                ) {
                    d.notes.push(format!("the paths bring: {paths}"));
                    d.help =
                        Some("load a value after the label before using the current result".into());
                }
                None
            }
            Cr::Lit(l, s) => Some(Arg::Lit(l.clone(), *s)),
            Cr::Val(t) => Some(Arg::Typed(Value::Cr(t.clone()), t.clone())),
        }
    }

    /// The CR as a BOOL condition (JMPC, CALC, RETC, S, R).
    fn cond_value(&mut self, cr: &Cr, span: Span) -> Option<Value> {
        match self.use_cr(cr, span)? {
            Arg::Typed(v, t) if t.is_bool() => Some(v),
            Arg::Typed(_, t) => {
                if let Some(d) = self.err(
                    COND_NOT_BOOL,
                    span,
                    format!(
                        "this instruction tests the current result, which must be BOOL; it is {t}"
                    ),
                ) {
                    d.help = Some("compare first, e.g. `GT 0` or `EQ x`".into());
                }
                None
            }
            Arg::Lit(LitClass::Pending(p), _) => {
                self.materialize(&p, Some(&Ty::BOOL)).map(|(v, _)| v)
            }
            Arg::Lit(l, s) => match coerce(&l, &Ty::BOOL) {
                Ok(c) => {
                    // The CR is BOOL from here on, so it must live in its local.
                    self.push(Op::SetCr {
                        ty: Ty::BOOL,
                        expr: Expr::Value(Value::Const(c)),
                    });
                    Some(Value::Cr(Ty::BOOL))
                }
                Err(m) => {
                    self.err(COND_NOT_BOOL, s, m);
                    None
                }
            },
        }
    }

    /// Make an argument a value of type `ty` for `dest` ("`x`", "input `PT` of t"):
    /// like [`Self::fit`], with a message that names both sides.
    fn fit_to(&mut self, arg: Arg, ty: &Ty, span: Span, dest: &str) -> Option<Value> {
        if let Arg::Typed(v, t) = &arg
            && t != ty
        {
            {
                let src = if matches!(v, Value::Cr(_) | Value::Saved(..)) {
                    "the current result"
                } else {
                    "the value"
                };
                if let Some(d) = self.err(
                    TYPE_MISMATCH,
                    span,
                    format!("{dest} is {ty}, but {src} is {t}"),
                ) {
                    d.help = conversion_hint(t, ty);
                }
                return None;
            }
        }
        self.fit(arg, ty, span)
    }

    /// Make an argument a value of type `ty`.
    fn fit(&mut self, arg: Arg, ty: &Ty, span: Span) -> Option<Value> {
        match arg {
            Arg::Typed(v, t) if t == *ty => Some(v),
            Arg::Typed(_, t) => {
                if let Some(d) = self.err(TYPE_MISMATCH, span, format!("expected {ty}, found {t}"))
                {
                    d.help = conversion_hint(&t, ty);
                }
                None
            }
            Arg::Lit(l, s) => self.lit_value(&l, ty, s, LITERAL_RANGE),
        }
    }

    fn operand(&mut self, o: &Operand) -> Option<Arg> {
        // Enumeration values: `Color#Red`, or a bare `Red` that names no variable.
        match o {
            Operand::Lit(ast::Literal {
                kind: ast::LitKind::Enum { ty, value },
                span,
                ..
            }) => {
                let Some((name, vals)) = self.env.types.enums.get(&ty.key()).cloned() else {
                    self.err(
                        UNKNOWN_TYPE,
                        ty.span,
                        format!("`{ty}` is not an enumeration type"),
                    );
                    return None;
                };
                let Some(v) = vals.iter().find(|v| value.is(v)) else {
                    let hint = suggest(&value.name, vals.iter().map(String::as_str))
                        .map(|s| format!("did you mean `{s}`?"));
                    if let Some(d) = self.err(
                        UNKNOWN_NAME,
                        *span,
                        format!("`{value}` is not a value of {name}"),
                    ) {
                        d.help = hint;
                    }
                    return None;
                };
                let c = Const::Enum {
                    ty: name,
                    value: v.clone(),
                };
                return Some(Arg::Typed(Value::Const(c.clone()), c.ty()));
            }
            Operand::Var(v)
                if v.path.is_empty()
                    && self.sig.var(&v.base.name).is_none()
                    && !(self.sig.kind == PouKind::Function && v.base.is(&self.sig.name)) =>
            {
                if let Some((ty, value)) = self.env.types.enum_of_value(&v.base.name) {
                    let c = Const::Enum { ty, value };
                    return Some(Arg::Typed(Value::Const(c.clone()), c.ty()));
                }
            }
            _ => {}
        }
        match o {
            Operand::Lit(l) => match lit_class(l) {
                LitClass::Typed(c) => Some(Arg::Typed(Value::Const(c.clone()), c.ty())),
                LitClass::Unsupported(m) => {
                    self.err(UNSUPPORTED, l.span, m);
                    None
                }
                LitClass::Invalid(m) => {
                    self.err(LITERAL_RANGE, l.span, m);
                    None
                }
                other => Some(Arg::Lit(other, l.span)),
            },
            Operand::Var(v) => {
                let p = self.place(v, false)?;
                Some(Arg::Typed(Value::Read(p.clone()), p.ty))
            }
            Operand::Addr(a) => {
                let p = self.addr_place(a, false)?;
                Some(Arg::Typed(Value::Read(p.clone()), p.ty))
            }
        }
    }

    fn addr_place(&mut self, a: &ast::DirectAddress, write: bool) -> Option<Place> {
        if !self.final_pass {
            // Resolution reports errors; report them once, on the final pass.
            let saved = std::mem::take(&mut self.cx.diags);
            let l = super::decls::resolve_addr(self.cx, a, None);
            self.cx.diags = saved;
            return l.map(|l| Place {
                range: None,
                ty: Ty::Elem(l.elem),
                root: Root::Addr(l),
                path: Vec::new(),
            });
        }
        let l = super::decls::resolve_addr(self.cx, a, None)?;
        if write && l.area == ast::Area::Input {
            self.err(
                NOT_WRITABLE,
                a.span,
                format!(
                    "`{}` is an input: the host writes it before each scan",
                    l.text
                ),
            );
            return None;
        }
        if !self.addresses.contains(&l) {
            self.addresses.push(l.clone());
        }
        Some(Place {
            range: None,
            ty: Ty::Elem(l.elem),
            root: Root::Addr(l),
            path: Vec::new(),
        })
    }

    fn place_of(&mut self, o: &Operand, write: bool) -> Option<Place> {
        match o {
            Operand::Var(v) => self.place(v, write),
            Operand::Lit(l) => {
                self.err(NOT_WRITABLE, l.span, "expected a variable, found a literal");
                None
            }
            Operand::Addr(a) => self.addr_place(a, write),
        }
    }

    /// Resolve a variable reference; `write` checks that it may be stored to.
    fn place(&mut self, v: &VarRef, write: bool) -> Option<Place> {
        let (root, mut ty, constant) = if let Some((i, var)) = self.sig.var(&v.base.name) {
            match &var.location {
                Some(l) if write && l.area == ast::Area::Input => {
                    self.err(
                        NOT_WRITABLE,
                        v.span,
                        format!(
                            "`{}` is located at the input `{}`: the host writes it",
                            v.base, l.text
                        ),
                    );
                    return None;
                }
                Some(l) => (Root::Addr(l.clone()), var.ty.clone(), var.constant),
                None if write && var.edge.is_some() => {
                    self.err(
                        NOT_WRITABLE,
                        v.span,
                        format!(
                            "`{}` is an edge input (R_EDGE/F_EDGE): it is read-only in the body",
                            v.base
                        ),
                    );
                    return None;
                }
                None => (Root::Var(i), var.ty.clone(), var.constant),
            }
        } else if self.sig.kind == PouKind::Function && v.base.is(&self.sig.name) {
            (Root::Ret, self.sig.ret.clone()?, false)
        } else if self.sig.poisoned.contains(&v.base.key()) {
            return None; // its declaration was already reported
        } else {
            let names: Vec<&str> = self.sig.vars.iter().map(|v| v.name.as_str()).collect();
            let hint = suggest(&v.base.name, names).map(|s| format!("did you mean `{s}`?"));
            let what = if self.is_function(&v.base.name) {
                format!("`{}` is a function, not a variable", v.base)
            } else {
                format!("unknown variable `{}`", v.base)
            };
            let pou_name = self.sig.name.clone();
            if let Some(d) = self.err(UNKNOWN_NAME, v.base.span, what) {
                d.label = format!("not declared in {pou_name}");
                d.help = hint;
            }
            return None;
        };
        if write && constant {
            self.err(NOT_WRITABLE, v.span, format!("`{}` is a CONSTANT", v.base));
            return None;
        }
        let mut range = self
            .sig
            .var(&v.base.name)
            .and_then(|(_, var)| var.range)
            .filter(|_| matches!(root, Root::Var(_)));
        let mut path = Vec::new();
        for acc in &v.path {
            match acc {
                Accessor::Field(f) => {
                    range = None;
                    let (Ty::Fb(fb) | Ty::Struct(fb)) = &ty else {
                        self.err(
                            UNKNOWN_MEMBER,
                            f.span,
                            format!("`{}` is {ty}, which has no members", v.base),
                        );
                        return None;
                    };
                    let fb = fb.clone();
                    if let Some(field) = self
                        .env
                        .types
                        .structs
                        .get(&fb.to_ascii_uppercase())
                        .and_then(|fs| fs.iter().find(|x| f.is(&x.name)))
                    {
                        range = field.range;
                    }
                    let (name, mty, is_input) = self.member(&fb, &f.name, f.span)?;
                    if write && !is_input {
                        self.err(
                            NOT_WRITABLE,
                            f.span,
                            format!("`{name}` is an output of {fb}; only the block sets it"),
                        );
                        return None;
                    }
                    path.push(PathElem::Field(name));
                    ty = mty;
                }
                Accessor::Index(subs, span) => {
                    range = None;
                    let Ty::Array { dims, elem } = &ty else {
                        self.err(
                            BAD_INDEX,
                            *span,
                            format!("`{}` is {ty}, not an array", v.base),
                        );
                        return None;
                    };
                    if subs.len() != dims.len() {
                        self.err(
                            BAD_INDEX,
                            *span,
                            format!(
                                "{} subscripts for an array of {} dimensions",
                                subs.len(),
                                dims.len()
                            ),
                        );
                        return None;
                    }
                    let (dims, elem) = (dims.clone(), (**elem).clone());
                    let mut vals = Vec::new();
                    for (s, (lo, hi)) in subs.iter().zip(&dims) {
                        match self.operand(s)? {
                            Arg::Typed(val, t) if t.elem().is_some_and(Elem::is_int) => {
                                vals.push(val)
                            }
                            Arg::Typed(_, t) => {
                                self.err(
                                    BAD_INDEX,
                                    s.span(),
                                    format!("a subscript must be an integer, not {t}"),
                                );
                                return None;
                            }
                            Arg::Lit(LitClass::Int(n), sp) => {
                                if n < *lo as i128 || n > *hi as i128 {
                                    self.err(
                                        BAD_INDEX,
                                        sp,
                                        format!("subscript {n} is outside the bounds {lo}..{hi}"),
                                    );
                                    return None;
                                }
                                vals.push(Value::Const(Const::Int(n, Elem::LINT)));
                            }
                            Arg::Lit(l, sp) => {
                                self.err(
                                    BAD_INDEX,
                                    sp,
                                    format!("a subscript must be an integer, not {}", describe(&l)),
                                );
                                return None;
                            }
                        }
                    }
                    path.push(PathElem::Index { dims, subs: vals });
                    ty = elem;
                }
                Accessor::Bit(_, span) => {
                    self.err(
                        UNSUPPORTED,
                        *span,
                        "bit access (`x.3`) is not supported yet",
                    );
                    return None;
                }
            }
        }
        if write && matches!(ty, Ty::Fb(_)) {
            self.err(
                NOT_WRITABLE,
                v.span,
                "cannot store to a function block instance",
            );
            return None;
        }
        // A whole array over 64 KiB would be copied through the stack.
        if super::size::is_large(self.env, &ty) {
            let msg = format!(
                "`{}` is an array of more than 64 KiB: it cannot be loaded, stored or passed as a whole",
                v.base
            );
            if let Some(d) = self.err(TOO_LARGE, v.span, msg) {
                d.help = Some("use its elements (`x[i]`), in a loop".into());
            }
            return None;
        }
        Some(Place {
            root,
            path,
            ty,
            range,
        })
    }

    /// A member of an FB type: (declared name, type, is it an input).
    fn member(&mut self, fb: &str, name: &str, span: Span) -> Option<(String, Ty, bool)> {
        let mut all: Vec<(String, Ty, bool)> = Vec::new();
        if let Some(s) = stdfb::lookup(fb) {
            all.extend(
                s.inputs
                    .iter()
                    .map(|(n, e)| (n.to_string(), Ty::Elem(*e), true)),
            );
            all.extend(
                s.outputs
                    .iter()
                    .map(|(n, e)| (n.to_string(), Ty::Elem(*e), false)),
            );
        } else if let Some(fields) = self.env.types.structs.get(&fb.to_ascii_uppercase()) {
            // Every field of a STRUCT can be read and written.
            all.extend(fields.iter().map(|f| (f.name.clone(), f.ty.clone(), true)));
        } else if let Some(sig) = self.env.pou(fb) {
            for v in &sig.vars {
                match v.kind {
                    ast::VarKind::Input => all.push((v.name.clone(), v.ty.clone(), true)),
                    ast::VarKind::Output => all.push((v.name.clone(), v.ty.clone(), false)),
                    _ => {}
                }
            }
        }
        if let Some(m) = all.iter().find(|(n, _, _)| n.eq_ignore_ascii_case(name)) {
            return Some(m.clone());
        }
        let hint = suggest(name, all.iter().map(|(n, _, _)| n.as_str()))
            .map(|s| format!("did you mean `{s}`?"));
        let list: Vec<&str> = all.iter().map(|(n, _, _)| n.as_str()).collect();
        if let Some(d) = self.err(
            UNKNOWN_MEMBER,
            span,
            format!("{fb} has no input or output `{name}`"),
        ) {
            d.notes.push(format!("{fb} has: {}", list.join(", ")));
            d.help = hint;
        }
        None
    }

    /// If the operand is a plain FB instance (of one of `types`, or any FB when
    /// `types` is empty), its place.
    fn fb_operand(&mut self, o: &Operand, types: &[&str]) -> Option<Place> {
        let Operand::Var(v) = o else { return None };
        let (_, var) = self.sig.var(&v.base.name)?;
        let Ty::Fb(t) = &var.ty else { return None };
        if v.path.is_empty()
            && (types.is_empty() || types.iter().any(|x| x.eq_ignore_ascii_case(t)))
        {
            let saved = self.final_pass;
            let p = self.place(v, false);
            self.final_pass = saved;
            return p;
        }
        None
    }

    /// Table 54: set one input from the CR and call the instance.
    fn fb_input(&mut self, inst: Place, input: &str, cr: Cr, span: Span) -> Cr {
        let Ty::Fb(fb) = inst.ty.clone() else {
            self.err(
                NOT_AN_FB,
                span,
                format!(
                    "`{input}` as an operator needs a function block instance; this is {}",
                    inst.ty
                ),
            );
            return cr;
        };
        let mut all: Vec<(String, Ty)> = Vec::new();
        if let Some(s) = stdfb::lookup(&fb) {
            all.extend(s.inputs.iter().map(|(n, e)| (n.to_string(), Ty::Elem(*e))));
        } else if let Some(sig) = self.env.pou(&fb) {
            all.extend(sig.inputs().map(|(_, v)| (v.name.clone(), v.ty.clone())));
        }
        let Some((name, ty)) = all.into_iter().find(|(n, _)| n.eq_ignore_ascii_case(input)) else {
            self.err(
                BAD_INPUT_OP,
                span,
                format!("`{input}` is not an input of {fb}"),
            );
            return cr;
        };
        let Some(arg) = self.use_cr(&cr, span) else {
            return cr;
        };
        let Some(value) = self.fit_to(arg, &ty, span, &format!("input `{name}` of {fb}")) else {
            return cr;
        };
        let (inouts, externals) = self.fb_refs(&fb);
        if let Some((n, _)) = inouts.first() {
            self.err(
                BAD_IN_OUT,
                span,
                format!("{fb} has VAR_IN_OUT `{n}`, which every call binds: use `CAL inst({n} := variable, ...)`"),
            );
            return cr;
        }
        self.push(Op::CallFb {
            inst,
            inputs: vec![(name, value)],
            outputs: Vec::new(),
            inouts: Vec::new(),
            externals,
            cond: None,
        });
        cr
    }

    /// A user FB's VAR_IN_OUTs (name, type) and the names of its VAR_EXTERNALs
    /// that the caller passes (the located ones need no passing).
    #[allow(clippy::type_complexity)]
    fn fb_refs(&self, fb: &str) -> (Vec<(String, Ty)>, Vec<(String, bool)>) {
        let Some(sig) = self
            .env
            .pou(fb)
            .filter(|s| s.kind == PouKind::FunctionBlock)
        else {
            return (Vec::new(), Vec::new());
        };
        let inouts = sig
            .vars
            .iter()
            .filter(|v| v.kind == ast::VarKind::InOut)
            .map(|v| (v.name.clone(), v.ty.clone()))
            .collect();
        let externals = sig
            .vars
            .iter()
            .filter(|v| v.kind == ast::VarKind::External && v.location.is_none())
            .map(|v| (v.name.clone(), v.constant))
            .collect();
        (inouts, externals)
    }

    /// The place bound to a VAR_IN_OUT `name : ty`: a writable variable of exactly that type.
    fn inout_place(&mut self, o: &Operand, name: &str, ty: &Ty, callee: &str) -> Option<Place> {
        if let Operand::Lit(l) = o {
            self.err(
                BAD_IN_OUT,
                l.span,
                format!("`{name}` is a VAR_IN_OUT of {callee}: it needs a variable, not a literal"),
            );
            return None;
        }
        let place = self.place_of(o, true)?;
        if &place.ty != ty {
            self.err(
                BAD_IN_OUT,
                o.span(),
                format!(
                    "`{name}` is a VAR_IN_OUT of {callee} of type {ty}; the variable is {} (a reference needs exactly the same type)",
                    place.ty
                ),
            );
            return None;
        }
        Some(place)
    }

    /// The argument list of a CAL of an FB.
    #[allow(clippy::type_complexity)]
    fn fb_args(
        &mut self,
        fb: &str,
        args: &CallArgs,
        span: Span,
    ) -> (
        Vec<(String, Value)>,
        Vec<(String, Place, bool)>,
        Vec<(String, Place)>,
    ) {
        let mut ins = Vec::new();
        let mut outs = Vec::new();
        let mut inouts: Vec<(String, Place)> = Vec::new();
        let (inout_decl, _) = self.fb_refs(fb);
        match args {
            CallArgs::Formal(list) => {
                for p in list {
                    if let Some((name, ty)) = inout_decl.iter().find(|(n, _)| p.name.is(n)) {
                        match &p.kind {
                            ParamKind::Input(o) => {
                                if inouts.iter().any(|(n, _)| n == name) {
                                    self.err(
                                        DUPLICATE_DECL,
                                        p.name.span,
                                        format!("`{name}` is bound twice"),
                                    );
                                } else if let Some(pl) = self.inout_place(o, name, ty, fb) {
                                    inouts.push((name.clone(), pl));
                                }
                            }
                            ParamKind::Output { .. } => {
                                self.err(
                                    BAD_IN_OUT,
                                    p.span,
                                    format!("`{name}` is a VAR_IN_OUT of {fb}: bind it with `{name} := variable`"),
                                );
                            }
                        }
                        continue;
                    }
                    let Some((name, ty, is_input)) = self.member(fb, &p.name.name, p.name.span)
                    else {
                        continue;
                    };
                    match &p.kind {
                        ParamKind::Input(o) => {
                            if !is_input {
                                self.err(
                                    NOT_WRITABLE,
                                    p.name.span,
                                    format!(
                                        "`{name}` is an output of {fb}: use `{name} => variable`"
                                    ),
                                );
                                continue;
                            }
                            let Some(a) = self.operand(o) else { continue };
                            if let Some(v) =
                                self.fit_to(a, &ty, o.span(), &format!("input `{name}` of {fb}"))
                            {
                                ins.push((name, v));
                            }
                        }
                        ParamKind::Output { negate, target } => {
                            if is_input {
                                self.err(
                                    NOT_WRITABLE,
                                    p.name.span,
                                    format!("`{name}` is an input of {fb}: use `{name} := value`"),
                                );
                                continue;
                            }
                            let Some(place) = self.place_of(target, true) else {
                                continue;
                            };
                            if place.ty != ty {
                                self.err(
                                    TYPE_MISMATCH,
                                    target.span(),
                                    format!("`{name}` is {ty}, the variable is {}", place.ty),
                                );
                                continue;
                            }
                            if *negate && !ty.is_logic() {
                                self.err(
                                    BAD_OPERATOR_TYPE,
                                    p.span,
                                    format!(
                                        "NOT needs a BOOL or bit-string output; `{name}` is {ty}"
                                    ),
                                );
                                continue;
                            }
                            outs.push((name, place, *negate));
                        }
                    }
                }
            }
            CallArgs::NonFormal(_) if !inout_decl.is_empty() => {
                self.err(
                    BAD_IN_OUT,
                    span,
                    format!(
                        "{fb} has VAR_IN_OUT `{}`: call it with a formal list (`CAL inst({} := variable, ...)`)",
                        inout_decl[0].0, inout_decl[0].0
                    ),
                );
            }
            CallArgs::NonFormal(list) => {
                let inputs: Vec<(String, Ty)> = if let Some(s) = stdfb::lookup(fb) {
                    s.inputs
                        .iter()
                        .map(|(n, e)| (n.to_string(), Ty::Elem(*e)))
                        .collect()
                } else if let Some(sig) = self.env.pou(fb) {
                    sig.inputs()
                        .map(|(_, v)| (v.name.clone(), v.ty.clone()))
                        .collect()
                } else {
                    Vec::new()
                };
                if list.len() > inputs.len() {
                    self.err(
                        ARG_COUNT,
                        span,
                        format!(
                            "{fb} has {} inputs; {} values given",
                            inputs.len(),
                            list.len()
                        ),
                    );
                }
                for (o, (name, ty)) in list.iter().zip(inputs) {
                    let Some(a) = self.operand(o) else { continue };
                    if let Some(v) =
                        self.fit_to(a, &ty, o.span(), &format!("input `{name}` of {fb}"))
                    {
                        ins.push((name, v));
                    }
                }
            }
        }
        (ins, outs, inouts)
    }

    fn is_function(&self, name: &str) -> bool {
        self.env
            .pou(name)
            .is_some_and(|s| s.kind == PouKind::Function)
            || stdfn::is_std(&name.to_ascii_uppercase())
    }

    /// A function call; `formal_only` for `CAL F(...)` (the CR is not an argument).
    fn fn_call(
        &mut self,
        name: &ast::Ident,
        args: &CallArgs,
        cr: Cr,
        span: Span,
        formal_only: bool,
    ) -> Cr {
        let bad = Cr::Undef(Why::Error);
        if let Some(sig) = self
            .env
            .pou(&name.name)
            .filter(|s| s.kind == PouKind::Function)
        {
            let inputs: Vec<(usize, String, Ty)> = sig
                .inputs()
                .map(|(i, v)| (i, v.name.clone(), v.ty.clone()))
                .collect();
            let inouts: Vec<(String, Ty)> = sig
                .vars
                .iter()
                .filter(|v| v.kind == ast::VarKind::InOut)
                .map(|v| (v.name.clone(), v.ty.clone()))
                .collect();
            // Positional order: inputs and in-outs as declared.
            let params: Vec<(bool, usize)> = {
                let (mut i, mut j) = (0, 0);
                sig.vars
                    .iter()
                    .filter_map(|v| match v.kind {
                        ast::VarKind::Input => {
                            i += 1;
                            Some((false, i - 1))
                        }
                        ast::VarKind::InOut => {
                            j += 1;
                            Some((true, j - 1))
                        }
                        _ => None,
                    })
                    .collect()
            };
            let mut inout_places: Vec<Option<Place>> = vec![None; inouts.len()];
            let ret = sig.ret.clone();
            let fname = sig.name.clone();
            let mut values: Vec<Option<Value>> = vec![None; inputs.len()];
            let mut outputs = Vec::new();
            let mut en: Option<Value> = None;
            // `ENO => x` on a function that never sets ENO: x gets EN (or TRUE).
            let mut eno_plain: Vec<(Place, bool)> = Vec::new();
            match args {
                CallArgs::NonFormal(list) if !formal_only => {
                    let total = list.len() + 1;
                    if total != params.len() {
                        if let Some(d) = self.err(ARG_COUNT, span, format!("{fname} takes {} input(s); this call gives {total} (the current result and {} operand(s))", params.len(), list.len())) {
                            d.notes.push(format!("inputs of {fname}: {}", inputs.iter().map(|(_, n, t)| format!("{n} : {t}")).chain(inouts.iter().map(|(n, t)| format!("{n} : {t} (VAR_IN_OUT)"))).collect::<Vec<_>>().join(", ")));
                        }
                        return bad;
                    }
                    if params[0].0 {
                        self.err(BAD_IN_OUT, span, format!("the first parameter of {fname}, `{}`, is a VAR_IN_OUT: the current result is a value, not a variable; use a formal call `{fname}({} := variable, ...)`", inouts[0].0, inouts[0].0));
                        return bad;
                    }
                    let Some(first) = self.use_cr(&cr, span) else {
                        return bad;
                    };
                    values[params[0].1] = self.fit(first, &inputs[params[0].1].2, span);
                    for (k, o) in list.iter().enumerate() {
                        match params[k + 1] {
                            (true, j) => {
                                let (n, t) = inouts[j].clone();
                                inout_places[j] = self.inout_place(o, &n, &t, &fname);
                                if inout_places[j].is_none() {
                                    return bad;
                                }
                            }
                            (false, j) => {
                                let Some(a) = self.operand(o) else { return bad };
                                values[j] = self.fit(a, &inputs[j].2, o.span());
                            }
                        }
                    }
                }
                CallArgs::NonFormal(_) => {
                    self.err(
                        ARG_COUNT,
                        span,
                        "CAL of a function needs a formal list: `CAL F(IN := x)`",
                    );
                    return bad;
                }
                CallArgs::Formal(list) => {
                    for p in list {
                        match &p.kind {
                            ParamKind::Input(o) if p.name.is("EN") => {
                                let Some(a) = self.operand(o) else { continue };
                                en = self.fit(a, &Ty::BOOL, o.span());
                            }
                            ParamKind::Output { negate, target }
                                if p.name.is("ENO") && sig.var("ENO").is_none() =>
                            {
                                let Some(place) = self.place_of(target, true) else {
                                    continue;
                                };
                                if place.ty != Ty::BOOL {
                                    self.err(
                                        TYPE_MISMATCH,
                                        target.span(),
                                        format!("`ENO` is BOOL, the variable is {}", place.ty),
                                    );
                                    continue;
                                }
                                eno_plain.push((place, *negate));
                            }
                            ParamKind::Input(o)
                                if let Some(j) = inouts.iter().position(|(n, _)| p.name.is(n)) =>
                            {
                                let (n, t) = inouts[j].clone();
                                inout_places[j] = self.inout_place(o, &n, &t, &fname);
                                if inout_places[j].is_none() {
                                    return bad;
                                }
                            }
                            ParamKind::Input(o) => {
                                let Some(k) = inputs.iter().position(|(_, n, _)| p.name.is(n))
                                else {
                                    self.err(
                                        UNKNOWN_MEMBER,
                                        p.name.span,
                                        format!("{fname} has no input `{}`", p.name),
                                    );
                                    continue;
                                };
                                let Some(a) = self.operand(o) else { continue };
                                values[k] = self.fit(a, &inputs[k].2, o.span());
                            }
                            ParamKind::Output { negate, target } => {
                                let Some((_, v)) = sig
                                    .var(&p.name.name)
                                    .filter(|(_, v)| v.kind == ast::VarKind::Output)
                                else {
                                    self.err(
                                        UNKNOWN_MEMBER,
                                        p.name.span,
                                        format!("{fname} has no output `{}`", p.name),
                                    );
                                    continue;
                                };
                                let ty = v.ty.clone();
                                let Some(place) = self.place_of(target, true) else {
                                    continue;
                                };
                                if place.ty != ty {
                                    self.err(
                                        TYPE_MISMATCH,
                                        target.span(),
                                        format!(
                                            "`{}` is {ty}, the variable is {}",
                                            p.name, place.ty
                                        ),
                                    );
                                    continue;
                                }
                                let k = sig
                                    .vars
                                    .iter()
                                    .filter(|o| o.kind == ast::VarKind::Output)
                                    .position(|o| o.name == v.name)
                                    .unwrap_or(0);
                                outputs.push((k, place, *negate));
                            }
                        }
                    }
                    for (k, (_, _, t)) in inputs.iter().enumerate() {
                        if values[k].is_none() {
                            values[k] = Some(Value::Const(default_const(t)));
                        }
                    }
                }
            }
            let Some(ret) = ret else { return bad };
            if let Some(j) = inout_places.iter().position(Option::is_none) {
                self.err(
                    BAD_IN_OUT,
                    span,
                    format!(
                        "{fname} has VAR_IN_OUT `{}`: every call binds it (`{fname}({} := variable, ...)`)",
                        inouts[j].0, inouts[j].0
                    ),
                );
                return bad;
            }
            if values.iter().any(Option::is_none) {
                return bad;
            }
            let inouts = inout_places.into_iter().flatten().collect();
            let args = values.into_iter().flatten().collect();
            let out_types = sig
                .vars
                .iter()
                .filter(|o| o.kind == ast::VarKind::Output)
                .map(|o| o.ty.clone())
                .collect();
            let eno = sig
                .vars
                .iter()
                .filter(|o| o.kind == ast::VarKind::Output)
                .position(|o| o.name == "ENO");
            self.push(Op::SetCr {
                ty: ret.clone(),
                expr: Expr::CallUser {
                    name: fname,
                    inouts,
                    args,
                    out_types,
                    outputs,
                    en: en.clone(),
                    eno,
                    ret: ret.clone(),
                },
            });
            for (place, negate) in eno_plain {
                let value = en.clone().unwrap_or(Value::Const(Const::Bool(true)));
                self.push(Op::Store {
                    place,
                    value,
                    negate,
                });
            }
            return Cr::Val(ret);
        }
        let key = name.key();
        if stdfn::is_std(&key) {
            let mut argv: Vec<(Arg, Span)> = Vec::new();
            match args {
                CallArgs::NonFormal(list) if !formal_only => {
                    let Some(first) = self.use_cr(&cr, span) else {
                        return bad;
                    };
                    argv.push((first, span));
                    for o in list {
                        let Some(a) = self.operand(o) else { return bad };
                        argv.push((a, o.span()));
                    }
                }
                CallArgs::NonFormal(_) => {
                    self.err(
                        ARG_COUNT,
                        span,
                        "CAL of a function needs a formal list: `CAL F(IN := x)`",
                    );
                    return bad;
                }
                CallArgs::Formal(list) => {
                    let mut named = Vec::new();
                    for p in list {
                        match &p.kind {
                            ParamKind::Input(o) => {
                                let Some(a) = self.operand(o) else { return bad };
                                named.push((p.name.clone(), a, o.span()));
                            }
                            ParamKind::Output { .. } => {
                                self.err(
                                    UNSUPPORTED,
                                    p.span,
                                    "standard functions have no outputs to read with `=>`",
                                );
                                return bad;
                            }
                        }
                    }
                    match stdfn::order_formal(&key, named) {
                        Ok(v) => argv = v,
                        Err((s, m)) => {
                            self.err(UNKNOWN_MEMBER, s.unwrap_or(span), m);
                            return bad;
                        }
                    }
                }
            }
            return self.std_call(&key, argv, name.span);
        }
        let is_var = self.sig.var(&name.name).is_some();
        let mut cands: Vec<String> = self
            .env
            .pous
            .values()
            .filter(|s| s.kind == PouKind::Function)
            .map(|s| s.name.clone())
            .collect();
        // A hash map's order: sorted, so that the suggestion is the same on
        // every run.
        cands.sort();
        cands.extend(stdfn::names().map(String::from));
        // A mistyped IL operator (`LDD`) lands here too.
        cands.extend(
            [
                "LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN", "OR", "ORN", "XOR", "XORN",
                "NOT", "ADD", "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT",
                "JMP", "JMPC", "JMPCN", "CAL", "CALC", "CALCN", "RET", "RETC", "RETCN", "S1", "R1",
                "CLK", "CU", "CD", "PV", "IN", "PT",
            ]
            .map(String::from),
        );
        let hint = suggest(&name.name, cands.iter().map(String::as_str))
            .map(|s| format!("did you mean `{s}`?"));
        if let Some(d) = self.err(
            UNKNOWN_FUNCTION,
            name.span,
            format!("unknown operator or function `{name}`"),
        ) {
            if is_var {
                d.help = Some(format!(
                    "`{name}` is a variable: write `LD {name}` or `ST {name}`"
                ));
            } else {
                d.help = hint;
                d.notes.push("a word in the operator field that is not an IL operator must name a FUNCTION; vendor built-ins are not IEC 61131-3".into());
            }
        }
        bad
    }

    /// A pending call as an argument where no type is expected: emit it
    /// with the types its arguments default to.
    fn settle(&mut self, a: Arg) -> Option<Arg> {
        match a {
            Arg::Lit(LitClass::Pending(p), _) => {
                let (v, t) = self.materialize(&p, None)?;
                Some(Arg::Typed(v, t))
            }
            a => Some(a),
        }
    }

    fn settle_cr(&mut self, cr: Cr) -> Cr {
        match cr {
            Cr::Lit(LitClass::Pending(p), _) => match self.materialize(&p, None) {
                Some((_, t)) => Cr::Val(t),
                None => Cr::Undef(Why::Error),
            },
            cr => cr,
        }
    }

    /// Emit a pending call with result type `force` (or its default): the
    /// CR local of that type holds the result.
    fn materialize(&mut self, p: &Pending, force: Option<&Ty>) -> Option<(Value, Ty)> {
        let shapes: Vec<stdfn::ArgShape> = p
            .args
            .iter()
            .map(|(a, _)| match a {
                PendArg::Typed(_, t) => stdfn::ArgShape::Ty(t.clone()),
                PendArg::Lit(l) => stdfn::ArgShape::Lit(l.clone()),
            })
            .collect();
        let res = match stdfn::resolve(&p.key, &shapes, force) {
            Ok(r) => r,
            Err(e) => {
                if let Some(d) = self.err(TYPE_MISMATCH, p.span, e.message) {
                    d.notes.push(format!("signature: {}", e.signature));
                }
                return None;
            }
        };
        if let Some(f) = force
            && res.ret != *f
        {
            self.err(
                TYPE_MISMATCH,
                p.span,
                format!(
                    "{} cannot give {f} here (its arguments make it {})",
                    p.key, res.ret
                ),
            );
            return None;
        }
        let mut values = Vec::new();
        for ((a, s), t) in p.args.iter().zip(&res.params) {
            let v = match a {
                PendArg::Typed(v, _) => v.clone(),
                PendArg::Lit(l) => self.lit_value(l, t, *s, LITERAL_RANGE)?,
            };
            values.push(v);
        }
        let ret = self.push_std_call(res, values);
        Some((Value::Cr(ret.clone()), ret))
    }

    /// A literal (or pending call) as a value of type `ty`.
    fn lit_value(
        &mut self,
        l: &LitClass,
        ty: &Ty,
        span: Span,
        code: &'static str,
    ) -> Option<Value> {
        if let LitClass::Pending(p) = l {
            return self.materialize(p, Some(ty)).map(|(v, _)| v);
        }
        match coerce(l, ty) {
            Ok(c) => Some(Value::Const(c)),
            Err(m) => {
                self.err(code, span, m);
                None
            }
        }
    }

    /// `CR := F(values)` for a resolved standard function; the CR's type.
    fn push_std_call(&mut self, res: stdfn::Resolved, values: Vec<Value>) -> Ty {
        let ret = res.ret.clone();
        self.push(Op::SetCr {
            ty: ret.clone(),
            expr: Expr::CallStd {
                call: res.call,
                args: values,
                arg_types: res.params,
                ret: res.ret,
            },
        });
        ret
    }

    fn std_call(&mut self, key: &str, argv: Vec<(Arg, Span)>, span: Span) -> Cr {
        let bad = Cr::Undef(Why::Error);
        let mut settled = Vec::new();
        for (a, s) in argv {
            let Some(a) = self.settle(a) else { return bad };
            settled.push((a, s));
        }
        let argv = settled;
        let shapes: Vec<stdfn::ArgShape> = argv
            .iter()
            .map(|(a, _)| match a {
                Arg::Typed(_, t) => stdfn::ArgShape::Ty(t.clone()),
                Arg::Lit(l, _) => stdfn::ArgShape::Lit(l.clone()),
            })
            .collect();
        if stdfn::needs_context(key, &shapes) {
            let args = argv
                .into_iter()
                .map(|(a, s)| match a {
                    Arg::Typed(v, t) => (PendArg::Typed(v, t), s),
                    Arg::Lit(l, _) => (PendArg::Lit(l), s),
                })
                .collect();
            let p = Pending {
                key: key.to_string(),
                args,
                span,
            };
            return Cr::Lit(LitClass::Pending(Box::new(p)), span);
        }
        match stdfn::resolve(key, &shapes, None) {
            Ok(res) => {
                let mut values = Vec::new();
                for ((a, s), t) in argv.into_iter().zip(&res.params) {
                    let Some(v) = self.fit(a, t, s) else {
                        return bad;
                    };
                    values.push(v);
                }
                Cr::Val(self.push_std_call(res, values))
            }
            Err(e) => {
                let code = if e.count { ARG_COUNT } else { TYPE_MISMATCH };
                if let Some(d) = self.err(code, span, e.message) {
                    d.notes.push(format!("signature: {}", e.signature));
                    if e.count {
                        d.notes
                            .push("in IL the current result is the first argument".into());
                    }
                }
                bad
            }
        }
    }

    /// `lhs op rhs` where lhs is the CR (or a saved CR) and rhs the operand.
    fn binary(&mut self, op: ExprOp, negate: bool, lhs: Arg, rhs: Arg, span: Span) -> Cr {
        let bad = Cr::Undef(Why::Error);
        let bop = op;
        // A pending call meeting only literals takes its default type.
        let pending = |a: &Arg| matches!(a, Arg::Lit(LitClass::Pending(_), _));
        if matches!(lhs, Arg::Lit(..))
            && matches!(rhs, Arg::Lit(..))
            && (pending(&lhs) || pending(&rhs))
        {
            let (Some(l), Some(r)) = (self.settle(lhs), self.settle(rhs)) else {
                return bad;
            };
            return self.binary(op, negate, l, r, span);
        }
        // Both untyped literals: fold at compile time.
        if let (Arg::Lit(a, sa), Arg::Lit(b, _)) = (&lhs, &rhs) {
            return match fold(bop, negate, a, b) {
                Ok(Folded::Lit(l)) => Cr::Lit(l, sa.to(span)),
                Ok(Folded::Bool(v)) => {
                    self.push(Op::SetCr {
                        ty: Ty::BOOL,
                        expr: Expr::Value(Value::Const(Const::Bool(v))),
                    });
                    Cr::Val(Ty::BOOL)
                }
                Err(m) => {
                    self.err(
                        if m.contains("zero") {
                            CONST_DIV_ZERO
                        } else {
                            BAD_OPERATOR_TYPE
                        },
                        span,
                        m,
                    );
                    bad
                }
            };
        }
        // TIME scaled by a number.
        if matches!(bop, BinOp::Mul | BinOp::Div)
            && let (Arg::Typed(lv, Ty::Elem(te)), r) = (&lhs, &rhs)
            && te.is_duration()
        {
            let (rv, ne) = match r {
                Arg::Typed(v, Ty::Elem(n)) if n.is_num() => (v.clone(), *n),
                Arg::Lit(LitClass::Int(n), _) if i64::try_from(*n).is_ok() => {
                    (Value::Const(Const::Int(*n, Elem::LINT)), Elem::LINT)
                }
                Arg::Lit(LitClass::Real(f, _), _) => {
                    (Value::Const(Const::Real(*f, Elem::LREAL)), Elem::LREAL)
                }
                _ => {
                    self.err(
                        TYPE_MISMATCH,
                        span,
                        format!("{} of {} needs a number", op.name(), te.name()),
                    );
                    return bad;
                }
            };
            self.push(Op::SetCr {
                ty: Ty::Elem(*te),
                expr: Expr::TimeScale {
                    div: bop == BinOp::Div,
                    time: *te,
                    lhs: lv.clone(),
                    num: ne,
                    rhs: rv,
                },
            });
            return Cr::Val(Ty::Elem(*te));
        }
        let (ty, lv, rv) = match (lhs, rhs) {
            (Arg::Typed(lv, t), Arg::Typed(rv, u)) => {
                if t != u {
                    if let Some(d) = self.err(TYPE_MISMATCH, span, format!("{} of {t} and {u}: the current result and the operand must have the same type", op.name())) {
                        d.help = conversion_hint(&u, &t);
                    }
                    return bad;
                }
                (t, lv, rv)
            }
            (Arg::Typed(lv, t), Arg::Lit(l, s)) => match self.lit_value(&l, &t, s, TYPE_MISMATCH) {
                Some(v) => (t, lv, v),
                None => return bad,
            },
            (Arg::Lit(l, s), Arg::Typed(rv, t)) => match self.lit_value(&l, &t, s, TYPE_MISMATCH) {
                Some(v) => (t, v, rv),
                None => return bad,
            },
            // Two literals were folded above.
            (Arg::Lit(..), Arg::Lit(..)) => return bad,
        };
        if let Err(m) = op_allowed(op, negate, &ty) {
            self.err(BAD_OPERATOR_TYPE, span, m);
            return bad;
        }
        let res = if op.is_compare() {
            Ty::BOOL
        } else {
            ty.clone()
        };
        self.push(Op::SetCr {
            ty: res.clone(),
            expr: Expr::Bin {
                op: bop,
                ty,
                lhs: lv,
                rhs: rv,
                negate_rhs: negate,
            },
        });
        Cr::Val(res)
    }
}

pub(crate) fn default_const(t: &Ty) -> Const {
    match t {
        Ty::Elem(Elem::BOOL) => Const::Bool(false),
        Ty::Elem(e) if e.int_range().is_some() => Const::Int(0, *e),
        Ty::Elem(e) if e.is_real() => Const::Real(0.0, *e),
        Ty::Elem(e) => Const::Time(0, *e),
        Ty::Str { wide, len } => Const::Str {
            value: String::new(),
            wide: *wide,
            len: *len,
        },
        _ => Const::Bool(false),
    }
}

fn op_allowed(op: ExprOp, negate: bool, t: &Ty) -> Result<(), String> {
    let name = op.name();
    if negate && !op.is_logic() {
        return Err(format!("{name} has no N modifier"));
    }
    let ok = match t {
        Ty::Elem(e) => {
            if op.is_logic() {
                t.is_logic()
            } else if op == ExprOp::Mod {
                e.is_int()
            } else if op.is_arith() {
                e.is_num() || (e.is_duration() && matches!(op, ExprOp::Add | ExprOp::Sub))
            } else {
                true
            }
        }
        Ty::Str { .. } => op.is_compare(),
        Ty::Enum(_) => matches!(op, ExprOp::Eq | ExprOp::Ne),
        _ => false,
    };
    if ok {
        return Ok(());
    }
    let what = if op.is_logic() {
        "BOOL or a bit string (BYTE, WORD, DWORD, LWORD)"
    } else if op == ExprOp::Mod {
        "an integer type"
    } else if op.is_arith() {
        "a number (or TIME for ADD and SUB)"
    } else {
        "an elementary type"
    };
    Err(format!("{name} needs {what}; the current result is {t}"))
}

enum Folded {
    Lit(LitClass),
    Bool(bool),
}

/// Evaluate an operation on two untyped literals exactly.
fn fold(op: BinOp, negate: bool, a: &LitClass, b: &LitClass) -> Result<Folded, String> {
    use LitClass::{Int, Real};
    let cmp = |o: std::cmp::Ordering| -> bool {
        match op {
            BinOp::Gt => o.is_gt(),
            BinOp::Ge => o.is_ge(),
            BinOp::Eq => o.is_eq(),
            BinOp::Ne => o.is_ne(),
            BinOp::Le => o.is_le(),
            _ => o.is_lt(),
        }
    };
    if negate {
        return Err("N on untyped literals: give one of them a type (BOOL#1, WORD#16#FF)".into());
    }
    match (a, b) {
        (Int(x), Int(y)) => {
            let (x, y) = (*x, *y);
            let r = match op {
                BinOp::And => Some(x & y),
                BinOp::Or => Some(x | y),
                BinOp::Xor => Some(x ^ y),
                BinOp::Add => x.checked_add(y),
                BinOp::Sub => x.checked_sub(y),
                BinOp::Mul => x.checked_mul(y),
                BinOp::Div | BinOp::Mod if y == 0 => {
                    return Err("division by zero in a constant expression".into());
                }
                BinOp::Div => x.checked_div(y),
                BinOp::Mod => x.checked_rem(y),
                _ => return Ok(Folded::Bool(cmp(x.cmp(&y)))),
            };
            r.map(|v| Folded::Lit(Int(v)))
                .ok_or_else(|| "constant expression overflows".into())
        }
        (Int(_) | Real(..), Int(_) | Real(..)) => {
            let f = |l: &LitClass| match l {
                Int(v) => *v as f64,
                Real(v, _) => *v,
                _ => 0.0,
            };
            let (x, y) = (f(a), f(b));
            let r = match op {
                BinOp::Add => x + y,
                BinOp::Sub => x - y,
                BinOp::Mul => x * y,
                BinOp::Div => x / y,
                BinOp::And | BinOp::Or | BinOp::Xor | BinOp::Mod => {
                    return Err("this operator needs integers".into());
                }
                _ => return Ok(Folded::Bool(x.partial_cmp(&y).is_some_and(cmp))),
            };
            Ok(Folded::Lit(Real(r, format!("{r:?}"))))
        }
        _ => Err("this operation on two literals needs typed literals".into()),
    }
}

/// "use INT_TO_REAL" when a conversion function exists.
fn conversion_hint(from: &Ty, to: &Ty) -> Option<String> {
    let (Ty::Elem(a), Ty::Elem(b)) = (from, to) else {
        return None;
    };
    let name = format!("{}_TO_{}", short(*a), short(*b));
    stdfn::is_std(&name).then(|| format!("convert with `{name}`"))
}

fn short(e: Elem) -> &'static str {
    match e {
        Elem::TOD => "TOD",
        Elem::DT => "DT",
        e => e.name(),
    }
}
