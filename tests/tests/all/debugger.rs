//! The debugger against the compiled Rust, scan by scan (issue 32's "Done
//! when"): the interpreter runs with the hook `ilc debug` attaches
//! (`il_interp::Hook`), which stops at the first statement of every scan
//! (a scan breakpoint) and after every statement of the program's own
//! frame. What it shows there — every variable of the frame, expanded into
//! instances and arrays through `Here::eval` and `Here::members` as the
//! adapter's Variables view expands them — is compared with the generated
//! struct's variables (its `visit`, `il_std::trace`) before and after each
//! scan. Any difference fails, naming the scan and the variable.

use std::collections::BTreeMap;

use il_codegen::ir::path::held;
use il_codegen::{SourceFile, ast::VarKind};
use il_interp::{Here, Hook, Value as V};
use il_std::trace::{Value as T, Visit, Visitor};
use il_std::{Area, Cycle, TIME};

/// Variables by path (`edge.Q`, `Cpu.Fast1.arr[2]`) → canonical text.
type Shown = BTreeMap<String, String>;

const STEP: TIME = TIME(10_000_000);

/// One text for a value on both sides: integers as numbers, REAL widened
/// exactly to f64 (as `il_std::trace` offers it), times in nanoseconds.
fn canon_interp(v: &V) -> String {
    match v {
        V::Bool(b) => b.to_string(),
        V::Int(i, _) => i.to_string(),
        V::Real(f) => format!("{:?}", f64::from(*f)),
        V::LReal(f) => format!("{f:?}"),
        V::Time(t, _) => format!("t{t}"),
        V::Enum { value, .. } => format!("enum {value}"),
        other => other.display(),
    }
}

fn canon_compiled(v: &T<'_>) -> String {
    match v {
        T::Bool(b) => b.to_string(),
        T::Int { value, .. } => value.to_string(),
        T::UInt { value, .. } => value.to_string(),
        T::Real(f) => format!("{f:?}"),
        T::Time(t) => format!("t{t}"),
        T::Enum { name, .. } => format!("enum {name}"),
        T::Str(b) => format!("'{}'", String::from_utf8_lossy(b)),
        T::WStr(u) => format!("\"{}\"", String::from_utf16_lossy(u)),
        other => format!("{other:?}"),
    }
}

/// The compiled side: every variable `visit` offers, by path.
#[derive(Default)]
struct Flat {
    path: Vec<String>,
    out: Shown,
}

impl Flat {
    fn at(&self, name: &str) -> String {
        let mut p = self.path.clone();
        p.push(name.to_string());
        p.join(".")
    }
}

fn subs(index: &[i64]) -> String {
    let s: Vec<String> = index.iter().map(i64::to_string).collect();
    format!("[{}]", s.join(", "))
}

impl Visitor for Flat {
    fn enter(&mut self, name: &str) {
        self.path.push(name.to_string());
    }
    fn enter_elem(&mut self, name: &str, index: &[i64]) {
        self.path.push(format!("{name}{}", subs(index)));
    }
    fn leave(&mut self) {
        self.path.pop();
    }
    fn var(&mut self, name: &str, _: &str, value: T<'_>) {
        self.out.insert(self.at(name), canon_compiled(&value));
    }
    fn elem(&mut self, name: &str, index: &[i64], _: &str, value: T<'_>) {
        let p = format!("{}{}", self.at(name), subs(index));
        self.out.insert(p, canon_compiled(&value));
    }
}

fn compiled(x: &impl Visit) -> Shown {
    let mut f = Flat::default();
    x.visit(&mut f);
    f.out
}

/// What the debugger shows of the innermost frame: its variables as the
/// Variables view lists them, compound ones expanded (by evaluating their
/// path, as the adapter does for a `variablesReference`). A VAR_EXTERNAL
/// is named `extern:NAME` (the compiled struct passes it by reference);
/// an in-out or temporary is not the instance's, and is left out.
fn shown(at: &Here<'_>, prefix: &str, externs: &Externs) -> Shown {
    let mut out = Shown::new();
    for (var, value) in at.vars(0) {
        if var.name.starts_with("__") || !held(var) {
            continue;
        }
        let key = if var.kind == VarKind::External {
            format!("extern:{}", var.name)
        } else {
            format!("{prefix}{}", var.name)
        };
        expand(at, (&var.name, &key), &value, externs, &mut out);
    }
    out
}

/// The VAR_EXTERNALs of each FUNCTION_BLOCK (its name and theirs, upper
/// case): a member of an instance that is a global's.
type Externs = std::collections::BTreeSet<(String, String)>;

