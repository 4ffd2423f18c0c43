//! A CONFIGURATION around `Main` (Ed.2 2.7): VAR_GLOBALs, one or two
//! RESOURCEs, TASKs of different INTERVAL and PRIORITY and SINGLE tasks on
//! BOOL globals, instances of `Main` bound to tasks (or to none) with inputs
//! from globals and outputs to globals, and VAR_ACCESS paths: READ_WRITE
//! ones onto the globals the host writes, READ_ONLY ones onto the outputs
//! and into the instances (variables, array elements, members of
//! structures, outputs of FB instances). The differential test runs the
//! emitted scheduler and `il_interp::ConfigMachine` side by side over
//! simulated time and compares every access path after every call.
//!
//! The host's writes are not part of the program: they are derived from the
//! checked configuration (`write_value`), so a shrunk reproducer replays
//! from its IL alone.

use super::*;

/// What the configuration may bind and name of `Main`.
pub struct Shape {
    /// Main's VAR_INPUTs (bound to globals with `:=`).
    pub inputs: Vec<Var>,
    /// Main's VAR_OUTPUTs (bound to globals with `=>`).
    pub outputs: Vec<Var>,
    /// Places of Main an access path may name (elementary types, constant
    /// subscripts only).
    pub paths: Vec<Var>,
}

/// The configuration's name in the IL (and of the generated struct).
pub const NAME: &str = "Plant";

/// Calls of the configuration per run, and the simulated time between them.
pub const STEPS: usize = 8;
pub const STEP_NS: i64 = 5_000_000;

/// The value the host writes to READ_WRITE access path `j` (in declaration
/// order) before call `k`.
pub fn write_value(k: usize, j: usize, t: T) -> Lit {
    random_lit(&mut Rng::new(((k as u64) << 16) | j as u64), t)
}

/// The CONFIGURATION text and the constructs it uses.
pub fn configuration(rng: &mut Rng, s: &Shape) -> (String, Vec<&'static str>) {
    let mut kinds = vec!["CONFIGURATION: tasks, programs, VAR_ACCESS"];
    let n_res = if rng.chance(40) { 2 } else { 1 };
    if n_res == 2 {
        kinds.push("CONFIGURATION with two RESOURCEs");
    }
    let mut globals: Vec<(String, T)> = Vec::new();
    let mut access: Vec<String> = Vec::new();
    let mut resources = String::new();
    let declare = |globals: &mut Vec<(String, T)>, name: &str, t: T| {
        let new = !globals.iter().any(|(n, _)| n == name);
        if new {
            globals.push((name.to_string(), t));
        }
        new
    };
    let mut inst = 0;
    for r in 1..=n_res {
        let mut body = String::new();
        let mut tasks = Vec::new();
        for k in 0..1 + rng.below(3) {
            let name = format!("t{r}_{k}");
            let prio = rng.below(4);
            if rng.chance(25) {
                let tick = format!("tick{r}_{k}");
                declare(&mut globals, &tick, T::Bool);
                access.push(format!("w_{tick} : {tick} : BOOL READ_WRITE"));
                body.push_str(&format!(
                    "    TASK {name} (SINGLE := {tick}, PRIORITY := {prio});\n"
                ));
                kinds.push("TASK SINGLE");
            } else {
                let ms = rng.pick(&[5, 10, 15, 20, 35]);
                body.push_str(&format!(
                    "    TASK {name} (INTERVAL := T#{ms}ms, PRIORITY := {prio});\n"
                ));
            }
            tasks.push(name);
        }
        for _ in 0..1 + rng.below(2) {
            inst += 1;
            let m = format!("m{inst}");
            let mut args = Vec::new();
            for v in &s.inputs {
                if rng.chance(60) {
                    // Shared by the instances, or this one's own.
                    let g = if rng.chance(50) {
                        format!("g_{}", v.name)
                    } else {
                        format!("g{inst}_{}", v.name)
                    };
                    if declare(&mut globals, &g, v.ty) {
                        access.push(format!("w_{g} : {g} : {} READ_WRITE", v.ty.name()));
                    }
                    args.push(format!("{} := {g}", v.name));
                }
            }
            for v in &s.outputs {
                if rng.chance(60) {
                    let g = format!("o{inst}_{}", v.name);
                    declare(&mut globals, &g, v.ty);
                    access.push(format!("r_{g} : {g} : {}", v.ty.name()));
                    args.push(format!("{} => {g}", v.name));
                }
            }
            let with = if rng.chance(85) {
                format!(" WITH {}", rng.pick(&tasks))
            } else {
                kinds.push("program instance without a task");
                String::new()
            };
            let args = if args.is_empty() {
                String::new()
            } else {
                format!(" ({})", args.join(", "))
            };
            body.push_str(&format!("    PROGRAM {m}{with} : Main{args};\n"));
            for _ in 0..1 + rng.below(3) {
                let p = rng.pick(&s.paths).clone();
                if p.name.contains(['[', '.']) {
                    kinds.push("VAR_ACCESS through elements and members");
                }
                access.push(format!(
                    "p{} : R{r}.{m}.{} : {}",
                    access.len(),
                    p.name,
                    p.ty.name()
                ));
            }
        }
        resources.push_str(&format!("RESOURCE R{r} ON PLC\n{body}END_RESOURCE\n"));
    }
    let mut globals: String = globals
        .iter()
        .map(|(n, t)| format!("    {n} : {};\n", t.name()))
        .collect();
    if rng.chance(50) {
        // The host's INT values fall inside and outside: a write outside is
        // refused by the generated setter and by the interpreter alike.
        globals.push_str("    level : INT (0..100);\n");
        access.push("w_level : level : INT READ_WRITE".to_string());
        kinds.push("VAR_ACCESS onto a subrange");
    }
    let access: String = access.iter().map(|a| format!("    {a};\n")).collect();
    kinds.sort();
    kinds.dedup();
    (
        format!(
            "\nCONFIGURATION {NAME}\nVAR_GLOBAL\n{globals}END_VAR\n{resources}VAR_ACCESS\n{access}END_VAR\nEND_CONFIGURATION\n"
        ),
        kinds,
    )
}
