//! The body checker: walks the instruction list, proving the type of the
//! current result (CR) at every instruction, and lowers it to [`ir`].
//!
//! Labels make the CR's type a flow problem: the walk is repeated until the
//! CR state at every label is stable (a fixpoint), then run once more to
//! report diagnostics and build the IR with those states.

use super::codes::*;
use super::env::{Env, PouSig};
use super::ir::{self, BinOp, CheckedPou, Const, Expr, Op, PathElem, Place, Root, Value};
use super::literals::{LitClass, PendArg, Pending, coerce, describe, lit_class, operand_ty};
use super::types::{Elem, Ty};
use super::{Cx, stdfb, stdfn, suggest};
use crate::ast::{
    self, Accessor, CallArgs, Cond, ExprOp, InstrKind, Operand, ParamKind, PouKind, Span, VarRef,
};

mod declare_fix;
mod fb_calls;
mod fn_calls;
mod instr;
mod join;
pub(crate) mod keys;
mod names;
mod operands;
mod operators;
mod place_table;
mod places;
mod subscripts;
mod values;

use join::{join, push_edge};
pub(crate) use names::{Key, Noted, table};
pub use operators::default_const;
use operators::*;

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

/// Checks a POU's body against its signature (the one in `env`, or a
/// duplicate's own from `env.duplicates`).
pub(crate) fn check_pou(
    cx: &mut Cx,
    env: &Env,
    pou: &ast::Pou,
    sig: &PouSig,
) -> Option<CheckedPou> {
    if pou.host.is_some() {
        return Some(host_pou(cx, env, pou, sig));
    }
    let mut labels = rustc_hash::FxHashMap::default();
    let mut label_spans = Vec::new();
    let mut label_names = Vec::new();
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
                label_names.push(id.name.to_string());
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
    let cx_names = cx.names.is_some();
    let mut w = Walk {
        cx,
        env,
        sig,
        pou,
        labels,
        label_names,
        label_in: vec![Cr::Dead; n],
        edges: vec![Vec::new(); n],
        label_pos,
        pos: 0,
        back_prev: vec![Vec::new(); n],
        back_now: vec![Vec::new(); n],
        final_pass: false,
        out: Vec::new(),
        counted: 0,
        cr_types: Vec::new(),
        save_types: Vec::new(),
        save_slots: Vec::new(),
        save_depth: 0,
        jumped: vec![false; n],
        cr_steps: Vec::new(),
        line: 0,
        col: 0,
        instr_lo: 0,
        addresses: Vec::new(),
        places: Vec::new(),
        place_ids: Default::default(),
        // Not for a duplicate's body: its names are not the table's symbols.
        noting: cx_names && env.pou(&sig.name).is_some_and(|s| std::ptr::eq(s, sig)),
        noted: Vec::new(),
    };
    // Fixpoint: the lattice per label is short (dead → literal → type → mixed),
    // so a few rounds settle it; the cap only guards against oscillation bugs.
    // Forward edges are used in the same round, so straight-line code with
    // any number of labels settles in two rounds; each round adds backward
    // edges, and the per-label lattice is short, so loops settle quickly too.
    //
    // A round that settles ran on the very states a final pass would use
    // (the label states and backward edges it leaves are the ones it
    // started from), so its statements and diagnostics are the final ones.
    // Every round but the first (which starts from nothing) therefore runs
    // as the final pass and is kept when it settles: no extra walk over the
    // body. A first round that settles is walked once more, as the final
    // pass (without labels, the first round is the final pass).
    let (stmts, steps) = output_size(&pou.body);
    if w.cx.cr_steps {
        w.cr_steps = Vec::with_capacity(steps);
    }
    let mut settled = false;
    for round in 0..64 {
        w.final_pass = round > 0 || n == 0;
        // Sized once: from the first round's count when there is one (a
        // later round's label states change few statements), else from the
        // syntax tree.
        if w.final_pass && w.out.capacity() == 0 {
            let want = if round == 0 { stmts } else { w.counted };
            w.out = Vec::with_capacity(want + want / 32);
        }
        let mark = w.cx.diags.len();
        w.edges.iter_mut().for_each(Vec::clear);
        w.back_now.iter_mut().for_each(Vec::clear);
        w.start_output();
        w.walk(&pou.body);
        let next: Vec<Cr> = w.edges.iter().map(|e| join(e)).collect();
        let same = next == w.label_in && w.back_now == w.back_prev;
        if same && w.final_pass {
            settled = true;
            break;
        }
        // Not the last round: what it reported is reported again later.
        w.cx.diags.truncate(mark);
        w.label_in = next;
        std::mem::swap(&mut w.back_prev, &mut w.back_now);
    }
    if !settled {
        // Never silently: report it rather than emit code from unsettled states.
        w.cx.err(UNSUPPORTED, pou.name.span, format!("the flow analysis of `{}` did not settle (too many nested loops); please report this", pou.name));
        w.final_pass = true;
        w.edges.iter_mut().for_each(Vec::clear);
        w.start_output();
        w.walk(&pou.body);
    }
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
    if let Some(names) = &mut w.cx.names {
        names.append(&mut w.noted);
    }
    Some(CheckedPou {
        kind: pou.kind,
        name: sig.name.clone(),
        doc: super::docs::leading(w.cx.file, pou.name.span),
        // Taken from the signature at the end of `check_all` (held
        // twice, they were a fifth of a program of small POUs).
        vars: Vec::new(),
        ret: sig.ret.clone(),
        body: w.out,
        label_count: n,
        addresses: w.addresses,
        places: w.places,
        cr_types: w.cr_types,
        save_types: w.save_types,
        retained: super::config::retain::retained(env, sig),
        cr_steps: w.cr_steps,
        host: false,
    })
}

