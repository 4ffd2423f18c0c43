//! Control flow: IL labels and jumps as structured Rust where possible.
//!
//! - No labels: straight-line code.
//! - Only forward jumps: each jumped-to label closes a labelled block that
//!   starts at the top of the body, so `JMP L` is `break 'L` from anywhere
//!   before `L` (blocks nest because they all start at the top).
//! - Any other pattern (backward jumps): a dispatcher loop over the code
//!   between labels, `__pc` holding the next block.

use super::Pou;
use crate::ast::PouKind;
use crate::sema::ir::{Op, PathElem, Stmt, Value};
use proc_macro2::{Ident, Punct, Spacing, Span, TokenStream};
use quote::{format_ident, quote};

/// Deeper nesting than this falls back to the dispatcher (rustc and
/// prettyplease recurse on nested blocks).
const MAX_NESTED_LABELS: usize = 128;

enum Mode {
    Straight,
    Blocks,
    Dispatch { block_of_label: Vec<usize> },
}

fn label_lifetime(l: usize) -> TokenStream {
    let mut t = TokenStream::new();
    t.extend([proc_macro2::TokenTree::Punct(Punct::new(
        '\'',
        Spacing::Joint,
    ))]);
    t.extend([proc_macro2::TokenTree::Ident(Ident::new(
        &format!("__l{l}"),
        Span::call_site(),
    ))]);
    t
}

