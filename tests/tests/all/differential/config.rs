//! The configuration part of the differential test: the generated
//! configuration (gen/config.rs) run by the emitted scheduler and by
//! `il_interp::ConfigMachine`, call by call.

use super::*;

/// The configuration of a generated program (gen/config.rs): its name and
/// access paths (name, type, READ_WRITE, onto a subrange), from the
/// checked IR.
pub(super) struct CfgCase {
    name: String,
    access: Vec<(String, T, bool, bool)>,
}

pub(super) fn config_case(prog: &il_codegen::ir::Program) -> Option<CfgCase> {
    let def = prog.configs.first()?;
    Some(CfgCase {
        name: def.name.clone(),
        access: def
            .access
            .iter()
            .map(|a| {
                (
                    a.name.clone(),
                    gen_type(&a.ty),
                    a.writable,
                    a.range.is_some(),
                )
            })
            .collect(),
    })
}

/// The host's writes before call `k`: (access path, type, value, onto a
/// subrange) of every READ_WRITE path.
fn config_writes(c: &CfgCase, k: usize) -> Vec<(&str, T, Lit, bool)> {
    c.access
        .iter()
        .filter(|a| a.2)
        .enumerate()
        .map(|(j, (n, t, _, sub))| {
            let v = generator::config::write_value(k, j, *t);
            (n.as_str(), *t, v, *sub)
        })
        .collect()
}

/// The configuration under the interpreter: one line per call (tagged
/// 1000 + k): faults and image, programs run, the (task, program) trace,
/// overruns per task, then every access path.
pub(super) fn interpret_config(
    prog: &il_codegen::ir::Program,
    c: &CfgCase,
) -> Result<Vec<String>, String> {
    let mut m = il_interp::ConfigMachine::new(prog, &c.name)?;
    let mut ctx = il_std::Cycle::new();
    let mut lines = Vec::new();
    for k in 0..generator::config::STEPS {
        for (n, t, l, sub) in config_writes(c, k) {
            match m.set_access(n, lit_value(t, &l)) {
                // Refused outside the subrange, as the generated setter
                // refuses it: the paths read after the call must agree.
                Err(e) if sub && e.contains("outside the subrange") => {}
                r => r?,
            }
        }
        let mut trace = String::new();
        let ran = m.run_traced(&mut ctx, |t, p| {
            let _ = write!(trace, "{t}:{p},");
        })?;
        let over: Vec<String> = m.overruns().iter().map(u64::to_string).collect();
        let mut line = format!(
            "{} {} ran={ran} trace={trace} over={}",
            1000 + k,
            fault_text(&ctx),
            over.join(",")
        );
        for (n, _, _, _) in &c.access {
            let v = m.access(n).ok_or_else(|| format!("no access path {n}"))?;
            let _ = write!(line, " {n}={}", canon(&v));
        }
        lines.push(line);
        ctx.advance(il_std::TIME(generator::config::STEP_NS));
    }
    Ok(lines)
}

/// The same calls of the generated configuration struct (the access paths
/// read by one function, not once per call: the crate's build is most of
/// this test's time).
pub(super) fn config_driver(i: usize, c: &CfgCase) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "fn access(c: &{}, ran: usize, trace: String) -> Vec<(&'static str, String)> {{",
        c.name
    );
    let _ = writeln!(
        s,
        "    let over: Vec<String> = c.overruns().iter().map(u64::to_string).collect();"
    );
    let _ = writeln!(
        s,
        "    vec![(\"ran\", ran.to_string()), (\"trace\", trace), (\"over\", over.join(\",\")),"
    );
    for (n, _, _, _) in &c.access {
        let _ = writeln!(
            s,
            "        (\"{n}\", crate::Canon::canon(&c.access_{n}())),"
        );
    }
    let _ = writeln!(s, "    ]\n}}");
    let _ = writeln!(s, "pub fn run_config(out: &mut String) {{");
    let _ = writeln!(s, "    let mut ctx = il_std::Cycle::new();");
    let _ = writeln!(s, "    let mut c = {}::default();", c.name);
    let _ = writeln!(
        s,
        "    fn step(c: &mut {}, ctx: &mut il_std::Cycle, out: &mut String, k: usize) {{ let mut trace = String::new(); let ran = c.run_traced(ctx, |t, p| {{ trace.push_str(t); trace.push(':'); trace.push_str(p); trace.push(','); }}); crate::line(out, {i}, 1000 + k, ctx, &access(c, ran, trace)); ctx.advance(il_std::TIME({}i64)); }}",
        c.name,
        generator::config::STEP_NS
    );
    for k in 0..generator::config::STEPS {
        for (n, t, l, sub) in config_writes(c, k) {
            // A subrange's setter says whether it wrote (`Result`).
            let ignore = if sub { "let _ = " } else { "" };
            let _ = writeln!(s, "    {ignore}c.set_access_{n}({});", lit_rust(t, &l));
        }
        let _ = writeln!(s, "    step(&mut c, &mut ctx, out, {k});");
    }
    s.push_str("}\n");
    s
}
