//! Reading a dump back (with the `vcd` crate's parser): the value of each
//! variable at each time, for tests and tools that compare runs.

use std::collections::HashMap;
use std::io::{self, BufRead};

use vcd::{Command, IdCode, ScopeItem, TimescaleUnit};

/// A value as read.
#[derive(Clone, Debug, PartialEq)]
pub enum Sample {
    /// A wire or integer: its bits (zero-extended as VCD does).
    Bits(u64),
    /// A real.
    Real(f64),
    /// A string.
    Str(String),
}

impl Sample {
    /// The bits as a signed number of `width` bits (two's complement).
    pub fn signed(&self, width: u32) -> Option<i64> {
        match self {
            Sample::Bits(b) if width > 0 && width < 64 => {
                let shift = 64 - width;
                Some(((*b << shift) as i64) >> shift)
            }
            Sample::Bits(b) => Some(*b as i64),
            _ => None,
        }
    }
}

/// One variable of a dump.
#[derive(Clone, Debug)]
pub struct Signal {
    /// Scopes and the name: `["Motor", "t1", "Q"]`.
    pub path: Vec<String>,
    /// `wire`, `integer`, `real`, `string`.
    pub var_type: String,
    /// Declared width in bits.
    pub width: u32,
    /// Each change: time (in timescale units) and value, in time order.
    pub changes: Vec<(u64, Sample)>,
}

impl Signal {
    /// The value at time `t` (the last change at or before it).
    pub fn at(&self, t: u64) -> Option<&Sample> {
        self.changes
            .iter()
            .rev()
            .find(|(ct, _)| *ct <= t)
            .map(|(_, v)| v)
    }
}

/// A whole dump.
#[derive(Clone, Debug)]
pub struct Dump {
    /// `$timescale`.
    pub timescale: Option<(u32, TimescaleUnit)>,
    /// The variables in declaration order.
    pub signals: Vec<Signal>,
    /// The `$comment`s after the header, with the time they follow.
    pub comments: Vec<(u64, String)>,
}

impl Dump {
    /// The variable with this path joined by `.` (`Motor.t1.Q`).
    pub fn signal(&self, path: &str) -> Option<&Signal> {
        self.signals.iter().find(|s| s.path.join(".") == path)
    }
}

fn bad(msg: String) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, msg)
}

/// Parse a dump.
pub fn parse(r: impl BufRead) -> io::Result<Dump> {
    let mut p = vcd::Parser::new(r);
    let header = p.parse_header()?;
    let mut signals = Vec::new();
    let mut by_code: HashMap<IdCode, usize> = HashMap::new();
    fn walk(
        items: &[ScopeItem],
        path: &mut Vec<String>,
        out: &mut Vec<Signal>,
        by_code: &mut HashMap<IdCode, usize>,
    ) {
        for it in items {
            match it {
                ScopeItem::Scope(s) => {
                    path.push(s.identifier.clone());
                    walk(&s.items, path, out, by_code);
                    path.pop();
                }
                ScopeItem::Var(v) => {
                    let mut p = path.clone();
                    p.push(v.reference.clone());
                    by_code.insert(v.code, out.len());
                    out.push(Signal {
                        path: p,
                        var_type: v.var_type.to_string(),
                        width: v.size,
                        changes: Vec::new(),
                    });
                }
                _ => {}
            }
        }
    }
    walk(&header.items, &mut Vec::new(), &mut signals, &mut by_code);
    let mut now = 0u64;
    let mut comments = Vec::new();
    for c in p {
        let mut put = |code: IdCode, v: Sample| -> io::Result<()> {
            let i = *by_code
                .get(&code)
                .ok_or_else(|| bad(format!("change of undeclared {code}")))?;
            signals[i].changes.push((now, v));
            Ok(())
        };
        match c? {
            Command::Timestamp(t) => now = t,
            Command::ChangeScalar(code, v) => {
                put(code, Sample::Bits((v == vcd::Value::V1) as u64))?;
            }
            Command::ChangeVector(code, v) => {
                let mut b = 0u64;
                for x in v.iter() {
                    if !matches!(x, vcd::Value::V0 | vcd::Value::V1) {
                        return Err(bad(format!("{code}: x or z in a vector")));
                    }
                    b = b << 1 | (x == vcd::Value::V1) as u64;
                }
                put(code, Sample::Bits(b))?;
            }
            Command::ChangeReal(code, r) => put(code, Sample::Real(r))?,
            Command::ChangeString(code, s) => put(code, Sample::Str(s))?,
            Command::Comment(s) => comments.push((now, s)),
            _ => {}
        }
    }
    Ok(Dump {
        timescale: header.timescale,
        signals,
        comments,
    })
}
