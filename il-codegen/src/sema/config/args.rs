//! The arguments of a program instance in a configuration: `PROGRAM p WITH t
//! : P(in := g_or_literal, out => g, io := g)`. Inputs are copied in before
//! each run, outputs copied out after it, and VAR_IN_OUTs are the global
//! itself (passed by reference, Ed.2 2.7.1).

use super::lookup::{lookup, unknown_global};
use crate::ast::{self, Operand, ParamKind, VarKind};
use crate::ir::{ConfigDef, GlobalRef, Init, Member, ProgArg};
use crate::sema::Cx;
use crate::sema::codes::*;
use crate::sema::env::{Env, PouSig};
use crate::sema::init::init_value;

/// The checked arguments of one program instance.
#[derive(Default)]
pub(crate) struct ProgArgs {
    pub inputs: Vec<(Member, ProgArg)>,
    pub outputs: Vec<(Member, GlobalRef)>,
    /// In the program's declaration order of its VAR_IN_OUTs.
    pub inouts: Vec<(Member, GlobalRef)>,
}

/// Variable `index` of the program, named `name`.
pub(super) fn member(index: usize, name: &str) -> Member {
    Member {
        name: name.into(),
        index: index as u32,
    }
}

pub(crate) fn program_args(
    cx: &mut Cx,
    env: &Env,
    def: &ConfigDef,
    res: usize,
    sig: &PouSig,
    pi: &ast::ProgramInstance,
    externals: &[(Member, GlobalRef, bool)],
) -> ProgArgs {
    let mut out = ProgArgs::default();
    let mut inouts: Vec<(Member, GlobalRef)> = Vec::new();
    let mut named: Vec<String> = Vec::new();
    for a in &pi.args {
        let want: &[VarKind] = match a.kind {
            ParamKind::Input(_) => &[VarKind::Input, VarKind::InOut],
            ParamKind::Output { .. } => &[VarKind::Output],
        };
        let Some((index, v)) = sig
            .var(&a.name.name)
            .filter(|(_, v)| want.contains(&v.kind))
        else {
            cx.err(
                BAD_CONFIG,
                a.name.span,
                format!(
                    "program `{}` has no {} `{}`",
                    sig.name,
                    if want[0] == VarKind::Input {
                        "input or in-out"
                    } else {
                        "output"
                    },
                    a.name
                ),
            );
            continue;
        };
        match &a.kind {
            ParamKind::Input(o) if v.kind == VarKind::InOut => {
                named.push(v.name.clone());
                let Operand::Var(g) = o else {
                    cx.err(
                        BAD_IN_OUT,
                        o.span(),
                        format!(
                            "`{}` is a VAR_IN_OUT of `{}`: bind it to a global variable, not a value",
                            v.name, sig.name
                        ),
                    );
                    continue;
                };
                if !g.path.is_empty() {
                    cx.err(
                        BAD_IN_OUT,
                        g.span(),
                        "a VAR_IN_OUT of a program is bound to a whole global (`io := g`)",
                    );
                    continue;
                }
                let Some((gr, gv)) = lookup(def, res, &g.base.name) else {
                    unknown_global(cx, def, res, &g.base, "VAR_IN_OUT");
                    continue;
                };
                let problem = if gv.ty != v.ty {
                    Some(format!(
                        "the VAR_IN_OUT `{}` is {}, the global `{}` is {}: a reference needs exactly its type",
                        v.name, v.ty, gv.name, gv.ty
                    ))
                } else if gv.constant {
                    Some(format!(
                        "the global `{}` is CONSTANT and cannot be passed by reference",
                        gv.name
                    ))
                } else if let Some(l) = &gv.location {
                    Some(format!(
                        "the global `{}` is at {} in the process image, which cannot be passed by reference: bind the VAR_IN_OUT to an unlocated global",
                        gv.name, l.text
                    ))
                } else if let Some((n, _, _)) = externals.iter().find(|(_, e, _)| *e == gr) {
                    Some(format!(
                        "`{}` also uses the global `{}` as VAR_EXTERNAL `{n}`: one variable cannot be both",
                        sig.name, gv.name
                    ))
                } else if let Some((n, _)) = inouts.iter().find(|(_, e)| *e == gr) {
                    Some(format!(
                        "the global `{}` is already bound to the VAR_IN_OUT `{n}`",
                        gv.name
                    ))
                } else {
                    None
                };
                match problem {
                    Some(m) => {
                        cx.err(BAD_IN_OUT, g.span(), m);
                    }
                    None => inouts.push((member(index, &v.name), gr)),
                }
            }
            ParamKind::Input(Operand::Lit(l)) => {
                let init = ast::Initializer::Simple(Operand::Lit(l.clone()));
                if let Some(Init::Const(c)) = init_value(cx, &env.types, &init, &v.ty, v.range) {
                    out.inputs.push((member(index, &v.name), ProgArg::Const(c)));
                }
            }
            ParamKind::Input(Operand::Var(g)) if g.path.is_empty() => {
                match lookup(def, res, &g.base.name) {
                    Some((gr, gv)) if gv.ty == v.ty => out
                        .inputs
                        .push((member(index, &v.name), ProgArg::Global(gr))),
                    Some((_, gv)) => {
                        cx.err(
                            BAD_CONFIG,
                            g.span(),
                            format!("input `{}` is {}, the global is {}", v.name, v.ty, gv.ty),
                        );
                    }
                    None => unknown_global(cx, def, res, &g.base, "program argument"),
                }
            }
            ParamKind::Output {
                negate: false,
                target: Operand::Var(g),
            } if g.path.is_empty() => match lookup(def, res, &g.base.name) {
                Some((_, gv)) if gv.constant => {
                    cx.err(
                        NOT_WRITABLE,
                        g.span(),
                        format!("the global `{}` is CONSTANT", gv.name),
                    );
                }
                Some((gr, gv)) if gv.ty == v.ty => out.outputs.push((member(index, &v.name), gr)),
                Some((_, gv)) => {
                    cx.err(
                        BAD_CONFIG,
                        g.span(),
                        format!("output `{}` is {}, the global is {}", v.name, v.ty, gv.ty),
                    );
                }
                None => unknown_global(cx, def, res, &g.base, "program argument"),
            },
            _ => {
                cx.err(
                    BAD_CONFIG,
                    a.span,
                    "a program argument must be a literal or a global (`IN := g`, `OUT => g`)",
                );
            }
        }
    }
    // Every VAR_IN_OUT is bound, in declaration order (the order of `call`'s
    // reference parameters).
    for v in sig.vars.iter().filter(|v| v.kind == VarKind::InOut) {
        match inouts.iter().position(|(n, _)| *n.name == *v.name) {
            Some(i) => out.inouts.push(inouts.swap_remove(i)),
            // A refused binding has its own error already.
            None if !named.iter().any(|n| n.eq_ignore_ascii_case(&v.name)) => {
                let d = cx.err(
                    BAD_IN_OUT,
                    pi.span,
                    format!(
                        "program `{}` has the VAR_IN_OUT `{}` : {}, which instance `{}` does not bind",
                        sig.name, v.name, v.ty, pi.name
                    ),
                );
                d.help = Some(format!("add `{} := some_global` to its arguments", v.name));
            }
            None => {}
        }
    }
    out
}
