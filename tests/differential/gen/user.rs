//! User types and the process image in generated programs: an enumeration
//! (with explicit values and a default), a subrange, a STRUCT with initial
//! values (one field of each), arrays of structures and a two-dimensional
//! array, located variables in all three areas and direct addresses as
//! operands. They become extra operands of `Main` (member and element paths,
//! constant and variable subscripts) that the typed body generator uses like
//! any variable, plus an enumeration block (`enum_block`).

use super::*;

/// What `Main` gains: declarations and operands.
pub struct Extras {
    /// The TYPE ... END_TYPE block (empty without user types).
    pub types: String,
    /// Declarations inside Main's VAR block.
    pub decls: String,
    /// Operands by type: paths, located variables, direct addresses.
    pub vars: Vec<Var>,
    /// Those of `vars` that may not be stored to (inputs of the image).
    pub readonly: Vec<String>,
    /// Located inputs, driven every scan like VAR_INPUTs.
    pub inputs: Vec<Var>,
    /// Places of the enumeration `Col`, to load and store.
    pub enums: Vec<String>,
    /// Which parts were generated, for the coverage summary.
    pub kinds: Vec<&'static str>,
}

/// The address size letter and byte width of a located type.
fn size_of(t: T) -> Option<(&'static str, usize)> {
    Some(match t {
        T::Bool => ("X", 0),
        T::Sint | T::Usint | T::Byte => ("B", 1),
        T::Int | T::Uint | T::Word => ("W", 2),
        T::Dint | T::Udint | T::Dword | T::Real => ("D", 4),
        T::Lint | T::Ulint | T::Lword | T::Lreal => ("L", 8),
        T::Time => return None,
    })
}

/// An address of `t` in slot `slot` (8 bytes each, so none overlap): `%IW4`.
fn address(area: char, t: T, slot: usize, bit: usize) -> String {
    let (letter, width) = size_of(t).unwrap_or(("X", 0));
    let byte = slot * 8;
    match byte.checked_div(width) {
        None => format!("%{area}X{byte}.{bit}"),
        Some(n) => format!("%{area}{letter}{n}"),
    }
}

