//! The `launch` request: its arguments (the launch.json schema the VS Code
//! extension contributes and the guide documents), and the program they
//! name, checked and ready to scan.

use serde_json::Value;

use crate::input::Front;
use crate::load::Chosen;
use crate::run::{SetArg, parse_set, parse_step};
use il_codegen::ir::Program;
use il_interp::il_std::TIME;
use il_interp::{ConfigMachine, Machine};

/// What `launch` asks for.
#[derive(Debug)]
pub struct Launch {
    /// The files to run (IL, PLCopen XML, CODESYS `.EXP`), folders expanded.
    pub files: Vec<String>,
    /// `program` as given (what messages name).
    pub program: String,
    pub pou: Option<String>,
    pub configuration: Option<String>,
    /// `None`: scan until the client stops the session.
    pub cycles: Option<u64>,
    pub cycle_time: TIME,
    pub sets: Vec<SetArg>,
    /// `force`: `{ "path": "value" }`, pinned from the first scan on.
    pub forces: Vec<(String, String)>,
    pub stop_on_entry: bool,
    /// Pace the scans by the wall clock (one per `cycleTime`).
    pub real_time: bool,
    pub front: Front,
}

/// The fields of our launch configuration.
const FIELDS: &[&str] = &[
    "program",
    "encoding",
    "pou",
    "configuration",
    "cycles",
    "cycleTime",
    "set",
    "force",
    "stopOnEntry",
    "realTime",
    "std",
    "dialect",
    "snippet",
];

/// Fields every client adds to a launch configuration (VS Code's own,
/// nvim-dap's): not ours, but no mistake of the user's either.
const CLIENT_FIELDS: &[&str] = &[
    "type",
    "request",
    "name",
    "noDebug",
    "cwd",
    "preLaunchTask",
    "postDebugTask",
    "presentation",
    "internalConsoleOptions",
    "debugServer",
];

/// Parse the arguments of `launch`; an unknown field is an error that names it.
/// `encoding` reads the files when the launch names no `encoding`.
pub fn parse(args: &Value, encoding: il_codegen::read::Encoding) -> Result<Launch, String> {
    let Some(obj) = args.as_object() else {
        return Err("launch needs arguments: an object with at least `program`".into());
    };
    for k in obj.keys() {
        if !FIELDS.contains(&k.as_str())
            && !CLIENT_FIELDS.contains(&k.as_str())
            && !k.starts_with("__")
        {
            let hint = il_codegen::diag::suggest(k, FIELDS.iter().copied())
                .map(|s| format!("; did you mean `{s}`?"))
                .unwrap_or_default();
            return Err(format!(
                "unknown launch field `{k}` (the fields are {}){hint}",
                FIELDS.join(", ")
            ));
        }
    }
    let string = |k: &str| -> Result<Option<String>, String> {
        match obj.get(k) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::String(s)) => Ok(Some(s.clone())),
            Some(_) => Err(format!("launch field `{k}` must be a string")),
        }
    };
    let boolean = |k: &str| -> Result<bool, String> {
        match obj.get(k) {
            None | Some(Value::Null) => Ok(false),
            Some(Value::Bool(b)) => Ok(*b),
            Some(_) => Err(format!("launch field `{k}` must be true or false")),
        }
    };
    // One path (a file or a folder) or a list of them.
    let paths: Vec<String> = match obj.get("program") {
        None | Some(Value::Null) => {
            return Err(
                "launch needs `program`: the IL, PLCopen XML or .EXP file (or folder) to run"
                    .into(),
            );
        }
        Some(Value::String(s)) => vec![s.clone()],
        Some(Value::Array(items)) if !items.is_empty() => items
            .iter()
            .map(|v| v.as_str().map(str::to_string))
            .collect::<Option<_>>()
            .ok_or("launch field `program` must be a path or a list of paths")?,
        Some(_) => return Err("launch field `program` must be a path or a list of paths".into()),
    };
    if paths.iter().any(|p| p == "-") {
        // `ilc run -` reads standard input; here it carries the protocol.
        return Err(
            "launch field `program`: `-` (standard input) carries the debug protocol: name a file"
                .into(),
        );
    }
    let program = paths.join("`, `");
    let files = crate::input::expand(paths.into_iter());
    let encoding = match string("encoding")? {
        None => encoding,
        Some(e) => il_codegen::read::Encoding::from_label(&e)
            .map_err(|why| format!("launch field `encoding`: {why}"))?,
    };
    let cycles = match obj.get("cycles") {
        None | Some(Value::Null) => None,
        Some(v) => match v.as_u64() {
            Some(n) if n >= 1 => Some(n),
            _ => {
                return Err(
                    "launch field `cycles` must be a whole number of scans, at least 1".into(),
                );
            }
        },
    };
    let cycle_time = match string("cycleTime")? {
        Some(t) => parse_step(&t).map_err(|e| format!("launch field `cycleTime`: {e}"))?,
        None => TIME::from_ms(10),
    };
    let mut sets = Vec::new();
    match obj.get("set") {
        None | Some(Value::Null) => {}
        Some(Value::Array(items)) => {
            for s in items {
                let s = s
                    .as_str()
                    .ok_or("launch field `set` must be a list of strings like \"start=TRUE@3\"")?;
                let s = parse_set(s).map_err(|e| format!("launch field `set`: {e}"))?;
                if let Some(n) = cycles
                    && s.cycle > n
                {
                    return Err(format!(
                        "launch field `set`: {}={}@{}: the run has only {n} cycles",
                        s.var, s.value, s.cycle
                    ));
                }
                sets.push(s);
            }
        }
        Some(_) => {
            return Err(
                "launch field `set` must be a list of strings like \"start=TRUE@3\"".into(),
            );
        }
    }
    let mut forces = Vec::new();
    match obj.get("force") {
        None | Some(Value::Null) => {}
        Some(Value::Object(m)) => {
            for (k, v) in m {
                let v = match v {
                    Value::String(s) => s.clone(),
                    Value::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
                    Value::Number(n) => n.to_string(),
                    _ => {
                        return Err(format!(
                            "launch field `force`: the value of `{k}` must be an IL literal"
                        ));
                    }
                };
                forces.push((k.clone(), v));
            }
        }
        Some(_) => {
            return Err("launch field `force` must be an object: { \"path\": \"value\" }".into());
        }
    }
    let standard = match string("std")?.as_deref() {
        None => il_codegen::Standard::default(),
        Some(s) => il_codegen::Standard::from_name(s)
            .ok_or_else(|| format!("launch field `std`: `{s}` is not iec2013 or iec2003"))?,
    };
    let dialect = match string("dialect")?.as_deref() {
        None => il_codegen::Dialect::default(),
        Some(s) => il_codegen::Dialect::from_name(s)
            .ok_or_else(|| format!("launch field `dialect`: `{s}` is not iec or m221"))?,
    };
    let pou = string("pou")?;
    let configuration = string("configuration")?;
    if pou.is_some() && configuration.is_some() {
        return Err("give `pou` or `configuration`, not both".into());
    }
    Ok(Launch {
        files,
        program,
        pou,
        configuration,
        cycles,
        cycle_time,
        sets,
        forces,
        stop_on_entry: boolean("stopOnEntry")?,
        real_time: boolean("realTime")?,
        front: Front {
            encoding,
            standard,
            snippet: boolean("snippet")?,
            dialect,
        },
    })
}