/// A host FUNCTION (`{extern}`): its interface only. Instructions or locals
/// would be silently dropped, so they are IL0140.
fn host_pou(cx: &mut Cx, env: &Env, pou: &ast::Pou, sig: &PouSig) -> CheckedPou {
    if let Some(first) = pou.body.first() {
        let span = first.span();
        cx.err(
            HOST_BODY,
            span,
            format!(
                "host {} `{}` has instructions: its body is the crate's Rust function",
                pou.kind.keyword(),
                pou.name
            ),
        );
    }
    for b in &pou.var_blocks {
        if !matches!(
            b.kind,
            ast::VarKind::Input | ast::VarKind::Output | ast::VarKind::InOut
        ) {
            cx.err(
                HOST_BODY,
                b.span,
                format!(
                    "host {} `{}` declares {}: it has only inputs, outputs and in-outs",
                    pou.kind.keyword(),
                    pou.name,
                    b.kind.keyword()
                ),
            );
        }
    }
    CheckedPou {
        kind: pou.kind,
        name: sig.name.clone(),
        doc: super::docs::leading(cx.file, pou.name.span),
        // Taken from the signature at the end of `check_all` (held
        // twice, they were a fifth of a program of small POUs).
        vars: Vec::new(),
        ret: sig.ret.clone(),
        body: Vec::new(),
        places: Vec::new(),
        label_count: 0,
        addresses: Vec::new(),
        cr_types: Vec::new(),
        save_types: Vec::new(),
        retained: super::config::retain::retained(env, sig),
        cr_steps: Vec::new(),
        host: true,
    }
}

/// About how many statements and CR steps the final pass records for
/// `body`: the output vectors are sized once (they are the largest part of
/// the checked program; growing them by doubling copies them and leaves
/// up to half unused).
fn output_size(body: &[ast::Stmt]) -> (usize, usize) {
    body.iter().fold((0, 0), |(stmts, steps), s| match s {
        ast::Stmt::Label(_) => (stmts + 1, steps + 1),
        ast::Stmt::Instr(i) => match &i.kind {
            // Save of the outer CR, the inner body, the operation, and room
            // for a pending call or a conversion (deep parentheses grew the
            // vector by doubling without it).
            InstrKind::Deferred { body, .. } => {
                let (a, b) = output_size(body);
                (stmts + 3 + a, steps + 1 + b)
            }
            // The operation (a `Nop` where there is none: `Walk::line_stmt`).
            _ => (stmts + 1, steps + 1),
        },
    })
}

