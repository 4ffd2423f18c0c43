//! A generator of random, well-typed IL programs for differential testing
//! (interpreter vs generated Rust). Deterministic: a seed gives one program.
//!
//! Every program has a user FUNCTION `Fn1`, a user FUNCTION_BLOCK `Blk` and a
//! PROGRAM `Main` whose VAR_INPUTs are driven with random values each scan.
//! Bodies cover every expression operator with and without `N`, `NOT`,
//! deferred parentheses (short and long form, nested), conversions, standard
//! functions, forward jumps with the CR carried to the label, bounded backward
//! loops, RETC, S/R, the standard blocks (timers with time advancing,
//! counters, edges, bistables) by CAL with formal lists and by input
//! operators, arrays with variable (possibly out-of-range) subscripts, and
//! integer DIV/MOD by (runtime) zero.
//!
//! Also (calls.rs, text.rs): a second FUNCTION `Fn2` with VAR_IN_OUT and
//! VAR_OUTPUT called formally (with `=>`) and non-formally, every FB call
//! form (formal with outputs, non-formal list, members then CAL, input
//! operators, CALC/CALCN), RET, STRING functions and comparisons, DATE/TOD/DT
//! functions, TIME conversions and REAL math. Each program lists the
//! constructs it used (`Program::kinds`, `coverage::CONSTRUCTS`).

#![allow(dead_code)]

mod bodies;
mod calls;
pub mod config;
pub mod coverage;
mod dialect;
mod text;
mod user;

/// xorshift64*.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    pub fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    pub fn chance(&mut self, percent: u64) -> bool {
        self.next() % 100 < percent
    }
    pub fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[self.below(xs.len())]
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum T {
    Bool,
    Sint,
    Int,
    Dint,
    Lint,
    Usint,
    Uint,
    Udint,
    Ulint,
    Byte,
    Word,
    Dword,
    Lword,
    Real,
    Lreal,
    Time,
}

pub const NUMERIC: &[T] = &[
    T::Sint,
    T::Int,
    T::Dint,
    T::Lint,
    T::Usint,
    T::Uint,
    T::Udint,
    T::Ulint,
    T::Real,
    T::Lreal,
];
pub const BITS: &[T] = &[T::Byte, T::Word, T::Dword, T::Lword];

impl T {
    pub fn name(self) -> &'static str {
        match self {
            T::Bool => "BOOL",
            T::Sint => "SINT",
            T::Int => "INT",
            T::Dint => "DINT",
            T::Lint => "LINT",
            T::Usint => "USINT",
            T::Uint => "UINT",
            T::Udint => "UDINT",
            T::Ulint => "ULINT",
            T::Byte => "BYTE",
            T::Word => "WORD",
            T::Dword => "DWORD",
            T::Lword => "LWORD",
            T::Real => "REAL",
            T::Lreal => "LREAL",
            T::Time => "TIME",
        }
    }
    pub fn rust(self) -> &'static str {
        match self {
            T::Bool => "bool",
            T::Sint => "i8",
            T::Int => "i16",
            T::Dint => "i32",
            T::Lint => "i64",
            T::Usint | T::Byte => "u8",
            T::Uint | T::Word => "u16",
            T::Udint | T::Dword => "u32",
            T::Ulint | T::Lword => "u64",
            T::Real => "f32",
            T::Lreal => "f64",
            T::Time => "il_std::TIME",
        }
    }
    pub fn is_int(self) -> bool {
        matches!(
            self,
            T::Sint | T::Int | T::Dint | T::Lint | T::Usint | T::Uint | T::Udint | T::Ulint
        )
    }
    pub fn is_signed(self) -> bool {
        matches!(self, T::Sint | T::Int | T::Dint | T::Lint)
    }
    pub fn is_bits(self) -> bool {
        matches!(self, T::Byte | T::Word | T::Dword | T::Lword)
    }
    pub fn is_real(self) -> bool {
        matches!(self, T::Real | T::Lreal)
    }
    pub fn is_num(self) -> bool {
        self.is_int() || self.is_real()
    }
    pub fn range(self) -> (i128, i128) {
        match self {
            T::Bool => (0, 1),
            T::Sint => (i8::MIN as i128, i8::MAX as i128),
            T::Int => (i16::MIN as i128, i16::MAX as i128),
            T::Dint => (i32::MIN as i128, i32::MAX as i128),
            T::Lint => (i64::MIN as i128, i64::MAX as i128),
            T::Usint | T::Byte => (0, u8::MAX as i128),
            T::Uint | T::Word => (0, u16::MAX as i128),
            T::Udint | T::Dword => (0, u32::MAX as i128),
            _ => (0, u64::MAX as i128),
        }
    }
}