fn externs(prog: &il_codegen::ir::Program) -> Externs {
    let mut out = Externs::new();
    for p in &prog.pous {
        for v in p.vars.iter().filter(|v| v.kind == VarKind::External) {
            out.insert((p.name.to_ascii_uppercase(), v.name.to_ascii_uppercase()));
        }
    }
    out
}

fn expand(at: &Here<'_>, (path, key): (&str, &str), v: &V, externs: &Externs, out: &mut Shown) {
    if !matches!(v, V::Fb(_) | V::StdFb(_) | V::Struct(_) | V::Array(_)) {
        out.insert(key.to_string(), canon_interp(v));
        return;
    }
    let (v, ty) = at
        .eval(0, path)
        .unwrap_or_else(|e| panic!("the debugger cannot evaluate `{path}`: {e}"));
    let fb = match &ty {
        il_codegen::ir::types::Ty::Fb(n) => n.to_ascii_uppercase(),
        _ => String::new(),
    };
    for m in at.members(&v, &ty) {
        let sep = if m.name.starts_with('[') { "" } else { "." };
        let p = format!("{path}{sep}{}", m.name);
        let k = if externs.contains(&(fb.clone(), m.name.to_ascii_uppercase())) {
            format!("extern:{}", m.name)
        } else {
            format!("{key}{sep}{}", m.name)
        };
        expand(at, (&p, &k), &m.value, externs, out);
    }
}

/// The hook: what the debugger showed at the scan's first stop, and after
/// the last statement of each program frame that ran, by frame path.
#[derive(Default)]
struct Watch {
    /// The scan has not stopped yet (set by the test before each scan).
    fresh: bool,
    at_start: Option<Shown>,
    /// The configuration's globals as the first program of the scan saw them.
    globals_at_start: Option<Shown>,
    after: BTreeMap<String, Shown>,
    stops: usize,
    externs: Externs,
    /// The frame path → the compiled path of its variables (`Fast1` → `Cpu.Fast1.`).
    prefix: BTreeMap<String, String>,
}

impl Watch {
    fn prefix(&self, at: &Here<'_>) -> (String, String) {
        let path = at.frames()[0].path.clone();
        let p = self.prefix.get(&path).cloned().unwrap_or_default();
        (path, p)
    }
}

impl Hook for Watch {
    fn before(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        if self.fresh && at.depth() == 1 {
            self.fresh = false;
            self.stops += 1;
            let (_, p) = self.prefix(at);
            self.at_start = Some(shown(at, &p, &self.externs));
            let globals = at
                .globals()
                .iter()
                .map(|(n, v, _)| (n.clone(), canon_interp(v)))
                .collect();
            self.globals_at_start = Some(globals);
        }
        Ok(())
    }
    fn after(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        if at.depth() == 1 {
            let (path, p) = self.prefix(at);
            let s = shown(at, &p, &self.externs);
            self.after.insert(path, s);
        }
        Ok(())
    }
}

/// Every variable the debugger shows has the compiled value, and every
/// compiled variable is shown (`externs` gives the compiled path of a
/// VAR_EXTERNAL: a global).
fn agree(scan: u64, when: &str, debugger: &Shown, rust: &Shown) {
    for (k, v) in debugger {
        let key = k.strip_prefix("extern:").unwrap_or(k);
        match rust.get(key) {
            Some(r) => assert_eq!(
                v, r,
                "scan {scan} ({when}): the debugger shows {key} = {v}, the compiled Rust has {r}"
            ),
            None => panic!(
                "scan {scan} ({when}): the debugger shows `{key}`, which the compiled Rust does not have ({rust:?})"
            ),
        }
    }
}

fn covers(scan: u64, debugger: &Shown, rust: &Shown, only: impl Fn(&str) -> bool) {
    for k in rust.keys().filter(|k| only(k)) {
        let shown = debugger
            .keys()
            .any(|d| d.strip_prefix("extern:").unwrap_or(d) == k);
        assert!(shown, "scan {scan}: the debugger does not show `{k}`");
    }
}

fn read(path: &str) -> String {
    let p = format!("{}/../{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{p}: {e}"))
}