impl Pou<'_> {
    pub(crate) fn body(&self) -> TokenStream {
        let mut stmts: &[Stmt] = &self.pou.body;
        // A RET at the very end is where the body ends anyway.
        if let Some(Stmt {
            op: Op::Return { cond: None },
            ..
        }) = stmts.last()
        {
            stmts = &stmts[..stmts.len() - 1];
        }
        let label_pos: Vec<Option<usize>> = {
            let mut v = vec![None; self.pou.label_count];
            for (i, s) in stmts.iter().enumerate() {
                if let Op::Label(l) = s.op {
                    v[l] = Some(i);
                }
            }
            v
        };
        let has_labels = label_pos.iter().any(Option::is_some);
        let targets = stmts.iter().filter_map(|s| {
            if let Op::Jump { label, .. } = s.op {
                Some(label)
            } else {
                None
            }
        });
        let forward_only = stmts.iter().enumerate().all(|(i, s)| match s.op {
            Op::Jump { label, .. } => label_pos[label].is_some_and(|p| p > i),
            _ => true,
        });
        let mode = if !has_labels {
            Mode::Straight
        } else if forward_only && targets.count() <= MAX_NESTED_LABELS {
            Mode::Blocks
        } else {
            let mut block_of_label = vec![0; self.pou.label_count];
            let mut b = 0;
            for s in stmts {
                if let Op::Label(l) = s.op {
                    b += 1;
                    block_of_label[l] = b;
                }
            }
            Mode::Dispatch { block_of_label }
        };
        match &mode {
            Mode::Straight => self.seq(stmts, &mode),
            Mode::Blocks => {
                let jumped: Vec<bool> = {
                    let mut v = vec![false; self.pou.label_count];
                    for s in stmts {
                        if let Op::Jump { label, .. } = s.op {
                            v[label] = true;
                        }
                    }
                    v
                };
                let mut segments = stmts.split(|s| matches!(s.op, Op::Label(_)));
                let mut acc = self.seq(segments.next().unwrap_or_default(), &mode);
                let labels = stmts.iter().filter_map(|s| {
                    if let Op::Label(l) = s.op {
                        Some(l)
                    } else {
                        None
                    }
                });
                for (l, seg) in labels.zip(segments) {
                    let seg = self.seq(seg, &mode);
                    acc = if jumped[l] {
                        let lt = label_lifetime(l);
                        quote!(#lt: { #acc } #seg)
                    } else {
                        quote!(#acc #seg)
                    };
                }
                acc
            }
            Mode::Dispatch { .. } => {
                let segments: Vec<&[Stmt]> =
                    stmts.split(|s| matches!(s.op, Op::Label(_))).collect();
                let last = segments.len() - 1;
                let arms = segments.iter().enumerate().map(|(k, seg)| {
                    let code = self.seq(seg, &mode);
                    let ends = matches!(
                        seg.last(),
                        Some(Stmt {
                            op: Op::Jump { cond: None, .. } | Op::Return { cond: None },
                            ..
                        })
                    );
                    let next = k + 1;
                    let tail = if ends {
                        quote!()
                    } else if k == last {
                        quote!(break '__dispatch;)
                    } else {
                        quote!(__pc = #next;)
                    };
                    quote!(#k => { #code #tail })
                });
                quote! {
                    let mut __pc: usize = 0;
                    '__dispatch: loop {
                        match __pc {
                            #(#arms)*
                            _ => break '__dispatch,
                        }
                    }
                }
            }
        }
    }

    fn seq(&self, stmts: &[Stmt], mode: &Mode) -> TokenStream {
        let mut out = TokenStream::new();
        let mut last_line = 0;
        for s in stmts {
            if self.opts.line_markers && s.line != last_line && s.line != 0 {
                let n = proc_macro2::Literal::u32_unsuffixed(s.line);
                out.extend(quote!(__il_line!(#n);));
                last_line = s.line;
            }
            out.extend(self.stmt(s, mode));
        }
        out
    }

    fn cond(
        &self,
        c: &Option<(crate::sema::ir::Value, bool)>,
        line: u32,
        body: TokenStream,
    ) -> TokenStream {
        match c {
            None => body,
            Some((v, true)) => {
                let v = self.value(v, line);
                quote!(if #v { #body })
            }
            Some((v, false)) => {
                let v = self.value(v, line);
                quote!(if !#v { #body })
            }
        }
    }

    fn stmt(&self, s: &Stmt, mode: &Mode) -> TokenStream {
        let line = s.line;
        match &s.op {
            Op::SetCr { ty, expr } => {
                let id = super::values::cr_ident(ty);
                let e = self.expr(expr, line);
                quote!(#id = #e;)
            }
            Op::Save { slot, value } => {
                let id = format_ident!("__save_{}", slot);
                let v = self.value(value, line);
                quote!(#id = #v;)
            }
            Op::Store {
                place,
                value,
                negate,
            } => {
                let v = self.value(value, line);
                let v = if *negate { quote!(!#v) } else { v };
                match (&place.range, place.ty.elem()) {
                    // A subrange store outside the bounds is skipped and recorded.
                    (Some((lo, hi)), Some(e)) => {
                        let ty = e.rust();
                        let (lo, hi) = (
                            crate::emit::values::constant(&crate::sema::ir::Const::Int(*lo, e)),
                            crate::emit::values::constant(&crate::sema::ir::Const::Int(*hi, e)),
                        );
                        let w = self.write(place, quote!(__r), line);
                        let fault = self.fault("SubrangeViolation", line);
                        quote!({ let __r: #ty = #v; if __r >= #lo && __r <= #hi { #w } else { #fault; } })
                    }
                    _ => self.write(place, v, line),
                }
            }
            Op::SetIf { place, value, cond } => {
                let c = self.value(cond, line);
                let w = self.write(
                    place,
                    if *value { quote!(true) } else { quote!(false) },
                    line,
                );
                quote!(if #c { #w })
            }
            Op::CallFb {
                inst,
                inputs,
                outputs,
                cond,
            } => {
                // An instance that is a plain path, with inputs that do not
                // read it: set the inputs in place, call, copy the outputs.
                if !inst.path.iter().any(|e| matches!(e, PathElem::Index { .. }))
                    && !inputs
                        .iter()
                        .any(|(_, v)| matches!(v, Value::Read(q) if q.root == inst.root))
                {
                    let path = self.simple_path(inst);
                    let sets = inputs.iter().map(|(n, v)| {
                        let f = super::rust_ident(n);
                        let v = self.value(v, line);
                        quote!(#path.#f = #v;)
                    });
                    let outs = outputs.iter().map(|(n, target, neg)| {
                        let f = super::rust_ident(n);
                        let v = quote!(#path.#f);
                        self.write(target, if *neg { quote!(!#v) } else { v }, line)
                    });
                    return self.cond(
                        cond,
                        line,
                        quote!({ #(#sets)* #path.call(__ctx); #(#outs)* }),
                    );
                }
                // Inputs are evaluated before the instance is borrowed.
                let ids: Vec<_> = (0..inputs.len())
                    .map(|k| format_ident!("__in{}", k))
                    .collect();
                let lets = inputs.iter().zip(&ids).map(|((_, v), id)| {
                    let v = self.value(v, line);
                    quote!(let #id = #v;)
                });
                let sets = inputs.iter().zip(&ids).map(|((n, _), id)| {
                    let f = super::rust_ident(n);
                    quote!(__fb.#f = #id;)
                });
                let call = self.with_fb(inst, quote!(#(#sets)* __fb.call(__ctx);), line);
                let outs = outputs.iter().map(|(n, target, neg)| {
                    let mut src = inst.clone();
                    src.path.push(crate::sema::ir::PathElem::Field(n.clone()));
                    let v = self.read(&src, line);
                    self.write(target, if *neg { quote!(!#v) } else { v }, line)
                });
                self.cond(cond, line, quote!({ #(#lets)* #call #(#outs)* }))
            }
            Op::Label(_) | Op::Nop => quote!(),
            Op::Jump { label, cond } => {
                let go = match mode {
                    Mode::Dispatch { block_of_label } => {
                        let b = block_of_label[*label];
                        quote!(__pc = #b; continue '__dispatch;)
                    }
                    _ => {
                        let lt = label_lifetime(*label);
                        quote!(break #lt;)
                    }
                };
                self.cond(cond, line, go)
            }
            Op::Return { cond } => {
                let r = if self.pou.kind == PouKind::Function {
                    quote!(return __ret;)
                } else {
                    quote!(return;)
                };
                self.cond(cond, line, r)
            }
        }
    }
}
