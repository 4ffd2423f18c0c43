//! `ilc run --vcd` and `--plot`: the watched variables of each scan offered
//! to an `il_std::trace::Visitor`, as generated code offers its variables,
//! so that the dump is written by the same recorder a host uses (il-trace).

use std::path::PathBuf;

use il_codegen::ir::types::{Elem, Ty};
use il_codegen::ir::{Program, TypeDef};
use il_interp::Value;
use il_interp::il_std::TIME;
use il_interp::il_std::trace::{Value as TValue, Visitor};
use il_trace::{AtomicFile, Recorder};

use crate::plot::{Lanes, Plot};

/// The watched places grouped by the scopes their names go through, in the
/// order they were first named: `t1.Q, start, t1.ET` is `t1 { Q, ET }, start`.
#[derive(Default)]
struct Tree {
    items: Vec<Item>,
}

enum Item {
    /// Watched place `i`, under its last name.
    Leaf(usize, String),
    Scope(String, Tree),
}

impl Tree {
    fn insert(&mut self, scopes: &[String], leaf: usize, name: String) {
        match scopes.split_first() {
            None => self.items.push(Item::Leaf(leaf, name)),
            Some((s, rest)) => {
                let found = self.items.iter_mut().find_map(|it| match it {
                    Item::Scope(n, t) if n == s => Some(t),
                    _ => None,
                });
                match found {
                    Some(t) => t.insert(rest, leaf, name),
                    None => {
                        let mut t = Tree::default();
                        t.insert(rest, leaf, name);
                        self.items.push(Item::Scope(s.clone(), t));
                    }
                }
            }
        }
    }
}

/// `a.b[1].c` → `["a", "b[1]"]`, `"c"`; a direct address (`%IX0.0`) is one
/// name. The path is read by the IR's host-path parser (constant
/// subscripts folded: `m[1 + 1]` is `m[2]`); text it refuses (which the
/// interpreter refused first) is one name.
fn split_path(text: &str) -> (Vec<String>, String) {
    use il_codegen::ir::path::{PathPart, parse};
    let flat = || {
        (
            Vec::new(),
            text.chars().filter(|c| !c.is_whitespace()).collect(),
        )
    };
    if text.trim_start().starts_with('%') {
        return flat();
    }
    let Ok(p) = parse(text) else { return flat() };
    let mut names = vec![p.root];
    for part in p.parts {
        match part {
            PathPart::Field(f) => names.push(f),
            PathPart::Index(subs) => {
                let subs: Vec<String> = subs.iter().map(i64::to_string).collect();
                if let Some(last) = names.last_mut() {
                    last.push_str(&format!("[{}]", subs.join(",")));
                }
            }
        }
    }
    let last = names.pop().unwrap_or_default();
    (names, last)
}

/// What is recorded of a run.
pub struct Waves<'p> {
    prog: &'p Program,
    top: String,
    tree: Tree,
    tys: Vec<Ty>,
    vcd: Option<(PathBuf, Recorder<AtomicFile>)>,
    plot: Option<(PathBuf, Lanes)>,
    /// The length of a timescale tick in ns, and the last sample's time:
    /// the `.gtkw` is zoomed to the run.
    tick_ns: i64,
    last: TIME,
    /// The watched places as named and their types.
    watched: Vec<(String, Ty)>,
}

