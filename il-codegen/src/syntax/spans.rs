//! Every span of a syntax tree, mutably: an item parsed again alone (see
//! `reparse`) is moved to its place in the file, and the items after an
//! edit by the edit's change of length. The structs are destructured whole,
//! so that a field added to the tree cannot be forgotten here.

use crate::ast::*;

/// Call `f` on every span of the node.
pub(crate) trait Spans {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span));
}

/// Move every span of `node` by `by` bytes.
pub(crate) fn shift<T: Spans + ?Sized>(node: &mut T, by: i64) {
    if by == 0 {
        return;
    }
    // Spans fit in u32 (sources over 4 GiB are refused) and a moved span
    // stays in the new text, so the sum is in range.
    let mv = |x: &mut u32| *x = (i64::from(*x) + by) as u32;
    node.spans(&mut |s: &mut Span| {
        mv(&mut s.lo);
        mv(&mut s.hi);
    });
}

impl<T: Spans> Spans for [T] {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        for x in self {
            x.spans(f);
        }
    }
}

impl<T: Spans> Spans for Vec<T> {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        self.as_mut_slice().spans(f);
    }
}

impl<T: Spans + ?Sized> Spans for Box<T> {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        (**self).spans(f);
    }
}

impl<T: Spans> Spans for Option<T> {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        if let Some(x) = self {
            x.spans(f);
        }
    }
}

impl Spans for Span {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        f(self);
    }
}

impl Spans for Ident {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        f(&mut self.span);
    }
}

impl Spans for Item {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            Item::Pou(p) => p.spans(f),
            Item::Types(t) => t.spans(f),
            Item::Configuration(c) => c.spans(f),
        }
    }
}

impl Spans for Pou {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let Pou {
            kind: _,
            name,
            return_type,
            var_blocks,
            body,
            begin_il: _,
            span,
            end_span,
            host,
        } = self;
        name.spans(f);
        return_type.spans(f);
        var_blocks.spans(f);
        body.spans(f);
        f(span);
        f(end_span);
        host.spans(f);
    }
}

impl Spans for Stmt {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            Stmt::Label(l) => l.spans(f),
            Stmt::Instr(i) => i.spans(f),
        }
    }
}

impl Spans for Instr {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let Instr {
            kind,
            op_span,
            span,
        } = self;
        kind.spans(f);
        f(op_span);
        f(span);
    }
}

impl Spans for InstrKind {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            InstrKind::Load { operand: o, .. }
            | InstrKind::Store { target: o, .. }
            | InstrKind::Set { target: o }
            | InstrKind::Reset { target: o }
            | InstrKind::Expr { operand: o, .. }
            | InstrKind::FbInput { instance: o, .. } => o.spans(f),
            InstrKind::Not | InstrKind::Return { .. } => {}
            InstrKind::Deferred {
                first,
                body,
                close_span,
                ..
            } => {
                first.spans(f);
                body.spans(f);
                f(close_span);
            }
            InstrKind::Jump { label, .. } => label.spans(f),
            InstrKind::Call { target, args, .. } => {
                target.spans(f);
                args.spans(f);
            }
            InstrKind::FnCall { name, args } => {
                name.spans(f);
                args.spans(f);
            }
        }
    }
}

impl Spans for CallArgs {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            CallArgs::Formal(p) => p.spans(f),
            CallArgs::NonFormal(o) => o.spans(f),
        }
    }
}

impl Spans for ParamAssign {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let ParamAssign { name, kind, span } = self;
        name.spans(f);
        match kind {
            ParamKind::Input(o) | ParamKind::Output { target: o, .. } => o.spans(f),
        }
        f(span);
    }
}

impl Spans for Operand {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            Operand::Lit(l) => l.spans(f),
            Operand::Var(v) => v.spans(f),
            Operand::Addr(a) => a.spans(f),
        }
    }
}

impl Spans for VarRef {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let VarRef { base, path } = self;
        base.spans(f);
        for a in path.iter_mut() {
            match a {
                Accessor::Field(id) => id.spans(f),
                Accessor::Index(subs, span) => {
                    subs.spans(f);
                    f(span);
                }
                Accessor::Part { span, .. } => f(span),
            }
        }
    }
}

