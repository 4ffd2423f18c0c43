//! Calls: the second user FUNCTION `Fn2` (VAR_IN_OUT and VAR_OUTPUT) and its
//! formal and non-formal calls, RET in user POUs, and every form of FB call
//! (formal lists with and without `=>` outputs, non-formal lists, members
//! stored then `CAL`, input operators, CALC/CALCN) on the standard blocks
//! and the user block `Blk`.

use super::*;

/// `FUNCTION Fn2 : ft` with inputs `a`, `c`, in-out `io`, outputs `o`, `ob`;
/// the text and the constructs it used.
pub(super) fn fn2(rng: &mut Rng, ft: T) -> (String, Vec<&'static str>) {
    let var = |n: &str, ty: T| Var { name: n.into(), ty };
    let vars = vec![
        var("a", ft),
        var("c", T::Bool),
        var("io", ft),
        var("o", ft),
        var("ob", T::Bool),
        var("tmp", ft),
        var("tb", T::Bool),
    ];
    let mut p = Pou::new(rng, vars, &["a", "c"]);
    p.in_function = true;
    for _ in 0..p.rng.below(3) {
        p.block(&[ft, T::Bool], 1);
    }
    // The outputs may be read before they are written (they start at the
    // type's default on every call), and the in-out is read and written.
    p.emit("LD io");
    p.same_type_op(ft, 0);
    p.emit("ST io");
    let first = *p.rng.pick(&["a", "o", "tmp"]);
    p.emit(format!("LD {first}"));
    p.same_type_op(ft, 0);
    p.emit("ST o");
    if p.rng.chance(60) {
        p.bool_cond();
        p.emit("ST ob");
    }
    let first = *p.rng.pick(&["a", "io", "o", "tmp"]);
    p.emit(format!("LD {first}"));
    p.same_type_op(ft, 0);
    p.emit("ST Fn2");
    if p.rng.chance(40) {
        p.ret_block(&[ft, T::Bool]);
    }
    let text = format!(
        "FUNCTION Fn2 : {t}\nVAR_INPUT\n    a : {t};\n    c : BOOL;\nEND_VAR\nVAR_IN_OUT\n    io : {t};\nEND_VAR\n\
         VAR_OUTPUT\n    o : {t};\n    ob : BOOL;\nEND_VAR\nVAR\n    tmp : {t};\n    tb : BOOL;\nEND_VAR\n{}\nEND_FUNCTION\n\n",
        p.lines.join("\n"),
        t = ft.name()
    );
    (text, p.kinds)
}

