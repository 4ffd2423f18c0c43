//! Breakpoints: IL lines (verified against the lines that hold an
//! instruction, moved to the next such line, refused with a reason), with
//! conditions, hit counts and log messages; function breakpoints on a POU.

use std::collections::HashMap;

use serde_json::{Value, json};

use super::Base;
use crate::source_map::SourceMap;
use il_codegen::ir::{Op, Program};

/// `hitCondition`: `5` (from the 5th hit on), `>= 5`, `> 5`, `== 5`, `% 5`
/// (every 5th), `< 5`, `<= 5`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Hit {
    AtLeast(u64),
    Above(u64),
    Exactly(u64),
    Every(u64),
    Below(u64),
    AtMost(u64),
}

impl Hit {
    pub fn parse(s: &str) -> Result<Hit, String> {
        let s = s.trim();
        let (op, n) = match s.find(|c: char| c.is_ascii_digit()) {
            Some(i) => (s[..i].trim(), s[i..].trim()),
            None => return Err(format!("hit count `{s}` has no number")),
        };
        let n: u64 = n
            .parse()
            .map_err(|_| format!("hit count `{s}`: `{n}` is not a whole number"))?;
        Ok(match op {
            "" | ">=" => Hit::AtLeast(n),
            ">" => Hit::Above(n),
            "=" | "==" => Hit::Exactly(n),
            "%" if n > 0 => Hit::Every(n),
            "<" => Hit::Below(n),
            "<=" => Hit::AtMost(n),
            _ => {
                return Err(format!(
                    "hit count `{s}`: write N, >= N, > N, == N, % N, < N or <= N"
                ));
            }
        })
    }

    pub fn holds(self, hits: u64) -> bool {
        match self {
            Hit::AtLeast(n) => hits >= n,
            Hit::Above(n) => hits > n,
            Hit::Exactly(n) => hits == n,
            Hit::Every(n) => hits.is_multiple_of(n),
            Hit::Below(n) => hits < n,
            Hit::AtMost(n) => hits <= n,
        }
    }
}

/// One breakpoint as the client set it, verified.
#[derive(Clone, Debug)]
pub struct Bp {
    pub id: i64,
    pub condition: Option<String>,
    pub hit: Option<Hit>,
    pub log: Option<String>,
    /// How often the condition held (what the hit count counts).
    pub hits: u64,
}

#[derive(Default)]
pub struct Breakpoints {
    /// By input (its index in the program's files) and the user's line
    /// there, from 1 (verified: a line that holds an instruction).
    pub lines: HashMap<(usize, u32), Vec<Bp>>,
    /// By POU name in upper case.
    pub functions: HashMap<String, Vec<Bp>>,
    /// Scan breakpoints (a function breakpoint named `scan N`): id and scan.
    pub scans: Vec<(i64, u64)>,
    /// Stop on runtime faults (the `faults` exception filter).
    pub faults: bool,
    next_id: i64,
}

/// The lines of each POU of input `file` that hold an instruction,
/// sorted, with the POU's name.
fn instruction_lines((prog, src): (&Program, &SourceMap), file: usize) -> Vec<(String, Vec<u32>)> {
    let mut pous: Vec<(String, Vec<u32>)> = prog
        .pous
        .iter()
        .filter(|p| src.file_of(&p.name) == file)
        .map(|p| {
            let mut lines: Vec<u32> = p
                .body
                .iter()
                .filter(|s| !matches!(s.op, Op::Label(_) | Op::Nop))
                .map(|s| src.line(&p.name, s.line))
                .collect();
            lines.sort_unstable();
            lines.dedup();
            (p.name.clone(), lines)
        })
        .filter(|(_, l)| !l.is_empty())
        .collect();
    pous.sort_by_key(|(_, l)| l[0]);
    pous
}

/// Where a breakpoint asked for on `line` (from 1) of input `file` goes:
/// the line itself when it holds an instruction, else the next one that
/// does in the same POU (the first POU whose last instruction is not
/// above `line`), or `None`.
pub fn place(prog: (&Program, &SourceMap), file: usize, line: u32) -> Option<u32> {
    instruction_lines(prog, file)
        .into_iter()
        .find_map(|(_, lines)| lines.into_iter().find(|&l| l >= line))
}

impl Breakpoints {
    fn id(&mut self) -> i64 {
        self.next_id += 1;
        self.next_id
    }

    /// The breakpoint `b` asks for, with the id the answer gives it.
    fn bp(&mut self, id: i64, b: &Value) -> Result<Bp, String> {
        let text = |k: &str| {
            b.get(k)
                .and_then(Value::as_str)
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .map(str::to_string)
        };
        let hit = text("hitCondition").map(|h| Hit::parse(&h)).transpose()?;
        if let Some(c) = text("condition") {
            super::cond::parse(&c)?;
        }
        Ok(Bp {
            id,
            condition: text("condition"),
            hit,
            log: text("logMessage"),
            hits: 0,
        })
    }

