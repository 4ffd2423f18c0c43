//! What a stopped session shows: the stack (PROGRAM → FB instance →
//! FUNCTION, each at its IL line), the scopes of a frame (the current
//! result with the scan number and simulated time first, then the POU's
//! variables by section), expandable instances, structures and arrays,
//! evaluation of paths, and writes.

use serde_json::{Value, json};

use super::{Handle, Session};
use il_codegen::ast::VarKind;
use il_interp::{Cr, Here, Value as V, fmt_dur};

/// The sections in the order a POU declares them, with their scope names.
const SECTIONS: &[(VarKind, &str)] = &[
    (VarKind::Input, "Inputs"),
    (VarKind::Output, "Outputs"),
    (VarKind::InOut, "In-outs"),
    (VarKind::Var, "Locals"),
    (VarKind::Temp, "Temporaries"),
    (VarKind::External, "Externals (globals)"),
    (VarKind::Global, "Globals"),
];

/// A value as the client shows it: compound values by their type.
fn shown(v: &V, ty: &str) -> String {
    match v {
        V::Fb(_) | V::StdFb(_) | V::Struct(_) => ty.to_string(),
        V::Array(items) => format!("{ty} ({} elements)", items.len()),
        _ => v.display(),
    }
}

fn compound(v: &V) -> bool {
    matches!(v, V::Fb(_) | V::StdFb(_) | V::Struct(_) | V::Array(_))
}

/// The frame depth of a `frameId` (ids count from 1, innermost first).
fn depth_of(at: &Here<'_>, args: &Value) -> Result<usize, String> {
    match args.get("frameId").and_then(Value::as_u64) {
        None => Ok(0),
        Some(id) if id >= 1 && (id as usize) <= at.depth() => Ok(id as usize - 1),
        Some(id) => Err(format!("there is no frame {id}")),
    }
}

impl Session {
    fn handle(&mut self, h: Handle) -> usize {
        self.handles.push(h);
        self.handles.len()
    }

    pub(super) fn stack_trace(&mut self, at: &Here<'_>) -> Result<Value, String> {
        let frames: Vec<Value> = at
            .frames()
            .iter()
            .enumerate()
            .map(|(d, f)| {
                let name = if f.path.eq_ignore_ascii_case(&f.pou) {
                    f.pou.clone()
                } else {
                    format!("{} ({})", f.path, f.pou)
                };
                // Each frame in the file of its POU, at the user's line.
                let source = super::source(self.src.path_of(&f.pou));
                let line = self.base.out(self.src.line(&f.pou, f.line));
                json!({ "id": d + 1, "name": name, "source": source, "line": line,
                        "column": self.base.column })
            })
            .collect();
        Ok(json!({ "stackFrames": frames, "totalFrames": frames.len() }))
    }

    pub(super) fn scopes(&mut self, at: &Here<'_>, args: &Value) -> Result<Value, String> {
        let depth = depth_of(at, args)?;
        let cr = self.handle(Handle::Cr(depth));
        let mut scopes = vec![json!({
            "name": "Current result", "variablesReference": cr, "expensive": false,
            "presentationHint": "registers",
        })];
        if at.result(depth).is_some() {
            let h = self.handle(Handle::Result(depth));
            scopes.push(json!({ "name": "Result", "variablesReference": h, "expensive": false }));
        }
        let vars = at.vars(depth);
        for &(kind, name) in SECTIONS {
            if vars.iter().any(|(v, _)| v.kind == kind && !hidden(&v.name)) {
                let h = self.handle(Handle::Section(depth, kind));
                let hint = if kind == VarKind::Var {
                    "locals"
                } else {
                    "arguments"
                };
                scopes.push(json!({
                    "name": name, "variablesReference": h, "expensive": false,
                    "presentationHint": hint,
                }));
            }
        }
        if !at.globals().is_empty() {
            let h = self.handle(Handle::Globals(depth));
            scopes.push(json!({ "name": "Configuration globals", "variablesReference": h, "expensive": false }));
        }
        if !at.pou().addresses.is_empty() && depth == 0 {
            let h = self.handle(Handle::Image(depth));
            scopes.push(
                json!({ "name": "Process image", "variablesReference": h, "expensive": false }),
            );
        }
        Ok(json!({ "scopes": scopes }))
    }