/// `examples/motor.il`, POU Motor, `start=TRUE@3`, 6 cycles: the launch of
/// the test, against the Motor build.rs compiled.
#[test]
fn motor_scan_by_scan_as_the_compiled_rust() {
    let text = read("examples/motor.il");
    // The program build.rs compiled is the example itself.
    assert_eq!(text, read("tests/plc/motor.il"));
    let prog = il_interp::load(&SourceFile::new("motor.il", text)).unwrap();
    let mut m = il_interp::Machine::new(&prog, "Motor").unwrap();
    m.set_hook(Some(Box::new(Watch {
        externs: externs(&prog),
        ..Watch::default()
    })));
    let mut rust = il_tests::via_build::Motor::default();
    let (mut ctx_i, mut ctx_r) = (Cycle::new(), Cycle::new());
    let mut runs = 0;
    for scan in 1..=6u64 {
        if scan == 3 {
            m.set("start", V::Bool(true)).unwrap();
            rust.start = true;
        }
        m.hook_mut::<Watch>().unwrap().fresh = true;
        let before = compiled(&rust);
        m.scan(&mut ctx_i).unwrap();
        rust.call(&mut ctx_r);
        let after = compiled(&rust);
        let w = m.hook_mut::<Watch>().unwrap();
        let start = w.at_start.take().expect("a stop at the scan's start");
        agree(scan, "stopped at its start", &start, &before);
        covers(scan, &start, &before, |_| true);
        let end = &w.after["Motor"];
        agree(scan, "after its last statement", end, &after);
        covers(scan, end, &after, |_| true);
        runs += usize::from(after["run"] == "true");
        ctx_i.advance(STEP);
        ctx_r.advance(STEP);
    }
    let w = m.take_hook::<Watch>().unwrap();
    assert_eq!(w.stops, 6);
    // The run the test is about happened: the motor started in scan 3.
    assert_eq!(runs, 4);
    assert_eq!(rust.starts, 1);
}

/// The configuration of two tasks of `plc/globals_tasks.il` (Fast every
/// 10 ms, Slow every 50 ms), 12 scans of 10 ms: each program instance as
/// the debugger showed it after its last statement, and the globals as
/// the next scan's first stop shows them, against the compiled `Plant`.
#[test]
fn two_task_configuration_scan_by_scan_as_the_compiled_rust() {
    let text = read("tests/plc/globals_tasks.il");
    let prog = il_interp::load(&SourceFile::new("globals_tasks.il", text)).unwrap();
    let mut m = il_interp::ConfigMachine::new(&prog, "Plant").unwrap();
    let mut watch = Watch {
        externs: externs(&prog),
        ..Watch::default()
    };
    for r in &m.def().resources {
        for p in &r.programs {
            watch.prefix.insert(
                p.name.clone(),
                format!("{}.{}.", r.name.as_deref().unwrap_or("?"), p.name),
            );
        }
    }
    m.set_hook(Some(Box::new(watch)));
    let mut rust = il_tests::via_build::Plant::default();
    let (mut ctx_i, mut ctx_r) = (Cycle::new(), Cycle::new());
    // `lamp` is located (AT %QX0.0): the compiled configuration keeps it in
    // the process image, not in a field.
    let compiled_plant = |rust: &il_tests::via_build::Plant, ctx: &Cycle| {
        let mut s = compiled(rust);
        s.insert("lamp".into(), ctx.io.bit(Area::Output, 0, 0).to_string());
        s
    };
    let mut previous = compiled_plant(&rust, &ctx_r);
    let globals = |s: &Shown| -> Shown {
        s.iter()
            .filter(|(k, _)| !k.contains('.'))
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect()
    };
    let mut slow = Vec::new();
    for scan in 1..=12u64 {
        let w = m.hook_mut::<Watch>().unwrap();
        w.fresh = true;
        w.after.clear();
        m.run(&mut ctx_i).unwrap();
        rust.run(&mut ctx_r);
        let now = compiled_plant(&rust, &ctx_r);
        let w = m.hook_mut::<Watch>().unwrap();
        // The first program's start shows the globals the last scan left.
        let g = w
            .globals_at_start
            .take()
            .expect("a stop at the scan's start");
        assert_eq!(
            g,
            globals(&previous),
            "scan {scan}: the globals at its start"
        );
        let mut all = Shown::new();
        for (inst, s) in &w.after {
            agree(scan, &format!("{inst} after its last statement"), s, &now);
            all.extend(s.clone());
        }
        // Every variable of every instance that ran in this scan is shown.
        covers(scan, &all, &now, |k| {
            w.after.keys().any(|i| k.starts_with(&format!("Cpu.{i}.")))
        });
        if w.after.contains_key("Slow1") {
            slow.push(scan);
        }
        assert!(
            w.after.contains_key("Fast1"),
            "scan {scan}: Fast runs every scan"
        );
        previous = now;
        ctx_i.advance(STEP);
        ctx_r.advance(STEP);
    }
    // Slow's task at 0, 50 and 100 ms: scans 1, 6 and 11.
    assert_eq!(slow, [1, 6, 11]);
    assert_eq!(previous["Cpu.Slow1.runs"], "3");
    assert_eq!(previous["ticks"], "12");
}
