//! Differential testing: random well-typed IL programs (tests/differential/gen/)
//! run under the reference interpreter and as generated Rust, compared variable
//! by variable after every scan (plus the fault count and the last fault).
//!
//! Values are compared by their canonical text: integers, TIME and dates by
//! their inner integer, strings byte by byte (hex), REAL/LREAL by Rust's
//! shortest round-trip text (`{:?}`), which is NaN-aware equality: exact for
//! every non-NaN value (`-0.0` and `0.0` differ, so do any two bit patterns
//! that are not NaN) and any NaN equal to any NaN (sign and payload of a NaN
//! are not compared: IEEE 754 leaves them open, and LLVM may fold them).
//!
//! Each run prints a coverage table (generated constructs, `gen/coverage.rs`,
//! and how many programs used each) and fails at 500 programs or more when
//! one of them was used by none.
//!
//! All programs of a run are compiled into ONE temporary crate (one build).
//! CI: a fixed seed and 500 programs. The long run:
//!
//! ```sh
//! IL_DIFF_COUNT=10000 IL_DIFF_SEED=7 cargo test -p il-tests --test all differential -- --nocapture
//! ```
//!
//! (`IL_DIFF_BATCH` programs per crate build, default 500.)
//!
//! A mismatch is shrunk by line deletion (each round builds all candidates in
//! one crate) and written to `tests/differential/regressions/seed_N.il` with its
//! inputs in `seed_N.scans`; `regressions_agree` runs every file kept there.
//! `tests/differential/compiler-bugs/` holds reproducers of compiler bugs the
//! generator found (and now avoids).

#[path = "../../differential/gen/mod.rs"]
mod generator;

use generator::{Lit, Program, T};
use il_codegen::diag::SourceFile;
use il_codegen::sema::ir::Loc;
use il_codegen::sema::types::Elem;
use il_interp::{Machine, Value, load};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

mod config;
use config::{CfgCase, config_case, config_driver, interpret_config};

