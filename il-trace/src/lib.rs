//! # il-trace — waveforms of IEC 61131-3 programs
//!
//! A [`Recorder`] writes the variables a generated FUNCTION_BLOCK, PROGRAM or
//! CONFIGURATION offers through `visit` (see [`il_std::trace`]) as a Value
//! Change Dump (IEEE 1364 §18), which GTKWave and Surfer show as waveforms.
//! The host calls [`Recorder::sample`] once per scan, after the scan:
//!
//! ```
//! use il_std::trace::{Visit, Visitor};
//! use il_std::{Cycle, TIME, TON};
//! let mut ctx = Cycle::new();
//! let mut t = TON::new();
//! t.PT = TIME::from_ms(20);
//! let mut buf = Vec::new();
//! let mut rec = il_trace::Recorder::new(&mut buf, "delay", TIME::from_ms(10)).unwrap();
//! for k in 0..4 {
//!     t.IN = k >= 1;
//!     t.call(&mut ctx);
//!     rec.sample(ctx.now(), &t).unwrap();
//!     ctx.advance(TIME::from_ms(10));
//! }
//! rec.finish().unwrap();
//! let vcd = String::from_utf8(buf).unwrap();
//! assert!(vcd.contains("$timescale 1 ms $end"));
//! assert!(vcd.contains("$var wire 1 ! IN $end"));
//! ```
//!
//! How IEC types are written: BOOL as a 1-bit `wire`; integers and bit strings
//! as `wire` vectors of their width (two's complement); REAL and LREAL as
//! `real`; TIME, LTIME, TIME_OF_DAY and DATE_AND_TIME as an `integer` counting
//! the timescale unit (truncated toward zero), DATE as an `integer` counting
//! days; enumerations as an `integer` of their value, each change followed by a
//! `$comment` naming the value; STRING and WSTRING as `string` variables (an
//! extension GTKWave and Surfer read), whitespace written as `\x20`-style escapes.
//! To write a file, [`AtomicFile`] makes sure that a host that stops halfway
//! (or an error) leaves no half-written dump behind.
//!
//! Each FB instance and STRUCT is a `$scope module`, elements of arrays are
//! named `a[1]` and `m[1,2]`.

pub mod read;

use std::fs;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use il_std::TIME;
use il_std::trace::{Value, Visit, Visitor};
use vcd::{IdCode, TimescaleUnit, VarType};

/// The timescale unit of a scan period: the coarsest of s, ms, us and ns
/// that divides it (so every scan falls on a whole tick), and its length in ns.
pub fn timescale(step: TIME) -> (TimescaleUnit, i64) {
    let ns = step.0;
    for (unit, len) in [
        (TimescaleUnit::S, 1_000_000_000),
        (TimescaleUnit::MS, 1_000_000),
        (TimescaleUnit::US, 1_000),
    ] {
        if ns > 0 && ns % len == 0 {
            return (unit, len);
        }
    }
    (TimescaleUnit::NS, 1)
}

/// A value as written: bits of a vector, a real or a string.
#[derive(Clone, Debug, PartialEq)]
enum Enc {
    Bits(u64),
    Real(u64),
    Str(String),
}

/// How a variable is declared in the header.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Wire(u32),
    Integer,
    Real,
    Str,
}

struct Signal {
    id: IdCode,
    kind: Kind,
    last: Enc,
}

/// Writes a VCD of the variables a block offers, one sample per scan.
pub struct Recorder<W: Write> {
    out: vcd::Writer<W>,
    top: String,
    tick_ns: i64,
    unit: TimescaleUnit,
    signals: Vec<Signal>,
    started: bool,
    last_tick: Option<u64>,
    /// The last `#time` written (only changes are).
    written_tick: Option<u64>,
    finished: bool,
}