impl<'p> Waves<'p> {
    /// `None` when neither output is asked for.
    pub fn new(
        prog: &'p Program,
        top: &str,
        watch: &[(String, Ty)],
        step: TIME,
        vcd: Option<&PathBuf>,
        plot: Option<&PathBuf>,
    ) -> Result<Option<Waves<'p>>, String> {
        if vcd.is_none() && plot.is_none() {
            return Ok(None);
        }
        let mut tree = Tree::default();
        for (i, p) in watch.iter().enumerate() {
            let (scopes, name) = split_path(&p.0);
            tree.insert(&scopes, i, name);
        }
        let vcd = match vcd {
            Some(path) => {
                let f = AtomicFile::create(path)
                    .map_err(|e| format!("--vcd {}: {e}", path.display()))?;
                let rec = Recorder::new(f, top, step)
                    .map_err(|e| format!("--vcd {}: {e}", path.display()))?;
                Some((path.clone(), rec))
            }
            None => None,
        };
        Ok(Some(Waves {
            prog,
            top: top.to_string(),
            tree,
            tys: watch.iter().map(|p| p.1.clone()).collect(),
            vcd,
            plot: plot.map(|p| (p.clone(), Lanes::new(step))),
            tick_ns: il_trace::timescale(step).1.max(1),
            last: TIME(0),
            watched: watch.to_vec(),
        }))
    }

    /// Record the values of the watched places after the scan at `now`.
    pub fn sample(&mut self, now: TIME, values: &[Value]) -> Result<(), String> {
        let offer = |v: &mut dyn Visitor| {
            offer_tree(v, &self.tree, values, &self.tys, self.prog);
        };
        if let Some((path, rec)) = &mut self.vcd {
            rec.sample_with(now, offer)
                .map_err(|e| format!("--vcd {}: {e}", path.display()))?;
        }
        if let Some((_, lanes)) = &mut self.plot {
            lanes.sample(now, offer);
        }
        self.last = now;
        Ok(())
    }

    /// Write the files (each complete, or not at all).
    pub fn finish(self) -> Result<(), String> {
        if let Some((path, mut rec)) = self.vcd {
            let err = |e: std::io::Error| format!("--vcd {}: {e}", path.display());
            rec.finish().map_err(err)?;
            rec.get_mut().commit().map_err(err)?;
            let end = u64::try_from(self.last.0 / self.tick_ns).unwrap_or(0);
            // Each watched enumeration's values, by its path in the dump.
            let mut enums = std::collections::BTreeMap::new();
            for (text, ty) in &self.watched {
                if let Ty::Enum(name) = ty {
                    let (mut scopes, leaf) = split_path(text);
                    scopes.push(leaf);
                    enums.insert(scopes.join("."), enum_values(self.prog, name.as_str()));
                }
            }
            write_save_files(&path, end, &enums)?;
        }
        if let Some((path, lanes)) = self.plot {
            Plot::new(&self.top, lanes)
                .write(&path)
                .map_err(|e| format!("--plot {}: {e}", path.display()))?;
        }
        Ok(())
    }
}

/// `FILE.gtkw` (and the enumerations' translate files) beside the dump,
/// from the dump as written.
fn write_save_files(
    vcd: &std::path::Path,
    end: u64,
    enums: &crate::gtkw::EnumValues,
) -> Result<(), String> {
    let err = |e: std::io::Error| format!("--vcd {}: {e}", vcd.display());
    let file = std::fs::File::open(vcd).map_err(err)?;
    let dump = il_trace::read::parse(std::io::BufReader::new(file)).map_err(err)?;
    let files = crate::gtkw::save_files(vcd, &dump, end, enums);
    for (path, text) in files.filters.iter().chain([&files.save]) {
        let mut f = AtomicFile::create(path).map_err(err)?;
        std::io::Write::write_all(&mut f, text.as_bytes()).map_err(err)?;
        f.commit().map_err(err)?;
    }
    Ok(())
}

fn offer_tree(v: &mut dyn Visitor, t: &Tree, values: &[Value], tys: &[Ty], prog: &Program) {
    for it in &t.items {
        match it {
            Item::Leaf(i, name) => {
                if let (Some(x), Some(ty)) = (values.get(*i), tys.get(*i)) {
                    offer(v, name, ty, x, prog);
                }
            }
            Item::Scope(name, sub) => {
                v.enter(name);
                offer_tree(v, sub, values, tys, prog);
                v.leave();
            }
        }
    }
}

fn type_def<'a>(prog: &'a Program, name: &str) -> Option<&'a TypeDef> {
    prog.types.iter().find(|d| match d {
        TypeDef::Struct { name: n, .. } | TypeDef::Enum { name: n, .. } => {
            n.eq_ignore_ascii_case(name)
        }
    })
}

/// Every value of an enumeration with its integer, for the `.gtkw`'s
/// translate file.
fn enum_values(prog: &Program, ty: &str) -> Vec<(i64, String)> {
    let mut out = Vec::new();
    if let Some(TypeDef::Enum { values, .. }) = type_def(prog, ty) {
        let mut next = 0i128;
        for (n, d) in values {
            let x = d.unwrap_or(next);
            out.push((x as i64, n.clone()));
            next = x + 1;
        }
    }
    out
}

/// The integer value of an enumeration value, as the generated Rust enum's
/// discriminant: explicit, or one more than the previous one.
fn enum_value(prog: &Program, ty: &str, value: &str) -> i64 {
    if let Some(TypeDef::Enum { values, .. }) = type_def(prog, ty) {
        let mut next = 0i128;
        for (n, d) in values {
            let x = d.unwrap_or(next);
            if n.eq_ignore_ascii_case(value) {
                return x as i64;
            }
            next = x + 1;
        }
    }
    0
}

