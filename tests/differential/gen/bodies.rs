//! POU bodies: random instructions, expressions, jumps and calls of the
//! right types, tracking the type of the current result.

use super::*;

impl Pou<'_> {
    pub(super) fn emit(&mut self, s: impl Into<String>) {
        self.lines.push(format!("    {}", s.into()));
    }
    pub(super) fn label(&mut self, l: &str) {
        self.lines.push(format!("{l}:"));
    }
    pub(super) fn vars_of(&self, t: T) -> Vec<String> {
        self.vars
            .iter()
            .filter(|v| v.ty == t)
            .map(|v| v.name.clone())
            .collect()
    }
    pub(super) fn writable(&self, t: T) -> Vec<String> {
        self.vars_of(t)
            .into_iter()
            .filter(|n| !self.readonly.contains(n))
            .collect()
    }

    /// An operand of type `t` (variable, array element or literal).
    pub(super) fn operand(&mut self, t: T, nonzero_lit: bool) -> String {
        let vars = self.vars_of(t);
        let arrays: Vec<_> = self.arrays.iter().filter(|a| a.1 == t).cloned().collect();
        if !arrays.is_empty() && self.rng.chance(15) {
            let (a, _, lo, hi) = self.rng.pick(&arrays).clone();
            let sub = self.subscript(lo, hi);
            return format!("{a}[{sub}]");
        }
        if !vars.is_empty() && self.rng.chance(65) {
            return self.rng.pick(&vars).clone();
        }
        self.literal(t, nonzero_lit)
    }

    /// A subscript of a dimension `lo..hi`: a literal inside it, an INT
    /// variable (any value: out of range is a recorded fault), or an
    /// expression over them with `+ - * / MOD`, parentheses and unary minus
    /// (a divisor variable may be 0: a recorded fault). An expression of
    /// literals only is kept inside the bounds (outside, it does not compile).
    pub(super) fn subscript(&mut self, lo: i64, hi: i64) -> String {
        let n = hi - lo + 1;
        let k = lo + self.rng.below(n as usize) as i64;
        let idx = self.vars_of(T::Int);
        if idx.is_empty() || self.rng.chance(25) {
            if self.rng.chance(30) {
                // Folded by the checker: `(k + 3) MOD n + lo` style, in range.
                let c = 1 + self.rng.below(5) as i64;
                self.mark("subscript expression");
                self.mark("subscript with MOD or division");
                return format!("({k} - {lo} + {c} * {n}) MOD {n} + {lo}");
            }
            return k.to_string();
        }
        let v = self.rng.pick(&idx).clone();
        let w = self.rng.pick(&idx).clone();
        if self.rng.chance(35) {
            return v;
        }
        self.mark("subscript expression");
        let e = match self.rng.below(7) {
            0 => format!("{v} MOD {n} + {lo}"),
            1 => format!("{v} / {} - {k}", 1 + self.rng.below(3)),
            2 => format!("{v} MOD {w}"),
            3 => format!("({v} + 1) * 2 / {w}"),
            4 => format!("-{v} + {k}"),
            5 => format!("-({v} - {w}) MOD {n}"),
            _ => format!("{v} - {w} * 2 + {k}"),
        };
        if e.contains("MOD") || e.contains('/') {
            self.mark("subscript with MOD or division");
        }
        e
    }

    pub(super) fn literal(&mut self, t: T, nonzero: bool) -> String {
        match t {
            T::Bool => if self.rng.chance(50) { "TRUE" } else { "FALSE" }.into(),
            T::Real | T::Lreal => {
                let v = *self.rng.pick(&[1.5, 0.25, 2.0, 3.0E2, 0.1, 7.0, 1.0E-3]);
                if self.rng.chance(30) {
                    format!("{}#-{v:?}", t.name())
                } else {
                    format!("{v:?}")
                }
            }
            T::Time => format!("T#{}ms", self.rng.pick(&[1, 5, 10, 20, 50, 1500])),
            _ => {
                let mut v = int_lit(self.rng, t);
                if nonzero && v == 0 {
                    v = 3;
                }
                if t.is_bits() && self.rng.chance(50) {
                    format!("16#{v:X}")
                } else if v < 0 || self.rng.chance(20) {
                    format!("{}#{v}", t.name())
                } else {
                    format!("{v}")
                }
            }
        }
    }

    /// Operators applicable to a CR of type `t` that keep its type.
    pub(super) fn same_type_op(&mut self, t: T, depth: usize) {
        let mut choices: Vec<&str> = Vec::new();
        if t == T::Bool || t.is_bits() {
            choices.extend(["AND", "OR", "XOR", "ANDN", "ORN", "XORN", "&", "&N", "NOT"]);
        }
        if t.is_num() {
            choices.extend(["ADD", "SUB", "MUL", "DIV"]);
        }
        if t.is_int() {
            choices.push("MOD");
        }
        if t == T::Time {
            choices.extend(["ADD", "SUB", "MULK", "DIVK"]);
        }
        let op = *self.rng.pick(&choices);
        if t == T::Time {
            self.mark("TIME arithmetic");
        }
        if matches!(op, "DIV" | "MOD") {
            self.mark("DIV/MOD");
        }
        match op {
            "NOT" => self.emit("NOT"),
            "MULK" | "DIVK" => {
                let reals: Vec<String> = [T::Real, T::Lreal]
                    .iter()
                    .flat_map(|t| self.vars_of(*t))
                    .collect();
                let k = if !reals.is_empty() && self.rng.chance(30) {
                    // TIME scaled by a real (truncated to whole ns)
                    self.rng.pick(&reals).clone()
                } else if self.rng.chance(50) && !self.vars_of(T::Dint).is_empty() {
                    let v = self.vars_of(T::Dint);
                    self.rng.pick(&v).clone()
                } else {
                    format!("{}", 1 + self.rng.below(4))
                };
                self.emit(format!("{} {k}", &op[..3]));
            }
            _ => {
                let divisor = matches!(op, "DIV" | "MOD");
                if matches!(op, "ADD" | "MUL" | "AND" | "OR" | "XOR") && self.rng.chance(10) {
                    // extensible function with an operand list: CR op a op b
                    let (a, b) = (self.operand(t, false), self.operand(t, false));
                    self.emit(format!("{op} {a}, {b}"));
                    self.mark("operand list (ADD a, b)");
                    return;
                }
                if depth < 3 && op != "&N" && op != "&" && self.rng.chance(18) {
                    self.paren(op, t, t, depth);
                } else {
                    let o = self.operand(t, divisor);
                    self.emit(format!("{op} {o}"));
                }
            }
        }
    }

    /// A variable of type `t`, or a typed literal: something whose load fixes the CR type.
    pub(super) fn typed_operand(&mut self, t: T) -> String {
        let vars = self.vars_of(t);
        if !vars.is_empty() && self.rng.chance(80) {
            return self.rng.pick(&vars).clone();
        }
        let l = self.literal(t, false);
        if t.is_int() || t.is_bits() || t.is_real() {
            let prefix = format!("{}#", t.name());
            format!("{prefix}{}", l.trim_start_matches(&prefix))
        } else {
            l
        }
    }

    /// `op(` ... `)` whose inner expression has type `inner`.
    pub(super) fn paren(&mut self, op: &str, inner: T, _outer: T, depth: usize) {
        self.mark("deferred parentheses");
        if self.open_parens > 0 {
            self.mark("nested parentheses");
        }
        self.open_parens += 1;
        let o = self.typed_operand(inner);
        if self.rng.chance(50) {
            self.emit(format!("{op}( {o}"));
        } else {
            self.emit(format!("{op}("));
            self.emit(format!("LD {o}"));
        }
        for _ in 0..self.rng.below(3) {
            self.same_type_op(inner, depth + 1);
        }
        self.emit(")");
        self.open_parens -= 1;
    }

    pub(super) fn store(&mut self, t: T) {
        let w = self.writable(t);
        if w.is_empty() {
            return;
        }
        let v = self.rng.pick(&w).clone();
        let arrays: Vec<_> = self.arrays.iter().filter(|a| a.1 == t).cloned().collect();
        if !arrays.is_empty() && self.rng.chance(15) {
            let (a, _, lo, hi) = self.rng.pick(&arrays).clone();
            let sub = self.subscript(lo, hi);
            self.emit(format!("ST {a}[{sub}]"));
            return;
        }
        if (t == T::Bool || t.is_bits()) && self.rng.chance(25) {
            self.emit(format!("STN {v}"));
        } else {
            self.emit(format!("ST {v}"));
        }
    }

    /// An expression starting with a load; returns the CR type at its end.
    pub(super) fn expr(&mut self, types: &[T]) -> T {
        let mut t = *self.rng.pick(types);
        // A load of a variable: an untyped literal would take its type from
        // what follows, and literal-only expressions are folded by the checker.
        let vars = self.vars_of(t);
        let o = self.rng.pick(&vars).clone();
        if (t == T::Bool || t.is_bits()) && self.rng.chance(20) {
            self.emit(format!("LDN {o}"));
        } else {
            self.emit(format!("LD {o}"));
        }
        for _ in 0..1 + self.rng.below(4) {
            match self.rng.below(10) {
                0 if t == T::Time => {
                    let to = *self.rng.pick(&[T::Dint, T::Lint, T::Lreal]);
                    self.emit(format!("TIME_TO_{}", to.name()));
                    self.mark("TIME conversion");
                    t = to;
                }
                0 if t != T::Bool => {
                    // conversion (to TIME from the signed integers too)
                    let mut to = *self.rng.pick(&[NUMERIC, BITS, &[T::Bool]].concat());
                    if matches!(t, T::Int | T::Dint | T::Lint) && self.rng.chance(15) {
                        to = T::Time;
                        self.mark("TIME conversion");
                    }
                    if to != t && (t.is_num() || t.is_bits()) {
                        self.emit(format!("{}_TO_{}", t.name(), to.name()));
                        self.mark("conversion");
                        if t.is_real() && to.is_int() {
                            self.mark("REAL to integer conversion");
                        }
                        t = to;
                    }
                }
                1 => t = self.std_fn(t),
                2 if t != T::Bool => {
                    // comparison, then BOOL
                    let op = *self.rng.pick(&["GT", "GE", "EQ", "NE", "LE", "LT"]);
                    if t == T::Time {
                        self.mark("TIME comparison");
                    }
                    if self.rng.chance(20) {
                        self.mark("comparison in parentheses");
                        self.paren(op, t, T::Bool, 1);
                    } else {
                        let o = self.operand(t, false);
                        self.emit(format!("{op} {o}"));
                    }
                    t = T::Bool;
                }
                3 if Some(t) == self.fn2 && !self.in_function && self.rng.chance(40) => {
                    if !self.fn2_call(t) {
                        self.same_type_op(t, 0);
                    }
                }
                3 if Some(t) == self.has_fn && !self.in_function => {
                    // Array elements, member paths and the process image as
                    // arguments too (compiler-bugs/fn_arg_array_element.il is
                    // fixed: arguments go into locals before the call).
                    let o = self.operand(t, false);
                    let f = self.operand(T::Bool, false);
                    if self.rng.chance(35) {
                        // formal call with EN (and ENO when Fn1 sets it)
                        let b = self.operand(t, false);
                        let en = self.operand(T::Bool, false);
                        self.emit("Fn1(");
                        self.emit(format!("    EN := {en},"));
                        self.emit(format!("    a := {o},"));
                        self.emit(format!("    b := {b},"));
                        let eno = self.writable(T::Bool);
                        if self.fn_eno && !eno.is_empty() {
                            self.emit(format!("    flag := {f},"));
                            let e = self.rng.pick(&eno).clone();
                            let not = if self.rng.chance(30) { "NOT " } else { "" };
                            self.emit(format!("    {not}ENO => {e}"));
                        } else {
                            self.emit(format!("    flag := {f}"));
                        }
                        self.emit(")");
                        self.mark("FUNCTION, formal with EN/ENO");
                    } else {
                        self.emit(format!("Fn1 {o}, {f}"));
                        self.mark("FUNCTION, operator form");
                    }
                }
                _ => self.same_type_op(t, 0),
            }
        }
        t
    }

    /// A standard function on a CR of type `t`; returns the new CR type.
    pub(super) fn std_fn(&mut self, t: T) -> T {
        if t.is_real() && self.rng.chance(70) {
            match self.rng.below(5) {
                0 => {
                    // an integer or a real exponent
                    let e = if self.rng.chance(50) {
                        format!("{}", self.rng.below(4))
                    } else {
                        self.operand(t, false)
                    };
                    self.emit(format!("EXPT {e}"));
                    self.mark("EXPT");
                }
                1 => {
                    self.emit("SQRT");
                    self.mark("SQRT");
                }
                2 => {
                    let f = *self
                        .rng
                        .pick(&["SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN"]);
                    self.emit(f);
                    self.mark("SIN/COS/TAN/ASIN/ACOS/ATAN");
                }
                3 => {
                    let f = *self.rng.pick(&["LN", "LOG", "EXP"]);
                    self.emit(f);
                    self.mark("LN/LOG/EXP");
                }
                _ => {
                    self.emit("TRUNC");
                    self.mark("TRUNC");
                    return T::Dint;
                }
            }
            return t;
        }
        if t.is_num() || t == T::Time {
            match self.rng.below(4) {
                0 => {
                    let (a, b) = (self.literal(t, false), self.literal(t, false));
                    self.emit(format!("LIMIT {a}, {b}"));
                    self.mark("LIMIT/MAX/MIN");
                }
                1 => {
                    let o = self.operand(t, false);
                    self.emit(format!("MAX {o}"));
                    self.mark("LIMIT/MAX/MIN");
                }
                2 => {
                    let o = self.operand(t, false);
                    self.emit(format!("MIN {o}"));
                    self.mark("LIMIT/MAX/MIN");
                }
                _ if t.is_signed() || t.is_real() => self.emit("ABS"),
                _ => self.emit("MOVE"),
            }
        } else if t.is_bits() {
            let op = *self.rng.pick(&["SHL", "SHR", "ROL", "ROR"]);
            let n = self.rng.below(70);
            self.emit(format!("{op} {n}"));
            self.mark("shift/rotate");
        } else if t == T::Bool {
            let o = self.operand(T::Bool, false);
            self.emit(format!("XOR {o}"));
        }
        t
    }

    pub(super) fn finish_expr(&mut self, t: T) {
        self.store(t);
        if t == T::Bool && self.rng.chance(30) {
            let w = self.writable(T::Bool);
            if !w.is_empty() {
                let v = self.rng.pick(&w).clone();
                let sr = if self.rng.chance(50) { "S" } else { "R" };
                self.emit(format!("{sr} {v}"));
                self.mark("S/R");
            }
        }
    }

    pub(super) fn bool_cond(&mut self) {
        let b = self.vars_of(T::Bool);
        let v = self.rng.pick(&b).clone();
        self.emit(format!("LD {v}"));
        if self.rng.chance(40) {
            let o = self.operand(T::Bool, false);
            let op = *self.rng.pick(&["AND", "OR", "XOR"]);
            self.emit(format!("{op} {o}"));
        }
    }

    pub(super) fn block(&mut self, types: &[T], depth: usize) {
        match self.rng.below(12) {
            0 if depth < 2 => {
                // forward jump over a block; sometimes with the CR carried.
                let l = format!("L{}", self.labels);
                self.labels += 1;
                self.bool_cond();
                let j = *self.rng.pick(&["JMPC", "JMPCN", "JMPNC"]);
                self.emit(format!("{j} {l}"));
                self.mark("forward jump");
                if self.rng.chance(50) {
                    self.block(types, depth + 1);
                    self.label(&l);
                } else {
                    self.mark("forward jump carrying the CR");
                    // CR (BOOL) carried to the label from both paths.
                    let o = self.operand(T::Bool, false);
                    self.emit(format!("LD {o}"));
                    self.label(&l);
                    self.finish_expr(T::Bool);
                }
            }
            1 if depth < 2 && !self.in_function && self.loops < self.max_loops => {
                // bounded backward loop
                let k = self.loops;
                self.loops += 1;
                let c = format!("cnt{k}");
                self.readonly.push(c.clone());
                let n = 1 + self.rng.below(4);
                self.emit("LD 0");
                self.emit(format!("ST {c}"));
                self.label(&format!("Loop{k}"));
                self.block(types, depth + 1);
                self.emit(format!("LD {c}"));
                self.emit("ADD 1");
                self.emit(format!("ST {c}"));
                self.emit(format!("LT {n}"));
                self.emit(format!("JMPC Loop{k}"));
                self.mark("backward loop");
            }
            2 | 3 if !self.fbs.is_empty() => self.fb_call(),
            4 => {
                // SEL / MUX select among operands of one type
                let t = *self.rng.pick(types);
                if self.rng.chance(50) {
                    self.bool_cond();
                    // The first operand typed: literals alone would make the result DINT/LREAL.
                    let (a, b) = (self.typed_operand(t), self.operand(t, false));
                    self.emit(format!("SEL {a}, {b}"));
                    self.mark("SEL");
                } else {
                    let ints: Vec<String> = self
                        .vars
                        .iter()
                        .filter(|v| v.ty.is_int())
                        .map(|v| v.name.clone())
                        .collect();
                    if ints.is_empty() {
                        return;
                    }
                    let k = self.rng.pick(&ints).clone();
                    self.emit(format!("LD {k}"));
                    let n = 2 + self.rng.below(3);
                    let mut ops: Vec<String> = (0..n).map(|_| self.operand(t, false)).collect();
                    ops[0] = self.typed_operand(t);
                    self.emit(format!("MUX {}", ops.join(", ")));
                    self.mark("MUX");
                }
                self.finish_expr(t);
            }
            5 if depth < 2 && self.rng.chance(50) => {
                // unconditional forward jump over a block (unreachable code)
                let l = format!("L{}", self.labels);
                self.labels += 1;
                self.emit(format!("JMP {l}"));
                self.mark("unconditional JMP");
                self.block(types, depth + 1);
                self.label(&l);
            }
            7 if !self.enums.is_empty() && self.rng.chance(60) => self.enum_block(),
            7 if self.rng.chance(50) => self.dialect_block(types),
            8 if self.strings && self.rng.chance(80) => self.string_block(),
            9 if self.dates && self.rng.chance(70) => self.date_block(),
            6 if depth == 0 && !self.in_function && self.rng.chance(15) => {
                self.bool_cond();
                let r = *self.rng.pick(&["RETC", "RETCN", "RETNC"]);
                self.emit(r);
                self.mark("RETC/RETCN in a PROGRAM");
            }
            _ => {
                let t = self.expr(types);
                self.finish_expr(t);
            }
        }
    }
}
