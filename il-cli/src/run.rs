//! `ilc run`: simulate scans of a PROGRAM or a CONFIGURATION with the
//! reference interpreter (no Rust compilation) and print a table of watched
//! variables per cycle.

use std::io::Write;

use crate::run_target::Target;
use il_codegen::ir::types::Ty;
use il_interp::il_std::{self, Cycle, TIME};
use il_interp::{ConfigMachine, Machine, Value, fmt_dur};

pub const EXAMPLES: &str = "\
Examples:
  ilc run motor.il --program Motor --cycles 5 --set start=TRUE@2 --watch start,run,starts
  ilc run timers.il --program Main --cycles 20 --step 50ms --watch t1.Q,t1.ET

  ilc run tank.il --cycles 10 --set %IX0.0=TRUE@2 --set %IW2=500 --watch state,tank.level,%QX0.0
  ilc run tank.il --set valves[2].open=TRUE --set state=TankState#Filling --watch valves[2]
  ilc run motor.il --program Motor --cycles 8 --set start=TRUE@2 --set start=FALSE@3 --vcd motor.vcd
  ilc run motor.il --program Motor --cycles 8 --set start=TRUE@2 --watch start,run --plot motor.svg
  ilc run motor.il --program Motor --cycles 3 --set start=TRUE@3 --flow

A CONFIGURATION runs with --config NAME (or alone when the file has one and no
single PROGRAM): each scan runs the programs whose TASK is released at that
time, then those without a task. Its names are globals (g, Resource.g), access
paths (VAR_ACCESS), program variables (inst.v, Resource.inst.v) and addresses:
  ilc run cfg.il --config Plant --cycles 6 --set start=TRUE@2 --watch count,Cpu.Main.n

Cycles are numbered from 1; scan k runs at time (k-1) * step. A --set without
@CYCLE is written before scan 1. Names are variables with members and elements
(tank.level, valves[2].open, m[1,2]), located variables and direct addresses
(%IX0.0, %IW2, %QD1), which are the process image the program reads and writes.
In a Modicon M221 program (an .smbp project, or a listing with --dialect m221)
its objects are named as the program writes them, through the import's mapping:
  ilc run --dialect m221 listing.il --set %I0.3=TRUE@2 --watch %Q0.0,%MW1,%C0.V,%TM0.Q