/// What a launch runs.
pub enum Target {
    Pou(Box<Machine>),
    Config(Box<ConfigMachine>),
}

/// What [`load`] makes: the checked program, the machine, where its
/// lines are in the user's files, and the warnings (rendered).
pub struct Loaded {
    pub prog: Program,
    pub target: Target,
    pub lines: crate::source_map::SourceMap,
    pub warnings: String,
    /// An M221 program: `set`, `force` and `evaluate` name its objects as
    /// it writes them (`%I0.3`, `%MW1`; [`crate::load::program_name`]).
    pub m221: bool,
}

/// The checked program, or the diagnostics that stop it (rendered), loaded
/// as `ilc run` loads it.
pub fn load(l: &Launch) -> Result<Loaded, String> {
    let (rendered, loaded) = crate::load::load(&crate::load::Request {
        files: &l.files,
        front: l.front,
        program: l.pou.as_deref(),
        config: l.configuration.as_deref(),
        names: ("`pou`", "`configuration`"),
        color: false,
    });
    let loaded = loaded.map_err(|e| format!("{rendered}{e}"))?;
    let prog = &loaded.prog;
    // A scan's error points into the user's file (an XML project's line).
    let target = match &loaded.chosen {
        Chosen::Config(c) => {
            let mut m = ConfigMachine::new(prog, c).map_err(|e| format!("{rendered}{e}"))?;
            m.set_locate(loaded.map.locator());
            Target::Config(Box::new(m))
        }
        Chosen::Pou(p) => {
            let mut m = Machine::new(prog, p).map_err(|e| format!("{rendered}{e}"))?;
            m.set_locate(loaded.map.locator());
            Target::Pou(Box::new(m))
        }
    };
    Ok(Loaded {
        target,
        prog: loaded.prog,
        lines: loaded.map,
        warnings: rendered,
        m221: loaded.m221,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn parse_default(v: &Value) -> Result<Launch, String> {
        parse(v, Default::default())
    }

    #[test]
    fn unknown_fields_and_bad_values_are_named() {
        let e = parse_default(&json!({"program": "a.il", "cylces": 3})).unwrap_err();
        assert!(
            e.contains("`cylces`") && e.contains("did you mean `cycles`"),
            "{e}"
        );
        assert!(parse_default(&json!({"program": "a.il", "cycles": 0})).is_err());
        assert!(parse_default(&json!({"program": "a.il", "cycles": 2, "set": ["x=1@3"]})).is_err());
        assert!(parse_default(&json!({"cycles": 2})).is_err());
        assert!(parse_default(&json!({"program": "-"})).is_err());
        assert!(parse_default(&json!({"program": []})).is_err());
        let l = parse_default(&json!({"program": ["a.il", "b.il"], "encoding": "koi8-r"})).unwrap();
        assert_eq!(l.files, ["a.il", "b.il"]);
        assert!(parse_default(&json!({"program": "a.il", "encoding": "nope"})).is_err());
        assert!(parse_default(&json!(null)).is_err());
        let l = parse_default(&json!({
            "program": "a.il", "type": "ilc", "request": "launch", "name": "x",
            "__sessionId": "1", "set": ["start=TRUE@3"], "cycleTime": "T#20ms",
            "force": {"stop": false}
        }))
        .unwrap();
        assert_eq!(l.sets[0].cycle, 3);
        assert_eq!(l.cycle_time, TIME::from_ms(20));
        assert_eq!(l.forces, [("stop".to_string(), "FALSE".to_string())]);
    }
}