impl<W: Write> Recorder<W> {
    /// A recorder writing to `w`; `top` names the outer scope (the instance),
    /// `step` (the scan period) chooses the timescale ([`timescale`]).
    pub fn new(w: W, top: &str, step: TIME) -> io::Result<Recorder<W>> {
        let (unit, tick_ns) = timescale(step);
        let mut out = vcd::Writer::new(w);
        out.version(concat!("il-trace ", env!("CARGO_PKG_VERSION")))?;
        out.timescale(1, unit)?;
        out.comment(&format!(
            "TIME, LTIME, TOD and DT values count {unit} (the timescale unit); DATE values count days"
        ))?;
        Ok(Recorder {
            out,
            top: clean(top),
            tick_ns,
            unit,
            signals: Vec::new(),
            started: false,
            last_tick: None,
            written_tick: None,
            finished: false,
        })
    }

    /// The timescale unit chosen.
    pub fn unit(&self) -> TimescaleUnit {
        self.unit
    }

    /// Record the variables of `block` at time `now` (after a scan).
    pub fn sample(&mut self, now: TIME, block: &dyn Visit) -> io::Result<()> {
        self.sample_with(now, |v| block.visit(v))
    }

    /// Record at time `now` whatever `f` offers the visitor it is given: the
    /// first call declares the variables (every later call must offer the
    /// same ones in the same order), each later call writes what changed.
    pub fn sample_with(&mut self, now: TIME, f: impl FnOnce(&mut dyn Visitor)) -> io::Result<()> {
        let tick = u64::try_from(now.0.div_euclid(self.tick_ns))
            .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "sample time before 0"))?;
        if self.last_tick.is_some_and(|t| tick < t) {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                format!("sample time {tick} {} goes backwards", self.unit),
            ));
        }
        if self.finished {
            return Err(io::Error::other("sample after finish"));
        }
        let first = !self.started;
        let mut pass = Pass {
            rec: self,
            first,
            index: 0,
            depth: 0,
            changes: Vec::new(),
            err: None,
            path: Vec::new(),
        };
        if first {
            let top = pass.rec.top.clone();
            pass.try_io(|o| o.add_module(&top));
        }
        f(&mut pass);
        let Pass {
            index,
            depth,
            changes,
            err,
            ..
        } = pass;
        if let Some(e) = err {
            return Err(e);
        }
        if depth != 0 {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "enter and leave do not match",
            ));
        }
        if index != self.signals.len() {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "the variables offered changed between samples",
            ));
        }
        if first {
            self.out.upscope()?;
            self.out.enddefinitions()?;
            self.out.timestamp(tick)?;
            self.written_tick = Some(tick);
            self.out.begin(vcd::SimulationCommand::Dumpvars)?;
            for i in 0..self.signals.len() {
                self.write_value(i)?;
            }
            self.out.end()?;
            // Enumerations: the names of their first values.
            for (_, _, note) in changes {
                if let Some(n) = note {
                    self.out.comment(&n)?;
                }
            }
            self.started = true;
        } else if !changes.is_empty() {
            self.out.timestamp(tick)?;
            self.written_tick = Some(tick);
            for (i, enc, note) in changes {
                self.signals[i].last = enc;
                self.write_value(i)?;
                if let Some(n) = note {
                    self.out.comment(&n)?;
                }
            }
        }
        self.last_tick = Some(tick);
        Ok(())
    }

    fn write_value(&mut self, i: usize) -> io::Result<()> {
        let s = &self.signals[i];
        match (&s.last, s.kind) {
            (Enc::Bits(b), Kind::Wire(1)) => self.out.change_scalar(s.id, *b & 1 == 1),
            (Enc::Bits(b), Kind::Wire(w)) => self.out.change_vector(s.id, bits(*b, w)),
            (Enc::Bits(b), _) => self.out.change_vector(s.id, bits(*b, 64)),
            (Enc::Real(r), _) => self.out.change_real(s.id, f64::from_bits(*r)),
            (Enc::Str(t), _) => self.out.change_string(s.id, t),
        }
    }

    /// Flush; the dump is complete. Later samples are refused. The time of
    /// the last sample is written even when nothing changed in it, so that
    /// a viewer's time axis (GTKWave ends it at the last time in the file)
    /// covers the whole run.
    pub fn finish(&mut self) -> io::Result<()> {
        if let Some(last) = self.last_tick
            && self.started
            && !self.finished
            && self.written_tick.is_some_and(|w| w < last)
        {
            self.out.timestamp(last)?;
            self.written_tick = Some(last);
        }
        if !self.started {
            // A header with no samples is still a valid (empty) dump.
            self.out.add_module(&self.top)?;
            self.out.upscope()?;
            self.out.enddefinitions()?;
            self.started = true;
        }
        self.finished = true;
        self.out.flush()
    }

    /// The writer, e.g. to [`AtomicFile::commit`] it after [`Recorder::finish`].
    pub fn get_mut(&mut self) -> &mut W {
        self.out.writer()
    }
}