(%I0.3 is the global I0_3, %C0.V is C0.V; the mangled names work too).
Values are IL literals (TRUE, 42, 16#FF, 1.5, T#10ms, 'text', TankState#Filling).
The table shows every watched variable after each scan; faults (division by
zero, index out of range) are reported on stderr.

--vcd FILE writes the same values as a Value Change Dump (IEEE 1364) for
GTKWave or Surfer: one $scope per program and FB instance/STRUCT, BOOL as 1-bit
wires, integers as vectors of their width, REAL/LREAL as real, TIME as an
integer counting the timescale unit, enumerations as their value (named in a
$comment), with the timescale the coarsest of s/ms/us/ns that divides --step.
--plot FILE draws a timing diagram (SVG): one lane per watched signal, BOOL as
high/low, numbers as stepped values, time in ms or s. Both files are written
whole at the end of the run, or not at all.
--flow prints, after the table, the current result (value and type) after every
IL line the last scan ran, in the order run (FB bodies included): the offline
\"flow control\" of CODESYS and TwinCAT.

Exit status: 0 ran, 1 the program has errors or a name/value is wrong,
2 the command line itself is wrong.";

/// `--set VAR=VALUE[@CYCLE]`.
#[derive(Clone, Debug, PartialEq)]
pub struct SetArg {
    pub var: String,
    pub value: String,
    /// Before which cycle (1-based) the value is written; 1 when not given.
    pub cycle: u64,
}

/// The names of one `--watch` value: split at commas outside brackets, so
/// that `m[1,2]` (an element of a 2-D array) stays one name.
pub fn split_watch(s: &str) -> Vec<String> {
    let (mut out, mut depth, mut start) = (Vec::new(), 0usize, 0);
    for (i, c) in s.char_indices() {
        match c {
            '[' => depth += 1,
            ']' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => {
                out.push(s[start..i].trim().to_string());
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(s[start..].trim().to_string());
    out.retain(|n| !n.is_empty());
    out
}

/// Parse `VAR=VALUE[@CYCLE]` (a usage error otherwise).
pub fn parse_set(s: &str) -> Result<SetArg, String> {
    let (var, rest) = s
        .split_once('=')
        .ok_or_else(|| format!("`{s}` is not VAR=VALUE[@CYCLE]"))?;
    let var = var.trim();
    if var.is_empty() {
        return Err(format!("`{s}` names no variable"));
    }
    // The cycle follows the last `@` (a string value may hold one, then use @CYCLE too).
    let (value, cycle) = match rest.rsplit_once('@') {
        Some((v, c)) if !c.is_empty() && c.chars().all(|c| c.is_ascii_digit()) => {
            let n: u64 = c
                .parse()
                .map_err(|_| format!("`{c}` is not a cycle number"))?;
            if n == 0 {
                return Err("cycles are numbered from 1".to_string());
            }
            (v, n)
        }
        _ => (rest, 1),
    };
    if value.trim().is_empty() {
        return Err(format!("`{s}` gives no value"));
    }
    Ok(SetArg {
        var: var.to_string(),
        value: value.trim().to_string(),
        cycle,
    })
}

/// Parse the scan period: `10ms`, `T#1s`, `1.5s` (a usage error otherwise).
pub fn parse_step(s: &str) -> Result<TIME, String> {
    let t = s.trim();
    let up = t.to_ascii_uppercase();
    let body = ["TIME#", "T#"]
        .iter()
        .find_map(|p| up.strip_prefix(p).map(|_| &t[p.len()..]))
        .unwrap_or(t);
    match il_std::literal::parse_duration(body) {
        Ok(ns) if ns >= 0 => Ok(TIME(ns)),
        Ok(_) => Err(format!("`{s}`: the step must not be negative")),
        Err(e) => Err(format!("`{s}` is not a duration like 10ms or T#1s ({e})")),
    }
}

pub struct Options {
    /// The sources, read as one program (several `.EXP` files of one
    /// CODESYS project, or a folder of them, expanded by the caller).
    pub files: Vec<String>,
    pub program: Option<String>,
    /// `--config NAME`: run this CONFIGURATION.
    pub config: Option<String>,
    pub cycles: u64,
    pub step: TIME,
    pub sets: Vec<SetArg>,
    /// Empty: every variable of the program.
    pub watch: Vec<String>,
    pub color: bool,
    /// `--std` and `--snippet`.
    pub front: crate::input::Front,
    /// `--vcd FILE`.
    pub vcd: Option<std::path::PathBuf>,
    /// `--plot FILE`.
    pub plot: Option<std::path::PathBuf>,
    /// `--flow`: the CR after every line of the last scan.
    pub flow: bool,
}

/// Run and print; the exit status (0 fine, 1 error).
pub fn run(o: &Options, out: &mut dyn Write, err: &mut dyn Write) -> u8 {
    match simulate(o, out, err) {
        Ok(()) => 0,
        Err(msg) => {
            if !msg.is_empty() {
                let _ = writeln!(err, "error: {msg}");
            }
            1
        }
    }
}

fn simulate(o: &Options, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), String> {
    // The loader `ilc debug` shares: an XML file (by its text or a `.xml`
    // name) is a PLCopen project whose IL POUs run, an `.EXP` a CODESYS
    // export; several files are one program.
    let (rendered, loaded) = crate::load::load(&crate::load::Request {
        files: &o.files,
        front: o.front,
        program: o.program.as_deref(),
        config: o.config.as_deref(),
        names: ("--program", "--config"),
        color: o.color,
    });
    let _ = write!(err, "{rendered}");
    let crate::load::Loaded {
        prog,
        map,
        chosen,
        m221,
    } = loaded?;
    match chosen {
        crate::load::Chosen::Config(c) => {
            let mut m = ConfigMachine::new(&prog, &c)?;
            m.set_locate(map.locator());
            scan_table(o, (&prog, &map, m221), &mut m, out, err)
        }
        crate::load::Chosen::Pou(name) => {
            let mut m = Machine::new(&prog, &name)?;
            m.set_locate(map.locator());
            scan_table(o, (&prog, &map, m221), &mut m, out, err)
        }
    }
}

/// Scan `m` `o.cycles` times and print the table (and the waves).
fn scan_table<T: Target>(
    o: &Options,
    (prog, map, m221): (
        &il_codegen::ir::Program,
        &crate::source_map::SourceMap,
        bool,
    ),
    m: &mut T,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<(), String> {
    for p in prog.pous.iter().filter(|p| p.host) {
        if p.kind != il_codegen::ast::PouKind::Function {
            writeln!(
                err,
                "note: `{}` is a host {} (its body is the crate's Rust code, or not IL): `ilc run` runs its interface only; its outputs keep their values",
                p.name,
                p.kind.keyword()
            )
            .map_err(|e| e.to_string())?;
            continue;
        }
        let ret = p.ret.as_ref().map_or("BOOL".to_string(), |t| t.to_string());
        writeln!(
            err,
            "note: `{}` is a host function ({{extern}}): its body is the crate's Rust code, which `ilc run` does not have; each call returns the {ret} default and leaves its outputs at their initial values",
            p.name
        )
        .map_err(|e| e.to_string())?;
    }
    // Every --set and --watch is resolved and checked before the first scan.
    let mut sets: Vec<(u64, T::Place, Value)> = Vec::new();
    for s in &o.sets {
        let place = m
            .lookup(&crate::load::program_name(&s.var, m221))
            .map_err(|e| format!("--set {}={}: {e}", s.var, s.value))?;
        let v = m
            .parse_for(&place, &s.value)
            .map_err(|e| format!("--set {}={}: {e}", s.var, s.value))?;
        if s.cycle > o.cycles {
            return Err(format!(
                "--set {}={}@{}: the run has only {} cycles",
                s.var, s.value, s.cycle, o.cycles
            ));
        }
        sets.push((s.cycle, place, v));
    }
    let watch_names: Vec<String> = if o.watch.is_empty() {
        m.watchable()
    } else {
        o.watch.clone()
    };
    let mut watch = Vec::with_capacity(watch_names.len());
    for w in &watch_names {
        if m221 && w.to_ascii_uppercase().contains(":X") {
            let word = &w[..w.to_ascii_uppercase().find(":X").unwrap_or(w.len())];
            return Err(format!(
                "--watch {w}: a bit of a word is not watched on its own; watch the word `{word}`"
            ));
        }
        let place = m
            .lookup(&crate::load::program_name(w, m221))
            .map_err(|e| format!("--watch {w}: {e}"))?;
        if matches!(m.describe(&place).1, Ty::Fb(_)) {
            return Err(format!(
                "--watch {w}: `{w}` is a function block instance; watch its members, e.g. `{w}.Q`"
            ));
        }
        watch.push(place);
    }
    // An M221 object keeps the name the user wrote (`%MW1`, not `MW1`).
    let described: Vec<(String, Ty)> = watch
        .iter()
        .zip(&watch_names)
        .map(|(p, w)| {
            let (t, ty) = m.describe(p);
            let shown = if crate::load::program_name(w, m221) != w.as_str() {
                w.clone()
            } else {
                t.to_string()
            };
            (shown, ty.clone())
        })
        .collect();

    let mut header = vec!["cycle".to_string(), "time".to_string()];
    header.extend(described.iter().map(|(t, _)| t.clone()));
    let mut rows = Vec::new();
    let mut waves = crate::wave::Waves::new(
        prog,
        &m.top(),
        &described,
        o.step,
        o.vcd.as_ref(),
        o.plot.as_ref(),
    )?;
    let mut ctx = Cycle::new();
    let mut faults_seen = 0u64;
    let mut flow = None;
    let mut fault_lines = Vec::new();
    for k in 1..=o.cycles {
        for (c, place, v) in &sets {
            if *c == k {
                m.set_at(&mut ctx, place, v.clone())?;
            }
        }
        let now = ctx.now();
        // Only the last scan runs through the hook: the others keep the
        // interpreter's speed.
        if o.flow && k == o.cycles {
            m.set_hook(Some(Box::new(crate::flow::Recorder(
                Default::default(),
                map.clone(),
            ))));
        }
        m.scan(&mut ctx)
            .map_err(|e| format!("cycle {k} (time {}): {e}", fmt_dur(now.0)))?;
        if let Some(rec) = m.take_hook::<crate::flow::Recorder>() {
            flow = Some((k, fmt_dur(now.0), rec));
        }
        let mut row = vec![k.to_string(), fmt_dur(now.0)];
        let values: Vec<Value> = watch.iter().map(|w| m.get_at(&ctx, w)).collect();
        row.extend(values.iter().map(Value::display));
        rows.push(row);
        if let Some(w) = &mut waves {
            w.sample(now, &values)?;
        }
        let new = ctx.fault_count() - faults_seen;
        if new > 0 {
            let recent: Vec<_> = ctx.faults().copied().collect();
            let shown = recent.len().min(new as usize);
            for f in &recent[recent.len() - shown..] {
                // At the line of the file the user wrote (an XML
                // project's or an export's, not the IL they became).
                fault_lines.push(format!(
                    "cycle {k}: fault {:?} in {} at {}",
                    f.kind,
                    f.pou,
                    map.place(f.pou, f.line)
                ));
            }
            faults_seen = ctx.fault_count();
        }
        ctx.advance(o.step);
    }
    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for r in &rows {
        for (w, c) in widths.iter_mut().zip(r) {
            *w = (*w).max(c.chars().count());
        }
    }
    // Columns of numbers are right-aligned (header too), the others left-aligned.
    let numeric: Vec<bool> = (0..header.len())
        .map(|i| rows.iter().all(|r| r[i].parse::<f64>().is_ok()))
        .collect();
    let line = |cells: &[String]| -> String {
        let mut s = String::new();
        for (i, (c, w)) in cells.iter().zip(&widths).enumerate() {
            if i > 0 {
                s.push_str("  ");
            }
            if numeric[i] {
                s.push_str(&format!("{c:>w$}"));
            } else {
                s.push_str(&format!("{c:<w$}"));
            }
        }
        s.trim_end().to_string()
    };
    let mut text = line(&header);
    text.push('\n');
    for r in &rows {
        text.push_str(&line(r));
        text.push('\n');
    }
    if let Some(w) = waves {
        w.finish()?;
    }
    out.write_all(text.as_bytes())
        .map_err(|e| format!("cannot write the table: {e}"))?;
    if let Some((k, time, rec)) = flow {
        crate::flow::print(&rec, map, k, &time, out)
            .map_err(|e| format!("cannot write the flow: {e}"))?;
    }
    for f in &fault_lines {
        let _ = writeln!(err, "warning: {f}");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn watch_lists_keep_subscripts_whole() {
        assert_eq!(split_watch("a, m[1,2] ,t1.Q"), ["a", "m[1,2]", "t1.Q"]);
        assert_eq!(split_watch("v[i, j].x,,b"), ["v[i, j].x", "b"]);
        assert_eq!(split_watch("%IX0.0"), ["%IX0.0"]);
        assert!(split_watch(" , ").is_empty());
    }

    #[test]
    fn set_syntax() {
        assert_eq!(
            parse_set("start=TRUE@3").unwrap(),
            SetArg {
                var: "start".into(),
                value: "TRUE".into(),
                cycle: 3
            }
        );
        assert_eq!(parse_set("x = 5").unwrap().cycle, 1);
        assert_eq!(parse_set("t=T#1s").unwrap().value, "T#1s");
        assert!(parse_set("x").is_err());
        assert!(parse_set("=1").is_err());
        assert!(parse_set("x=1@0").is_err());
        assert!(parse_set("x=").is_err());
    }

    #[test]
    fn step_syntax() {
        assert_eq!(parse_step("10ms").unwrap(), TIME::from_ms(10));
        assert_eq!(parse_step("T#1s").unwrap(), TIME::from_ms(1000));
        assert!(parse_step("ten").is_err());
        assert!(parse_step("-1s").is_err());
    }
}