    pub(super) fn variables(&mut self, at: &Here<'_>, args: &Value) -> Result<Value, String> {
        let r = args
            .get("variablesReference")
            .and_then(Value::as_u64)
            .unwrap_or(0) as usize;
        let h = r
            .checked_sub(1)
            .and_then(|i| self.handles.get(i))
            .cloned()
            .ok_or_else(|| {
                format!("no variables under reference {r} (they last until the run goes on)")
            })?;
        let mut out = Vec::new();
        match h {
            Handle::Cr(depth) => {
                let (src, base) = (&self.src, self.base);
                let (value, ty) = match at.cr(depth) {
                    Some(Cr::Value(v, t)) => (v.display(), t.to_string()),
                    Some(Cr::Undefined(_)) => (
                        crate::flow::cr_text(at, depth, &|pou, l| base.out(src.line(pou, l))),
                        "undefined".into(),
                    ),
                    None => ("undefined".into(), "undefined".into()),
                };
                out.push(
                    json!({ "name": "CR", "value": value, "type": ty, "variablesReference": 0 }),
                );
                out.push(json!({ "name": "scan", "value": self.scan.to_string(), "type": "scan", "variablesReference": 0 }));
                out.push(json!({ "name": "time", "value": format!("T#{}", fmt_dur(self.now.0)), "type": "TIME", "variablesReference": 0 }));
                let flow = self.handle(Handle::Flow);
                out.push(json!({
                    "name": "flow", "value": format!("{} lines run in this scan", self.flow.len()),
                    "variablesReference": flow,
                }));
            }
            Handle::Flow => {
                for (pou, line, cr) in &self.flow {
                    let line = self.base.out(self.src.line(pou, *line));
                    out.push(json!({ "name": format!("{pou} line {line}"), "value": cr, "variablesReference": 0 }));
                }
            }
            Handle::Section(depth, kind) => {
                for (v, x) in at.vars(depth) {
                    if v.kind != kind || hidden(&v.name) {
                        continue;
                    }
                    let ty = v.ty.to_string();
                    out.push(self.variable(&v.name, &x, &ty, depth, v.name.clone()));
                }
            }
            Handle::Globals(depth) => {
                for (name, v, ty) in at.globals() {
                    out.push(self.variable(name, v, &ty.to_string(), depth, name.clone()));
                }
            }
            Handle::Result(depth) => {
                if let Some((name, v, ty)) = at.result(depth) {
                    out.push(self.variable(&name, &v, &ty.to_string(), depth, name.clone()));
                }
            }
            Handle::Image(depth) => {
                let addrs: Vec<String> =
                    at.pou().addresses.iter().map(|l| l.text.clone()).collect();
                for a in addrs {
                    let (v, ty) = at.eval(depth, &a)?;
                    out.push(self.variable(&a, &v, &ty.to_string(), depth, a.clone()));
                }
            }
            Handle::Path(depth, path) => {
                let (v, ty) = at.eval(depth, &path)?;
                for m in at.members(&v, &ty) {
                    let child = if m.name.starts_with('[') {
                        format!("{path}{}", m.name)
                    } else {
                        format!("{path}.{}", m.name)
                    };
                    out.push(self.variable(&m.name, &m.value, &m.ty, depth, child));
                }
            }
        }
        Ok(json!({ "variables": out }))
    }

    fn variable(&mut self, name: &str, v: &V, ty: &str, depth: usize, path: String) -> Value {
        let reference = if compound(v) {
            self.handle(Handle::Path(depth, path.clone()))
        } else {
            0
        };
        json!({
            "name": name, "value": shown(v, ty), "type": ty,
            "variablesReference": reference, "evaluateName": path,
        })
    }

    pub(super) fn evaluate(&mut self, at: &Here<'_>, args: &Value) -> Result<Value, String> {
        let depth = depth_of(at, args)?;
        let e = args
            .get("expression")
            .and_then(Value::as_str)
            .ok_or("evaluate needs `expression`")?;
        let named = crate::load::program_name(e.trim(), self.m221);
        let (v, ty) = match at.eval(depth, &named) {
            Ok(x) => x,
            // A comparison (`count > 5`) as a breakpoint condition reads it.
            Err(err) => match super::cond::parse(e) {
                Ok(super::cond::Cond::Cmp(..)) if depth == 0 => {
                    let b = super::cond::holds(at, e)?;
                    (
                        V::Bool(b),
                        il_codegen::ir::types::Ty::Elem(il_codegen::ir::types::Elem::BOOL),
                    )
                }
                _ => return Err(err),
            },
        };
        let ty = ty.to_string();
        let reference = if compound(&v) {
            self.handle(Handle::Path(depth, e.trim().to_string()))
        } else {
            0
        };
        Ok(json!({ "result": shown(&v, &ty), "type": ty, "variablesReference": reference }))
    }

    pub(super) fn set_variable(
        &mut self,
        at: &mut Here<'_>,
        args: &Value,
    ) -> Result<Value, String> {
        let r = args
            .get("variablesReference")
            .and_then(Value::as_u64)
            .unwrap_or(0) as usize;
        let name = args
            .get("name")
            .and_then(Value::as_str)
            .ok_or("setVariable needs `name`")?;
        let value = args
            .get("value")
            .and_then(Value::as_str)
            .ok_or("setVariable needs `value`")?;
        let h = r.checked_sub(1).and_then(|i| self.handles.get(i)).cloned();
        // Any frame's: an outer frame's variable is written when the call
        // it is in returns (its view shows the value now).
        let (depth, path) = match h {
            Some(Handle::Section(d, _) | Handle::Image(d)) => (d, name.to_string()),
            Some(Handle::Path(d, p)) if name.starts_with('[') => (d, format!("{p}{name}")),
            Some(Handle::Path(d, p)) => (d, format!("{p}.{name}")),
            Some(Handle::Result(_)) => {
                return Err("a FUNCTION's result is set by its own instructions".into());
            }
            Some(Handle::Globals(_)) => {
                return Err(
                    "a global is set through a program's VAR_EXTERNAL (or with force)".into(),
                );
            }
            _ => return Err(format!("`{name}` cannot be set here")),
        };
        let v = at.set_in(depth, &path, value)?;
        let (_, ty) = at.eval(depth, &path)?;
        let ty = ty.to_string();
        Ok(json!({ "value": shown(&v, &ty), "type": ty }))
    }
}

/// Variables the compiler adds (`__...`) are not the user's.
fn hidden(name: &str) -> bool {
    name.starts_with("__")
}
