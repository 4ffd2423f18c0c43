//! A trace of any generated program, from its `visit` (il-std's `Visitor`):
//! a header of every elementary variable's path (`s1.t.ET`) and one line of
//! their values per scan, as `ilc run --watch PATHS` prints them. The size
//! check compares its 2,000-line program with the interpreter this way.
//! Lines start with `x ` to keep them apart from the example's own trace.

use cortex_m_semihosting::hprint;
use il_std::trace::{Value, Visit, Visitor};
use il_std::{LTIME, TIME};

/// Prints the header (`x cycle time PATH...`).
pub fn header(p: &dyn Visit) {
    hprint!("x cycle time");
    p.visit(&mut Trace::new(true));
    hprint!("\n");
}

/// Prints scan `k`'s line (`x K TIME VALUE...`).
pub fn line(k: u32, now: TIME, p: &dyn Visit) {
    hprint!("x {} {}", k, now);
    p.visit(&mut Trace::new(false));
    hprint!("\n");
}

/// The path of the instance being visited, as bytes (names are ASCII
/// identifiers), and whether to print paths or values.
struct Trace {
    path: [u8; 128],
    len: usize,
    /// Where each entered level began in `path`.
    marks: [usize; 16],
    depth: usize,
    names: bool,
}

impl Trace {
    fn new(names: bool) -> Self {
        Trace {
            path: [0; 128],
            len: 0,
            marks: [0; 16],
            depth: 0,
            names,
        }
    }

    fn push(&mut self, s: &[u8]) {
        for &b in s {
            if let Some(slot) = self.path.get_mut(self.len) {
                *slot = b;
                self.len += 1;
            }
        }
    }

    /// The current path, then `name` (and `[i,j]`).
    fn print_path(&self, name: &str, index: &[i64]) {
        let prefix = core::str::from_utf8(&self.path[..self.len]).unwrap_or("?");
        hprint!(" {}{}", prefix, name);
        print_index(index);
    }

    fn print_value(ty: &str, value: Value<'_>) {
        match value {
            Value::Bool(b) => hprint!(" {}", if b { "TRUE" } else { "FALSE" }),
            Value::Int { value, .. } => hprint!(" {}", value),
            Value::UInt { value, .. } => hprint!(" {}", value),
            // REAL is widened to f64 for tools; ilc prints it as f32.
            Value::Real(f) if ty == "REAL" => hprint!(" {:?}", f as f32),
            Value::Real(f) => hprint!(" {:?}", f),
            Value::Time(ns) if ty == "TIME" => hprint!(" {}", TIME(ns)),
            Value::Time(ns) if ty == "LTIME" => hprint!(" {}", LTIME(ns)),
            Value::Enum { name, .. } => hprint!(" {}#{}", ty, name),
            // Not in the size check's program; shown so that a diff fails.
            _ => hprint!(" <{}>", ty),
        }
    }
}

fn print_index(index: &[i64]) {
    for (n, i) in index.iter().enumerate() {
        hprint!("{}{}", if n == 0 { "[" } else { "," }, i);
    }
    if !index.is_empty() {
        hprint!("]");
    }
}

impl Visitor for Trace {
    fn enter(&mut self, name: &str) {
        self.enter_elem(name, &[]);
    }
    fn enter_elem(&mut self, name: &str, index: &[i64]) {
        if let Some(m) = self.marks.get_mut(self.depth) {
            *m = self.len;
        }
        self.depth += 1;
        self.push(name.as_bytes());
        for (n, i) in index.iter().enumerate() {
            self.push(if n == 0 { b"[" } else { b"," });
            // An index as decimal digits.
            let mut digits = [0u8; 20];
            let (mut v, mut at) = (i.unsigned_abs(), digits.len());
            loop {
                at -= 1;
                digits[at] = b'0' + (v % 10) as u8;
                v /= 10;
                if v == 0 {
                    break;
                }
            }
            if *i < 0 {
                self.push(b"-");
            }
            self.push(&digits[at..]);
        }
        if !index.is_empty() {
            self.push(b"]");
        }
        self.push(b".");
    }
    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
        self.len = self.marks.get(self.depth).copied().unwrap_or(0);
    }
    fn var(&mut self, name: &str, ty: &str, value: Value<'_>) {
        self.elem(name, &[], ty, value);
    }
    fn elem(&mut self, name: &str, index: &[i64], ty: &str, value: Value<'_>) {
        if self.names {
            self.print_path(name, index);
        } else {
            Self::print_value(ty, value);
        }
    }
}