/// The CR as tools see it ([`ir::CrState`]).
fn cr_state(cr: &Cr) -> ir::CrState {
    match cr {
        Cr::Dead => ir::CrState::Dead,
        // A line as data: a check that reuses this POU's results after an
        // edit that moved its lines moves it (see `sema/reuse.rs`).
        Cr::Undef(Why::AfterCal(line)) => ir::CrState::AfterCal(*line),
        Cr::Undef(Why::Start) => ir::CrState::Undefined("no value loaded".into()),
        Cr::Undef(Why::Error) => ir::CrState::Undefined("after an error".into()),
        Cr::Undef(Why::Mixed(m)) => ir::CrState::Undefined(match m.split_once('\u{0}') {
            Some((label, _)) => format!("the paths into `{label}` disagree"),
            None => m.clone(),
        }),
        Cr::Lit(l, _) => ir::CrState::Literal(describe(l)),
        Cr::Val(t) => ir::CrState::Typed(t.clone()),
    }
}

struct Walk<'a, 'c> {
    cx: &'a mut Cx<'c>,
    env: &'a Env,
    sig: &'a PouSig,
    /// The POU's syntax (where a fix may declare a variable).
    pou: &'a ast::Pou,
    labels: rustc_hash::FxHashMap<String, usize>,
    /// Each label as declared (suggestions show the user's spelling).
    label_names: Vec<String>,
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
    /// The statements a round before the final pass would have pushed (it
    /// pushes none): the final pass's `out` is sized from it.
    counted: usize,
    cr_types: Vec<Ty>,
    save_types: Vec<Ty>,
    /// The save slots of each depth of parentheses (indexes into
    /// `save_types`), and the depth being walked.
    save_slots: Vec<Vec<u32>>,
    save_depth: usize,
    jumped: Vec<bool>,
    /// The CR at every instruction and label, recorded on the final pass.
    cr_steps: Vec<ir::CrStep>,
    line: u32,
    /// Column (1-based) of the instruction being walked.
    col: u32,
    /// Where the instruction being walked starts (its operator), for the
    /// fixes that insert an instruction before it.
    instr_lo: u32,
    addresses: Vec<ir::Loc>,
    /// The body's place table, and the index of each place without
    /// subscripts in it by a hash of its root and steps ([`place_table`]).
    places: Vec<Place>,
    place_ids: rustc_hash::FxHashMap<u64, u32>,
    /// Note the names resolved ([`names`]), and those of the final pass.
    noting: bool,
    noted: Noted,
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

    /// The statements pushed next come from the source at `span`.
    fn at(&mut self, span: Span) {
        // Only the final pass builds statements, which need the column.
        // Instructions come in order: the previous line is the best guess.
        let near = self.line as usize;
        self.instr_lo = span.lo;
        if self.final_pass {
            let (line, col) = self.cx.file.line_col_near(span.lo, near);
            self.line = line as u32;
            self.col = col as u32;
        } else {
            self.line = self.cx.file.line_of_near(span.lo, near) as u32;
        }
    }

    /// A 3rd-edition form at `span` (an error under the 2nd edition).
    fn feature(&mut self, feature: crate::dialect::Feature, span: Span) {
        if self.final_pass {
            self.cx.feature(feature, span);
        }
    }

    /// `value` of type `from` widened to `to` (3rd edition), when the
    /// table has that widening.
    fn widen(&mut self, value: Value, from: &Ty, to: &Ty, span: Span) -> Option<Value> {
        let w = super::widen::widening(from, to)?;
        self.feature(
            crate::dialect::Feature::Widening {
                from: from.to_string(),
                to: to.to_string(),
            },
            span,
        );
        Some(match value {
            Value::Const(c) => Value::Const(super::widen::widen_const(&c, w.to)?),
            v => Value::Widen(Box::new((v, w))),
        })
    }

    fn push(&mut self, op: Op) {
        // The rounds before the final pass only settle the label states;
        // their statements would be thrown away: only counted.
        if !self.final_pass {
            self.counted += 1;
            return;
        }
        self.out.push(ir::Stmt {
            op,
            line: self.line,
            col: self.col,
        });
    }

    /// The index of the CR local of type `ty` ([`Value::Cr`],
    /// [`Op::SetCr`]), added on its first use. A round before the final
    /// pass adds too; the final pass starts from an empty list.
    pub(super) fn cr_index(&mut self, ty: &Ty) -> u32 {
        let i = match self.cr_types.iter().position(|t| t == ty) {
            Some(i) => i,
            None => {
                self.cr_types.push(ty.clone());
                self.cr_types.len() - 1
            }
        };
        // A POU has a CR local per type it uses: a handful.
        i as u32
    }