/// A value to drive an input with.
#[derive(Clone, Debug, PartialEq)]
pub enum Lit {
    Bool(bool),
    Int(i128),
    Real(f64),
    /// Nanoseconds.
    Time(i64),
}

#[derive(Clone, Debug)]
pub struct Var {
    pub name: String,
    pub ty: T,
}

pub struct Program {
    pub il: String,
    /// Inputs of `Main`, with the value of each scan.
    pub inputs: Vec<Var>,
    pub scans: Vec<Vec<Lit>>,
    /// Time advanced after each scan (ns).
    pub step_ns: i64,
    /// The user-type and process-image features it uses (coverage summary).
    pub kinds: Vec<&'static str>,
}

struct Pou<'r> {
    rng: &'r mut Rng,
    lines: Vec<String>,
    vars: Vec<Var>,
    /// Variables not to store into (loop counters, inputs of functions...).
    readonly: Vec<String>,
    labels: usize,
    loops: usize,
    /// Standard blocks and user blocks available: (instance, type).
    fbs: Vec<(String, &'static str)>,
    /// Arrays `ARRAY[0..1]` of standard blocks: (array, block type).
    fb_arrays: Vec<(String, &'static str)>,
    has_fn: Option<T>,
    arrays: Vec<(String, T, i64, i64)>,
    in_function: bool,
    max_loops: usize,
    /// Fn1 stores ENO, so a call may read it with `ENO =>`.
    fn_eno: bool,
    /// Places of the enumeration `Col` (user.rs).
    enums: Vec<String>,
    /// `Fn2` (VAR_IN_OUT, VAR_OUTPUT) exists, of this type (calls.rs).
    fn2: Option<T>,
    /// The string and date variables of text.rs exist.
    strings: bool,
    dates: bool,
    /// Constructs used (coverage.rs).
    kinds: Vec<&'static str>,
    /// Deferred parentheses open where the next instruction goes.
    open_parens: usize,
}

impl<'r> Pou<'r> {
    fn new(rng: &'r mut Rng, vars: Vec<Var>, readonly: &[&str]) -> Pou<'r> {
        Pou {
            rng,
            lines: Vec::new(),
            vars,
            readonly: readonly.iter().map(|s| s.to_string()).collect(),
            labels: 0,
            loops: 0,
            fbs: Vec::new(),
            fb_arrays: Vec::new(),
            has_fn: None,
            arrays: Vec::new(),
            in_function: false,
            max_loops: 0,
            fn_eno: false,
            enums: Vec::new(),
            fn2: None,
            strings: false,
            dates: false,
            kinds: Vec::new(),
            open_parens: 0,
        }
    }
    pub(super) fn mark(&mut self, k: &'static str) {
        if !self.kinds.contains(&k) {
            self.kinds.push(k);
        }
    }
}

fn int_lit(rng: &mut Rng, t: T) -> i128 {
    let (lo, hi) = t.range();
    match rng.below(6) {
        0 => lo,
        1 => hi,
        2 => 0,
        3 => 1.min(hi),
        4 if t.is_signed() => -1,
        _ => {
            let span = (hi - lo) as u128;
            lo + (rng.next() as u128 % (span + 1)) as i128
        }
    }
}

pub fn random_lit(rng: &mut Rng, t: T) -> Lit {
    match t {
        T::Bool => Lit::Bool(rng.chance(50)),
        T::Real | T::Lreal => {
            Lit::Real(*rng.pick(&[0.0, 1.0, -1.5, 0.1, 1e9, -3.25e-3, 123.456, 7.0, -0.0]))
        }
        T::Time => Lit::Time(*rng.pick(&[0, 5, 10, 25, 100, 1500]) * 1_000_000),
        _ => Lit::Int(int_lit(rng, t)),
    }
}

fn decls(vars: &[Var]) -> String {
    vars.iter()
        .map(|v| format!("    {} : {};\n", v.name, v.ty.name()))
        .collect()
}

/// Generate program number `seed`.
pub fn generate(seed: u64) -> Program {
    let mut rng = Rng::new(seed);
    // The configuration draws from a stream of its own, so the rest of a
    // seed's program is the same with and without it.
    let mut crng = Rng::new(seed ^ 0xC0F1_6000_0000_0001);
    let with_config = crng.chance(25);
    let mut types = vec![T::Bool];
    for _ in 0..1 + rng.below(3) {
        let t = *rng.pick(&[NUMERIC, BITS].concat());
        if !types.contains(&t) {
            types.push(t);
        }
    }
    let with_time = rng.chance(50);
    if with_time {
        types.push(T::Time);
    }
    if !types.contains(&T::Int) && rng.chance(50) {
        types.push(T::Int);
    }
    if types.contains(&T::Time) && !types.contains(&T::Dint) && rng.chance(50) {
        types.push(T::Dint);
    }
    let ft = *rng.pick(
        &types[1..]
            .iter()
            .copied()
            .filter(|t| *t != T::Time)
            .collect::<Vec<_>>()
            .into_iter()
            .chain([T::Int])
            .collect::<Vec<_>>(),
    );
    let mut il = String::new();
    let mut kinds: Vec<&'static str> = Vec::new();

    let fn_eno = rng.chance(50);
    // FUNCTION Fn1 : ft
    {
        let vars = vec![
            Var {
                name: "a".into(),
                ty: ft,
            },
            Var {
                name: "b".into(),
                ty: ft,
            },
            Var {
                name: "flag".into(),
                ty: T::Bool,
            },
        ];
        let mut p = Pou::new(&mut rng, vars.clone(), &["a", "b", "flag"]);
        p.in_function = true;
        p.vars.push(Var {
            name: "tmp".into(),
            ty: ft,
        });
        p.vars.push(Var {
            name: "tb".into(),
            ty: T::Bool,
        });
        if fn_eno {
            p.emit("LD flag");
            p.emit("ST ENO");
        }
        for _ in 0..1 + p.rng.below(3) {
            p.block(&[ft, T::Bool], 1);
        }
        let first = if p.rng.chance(50) { "a" } else { "tmp" };
        p.emit(format!("LD {first}"));
        p.same_type_op(ft, 0);
        p.emit("ST Fn1");
        if p.rng.chance(30) {
            p.emit("LD flag");
            p.emit("RETC");
            p.emit("LD tmp");
            p.emit("ST Fn1");
            p.mark("RETC in a FUNCTION");
        }
        kinds.extend(p.kinds.iter().copied());
        il.push_str(&format!(
            "FUNCTION Fn1 : {}\nVAR_INPUT\n{}END_VAR\nVAR\n    tmp : {};\n    tb : BOOL;\nEND_VAR\n{}\nEND_FUNCTION\n\n",
            ft.name(),
            decls(&vars),
            ft.name(),
            p.lines.join("\n")
        ));
    }

    // FUNCTION Fn2 : ft, with VAR_IN_OUT and VAR_OUTPUT (calls.rs)
    let with_fn2 = rng.chance(50);
    if with_fn2 {
        let (text, k) = calls::fn2(&mut rng, ft);
        il.push_str(&text);
        kinds.extend(k);
    }

    // FUNCTION_BLOCK Blk
    {
        let ins = vec![
            Var {
                name: "x".into(),
                ty: ft,
            },
            Var {
                name: "en".into(),
                ty: T::Bool,
            },
        ];
        let outs = vec![
            Var {
                name: "y".into(),
                ty: ft,
            },
            Var {
                name: "q".into(),
                ty: T::Bool,
            },
        ];
        let locals = vec![
            Var {
                name: "acc".into(),
                ty: ft,
            },
            Var {
                name: "m".into(),
                ty: T::Bool,
            },
            Var {
                name: "cnt0".into(),
                ty: T::Int,
            },
            Var {
                name: "cnt1".into(),
                ty: T::Int,
            },
        ];
        let mut p = Pou::new(
            &mut rng,
            [ins.clone(), outs.clone(), locals.clone()].concat(),
            &["x", "en"],
        );
        p.fbs = vec![("rt".into(), "R_TRIG")];
        p.has_fn = Some(ft);
        p.max_loops = 2;
        p.fn_eno = fn_eno;
        p.fn2 = with_fn2.then_some(ft);
        for _ in 0..1 + p.rng.below(4) {
            p.block(&[ft, T::Bool], 0);
        }
        if p.rng.chance(30) {
            p.ret_block(&[ft, T::Bool]);
        }
        kinds.extend(p.kinds.iter().copied());
        il.push_str(&format!(
            "FUNCTION_BLOCK Blk\nVAR_INPUT\n{}END_VAR\nVAR_OUTPUT\n{}END_VAR\nVAR\n{}    rt : R_TRIG;\nEND_VAR\n{}\nEND_FUNCTION_BLOCK\n\n",
            decls(&ins),
            decls(&outs),
            decls(&locals),
            p.lines.join("\n")
        ));
    }

    // PROGRAM Main
    let mut inputs = Vec::new();
    let mut locals = Vec::new();
    for &t in &types {
        for k in 0..2 {
            inputs.push(Var {
                name: format!("i{}_{k}", t.name().to_lowercase()),
                ty: t,
            });
            locals.push(Var {
                name: format!("v{}_{k}", t.name().to_lowercase()),
                ty: t,
            });
        }
    }
    let n_loops = 4;
    for k in 0..n_loops {
        locals.push(Var {
            name: format!("cnt{k}"),
            ty: T::Int,
        });
    }
    let arr_t = types[rng.below(types.len())];
    let arrays = vec![("arr".to_string(), arr_t, 0i64, 3i64)];
    let mut fbs: Vec<(String, &'static str)> = vec![
        ("r1".into(), "R_TRIG"),
        ("f1".into(), "F_TRIG"),
        ("s1".into(), "SR"),
        ("b1".into(), "Blk"),
    ];
    if types.contains(&T::Int) {
        fbs.push(("c1".into(), "CTU"));
        fbs.push(("c2".into(), "CTD"));
        fbs.push(("c3".into(), "CTUD"));
    }
    fbs.push(("rs1".into(), "RS"));
    fbs.push(("t1".into(), "TON"));
    fbs.push(("t2".into(), "TOF"));
    fbs.push(("t3".into(), "TP"));
    // Elements of arrays of blocks: input operators and CAL on `ca[i MOD 2]`.
    let mut fb_arrays: Vec<(String, &'static str)> = vec![
        ("sra".into(), "SR"),
        ("rsa".into(), "RS"),
        ("ea".into(), "R_TRIG"),
        ("ta".into(), "TON"),
    ];
    if types.contains(&T::Int) {
        fb_arrays.push(("ca".into(), "CTU"));
        fb_arrays.push(("da".into(), "CTD"));
        fb_arrays.push(("cda".into(), "CTUD"));
    }
    let extras = user::extras(&mut rng, &types);
    let with_strings = rng.chance(50);
    let with_dates = rng.chance(40);
    let text_decls = text::decls(with_strings, with_dates);
    let body = {
        let mut readonly: Vec<String> = inputs.iter().map(|v| v.name.clone()).collect();
        readonly.extend(extras.readonly.iter().cloned());
        let ro: Vec<&str> = readonly.iter().map(String::as_str).collect();
        let mut p = Pou::new(
            &mut rng,
            [
                inputs.clone(),
                locals.clone(),
                extras.vars.clone(),
                text::vars(with_strings, with_dates),
            ]
            .concat(),
            &ro,
        );
        p.fbs = fbs.clone();
        p.fb_arrays = fb_arrays.clone();
        p.has_fn = Some(ft);
        p.arrays = arrays.clone();
        p.max_loops = n_loops;
        p.fn_eno = fn_eno;
        p.enums = extras.enums.clone();
        p.fn2 = with_fn2.then_some(ft);
        p.strings = with_strings;
        p.dates = with_dates;
        let n = 3 + p.rng.below(8);
        for _ in 0..n {
            p.block(&types, 0);
        }
        // The string and date variables get a block or two of their own.
        if p.strings {
            for _ in 0..1 + p.rng.below(2) {
                p.string_block();
            }
        }
        if p.dates {
            p.date_block();
        }
        if p.rng.chance(30) {
            p.bool_cond();
            p.emit("RETC");
            p.mark("RETC/RETCN in a PROGRAM");
            p.block(&types, 2);
        }
        kinds.extend(p.kinds.iter().copied());
        p.lines.join("\n")
    };
    let fb_decls: String = fbs
        .iter()
        .map(|(n, t)| format!("    {n} : {t};\n"))
        .chain(
            fb_arrays
                .iter()
                .map(|(n, t)| format!("    {n} : ARRAY[0..1] OF {t};\n")),
        )
        .collect();
    // With a configuration, the second local of each type is a VAR_OUTPUT
    // it can bind to a global.
    let (outputs, locals): (Vec<Var>, Vec<Var>) = locals
        .into_iter()
        .partition(|v| with_config && v.name.starts_with('v') && v.name.ends_with("_1"));
    let output_decls = if outputs.is_empty() {
        String::new()
    } else {
        format!("VAR_OUTPUT\n{}END_VAR\n", decls(&outputs))
    };
    il.push_str(&format!(
        "PROGRAM Main\nVAR_INPUT\n{}END_VAR\n{output_decls}VAR\n{}    arr : ARRAY[0..3] OF {};\n{}{}END_VAR\n{}\nEND_PROGRAM\n",
        decls(&inputs),
        decls(&locals),
        arr_t.name(),
        fb_decls,
        extras.decls + &text_decls,
        body
    ));
    let mut il = format!("{}{il}", extras.types);
    if with_config {
        let mut paths: Vec<Var> = locals
            .iter()
            .chain(&outputs)
            .filter(|v| v.name.starts_with('v'))
            .cloned()
            .collect();
        for k in 0..4 {
            paths.push(Var {
                name: format!("arr[{k}]"),
                ty: arr_t,
            });
        }
        paths.push(Var {
            name: "b1.y".into(),
            ty: ft,
        });
        paths.push(Var {
            name: "b1.acc".into(),
            ty: ft,
        });
        paths.push(Var {
            name: "t1.Q".into(),
            ty: T::Bool,
        });
        paths.push(Var {
            name: "t2.ET".into(),
            ty: T::Time,
        });
        if types.contains(&T::Int) {
            paths.push(Var {
                name: "c1.CV".into(),
                ty: T::Int,
            });
        }
        // Members and elements with constant subscripts (not the subrange
        // members, whose type is `Sub`).
        paths.extend(
            extras
                .vars
                .iter()
                .filter(|v| v.name.contains(['.', '[']) && !v.name.contains("cnt"))
                .filter(|v| !v.name.ends_with(".s") && !v.name.starts_with('%'))
                .cloned(),
        );
        let shape = config::Shape {
            inputs: inputs.clone(),
            outputs: outputs.clone(),
            paths,
        };
        let (text, k) = config::configuration(&mut crng, &shape);
        il.push_str(&text);
        kinds.extend(k);
    }
    // Located inputs are driven like the VAR_INPUTs (through the image).
    inputs.extend(extras.inputs.iter().cloned());

    let n_scans = 4 + rng.below(4);
    let mut scans = Vec::new();
    for _ in 0..n_scans {
        scans.push(inputs.iter().map(|v| random_lit(&mut rng, v.ty)).collect());
    }
    Program {
        il,
        inputs,
        scans,
        step_ns: *rng.pick(&[1_000_000i64, 5_000_000, 10_000_000]),
        kinds: {
            kinds.extend(extras.kinds);
            kinds.sort();
            kinds.dedup();
            kinds
        },
    }
}