/// The bits of `b` of width `w`, most significant first, leading zeros left
/// out (VCD extends a vector whose first bit is 0 with zeros).
fn bits(b: u64, w: u32) -> impl Iterator<Item = vcd::Value> {
    let w = w.clamp(1, 64);
    let b = if w < 64 { b & ((1u64 << w) - 1) } else { b };
    let top = (64 - b.leading_zeros()).clamp(1, w);
    (0..top)
        .rev()
        .map(move |k| vcd::Value::from(b >> k & 1 == 1))
}

/// A vector's declared width: 1 to 64 bits.
fn width(bits: u8) -> u32 {
    u32::from(bits).clamp(1, 64)
}

/// A name with no whitespace (VCD separates tokens by it).
fn clean(name: &str) -> String {
    name.chars().filter(|c| !c.is_whitespace()).collect()
}

/// `name[1,2]`.
fn indexed(name: &str, index: &[i64]) -> String {
    let ix: Vec<String> = index.iter().map(i64::to_string).collect();
    format!("{}[{}]", clean(name), ix.join(","))
}

/// A string value with whitespace, `\` and control characters as `\xNN`.
fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        if c.is_whitespace() || c.is_control() || c == '\\' {
            for u in c.to_string().bytes() {
                out.push_str(&format!("\\x{u:02x}"));
            }
        } else {
            out.push(c);
        }
    }
    out
}

/// One pass of the visitor over the variables.
struct Pass<'r, W: Write> {
    rec: &'r mut Recorder<W>,
    first: bool,
    index: usize,
    depth: usize,
    changes: Vec<(usize, Enc, Option<String>)>,
    err: Option<io::Error>,
    /// The scopes entered, for naming enumeration values in comments.
    path: Vec<String>,
}

impl<W: Write> Pass<'_, W> {
    fn try_io(&mut self, f: impl FnOnce(&mut vcd::Writer<W>) -> io::Result<()>) {
        if self.err.is_none()
            && let Err(e) = f(&mut self.rec.out)
        {
            self.err = Some(e);
        }
    }

    fn scope(&mut self, name: String) {
        self.depth += 1;
        if self.first {
            self.try_io(|o| o.add_module(&name));
        }
        self.path.push(name);
    }

    /// `tank.state = Filling`: the variable's path below the top scope.
    fn note(&self, name: &str, value: &str) -> String {
        let mut p = self.path.join(".");
        if !p.is_empty() {
            p.push('.');
        }
        format!("{p}{name} = {value}")
    }

    fn signal(&mut self, name: String, value: Value<'_>) {
        let tick = self.rec.tick_ns;
        let (kind, enc) = match value {
            Value::Bool(b) => (Kind::Wire(1), Enc::Bits(b as u64)),
            Value::Int { value, bits } => (Kind::Wire(width(bits)), Enc::Bits(value as u64)),
            Value::UInt { value, bits } => (Kind::Wire(width(bits)), Enc::Bits(value)),
            Value::Real(r) => (Kind::Real, Enc::Real(r.to_bits())),
            Value::Time(ns) => (Kind::Integer, Enc::Bits((ns / tick) as u64)),
            Value::Date(d) => (Kind::Integer, Enc::Bits(d as u64)),
            Value::Enum { value, .. } => (Kind::Integer, Enc::Bits(value as u64)),
            Value::Str(b) => (Kind::Str, Enc::Str(escape(&String::from_utf8_lossy(b)))),
            Value::WStr(u) => (Kind::Str, Enc::Str(escape(&String::from_utf16_lossy(u)))),
        };
        let i = self.index;
        self.index += 1;
        if self.first {
            let (ty, width) = match kind {
                Kind::Wire(w) => (VarType::Wire, w),
                Kind::Integer => (VarType::Integer, 64),
                Kind::Real => (VarType::Real, 64),
                Kind::Str => (VarType::String, 1),
            };
            let mut id = None;
            self.try_io(|o| {
                id = Some(o.add_var(ty, width, &name, None)?);
                Ok(())
            });
            if let Value::Enum { name: v, .. } = value {
                let note = self.note(&name, v);
                self.changes.push((i, enc.clone(), Some(note)));
            }
            if let Some(id) = id {
                self.rec.signals.push(Signal {
                    id,
                    kind,
                    last: enc,
                });
            }
            return;
        }
        match self.rec.signals.get(i) {
            Some(s) if s.kind != kind && self.err.is_none() => {
                self.err = Some(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    format!("`{name}` changed its type between samples"),
                ));
            }
            Some(s) if s.last != enc => {
                let note = match value {
                    Value::Enum { name: v, .. } => Some(self.note(&name, v)),
                    _ => None,
                };
                self.changes.push((i, enc, note));
            }
            _ => {}
        }
    }
}