impl Spans for Subscript {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            Subscript::Operand(o) => o.spans(f),
            Subscript::Neg { operand, span } => {
                operand.spans(f);
                f(span);
            }
            Subscript::Bin { lhs, rhs, span, .. } => {
                lhs.spans(f);
                rhs.spans(f);
                f(span);
            }
        }
    }
}

impl Spans for DirectAddress {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        f(&mut self.span);
    }
}

impl Spans for Literal {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let Literal {
            kind,
            type_prefix,
            span,
        } = self;
        if let LitKind::Enum(e) = kind {
            e.ty.spans(f);
            e.value.spans(f);
        }
        type_prefix.spans(f);
        f(span);
    }
}

impl Spans for VarBlock {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let VarBlock {
            kind: _,
            constant: _,
            retain: _,
            decls,
            span,
        } = self;
        decls.spans(f);
        f(span);
    }
}

impl Spans for VarDecl {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let VarDecl {
            names,
            location,
            ty,
            edge: _,
            init,
            span,
        } = self;
        names.spans(f);
        location.spans(f);
        ty.spans(f);
        init.spans(f);
        f(span);
    }
}

impl Spans for TypeSpec {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            TypeSpec::Named(id) => id.spans(f),
            TypeSpec::String { len, span, .. } => {
                len.spans(f);
                f(span);
            }
            TypeSpec::Array { dims, elem, span } => {
                dims.spans(f);
                elem.spans(f);
                f(span);
            }
            TypeSpec::Subrange { base, range, span } => {
                base.spans(f);
                range.spans(f);
                f(span);
            }
            TypeSpec::Enum { values, span } => {
                for v in values.iter_mut() {
                    v.name.spans(f);
                    v.value.spans(f);
                }
                f(span);
            }
            TypeSpec::Struct { fields, span } => {
                fields.spans(f);
                f(span);
            }
        }
    }
}

impl Spans for Subrange {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let Subrange { lo, hi, span } = self;
        lo.spans(f);
        hi.spans(f);
        f(span);
    }
}

impl Spans for ConstExpr {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            ConstExpr::Lit(l) => l.spans(f),
            ConstExpr::Name(n) => n.spans(f),
        }
    }
}

impl Spans for Initializer {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        match self {
            Initializer::Simple(o) => o.spans(f),
            Initializer::Array { elems, span } => {
                for (lit, init) in elems.iter_mut() {
                    lit.spans(f);
                    init.spans(f);
                }
                f(span);
            }
            Initializer::Struct { fields, span } => {
                for (name, init) in fields.iter_mut() {
                    name.spans(f);
                    init.spans(f);
                }
                f(span);
            }
        }
    }
}

impl Spans for TypeDecl {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let TypeDecl {
            name,
            spec,
            init,
            span,
        } = self;
        name.spans(f);
        spec.spans(f);
        init.spans(f);
        f(span);
    }
}

impl Spans for Configuration {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let Configuration {
            name,
            globals,
            resources,
            var_config,
            var_access,
            span,
        } = self;
        name.spans(f);
        globals.spans(f);
        resources.spans(f);
        var_config.spans(f);
        var_access.spans(f);
        f(span);
    }
}

impl Spans for Resource {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let Resource {
            name,
            on,
            globals,
            tasks,
            programs,
            span,
        } = self;
        name.spans(f);
        on.spans(f);
        globals.spans(f);
        tasks.spans(f);
        programs.spans(f);
        f(span);
    }
}

impl Spans for Task {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let Task {
            name,
            single,
            interval,
            priority,
            span,
        } = self;
        name.spans(f);
        single.spans(f);
        interval.spans(f);
        priority.spans(f);
        f(span);
    }
}

impl Spans for ProgramInstance {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let ProgramInstance {
            name,
            retain: _,
            task,
            program,
            args,
            span,
        } = self;
        name.spans(f);
        task.spans(f);
        program.spans(f);
        args.spans(f);
        f(span);
    }
}

impl Spans for ConfigVar {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let ConfigVar {
            path,
            location,
            ty,
            init,
            span,
        } = self;
        path.spans(f);
        location.spans(f);
        ty.spans(f);
        init.spans(f);
        f(span);
    }
}

impl Spans for AccessVar {
    fn spans(&mut self, f: &mut dyn FnMut(&mut Span)) {
        let AccessVar {
            name,
            path,
            ty,
            writable: _,
            span,
        } = self;
        name.spans(f);
        path.spans(f);
        ty.spans(f);
        f(span);
    }
}
