//! The runner of the differential test: each case interpreted, compiled to
//! Rust with a driver that prints the same lines, all cases built into one
//! crate and run, and the two outputs compared.

use super::*;

/// The variables compared: every variable of Main but its FB instances
/// and arrays of them (their outputs are compared where the body reads them).
pub(super) fn watched(m: &Machine) -> Vec<String> {
    fn instance(v: &Value) -> bool {
        match v {
            Value::Fb(_) | Value::StdFb(_) => true,
            Value::Array(e) => e.first().is_some_and(instance),
            _ => false,
        }
    }
    m.vars()
        .into_iter()
        .filter(|(_, v)| !instance(v))
        .map(|(n, _)| n)
        .collect()
}

/// Interpret: one line per scan.
pub(super) fn interpret(
    prog: &il_codegen::ir::Program,
    p: &Program,
) -> Result<Vec<String>, String> {
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
pub(super) fn set_input(v: &generator::Var, l: &Lit, loc: Option<&Loc>) -> String {
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
pub(super) fn canon_impls(prog: &il_codegen::ir::Program) -> String {
    use il_codegen::ir::TypeDef;
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
pub(super) fn driver(
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

pub(super) const MAIN_RS: &str = r#"
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

pub(super) struct Case {
    pub(super) index: usize,
    pub(super) seed: u64,
    pub(super) program: Program,
    pub(super) expected: Vec<String>,
    pub(super) rust: String,
    pub(super) names: Vec<String>,
    /// Where each input lives when it is located (the checker's decision).
    pub(super) locs: Vec<Option<Loc>>,
    pub(super) canon_impls: String,
    /// The configuration it declares, run after the program's scans.
    pub(super) config: Option<CfgCase>,
}

/// Build one crate with every case and run it; the output lines per case.
pub(super) fn build_and_run(dir: &Path, cases: &[Case]) -> Vec<Vec<String>> {
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

pub(super) fn write_if_changed(path: &Path, text: &str) {
    if std::fs::read_to_string(path).ok().as_deref() != Some(text) {
        std::fs::write(path, text).unwrap();
    }
}

pub(super) fn prepare(index: usize, seed: u64, program: Program) -> Result<Case, String> {
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

pub(super) fn first_difference(a: &[String], b: &[String]) -> Option<String> {
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

pub(super) fn tmp_dir(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}