/// Offer one value named `name` of type `ty`: a scalar as a variable, a
/// STRUCT as a scope of its fields, an array element by element.
fn offer(v: &mut dyn Visitor, name: &str, ty: &Ty, x: &Value, prog: &Program) {
    match (ty, x) {
        (Ty::Struct(_), Value::Struct(_)) => {
            v.enter(name);
            fields(v, ty, x, prog);
            v.leave();
        }
        (Ty::Array(a), Value::Array(items)) => {
            let (dims, elem) = (&a.dims, &a.elem);
            let mut ix: Vec<i64> = dims.iter().map(|(lo, _)| *lo).collect();
            for item in items {
                match (elem, item) {
                    (Ty::Struct(_), Value::Struct(_)) => {
                        v.enter_elem(name, &ix);
                        fields(v, elem, item, prog);
                        v.leave();
                    }
                    // Instances are not watched; nested arrays are not IEC.
                    (Ty::Fb(_) | Ty::Array { .. }, _) => {}
                    _ => scalar(elem, item, prog, &mut |t, s| v.elem(name, &ix, t, s)),
                }
                // Row-major: the last index runs fastest.
                for (k, (lo, hi)) in dims.iter().enumerate().rev() {
                    if ix[k] < *hi {
                        ix[k] += 1;
                        break;
                    }
                    ix[k] = *lo;
                }
            }
        }
        (Ty::Fb(_), _) => {}
        _ => scalar(ty, x, prog, &mut |t, s| v.var(name, t, s)),
    }
}

fn fields(v: &mut dyn Visitor, ty: &Ty, x: &Value, prog: &Program) {
    let (Ty::Struct(n), Value::Struct(s)) = (ty, x) else {
        return;
    };
    let Some(TypeDef::Struct { fields, .. }) = type_def(prog, n) else {
        return;
    };
    for (f, (_, fx)) in fields.iter().zip(&s.fields) {
        offer(v, &f.name, &f.ty, fx, prog);
    }
}

/// An elementary, string or enumeration value as the trace value generated
/// code would give for it.
fn scalar(ty: &Ty, x: &Value, prog: &Program, put: &mut dyn FnMut(&str, TValue<'_>)) {
    let tname = ty.to_string();
    let signed = |e: Elem| matches!(e, Elem::SINT | Elem::INT | Elem::DINT | Elem::LINT);
    match x {
        Value::Bool(b) => put(&tname, TValue::Bool(*b)),
        Value::Int(n, e) => {
            let bits = match e {
                Elem::SINT | Elem::USINT | Elem::BYTE => 8,
                Elem::INT | Elem::UINT | Elem::WORD => 16,
                Elem::DINT | Elem::UDINT | Elem::DWORD => 32,
                _ => 64,
            };
            if signed(*e) {
                put(
                    &tname,
                    TValue::Int {
                        value: *n as i64,
                        bits,
                    },
                )
            } else {
                put(
                    &tname,
                    TValue::UInt {
                        value: *n as u64,
                        bits,
                    },
                )
            }
        }
        Value::Real(f) => put(&tname, TValue::Real(*f as f64)),
        Value::LReal(f) => put(&tname, TValue::Real(*f)),
        Value::Time(n, Elem::DATE) => put(&tname, TValue::Date(*n)),
        Value::Time(n, _) => put(&tname, TValue::Time(*n)),
        Value::Enum { ty: et, value } => put(
            &tname,
            TValue::Enum {
                value: enum_value(prog, et, value),
                name: value,
            },
        ),
        Value::Str { units, wide: false } => {
            let bytes: Vec<u8> = units.iter().map(|&u| u as u8).collect();
            put(&tname, TValue::Str(&bytes))
        }
        Value::Str { units, wide: true } => put(&tname, TValue::WStr(units)),
        Value::Array(_) | Value::Struct(_) | Value::Fb(_) | Value::StdFb(_) => {}
    }
}

#[cfg(test)]
mod tests {
    use super::split_path;

    #[test]
    fn paths_split_at_dots_outside_brackets() {
        let s = |t: &str| split_path(t);
        assert_eq!(s("start"), (vec![], "start".to_string()));
        assert_eq!(s("t1.Q"), (vec!["t1".to_string()], "Q".to_string()));
        assert_eq!(
            s("valves[2].open"),
            (vec!["valves[2]".to_string()], "open".to_string())
        );
        assert_eq!(s("m[1, 2]"), (vec![], "m[1,2]".to_string()));
        assert_eq!(s("%IX0.0"), (vec![], "%IX0.0".to_string()));
        assert_eq!(
            s("line.t[3 MOD 2 + 1].Q"),
            (
                vec!["line".to_string(), "t[2]".to_string()],
                "Q".to_string()
            )
        );
    }
}