impl<W: Write> Visitor for Pass<'_, W> {
    fn enter(&mut self, name: &str) {
        self.scope(clean(name));
    }
    fn enter_elem(&mut self, name: &str, index: &[i64]) {
        self.scope(indexed(name, index));
    }
    fn leave(&mut self) {
        if self.depth == 0 {
            if self.err.is_none() {
                self.err = Some(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    "leave without enter",
                ));
            }
            return;
        }
        self.depth -= 1;
        self.path.pop();
        if self.first {
            self.try_io(|o| o.upscope());
        }
    }
    fn var(&mut self, name: &str, _ty: &str, value: Value<'_>) {
        self.signal(clean(name), value);
    }
    fn elem(&mut self, name: &str, index: &[i64], _ty: &str, value: Value<'_>) {
        self.signal(indexed(name, index), value);
    }
}

/// A file written under a temporary name beside its path and renamed into
/// place by [`AtomicFile::commit`]: until then the path keeps what it held,
/// and dropping an uncommitted file removes the temporary.
pub struct AtomicFile {
    tmp: PathBuf,
    path: PathBuf,
    file: Option<BufWriter<fs::File>>,
}

impl AtomicFile {
    /// Start writing `path` (its directory must exist).
    pub fn create(path: impl AsRef<Path>) -> io::Result<AtomicFile> {
        let path = path.as_ref().to_path_buf();
        let name = path
            .file_name()
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file name"))?;
        let mut tmp_name = std::ffi::OsString::from(".");
        tmp_name.push(name);
        tmp_name.push(format!(".{}.tmp", std::process::id()));
        let tmp = path.with_file_name(tmp_name);
        let file = fs::File::create(&tmp)?;
        Ok(AtomicFile {
            tmp,
            path,
            file: Some(BufWriter::new(file)),
        })
    }

    /// Flush, sync and rename the file into place (once).
    pub fn commit(&mut self) -> io::Result<()> {
        let done = match self.file.take() {
            Some(f) => f
                .into_inner()
                .map_err(io::IntoInnerError::into_error)
                .and_then(|f| f.sync_all())
                .and_then(|()| fs::rename(&self.tmp, &self.path)),
            None => Err(io::Error::other("file already committed")),
        };
        if done.is_err() {
            let _ = fs::remove_file(&self.tmp);
        }
        done
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.file {
            Some(f) => f.write(buf),
            None => Err(io::Error::other("file already committed")),
        }
    }
    fn flush(&mut self) -> io::Result<()> {
        match &mut self.file {
            Some(f) => f.flush(),
            None => Ok(()),
        }
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.file.take().is_some() {
            let _ = fs::remove_file(&self.tmp);
        }
    }
}