    /// Keep the line of the instruction whose statements start at `at`: the
    /// emitter writes an IL line's comment above its first statement, so a
    /// `Nop` is needed only when the instruction pushed none on its own line
    /// (`LD 5`, or `ADD(` whose operand is on the next line). Most
    /// instructions push one statement on their line; a `Nop` before each
    /// was half the checked IR.
    fn line_stmt(&mut self, at: usize, line: u32, col: u32) {
        if !self.final_pass {
            // `at` is the count before the instruction here.
            if self.counted == at {
                self.counted += 1;
            }
            return;
        }
        if self.out.get(at).is_some_and(|s| s.line == line) {
            return;
        }
        let nop = ir::Stmt {
            op: Op::Nop,
            line,
            col,
        };
        // Only this instruction's statements move.
        self.out.insert(at, nop);
    }

    /// Forget the statements and records of an earlier round.
    fn start_output(&mut self) {
        self.out.clear();
        self.counted = 0;
        self.cr_steps.clear();
        self.noted.clear();
        self.cr_types.clear();
        self.addresses.clear();
        self.places.clear();
        self.place_ids.clear();
    }

    fn walk(&mut self, body: &[ast::Stmt]) {
        self.save_types.clear();
        self.save_slots.clear();
        self.save_depth = 0;
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
                    self.at(id.span);
                    // This round's edges (all from before the label) plus the
                    // previous round's backward edges.
                    let mut into = self.edges[l].clone();
                    into.extend(self.back_prev[l].iter().cloned());
                    crate::step_counter::add(1 + into.len() as u64);
                    let before = cr;
                    cr = match join(&into) {
                        Cr::Undef(Why::Mixed(paths)) => {
                            Cr::Undef(Why::Mixed(format!("{}\u{0}{paths}", id.name)))
                        }
                        other => other,
                    };
                    self.step(id.span, true, &before, &cr);
                    self.push(Op::Label(l));
                    warned_dead = false;
                }
                ast::Stmt::Instr(i) => {
                    self.at(i.span);
                    if cr == Cr::Dead {
                        if !warned_dead && self.final_pass {
                            self.cx
                                .warn(UNREACHABLE, i.span, "this instruction can never run")
                                .set_label("no label leads here after the JMP or RET above");
                        }
                        warned_dead = true;
                        self.step(i.span, false, &Cr::Dead, &Cr::Dead);
                        self.note_dead(i);
                        continue;
                    }
                    let at = if self.final_pass {
                        self.out.len()
                    } else {
                        self.counted
                    };
                    let (line, col) = (self.line, self.col);
                    let errors = self.cx.diags.len();
                    cr = self.instr(i, cr, false);
                    if self.cx.diags.len() > errors {
                        // It stopped at the error: its other names still count.
                        self.note_dead(i);
                    }
                    self.line_stmt(at, line, col);
                }
            }
        }
    }

    /// On the final pass, record the CR before and after an instruction (or
    /// at a label) for tools: [`ir::CrStep`].
    #[inline(never)]
    fn step(&mut self, span: Span, label: bool, before: &Cr, after: &Cr) {
        if !self.final_pass || !self.cx.cr_steps {
            return;
        }
        let paths = match after {
            Cr::Undef(Why::Mixed(m)) if label => m.split_once('\u{0}').map(|(_, p)| p.to_string()),
            _ => None,
        };
        self.cr_steps.push(ir::CrStep {
            span,
            label,
            before: cr_state(before),
            after: cr_state(after),
            paths,
        });
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
            push_edge(&mut self.back_now[l], (span, class.clone(), self.line));
        }
        push_edge(&mut self.edges[l], (span, class, self.line));
        if let (Cr::Lit(lit, lspan), Cr::Val(t)) = (cr, &self.label_in[l].clone())
            && !matches!(lit, LitClass::Pending(_))
        {
            match coerce(lit, t) {
                Ok(c) => {
                    let cr = self.cr_index(t);
                    self.push(Op::SetCr {
                        cr,
                        expr: Expr::Value(Value::Const(c)),
                    })
                }
                Err(m) => {
                    let lspan = *lspan;
                    self.err(LITERAL_RANGE, lspan, m);
                }
            }
        }
    }
}
