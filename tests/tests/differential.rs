//! Differential testing: random well-typed IL programs (tests/differential/gen.rs)
//! run under the reference interpreter and as generated Rust, compared variable
//! by variable after every scan (plus the fault count and the last fault).
//!
//! All programs of a run are compiled into ONE temporary crate (one build).
//! CI: a fixed seed and 500 programs. The long run:
//!
//! ```sh
//! IL_DIFF_COUNT=10000 IL_DIFF_SEED=7 cargo test -p il-tests --test differential -- --nocapture
//! ```
//!
//! Reproducers of past mismatches live in tests/differential/regressions/*.il
//! and are run by `regressions_agree` (inputs: every input FALSE/0 and then
//! the generator's patterns for their seed are not needed: they run 5 scans
//! with default inputs).

#[path = "../differential/gen.rs"]
mod generator;

use generator::{Lit, Program, T};
use il_codegen::diag::SourceFile;
use il_codegen::interp::{Machine, Value, load};
use il_codegen::sema::types::Elem;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

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
        Value::Array(items) => items.iter().map(canon).collect::<Vec<_>>().join(","),
        other => other.display(),
    }
}

fn fault_text(ctx: &il_std::Cycle) -> String {
    format!(
        "faults={} last={:?}",
        ctx.fault_count(),
        ctx.last_fault().map(|f| (f.kind, f.line))
    )
}

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
    for (k, scan) in p.scans.iter().enumerate() {
        for (v, l) in p.inputs.iter().zip(scan) {
            m.set(&v.name, lit_value(v.ty, l))?;
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
    Ok(lines)
}

/// The Rust driver of one program: a module with the generated code and `run`.
fn driver(i: usize, names: &[String], p: &Program) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "pub fn run(out: &mut String) {{");
    let _ = writeln!(s, "    let mut ctx = il_std::Cycle::new();");
    let _ = writeln!(s, "    let mut m = Main::default();");
    for (k, scan) in p.scans.iter().enumerate() {
        for (v, l) in p.inputs.iter().zip(scan) {
            let _ = writeln!(s, "    m.{} = {};", v.name, lit_rust(v.ty, l));
        }
        let _ = writeln!(s, "    m.call(&mut ctx);");
        let _ = write!(s, "    crate::line(out, {i}, {k}, &ctx, &[");
        for n in names {
            let _ = write!(s, "(\"{n}\", crate::Canon::canon(&m.{n})), ");
        }
        let _ = writeln!(s, "]);");
        let _ = writeln!(s, "    ctx.advance(il_std::TIME({}i64));", p.step_ns);
    }
    s.push_str("}\n");
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
impl<T: Canon, const N: usize> Canon for [T; N] {
    fn canon(&self) -> String { self.iter().map(Canon::canon).collect::<Vec<_>>().join(",") }
}
pub fn line(out: &mut String, i: usize, k: usize, ctx: &il_std::Cycle, vars: &[(&str, String)]) {
    use std::fmt::Write;
    let _ = write!(out, "p{i} {k} faults={} last={:?}", ctx.fault_count(), ctx.last_fault().map(|f| (f.kind, f.line)));
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
}

/// Build one crate with every case and run it; the output lines per case.
fn build_and_run(dir: &Path, cases: &[Case]) -> Vec<Vec<String>> {
    let src = dir.join("src");
    std::fs::create_dir_all(&src).unwrap();
    let il_std = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/il-std")
        .canonicalize()
        .unwrap();
    std::fs::write(
        dir.join("Cargo.toml"),
        format!(
            "[package]\nname = \"il-differential\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
             [dependencies]\nil-std = {{ path = {:?} }}\n\n[workspace]\n\n\
             [profile.dev]\nopt-level = 0\ndebug = false\nincremental = false\n",
            il_std.display().to_string()
        ),
    )
    .unwrap();
    let mut main = String::from("#![allow(clippy::all)]\n");
    main.push_str(MAIN_RS);
    for c in cases {
        let name = format!("p{}.rs", c.index);
        let text = format!("{}\n{}", c.rust, driver(c.index, &c.names, &c.program));
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
        .env("CARGO_TARGET_DIR", dir.join("target"))
        .status()
        .expect("run cargo");
    assert!(
        status.success(),
        "the generated crate in {} does not build",
        dir.display()
    );
    let exe = dir.join("target/debug/il-differential");
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
    let names = watched(&Machine::new(&prog, "Main")?);
    let (rust, _) = il_codegen::compile_to_file(&file).map_err(|d| format!("{d:?}"))?;
    Ok(Case {
        index,
        seed,
        program,
        expected,
        rust,
        names,
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
    for i in 0..count {
        let seed = base.wrapping_add(i as u64);
        let p = generator::generate(seed);
        match prepare(i, seed, p) {
            Ok(c) => cases.push(c),
            Err(e) => refused.push(format!(
                "seed {seed}: {e}\n{}",
                generator::generate(seed).il
            )),
        }
    }
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
    let batch = env_num("IL_DIFF_BATCH", 500) as usize;
    for (b, chunk) in cases.chunks(batch).enumerate() {
        let got = build_and_run(&tmp_dir(&format!("differential_{b}")), chunk);
        for (c, g) in chunk.iter().zip(got) {
            if let Some(d) = first_difference(&c.expected, &g) {
                mismatches.push(format!("seed {} ({d}):\n{}", c.seed, c.program.il));
            }
        }
    }
    println!(
        "{} programs compared, {} mismatches",
        cases.len(),
        mismatches.len()
    );
    assert!(
        mismatches.is_empty(),
        "{} mismatches; first: {}",
        mismatches.len(),
        mismatches[0]
    );
}