impl Pou<'_> {
    /// A conditional RET: `JMPC L / <block> / RET / L: <block>` (the label is
    /// reached by the jump only, with a BOOL CR).
    pub(super) fn ret_block(&mut self, types: &[T]) {
        let l = format!("L{}", self.labels);
        self.labels += 1;
        self.bool_cond();
        let j = *self.rng.pick(&["JMPC", "JMPCN"]);
        self.emit(format!("{j} {l}"));
        self.block(types, 2);
        self.emit("RET");
        self.label(&l);
        self.block(types, 2);
        self.mark(if self.in_function {
            "RET in a FUNCTION"
        } else {
            "RET in a FUNCTION_BLOCK"
        });
    }

    /// A call of `Fn2` with the CR (type `t`) as `a`, formal or not.
    /// Returns false when there is no variable to pass as the in-out.
    pub(super) fn fn2_call(&mut self, t: T) -> bool {
        let io: Vec<String> = self.writable(t);
        if io.is_empty() {
            return false;
        }
        let io = self.rng.pick(&io).clone();
        if self.rng.chance(60) {
            let mut params = Vec::new();
            let a = self.operand(t, false);
            params.push(format!("a := {a}"));
            if self.rng.chance(70) {
                let c = self.operand(T::Bool, false);
                params.push(format!("c := {c}"));
            }
            params.push(format!("io := {io}"));
            let outs = self.writable(t);
            if self.rng.chance(60) {
                let o = self.rng.pick(&outs).clone();
                params.push(format!("o => {o}"));
            }
            let bools = self.writable(T::Bool);
            if !bools.is_empty() && self.rng.chance(50) {
                let b = self.rng.pick(&bools).clone();
                let not = if self.rng.chance(30) { "NOT " } else { "" };
                params.push(format!("{not}ob => {b}"));
            }
            self.emit("Fn2(");
            let n = params.len();
            for (k, q) in params.into_iter().enumerate() {
                let comma = if k + 1 < n { "," } else { "" };
                self.emit(format!("    {q}{comma}"));
            }
            self.emit(")");
            self.mark("FUNCTION, VAR_IN_OUT + VAR_OUTPUT formal (=>)");
        } else {
            let c = self.operand(T::Bool, false);
            self.emit(format!("Fn2 {c}, {io}"));
            self.mark("FUNCTION, VAR_IN_OUT non-formal");
        }
        true
    }

    /// A time operand for PT: mostly a literal, sometimes a TIME variable
    /// (which may hold a negative duration).
    fn pt(&mut self) -> String {
        if !self.vars_of(T::Time).is_empty() && self.rng.chance(20) {
            self.operand(T::Time, false)
        } else {
            self.literal(T::Time, false)
        }
    }

    /// Set the inputs `ins` (name, value) of `inst` by one of the call forms:
    /// formal list (with `outs` as `=>` outputs sometimes), non-formal list,
    /// members stored then CAL, or (when `ops`) the input operators.
    fn call_form(&mut self, inst: &str, ins: &[(&str, String)], outs: &[(&str, T)], ops: bool) {
        let formal: Vec<String> = ins.iter().map(|(n, v)| format!("{n} := {v}")).collect();
        match self.rng.below(if ops { 5 } else { 4 }) {
            0 | 1 => {
                let mut list = formal;
                if self.rng.chance(50) {
                    for (n, t) in outs {
                        let w = self.writable(*t);
                        if !w.is_empty() && self.rng.chance(70) {
                            let v = self.rng.pick(&w).clone();
                            list.push(format!("{n} => {v}"));
                            self.mark("FB: CAL formal with outputs (=>)");
                        }
                    }
                }
                self.emit(format!("CAL {inst}({})", list.join(", ")));
                self.mark("FB: CAL formal list");
            }
            2 => {
                let vals: Vec<&str> = ins.iter().map(|(_, v)| v.as_str()).collect();
                self.emit(format!("CAL {inst}({})", vals.join(", ")));
                self.mark("FB: CAL non-formal list");
            }
            3 => {
                for (n, v) in ins {
                    self.emit(format!("LD {v}"));
                    self.emit(format!("ST {inst}.{n}"));
                }
                self.emit(format!("CAL {inst}"));
                self.mark("FB: members stored, then CAL");
            }
            _ => {
                // Each input operator sets that input and calls the block.
                for (n, v) in ins {
                    self.emit(format!("LD {v}"));
                    self.emit(format!("{n} {inst}"));
                }
                self.mark("FB: input operators");
                if inst.contains('[') {
                    self.mark("FB: input operators on an array element");
                }
            }
        }
    }

    pub(super) fn fb_call(&mut self) {
        let (inst, ty) = if !self.fb_arrays.is_empty() && self.rng.chance(25) {
            let (a, ty) = self.rng.pick(&self.fb_arrays).clone();
            let sub = self.subscript(0, 1);
            self.mark("FB array element");
            (format!("{a}[{sub}]"), ty)
        } else {
            let k = self.rng.below(self.fbs.len());
            self.fbs[k].clone()
        };
        let b = self.vars_of(T::Bool);
        let bv = |s: &mut Self| s.rng.pick(&b).clone();
        let pv = |s: &mut Self| format!("{}", 1 + s.rng.below(5));
        let out_bool = |s: &mut Self, o: &str| {
            s.emit(format!("LD {inst}.{o}"));
            s.store(T::Bool);
        };
        match ty {
            "TON" | "TOF" | "TP" => {
                self.mark(ty);
                let (x, pt) = (bv(self), self.pt());
                let ins = [("IN", x), ("PT", pt)];
                self.call_form(&inst, &ins, &[("Q", T::Bool), ("ET", T::Time)], true);
                out_bool(self, "Q");
                if !self.writable(T::Time).is_empty() {
                    self.emit(format!("LD {inst}.ET"));
                    self.store(T::Time);
                }
            }
            "CTU" | "CTD" => {
                self.mark(ty);
                let (c, r) = if ty == "CTU" {
                    ("CU", "R")
                } else {
                    ("CD", "LD")
                };
                let mut ins = vec![(c, bv(self))];
                if self.rng.chance(70) {
                    ins.insert(0, (r, bv(self)));
                }
                if self.rng.chance(70) {
                    ins.insert(0, ("PV", pv(self)));
                }
                let ins: Vec<(&str, String)> = if self.rng.chance(50) {
                    // the standard's order: CU/CD, R/LD, PV
                    ins.into_iter().rev().collect()
                } else {
                    ins
                };
                // A non-formal list must give every input in order.
                let full = ins.len() == 3 && ins[0].0 == c;
                let ops = true;
                if full {
                    self.call_form(&inst, &ins, &[("Q", T::Bool), ("CV", T::Int)], ops);
                } else {
                    self.call_partial(&inst, &ins, ops);
                }
                out_bool(self, "Q");
                self.emit(format!("LD {inst}.CV"));
                self.store(T::Int);
            }
            "CTUD" => {
                self.mark(ty);
                let ins = [
                    ("CU", bv(self)),
                    ("CD", bv(self)),
                    ("R", bv(self)),
                    ("LD", bv(self)),
                    ("PV", pv(self)),
                ];
                let outs = [("QU", T::Bool), ("QD", T::Bool), ("CV", T::Int)];
                self.call_form(&inst, &ins, &outs, true);
                out_bool(self, "QU");
                out_bool(self, "QD");
                self.emit(format!("LD {inst}.CV"));
                self.store(T::Int);
            }
            "R_TRIG" | "F_TRIG" => {
                self.mark(ty);
                let ins = [("CLK", bv(self))];
                self.call_form(&inst, &ins, &[("Q", T::Bool)], true);
                out_bool(self, "Q");
            }
            "RS" | "SR" => {
                self.mark(ty);
                let ins = if ty == "SR" {
                    [("S1", bv(self)), ("R", bv(self))]
                } else {
                    [("S", bv(self)), ("R1", bv(self))]
                };
                self.call_form(&inst, &ins, &[("Q1", T::Bool)], true);
                out_bool(self, "Q1");
            }
            _ => {
                // user block Blk(x : T, en : BOOL) => (y : T, q : BOOL)
                let t = self.has_fn.unwrap_or(T::Int);
                let (x, en) = (self.operand(t, false), bv(self));
                if self.rng.chance(20) {
                    self.bool_cond();
                    let c = *self.rng.pick(&["CALC", "CALCN", "CALNC"]);
                    self.emit(format!("{c} {inst}(x := {x}, en := {en})"));
                    self.mark("FB: CALC/CALCN");
                } else {
                    let ins = [("x", x), ("en", en)];
                    self.call_form(&inst, &ins, &[("y", t), ("q", T::Bool)], false);
                }
                self.emit(format!("LD {inst}.y"));
                self.store(t);
                out_bool(self, "q");
            }
        }
    }

    /// Some inputs only: formal list, members then CAL, or input operators.
    fn call_partial(&mut self, inst: &str, ins: &[(&str, String)], ops: bool) {
        if ops && self.rng.chance(50) {
            for (n, v) in ins {
                self.emit(format!("LD {v}"));
                self.emit(format!("{n} {inst}"));
            }
            self.mark("FB: input operators");
            if inst.contains('[') {
                self.mark("FB: input operators on an array element");
            }
        } else if self.rng.chance(50) {
            let l: Vec<String> = ins.iter().map(|(n, v)| format!("{n} := {v}")).collect();
            self.emit(format!("CAL {inst}({})", l.join(", ")));
            self.mark("FB: CAL formal list");
        } else {
            for (n, v) in ins {
                self.emit(format!("LD {v}"));
                self.emit(format!("ST {inst}.{n}"));
            }
            self.emit(format!("CAL {inst}"));
            self.mark("FB: members stored, then CAL");
        }
    }
}