    /// `setBreakpoints` for one file of the launched program (they replace
    /// that file's): the answer's body, lines numbered as the client does.
    pub fn set_lines(
        &mut self,
        prog: (&Program, &SourceMap),
        base: Base,
        args: &Value,
    ) -> Result<Value, String> {
        let path = args
            .pointer("/source/path")
            .and_then(Value::as_str)
            .unwrap_or("");
        let files = prog.1.files();
        let file = match files.iter().position(|f| same_file(path, &f.path)) {
            Some(k) => k,
            // No path: the program's only file.
            None if path.is_empty() && files.len() == 1 => 0,
            None if path.is_empty() => {
                return Err(
                    "setBreakpoints needs `source.path`: the program has several files".into(),
                );
            }
            None => {
                let names: Vec<&str> = files.iter().map(|f| f.path.as_str()).collect();
                let mut out = Vec::new();
                for b in args
                    .get("breakpoints")
                    .and_then(Value::as_array)
                    .into_iter()
                    .flatten()
                {
                    let id = self.id();
                    out.push(json!({ "id": id, "verified": false, "line": b.get("line"),
                        "message": format!("`{path}` is not a file of the launched program (`{}`)", names.join("`, `")) }));
                }
                return Ok(json!({ "breakpoints": out }));
            }
        };
        self.lines.retain(|(f, _), _| *f != file);
        let asked = args
            .get("breakpoints")
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default();
        let mut out = Vec::new();
        for b in &asked {
            // Messages name lines as the client numbers them.
            let line = b.get("line").and_then(Value::as_u64).unwrap_or(0);
            let refuse = |id: i64, why: String| json!({ "id": id, "verified": false, "line": line, "message": why });
            let id = self.id();
            let Some(from1) = base.read(line) else {
                out.push(refuse(id, format!("there is no line {line}")));
                continue;
            };
            let Some(at) = place(prog, file, from1) else {
                out.push(refuse(
                    id,
                    format!(
                        "line {line} holds no instruction, and no instruction of a POU follows it"
                    ),
                ));
                continue;
            };
            match self.bp(id, b) {
                Ok(bp) => {
                    self.lines.entry((file, at)).or_default().push(bp);
                    let mut v = json!({ "id": id, "verified": true, "line": base.out(at) });
                    if at != from1 {
                        v["message"] =
                            json!(format!("moved from line {line}: it holds no instruction"));
                    }
                    out.push(v);
                }
                Err(why) => out.push(refuse(id, why)),
            }
        }
        Ok(json!({ "breakpoints": out }))
    }

    /// `setFunctionBreakpoints`: stop at the first instruction of a POU,
    /// or (named `scan N`) at the first instruction of scan N.
    pub fn set_functions(
        &mut self,
        (prog, src): (&Program, &SourceMap),
        base: Base,
        args: &Value,
    ) -> Value {
        self.functions.clear();
        self.scans.clear();
        let asked = args
            .get("breakpoints")
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default();
        let mut out = Vec::new();
        for b in &asked {
            let name = b.get("name").and_then(Value::as_str).unwrap_or("").trim();
            if let Some(n) = scan_number(name) {
                let id = self.id();
                match n {
                    Some(n) => {
                        self.scans.push((id, n));
                        out.push(json!({ "id": id, "verified": true }));
                    }
                    None => out.push(json!({ "id": id, "verified": false,
                        "message": format!("`{name}`: scans are numbered from 1") })),
                }
                continue;
            }
            let pou = prog.pous.iter().find(|p| p.name.eq_ignore_ascii_case(name));
            let id = self.id();
            match (pou, self.bp(id, b)) {
                (Some(p), Ok(bp)) if !p.body.is_empty() => {
                    let line = base.out(src.line(&p.name, p.body[0].line));
                    self.functions
                        .entry(p.name.to_ascii_uppercase())
                        .or_default()
                        .push(bp);
                    out.push(json!({ "id": id, "verified": true, "line": line,
                        "source": super::source(src.path_of(&p.name)) }));
                }
                (Some(p), Ok(_)) => out.push(json!({ "id": id, "verified": false,
                    "message": format!("{} has no instructions", p.name) })),
                (None, _) => {
                    let names = prog.pous.iter().map(|p| p.name.as_str());
                    let hint = il_codegen::diag::suggest(name, names)
                        .map(|s| format!("; did you mean `{s}`?"))
                        .unwrap_or_default();
                    out.push(json!({ "id": id, "verified": false,
                        "message": format!("no POU named `{name}`{hint}") }))
                }
                (_, Err(why)) => out.push(json!({ "id": id, "verified": false, "message": why })),
            }
        }
        json!({ "breakpoints": out })
    }
}

/// `scan 3` → `Some(Some(3))`; `scan 0`, `scan x` → `Some(None)`; a POU name → `None`.
fn scan_number(name: &str) -> Option<Option<u64>> {
    let (word, n) = name.split_once(char::is_whitespace)?;
    if !word.eq_ignore_ascii_case("scan") {
        return None;
    }
    Some(n.trim().parse::<u64>().ok().filter(|&n| n >= 1))
}

/// Whether a client's path names the launched file (both as given, or both
/// resolved: clients send absolute paths, launch.json may hold a relative one).
fn same_file(a: &str, b: &str) -> bool {
    if a == b {
        return true;
    }
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hit_counts() {
        assert_eq!(Hit::parse("3"), Ok(Hit::AtLeast(3)));
        assert_eq!(Hit::parse("% 2"), Ok(Hit::Every(2)));
        assert!(Hit::parse("%0").is_err());
        assert!(Hit::parse("lots").is_err());
        assert!(Hit::parse("!3").is_err());
        assert!(Hit::Every(2).holds(4) && !Hit::Every(2).holds(3));
        assert!(Hit::Exactly(2).holds(2) && !Hit::Exactly(2).holds(3));
    }
}