pub fn extras(rng: &mut Rng, types: &[T]) -> Extras {
    let mut x = Extras {
        types: String::new(),
        decls: String::new(),
        vars: Vec::new(),
        readonly: Vec::new(),
        inputs: Vec::new(),
        enums: Vec::new(),
        kinds: Vec::new(),
    };
    let var = |name: String, ty: T| Var { name, ty };
    if rng.chance(65) {
        // TYPEs: the record's field `a` has one of the program's types.
        let ft = *rng.pick(types);
        let (lo, hi) = *rng.pick(&[(-10i64, 10i64), (3, 9), (0, 100), (-20, -2)]);
        let a_init = if rng.chance(50) {
            format!(" := {}", lit_text(&random_lit(rng, ft), ft))
        } else {
            String::new()
        };
        let default = *rng.pick(&["Red", "Green", "Blue"]);
        x.types = format!(
            "TYPE\n    Col : (Red, Green := 5, Blue) := {default};\n    Sub : INT ({lo}..{hi});\n    \
             Rec : STRUCT\n        a : {}{a_init};\n        b : BOOL := TRUE;\n        c : Col := Blue;\n        \
             s : Sub;\n    END_STRUCT;\nEND_TYPE\n\n",
            ft.name()
        );
        let gt = *rng.pick(types);
        x.decls.push_str(&format!(
            "    col : Col;\n    col2 : Col := Red;\n    sub : Sub;\n    rec : Rec;\n    \
             recs : ARRAY[0..2] OF Rec;\n    grid : ARRAY[1..2, 0..1] OF {};\n",
            gt.name()
        ));
        x.kinds
            .extend(["enum", "subrange", "struct", "array of struct", "2-d array"]);
        x.vars.push(var("sub".into(), T::Int));
        x.vars.push(var("rec.a".into(), ft));
        x.vars.push(var("rec.b".into(), T::Bool));
        x.vars.push(var("rec.s".into(), T::Int));
        let k = rng.below(3);
        x.vars.push(var(format!("recs[{k}].a"), ft));
        x.vars
            .push(var(format!("recs[{}].b", rng.below(3)), T::Bool));
        // Variable subscripts: loop counters run to 4, past the bounds.
        let c = rng.below(4);
        x.vars.push(var(format!("recs[cnt{c}].a"), ft));
        x.vars.push(var(format!("recs[cnt{c}].s"), T::Int));
        x.vars.push(var(
            format!("grid[{}, {}]", 1 + rng.below(2), rng.below(2)),
            gt,
        ));
        x.vars
            .push(var(format!("grid[2, cnt{}]", rng.below(4)), gt));
        x.enums.extend([
            "col".to_string(),
            "col2".into(),
            "rec.c".into(),
            format!("recs[{}].c", rng.below(3)),
            format!("recs[cnt{}].c", rng.below(4)),
        ]);
    }
    let located: Vec<T> = types
        .iter()
        .copied()
        .filter(|t| size_of(*t).is_some())
        .collect();
    if !located.is_empty() && rng.chance(65) {
        x.kinds.push("located variables");
        // Slot k of each area: the k-th located variable of that area.
        for (k, &t) in located.iter().enumerate().take(3) {
            let bit = rng.below(8);
            let (i, q, m) = (format!("li{k}"), format!("lq{k}"), format!("lm{k}"));
            x.decls.push_str(&format!(
                "    {i} AT {} : {};\n    {q} AT {} : {};\n    {m} AT {} : {};\n",
                address('I', t, k, bit),
                t.name(),
                address('Q', t, k, bit),
                t.name(),
                address('M', t, k, bit),
                t.name()
            ));
            x.inputs.push(var(i.clone(), t));
            x.vars.push(var(i.clone(), t));
            x.readonly.push(i);
            x.vars.push(var(q, t));
            x.vars.push(var(m, t));
        }
        // Direct addresses as operands, of the type of their size; slots
        // 3.. are free of located variables.
        let direct: &[(T, char)] = &[
            (T::Bool, 'I'),
            (T::Bool, 'Q'),
            (T::Byte, 'M'),
            (T::Word, 'Q'),
            (T::Dword, 'M'),
            (T::Lword, 'Q'),
        ];
        for (n, &(t, area)) in direct.iter().enumerate() {
            if t != T::Bool && !types.contains(&t) {
                continue;
            }
            let a = address(area, t, 3 + n, rng.below(8));
            if area == 'I' {
                x.readonly.push(a.clone());
            }
            x.vars.push(var(a, t));
            x.kinds.push("direct addresses");
        }
    }
    x.kinds.dedup();
    x
}

/// An IL literal for a value of type `t`.
fn lit_text(l: &Lit, t: T) -> String {
    match l {
        Lit::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Lit::Int(v) => format!("{}#{v}", t.name()),
        Lit::Real(f) => format!("{}#{f:?}", t.name()),
        Lit::Time(ns) => format!("T#{}ms", ns / 1_000_000),
    }
}

impl Pou<'_> {
    /// Enumeration values: compared (EQ/NE) or stored.
    pub(super) fn enum_block(&mut self) {
        let places = self.enums.clone();
        if places.is_empty() {
            return;
        }
        let operand = |s: &mut Self| {
            if s.rng.chance(40) {
                format!("Col#{}", s.rng.pick(&["Red", "Green", "Blue"]))
            } else {
                s.rng.pick(&places).clone()
            }
        };
        let first = self.rng.pick(&places).clone();
        self.emit(format!("LD {first}"));
        if self.rng.chance(50) {
            let op = *self.rng.pick(&["EQ", "NE"]);
            let o = operand(self);
            self.emit(format!("{op} {o}"));
            self.finish_expr(T::Bool);
        } else {
            let to = self.rng.pick(&places).clone();
            self.emit(format!("ST {to}"));
        }
    }
}