fn env_num(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn elem(t: T) -> Elem {
    Elem::from_name(t.name()).expect("elementary type")
}

fn lit_value(t: T, l: &Lit) -> Value {
    match (t, l) {
        (_, Lit::Bool(b)) => Value::Bool(*b),
        (_, Lit::Int(v)) => Value::Int(*v, elem(t)),
        (T::Real, Lit::Real(f)) => Value::Real(*f as f32),
        (_, Lit::Real(f)) => Value::LReal(*f),
        (_, Lit::Time(ns)) => Value::Time(*ns, Elem::TIME),
    }
}

fn lit_rust(t: T, l: &Lit) -> String {
    match (t, l) {
        (_, Lit::Bool(b)) => b.to_string(),
        (_, Lit::Int(v)) => format!("({v}i128) as {}", t.rust()),
        (T::Real, Lit::Real(f)) => format!("f32::from_bits({:#x})", (*f as f32).to_bits()),
        (_, Lit::Real(f)) => format!("f64::from_bits({:#x})", f.to_bits()),
        (_, Lit::Time(ns)) => format!("il_std::TIME({ns}i64)"),
    }
}

/// The canonical text of a value (the driver's `Canon` prints the same).
fn canon(v: &Value) -> String {
    match v {
        Value::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Value::Int(x, _) => x.to_string(),
        Value::Real(f) => format!("{f:?}"),
        Value::LReal(f) => format!("{f:?}"),
        Value::Time(ns, _) => ns.to_string(),
        // Hex units: strings may hold line breaks, and the lines are the protocol.
        Value::Str { units, .. } => units.iter().map(|u| format!("{u:02x}")).collect(),
        Value::Array(items) => items.iter().map(canon).collect::<Vec<_>>().join(","),
        Value::Enum { value, .. } => value.clone(),
        Value::Struct(s) => {
            let fields: Vec<String> = s.fields.iter().map(|(_, v)| canon(v)).collect();
            format!("({})", fields.join(";"))
        }
        other => other.display(),
    }
}

fn fault_text(ctx: &il_std::Cycle) -> String {
    format!(
        "faults={} last={:?} io={}",
        ctx.fault_count(),
        ctx.last_fault().map(|f| (f.kind, f.line)),
        io_text(ctx)
    )
}

/// The outputs and memory the generated programs use (the driver's `io`
/// prints the same): located variables and direct addresses, byte by byte.
fn io_text(ctx: &il_std::Cycle) -> String {
    let mut s = String::new();
    for a in [il_std::Area::Output, il_std::Area::Memory] {
        for b in 0..IO_BYTES {
            let _ = write!(s, "{:02x}", ctx.io.byte(a, b));
        }
    }
    s
}

/// Bytes of each area that generated programs use (user.rs: slots of 8 bytes).
const IO_BYTES: usize = 72;

/// The variables compared: every variable of Main but its FB instances.
fn watched(m: &Machine) -> Vec<String> {
    m.vars()
        .into_iter()
        .filter(|(_, v)| !matches!(v, Value::Fb(_) | Value::StdFb(_)))
        .map(|(n, _)| n)
        .collect()
}

/// Interpret: one line per scan.
fn interpret(prog: &il_codegen::sema::ir::Program, p: &Program) -> Result<Vec<String>, String> {
    let mut m = Machine::new(prog, "Main")?;
    let names = watched(&m);
    let mut ctx = il_std::Cycle::new();
    let mut lines = Vec::new();
    let places = p
        .inputs
        .iter()
        .map(|v| m.lookup(&v.name))
        .collect::<Result<Vec<_>, _>>()?;
    for (k, scan) in p.scans.iter().enumerate() {
        for ((v, l), place) in p.inputs.iter().zip(scan).zip(&places) {
            m.set_at(&mut ctx, place, lit_value(v.ty, l))?;
        }
        m.scan(&mut ctx)?;
        let mut line = format!("{k} {}", fault_text(&ctx));
        for n in &names {
            let _ = write!(
                line,
                " {n}={}",
                canon(&m.get(n).unwrap_or(Value::Bool(false)))
            );
        }
        lines.push(line);
        ctx.advance(il_std::TIME(p.step_ns));
    }
    if let Some(c) = config_case(prog) {
        lines.extend(interpret_config(prog, &c)?);
    }
    Ok(lines)
}

/// How the driver sets an input: a field of `Main`, or the process image
/// where the checker placed the located variable.
fn set_input(v: &generator::Var, l: &Lit, loc: Option<&Loc>) -> String {
    let val = lit_rust(v.ty, l);
    let Some(loc) = loc else {
        return format!("m.{} = {val};", v.name);
    };
    let area = format!("il_std::Area::{:?}", loc.area);
    let b = loc.byte;
    if let Some(bit) = loc.bit {
        return format!("ctx.io.set_bit({area}, {b}, {bit}, {val});");
    }
    let (set, conv) = match loc.elem {
        Elem::REAL => ("set_dword", ".to_bits()"),
        Elem::LREAL => ("set_lword", ".to_bits()"),
        Elem::BYTE | Elem::SINT | Elem::USINT => ("set_byte", " as u8"),
        Elem::WORD | Elem::INT | Elem::UINT => ("set_word", " as u16"),
        Elem::DWORD | Elem::DINT | Elem::UDINT => ("set_dword", " as u32"),
        _ => ("set_lword", " as u64"),
    };
    format!("ctx.io.{set}({area}, {b}, ({val}){conv});")
}

/// `Canon` for the program's user types (the interpreter's `canon` prints the same).
fn canon_impls(prog: &il_codegen::sema::ir::Program) -> String {
    use il_codegen::sema::ir::TypeDef;
    let mut s = String::new();
    for t in &prog.types {
        match t {
            TypeDef::Enum { name, .. } => {
                let _ = writeln!(
                    s,
                    "impl crate::Canon for {name} {{ fn canon(&self) -> String {{ format!(\"{{self:?}}\") }} }}"
                );
            }
            TypeDef::Struct { name, fields } => {
                let parts: Vec<String> = fields
                    .iter()
                    .map(|f| format!("crate::Canon::canon(&self.{})", f.name))
                    .collect();
                let _ = writeln!(
                    s,
                    "impl crate::Canon for {name} {{ fn canon(&self) -> String {{ format!(\"({{}})\", [{}].join(\";\")) }} }}",
                    parts.join(", ")
                );
            }
        }
    }
    s
}

/// The Rust driver of one program: a module with the generated code and `run`.
fn driver(
    i: usize,
    names: &[String],
    p: &Program,
    locs: &[Option<Loc>],
    config: Option<&CfgCase>,
) -> String {
    let mut s = String::new();
    // The watched variables once, not once per scan: the generated crate is
    // a third smaller, and its build is most of this test's time.
    let _ = writeln!(
        s,
        "fn vars(m: &Main) -> Vec<(&'static str, String)> {{ vec!["
    );
    for n in names {
        let _ = writeln!(s, "(\"{n}\", crate::Canon::canon(&m.{n})),");
    }
    let _ = writeln!(s, "] }}");
    let _ = writeln!(s, "pub fn run(out: &mut String) {{");
    let _ = writeln!(s, "    let mut ctx = il_std::Cycle::new();");
    let _ = writeln!(s, "    let mut m = Main::default();");
    for (k, scan) in p.scans.iter().enumerate() {
        for ((v, l), loc) in p.inputs.iter().zip(scan).zip(locs) {
            let _ = writeln!(s, "    {}", set_input(v, l, loc.as_ref()));
        }
        let _ = writeln!(s, "    m.call(&mut ctx);");
        let _ = writeln!(s, "    crate::line(out, {i}, {k}, &ctx, &vars(&m));");
        let _ = writeln!(s, "    ctx.advance(il_std::TIME({}i64));", p.step_ns);
    }
    if let Some(c) = config {
        let _ = writeln!(s, "    run_config(out);");
        s.push_str("}\n");
        s.push_str(&config_driver(i, c));
    } else {
        s.push_str("}\n");
    }
    s
}

const MAIN_RS: &str = r#"
pub trait Canon { fn canon(&self) -> String; }
impl Canon for bool { fn canon(&self) -> String { if *self { "TRUE".into() } else { "FALSE".into() } } }
macro_rules! ints { ($($t:ty),*) => { $(impl Canon for $t { fn canon(&self) -> String { self.to_string() } })* } }
ints!(i8, i16, i32, i64, u8, u16, u32, u64);
impl Canon for f32 { fn canon(&self) -> String { format!("{self:?}") } }
impl Canon for f64 { fn canon(&self) -> String { format!("{self:?}") } }
impl Canon for il_std::TIME { fn canon(&self) -> String { self.0.to_string() } }
impl Canon for il_std::DATE { fn canon(&self) -> String { self.0.to_string() } }
impl Canon for il_std::TOD { fn canon(&self) -> String { self.0.to_string() } }
impl Canon for il_std::DT { fn canon(&self) -> String { self.0.to_string() } }
impl<const N: usize> Canon for il_std::STRING<N> {
    fn canon(&self) -> String { self.as_bytes().iter().map(|u| format!("{u:02x}")).collect() }
}
impl<T: Canon, const N: usize> Canon for [T; N] {
    fn canon(&self) -> String { self.iter().map(Canon::canon).collect::<Vec<_>>().join(",") }
}
pub fn line(out: &mut String, i: usize, k: usize, ctx: &il_std::Cycle, vars: &[(&'static str, String)]) {
    use std::fmt::Write;
    let _ = write!(out, "p{i} {k} faults={} last={:?} io=", ctx.fault_count(), ctx.last_fault().map(|f| (f.kind, f.line)));
    for a in [il_std::Area::Output, il_std::Area::Memory] {
        for b in 0..IO_BYTES { let _ = write!(out, "{:02x}", ctx.io.byte(a, b)); }
    }
    for (n, v) in vars { let _ = write!(out, " {n}={v}"); }
    out.push('\n');
}
"#;

struct Case {
    index: usize,
    seed: u64,
    program: Program,
    expected: Vec<String>,
    rust: String,
    names: Vec<String>,
    /// Where each input lives when it is located (the checker's decision).
    locs: Vec<Option<Loc>>,
    canon_impls: String,
    /// The configuration it declares, run after the program's scans.
    config: Option<CfgCase>,
}

/// Build one crate with every case and run it; the output lines per case.
fn build_and_run(dir: &Path, cases: &[Case]) -> Vec<Vec<String>> {
    let src = dir.join("src");
    // One target directory for every generated crate (il-std is built once);
    // distinct package names keep their executables apart.
    let crate_name = dir.file_name().unwrap().to_string_lossy().replace('_', "-");
    let target = dir.parent().unwrap().join("differential-target");
    std::fs::create_dir_all(&src).unwrap();
    let il_std = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../il-std")
        .canonicalize()
        .unwrap();
    std::fs::write(
        dir.join("Cargo.toml"),
        format!(
            "[package]\nname = \"{}\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
             [dependencies]\nil-std = {{ path = {:?} }}\n\n[workspace]\n\n\
             [profile.dev]\nopt-level = 0\ndebug = false\nincremental = false\n",
            crate_name,
            il_std.display().to_string()
        ),
    )
    .unwrap();
    let mut main = String::from("#![allow(clippy::all, dead_code)]\n");
    main.push_str(MAIN_RS);
    let _ = writeln!(main, "const IO_BYTES: usize = {IO_BYTES};");
    for c in cases {
        let name = format!("p{}.rs", c.index);
        let text = format!(
            "{}\n{}\n{}",
            c.rust,
            c.canon_impls,
            driver(c.index, &c.names, &c.program, &c.locs, c.config.as_ref())
        );
        write_if_changed(&src.join(&name), &text);
        let _ = writeln!(main, "#[path = {name:?}] mod p{};", c.index);
    }
    main.push_str("fn main() {\n    let mut out = String::new();\n");
    for c in cases {
        let _ = writeln!(main, "    p{}::run(&mut out);", c.index);
    }
    main.push_str("    print!(\"{out}\");\n}\n");
    write_if_changed(&src.join("main.rs"), &main);

    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = Command::new(&cargo)
        .args(["build", "--quiet", "--offline"])
        .current_dir(dir)
        .env_remove("RUSTFLAGS")
        .env("CARGO_TARGET_DIR", &target)
        .status()
        .expect("run cargo");
    assert!(
        status.success(),
        "the generated crate in {} does not build",
        dir.display()
    );
    let exe = target.join("debug").join(&crate_name);
    let out = Command::new(&exe)
        .output()
        .expect("run the generated programs");
    assert!(
        out.status.success(),
        "the generated programs crashed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut per: Vec<Vec<String>> = vec![Vec::new(); cases.len()];
    let pos: std::collections::HashMap<usize, usize> = cases
        .iter()
        .enumerate()
        .map(|(k, c)| (c.index, k))
        .collect();
    for l in text.lines() {
        let (tag, rest) = l.split_once(' ').unwrap();
        let i: usize = tag[1..].parse().unwrap();
        per[pos[&i]].push(rest.to_string());
    }
    per
}

fn write_if_changed(path: &Path, text: &str) {
    if std::fs::read_to_string(path).ok().as_deref() != Some(text) {
        std::fs::write(path, text).unwrap();
    }
}

fn prepare(index: usize, seed: u64, program: Program) -> Result<Case, String> {
    let file = SourceFile::new(format!("p{index}.il"), program.il.clone());
    let prog = load(&file).map_err(|e| format!("the checker refuses it:\n{e}"))?;
    let expected = interpret(&prog, &program).map_err(|e| format!("interpreter: {e}"))?;
    let m = Machine::new(&prog, "Main")?;
    let names = watched(&m);
    let locs = program
        .inputs
        .iter()
        .map(|v| m.lookup(&v.name).map(|p| p.location().cloned()))
        .collect::<Result<Vec<_>, _>>()?;
    let canon_impls = canon_impls(&prog);
    let config = config_case(&prog);
    let rust = il_codegen::Program::new()
        .il(file.clone())
        .check()
        .files(Default::default())
        .ok_or("the compiler refuses what the checker accepts")?
        .remove(0);
    Ok(Case {
        index,
        seed,
        program,
        expected,
        rust,
        names,
        locs,
        canon_impls,
        config,
    })
}

fn first_difference(a: &[String], b: &[String]) -> Option<String> {
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        if x != y {
            let xs: Vec<&str> = x.split(' ').collect();
            let ys: Vec<&str> = y.split(' ').collect();
            let diffs: Vec<String> = xs
                .iter()
                .zip(&ys)
                .filter(|(p, q)| p != q)
                .map(|(p, q)| format!("interpreter {p} / compiled {q}"))
                .collect();
            return Some(format!("scan {k}: {}", diffs.join("; ")));
        }
    }
    (a.len() != b.len()).then(|| format!("{} scans vs {}", a.len(), b.len()))
}

fn tmp_dir(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

#[test]
fn interpreter_agrees_with_generated_rust() {
    let count = env_num("IL_DIFF_COUNT", 500) as usize;
    let base = env_num("IL_DIFF_SEED", 20_261_122);
    let mut cases = Vec::new();
    let mut refused = Vec::new();
    let mut coverage: std::collections::BTreeMap<&str, usize> = Default::default();
    for i in 0..count {
        let seed = base.wrapping_add(i as u64);
        let p = generator::generate(seed);
        for k in &p.kinds {
            *coverage.entry(k).or_default() += 1;
        }
        match prepare(i, seed, p) {
            Ok(c) => cases.push(c),
            Err(e) => refused.push(format!(
                "seed {seed}: {e}\n{}",
                generator::generate(seed).il
            )),
        }
    }
    print_coverage(count, &coverage);
    let mut kinds: Vec<String> = refused
        .iter()
        .filter_map(|r| {
            r.lines()
                .nth(1)
                .map(|l| l.split(" (at line").next().unwrap_or(l).to_string())
        })
        .collect();
    kinds.sort();
    kinds.dedup();
    for k in &kinds {
        eprintln!("refused: {k}");
    }
    assert!(
        refused.is_empty(),
        "{} of {count} generated programs could not be run (generator or compiler bug); first:\n{}",
        refused.len(),
        refused[0]
    );
    // Batches keep each crate to a size rustc handles quickly.
    let mut mismatches = Vec::new();
    let mut first_bad = None;
    let batch = env_num("IL_DIFF_BATCH", 500) as usize;
    for (b, chunk) in cases.chunks(batch).enumerate() {
        let got = build_and_run(&tmp_dir(&format!("differential_{base}_{b}")), chunk);
        for (c, g) in chunk.iter().zip(got) {
            if let Some(d) = first_difference(&c.expected, &g) {
                first_bad.get_or_insert(c.seed);
                mismatches.push(format!("seed {} ({d}):\n{}", c.seed, c.program.il));
            }
        }
    }
    println!(
        "{} programs compared, {} mismatches",
        cases.len(),
        mismatches.len()
    );
    if let Some(seed) = first_bad {
        let p = generator::generate(seed);
        let (il, prog) = shrink(p);
        let path = save_regression(seed, &il, &prog);
        mismatches.insert(
            0,
            format!("shrunk reproducer written to {}:\n{il}", path.display()),
        );
    }
    assert!(
        mismatches.is_empty(),
        "{} mismatches; first: {}",
        mismatches.len(),
        mismatches[0]
    );
    let unused: Vec<&str> = generator::coverage::CONSTRUCTS
        .iter()
        .copied()
        .filter(|k| !coverage.contains_key(k))
        .collect();
    assert!(
        count < 500 || unused.is_empty(),
        "constructs no generated program used: {unused:?}"
    );
}

/// The coverage table: construct -> how many programs used it (marks that
/// are not in `CONSTRUCTS` are printed too, and fail the test: the list and
/// the generator must agree).
fn print_coverage(count: usize, coverage: &std::collections::BTreeMap<&str, usize>) {
    println!("coverage of {count} generated programs (construct: programs using it):");
    let list = generator::coverage::CONSTRUCTS;
    let width = list.iter().map(|k| k.len()).max().unwrap_or(0);
    for k in list {
        let n = coverage.get(k).copied().unwrap_or(0);
        println!(
            "  {k:width$}  {n:>6}{}",
            if n == 0 { "  <- none" } else { "" }
        );
    }
    let stray: Vec<&&str> = coverage.keys().filter(|k| !list.contains(k)).collect();
    assert!(
        stray.is_empty(),
        "marks missing from coverage::CONSTRUCTS: {stray:?}"
    );
}

/// Body lines of the program that may be deleted (instructions and labels).
fn body_lines(il: &str) -> Vec<usize> {
    let mut in_var = false;
    let mut out = Vec::new();
    for (k, l) in il.lines().enumerate() {
        let t = l.trim();
        if t.starts_with("VAR") {
            in_var = true;
        } else if t == "END_VAR" {
            in_var = false;
        } else if !in_var
            && !t.is_empty()
            && !t.starts_with("FUNCTION")
            && !t.starts_with("END_")
            && !t.starts_with("PROGRAM")
            && !t.starts_with("(*")
        {
            out.push(k);
        }
    }
    out
}

fn without(il: &str, drop: &[usize]) -> String {
    il.lines()
        .enumerate()
        .filter(|(k, _)| !drop.contains(k))
        .map(|(_, l)| format!("{l}\n"))
        .collect()
}

/// Delta debugging by line deletion: each round builds every candidate that
/// still checks into one crate and keeps the smallest that still mismatches.
fn shrink(p: Program) -> (String, Program) {
    let mut p = p;
    for _round in 0..40 {
        let lines = body_lines(&p.il);
        let mut candidates = Vec::new();
        for size in [16, 8, 4, 2, 1] {
            if size > lines.len() {
                continue;
            }
            let mut start = 0;
            while start < lines.len() {
                let drop: Vec<usize> = lines[start..(start + size).min(lines.len())].to_vec();
                candidates.push(without(&p.il, &drop));
                start += size;
            }
        }
        let mut cases = Vec::new();
        for (i, il) in candidates.iter().enumerate() {
            let q = Program {
                il: il.clone(),
                inputs: p.inputs.clone(),
                scans: p.scans.clone(),
                step_ns: p.step_ns,
                kinds: p.kinds.clone(),
            };
            if let Ok(c) = prepare(i, 0, q) {
                cases.push(c);
            }
            if cases.len() >= 150 {
                break;
            }
        }
        if cases.is_empty() {
            break;
        }
        let got = build_and_run(&tmp_dir("differential_shrink"), &cases);
        let best = cases
            .into_iter()
            .zip(got)
            .filter(|(c, g)| first_difference(&c.expected, g).is_some())
            .min_by_key(|(c, _)| c.program.il.len());
        match best {
            Some((c, _)) => p = c.program,
            None => break,
        }
    }
    (p.il.clone(), p)
}

fn lit_text(l: &Lit) -> String {
    match l {
        Lit::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Lit::Int(v) => v.to_string(),
        Lit::Real(f) => format!("{f:?}"),
        Lit::Time(ns) => format!("T#{}", il_interp::fmt_dur(*ns)),
    }
}

/// `regressions/seed_N.il` and `seed_N.scans` (line 1: `step_ns=N`, then one
/// line of `input=value` per scan).
fn save_regression(seed: u64, il: &str, p: &Program) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("differential/regressions");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("seed_{seed}.il"));
    std::fs::write(&path, il).unwrap();
    let mut scans = format!("step_ns={}\n", p.step_ns);
    for s in &p.scans {
        let cells: Vec<String> = p
            .inputs
            .iter()
            .zip(s)
            .map(|(v, l)| format!("{}={}", v.name, lit_text(l)))
            .collect();
        scans.push_str(&cells.join(" "));
        scans.push('\n');
    }
    std::fs::write(path.with_extension("scans"), scans).unwrap();
    path
}

fn value_lit(v: &Value) -> Lit {
    match v {
        Value::Bool(b) => Lit::Bool(*b),
        Value::Int(x, _) => Lit::Int(*x),
        Value::Real(f) => Lit::Real(*f as f64),
        Value::LReal(f) => Lit::Real(*f),
        Value::Time(ns, _) => Lit::Time(*ns),
        other => panic!("not an input value: {other:?}"),
    }
}

fn gen_type(t: &il_codegen::sema::types::Ty) -> T {
    let name = t.to_string();
    [
        T::Bool,
        T::Sint,
        T::Int,
        T::Dint,
        T::Lint,
        T::Usint,
        T::Uint,
        T::Udint,
        T::Ulint,
        T::Byte,
        T::Word,
        T::Dword,
        T::Lword,
        T::Real,
        T::Lreal,
        T::Time,
    ]
    .into_iter()
    .find(|g| g.name() == name)
    .unwrap_or_else(|| panic!("input of type {name}"))
}

/// Every kept reproducer still agrees (one crate build for all of them).
#[test]
fn regressions_agree() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("differential/regressions");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    files.retain(|p| p.extension().is_some_and(|e| e == "il"));
    files.sort();
    let mut cases = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let il = std::fs::read_to_string(f).unwrap();
        let scans = std::fs::read_to_string(f.with_extension("scans")).unwrap();
        let mut lines = scans.lines();
        let step_ns: i64 = lines
            .next()
            .and_then(|l| l.strip_prefix("step_ns="))
            .and_then(|n| n.parse().ok())
            .expect("step_ns=N");
        let prog = load(&SourceFile::new(f.display().to_string(), il.clone()))
            .unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let m = Machine::new(&prog, "Main").unwrap();
        let mut inputs: Vec<generator::Var> = Vec::new();
        let mut rows = Vec::new();
        for l in lines.filter(|l| !l.trim().is_empty()) {
            let mut row = Vec::new();
            for cell in l.split_whitespace() {
                let (n, v) = cell.split_once('=').unwrap();
                let val = m.parse_value(n, v).unwrap_or_else(|e| panic!("{e}"));
                if rows.is_empty() {
                    inputs.push(generator::Var {
                        name: n.to_string(),
                        ty: gen_type(&m.type_of(n).unwrap()),
                    });
                }
                row.push(value_lit(&val));
            }
            rows.push(row);
        }
        let p = Program {
            il,
            inputs,
            scans: rows,
            step_ns,
            kinds: Vec::new(),
        };
        cases.push(prepare(i, 0, p).unwrap_or_else(|e| panic!("{}: {e}", f.display())));
    }
    assert!(!cases.is_empty(), "no reproducers in {}", dir.display());
    let got = build_and_run(&tmp_dir("differential_regressions"), &cases);
    for ((c, g), f) in cases.iter().zip(got).zip(&files) {
        if let Some(d) = first_difference(&c.expected, &g) {
            panic!("{}: {d}", f.display());
        }
    }
}
