//! # il-examples — IEC 61131-3 Instruction List programs driven from Rust
//!
//! Each module runs one PLC program over simulated time and returns its
//! [`Timeline`]: one row per scan in which an input or an output changed.
//! The binaries in `examples/` print it (`cargo run -p il-examples --example
//! traffic_light`), and the tests in `tests/` check the same time-lines.
//!
//! | module | IL | front end | shows |
//! |---|---|---|---|
//! | [`traffic_light`] | `plc/traffic_light.il` | build.rs | TON, `MUX`, forward jumps, `RET` |
//! | [`motor_starter`] | `plc/motor_starter.il` | build.rs | SR, RS, R_TRIG, located variables, the process image |
//! | [`conveyor`] | `plc/conveyor.il` | build.rs | CTU, CTD, TP, input operators |
//! | [`batch_weigh`] | `plc/batch_weigh.il` | build.rs | a FUNCTION with EN/ENO, BCD, parentheses, a recorded fault |
//! | [`stair_light`] | inline in `src/stair_light.rs` | `il!` | TOF, TIME comparison |
//! | [`readme_motor`] | `motor.il` (the README's) | `il!(file = ...)` | R_TRIG, a forward jump |
//! | [`trace_motor`] | `motor.il` | `il!(file = ...)` | `visit` and il-trace: a VCD waveform of every variable |
//! | [`bottling`] | `plc/bottling.il` | build.rs | a CONFIGURATION of two tasks, VAR_GLOBAL/VAR_EXTERNAL, a located global |
//!
//! `build.rs` compiles every `plc/*.il` file with [`il_codegen::Builder`]
//! into `OUT_DIR`; [`plc`] includes the generated Rust. Every program is
//! driven the same way:
//!
//! ```
//! use il_examples::plc::TrafficLight;
//! use il_std::{Cycle, TIME};
//!
//! let mut ctx = Cycle::new();             // time T#0s, no faults
//! let mut light = TrafficLight::default();
//! light.enable = true;                    // inputs are pub fields
//! light.call(&mut ctx);                   // one scan
//! assert!(light.red);
//! ctx.advance(TIME::from_secs(5));        // simulated time
//! light.call(&mut ctx);
//! assert!(light.red && light.yellow);     // 5 s of red, then red + yellow
//! ```
//!
//! [`il_codegen::Builder`]: https://docs.rs/il-codegen
#![forbid(unsafe_code)]
#![deny(missing_docs)]

use core::fmt;
use il_std::TIME;

pub mod batch_weigh;
pub mod bottling;
pub mod conveyor;
pub mod motor_starter;
pub mod readme_motor;
pub mod stair_light;
pub mod trace_motor;
pub mod traffic_light;

/// The programs of `plc/*.il`, compiled by `build.rs` (one program: the
/// files could use each other's function blocks).
pub mod plc {
    include!(concat!(env!("OUT_DIR"), "/batch_weigh.rs"));
    include!(concat!(env!("OUT_DIR"), "/bottling.rs"));
    include!(concat!(env!("OUT_DIR"), "/conveyor.rs"));
    include!(concat!(env!("OUT_DIR"), "/motor_starter.rs"));
    include!(concat!(env!("OUT_DIR"), "/traffic_light.rs"));
}

/// The scan period every example uses: the host calls the program, then
/// advances the simulated time by this much.
pub const SCAN: TIME = TIME::from_ms(100);

/// An example's entry point: runs the program and returns its time-line.
pub type Example = fn() -> Timeline;

/// Every example: its name (as in `cargo run --example NAME`) and the
/// function that runs it.
pub const ALL: &[(&str, Example)] = &[
    ("traffic_light", traffic_light::run),
    ("motor_starter", motor_starter::run),
    ("conveyor", conveyor::run),
    ("batch_weigh", batch_weigh::run),
    ("stair_light", stair_light::run),
    ("readme_motor", readme_motor::run),
    ("bottling", bottling::run),
    ("trace_motor", trace_motor::run),
];

/// One value of a time-line column, formatted for a narrow column.
pub trait Cell {
    /// The text shown in the column.
    fn cell(&self) -> String;
}

impl Cell for bool {
    /// `1` or `0`, as on a PLC's status display.
    fn cell(&self) -> String {
        if *self { "1" } else { "0" }.to_string()
    }
}

macro_rules! cell_display {
    ($($t:ty),*) => {$(
        impl Cell for $t {
            fn cell(&self) -> String {
                self.to_string()
            }
        }
    )*};
}
cell_display!(i16, i32, u16, u64, TIME);

impl Cell for &str {
    fn cell(&self) -> String {
        (*self).to_string()
    }
}

/// A time-line of a program's inputs and outputs over simulated time.
///
/// [`Timeline::record`] is called after every scan; a row is kept only when
/// a value differs from the previous row (or an event note is given), so the
/// printed table shows the transitions. [`fmt::Display`] aligns the columns.
#[derive(Clone, Debug, PartialEq)]
pub struct Timeline {
    title: String,
    inputs: Vec<&'static str>,
    outputs: Vec<&'static str>,
    rows: Vec<Row>,
    footer: Vec<String>,
}

/// One kept row of a [`Timeline`].
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Simulated time of the scan.
    pub time: TIME,
    /// Inputs then outputs, in column order.
    pub values: Vec<String>,
    /// What the simulated operator or plant did in this scan.
    pub note: String,
}

impl Timeline {
    /// An empty time-line with these input and output column names.
    pub fn new(title: &str, inputs: &[&'static str], outputs: &[&'static str]) -> Self {
        Timeline {
            title: title.to_string(),
            inputs: inputs.to_vec(),
            outputs: outputs.to_vec(),
            rows: Vec::new(),
            footer: Vec::new(),
        }
    }

    /// Records the values after the scan at `time` (inputs then outputs);
    /// keeps the row when a value changed or `note` is not empty.
    pub fn record(&mut self, time: TIME, values: &[&dyn Cell], note: &str) {
        let values: Vec<String> = values.iter().map(|v| v.cell()).collect();
        debug_assert_eq!(values.len(), self.inputs.len() + self.outputs.len());
        if note.is_empty() && self.rows.last().is_some_and(|r| r.values == values) {
            return;
        }
        self.rows.push(Row {
            time,
            values,
            note: note.to_string(),
        });
    }

    /// Adds a line printed under the table (e.g. the recorded faults).
    pub fn footer(&mut self, line: impl Into<String>) {
        self.footer.push(line.into());
    }

    /// The kept rows.
    pub fn rows(&self) -> &[Row] {
        &self.rows
    }

    /// The footer lines.
    pub fn footer_lines(&self) -> &[String] {
        &self.footer
    }

    fn column(&self, name: &str) -> usize {
        self.inputs
            .iter()
            .chain(&self.outputs)
            .position(|c| *c == name)
            .unwrap_or_else(|| panic!("no column `{name}` in {}", self.title))
    }

    /// The value of column `name` after the last scan at or before `time`.
    ///
    /// # Panics
    /// When there is no such column or no row at or before `time`.
    pub fn at(&self, time: TIME, name: &str) -> &str {
        let c = self.column(name);
        let row = self
            .rows
            .iter()
            .rev()
            .find(|r| r.time <= time)
            .unwrap_or_else(|| panic!("no row at or before {time}"));
        &row.values[c]
    }

    /// Every change of column `name`: the time and the new value (the first
    /// row counts as a change).
    pub fn changes(&self, name: &str) -> Vec<(TIME, &str)> {
        let c = self.column(name);
        let mut out: Vec<(TIME, &str)> = Vec::new();
        for r in &self.rows {
            if out.last().is_none_or(|(_, v)| *v != r.values[c]) {
                out.push((r.time, &r.values[c]));
            }
        }
        out
    }

    /// The times (in milliseconds) at which column `name` became `value`.
    pub fn times_of(&self, name: &str, value: &str) -> Vec<i64> {
        self.changes(name)
            .into_iter()
            .filter(|(_, v)| *v == value)
            .map(|(t, _)| t.as_ms())
            .collect()
    }
}

impl fmt::Display for Timeline {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.inputs.iter().chain(&self.outputs).copied().collect();
        let width: Vec<usize> = names
            .iter()
            .enumerate()
            .map(|(i, n)| {
                self.rows
                    .iter()
                    .map(|r| r.values[i].len())
                    .chain([n.len()])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let line = |f: &mut fmt::Formatter<'_>, time: &str, cells: &[&str], note: &str| {
            let mut s = format!("{time:>8} |");
            for (i, (c, w)) in cells.iter().zip(&width).enumerate() {
                if i == self.inputs.len() {
                    s.push_str(" |");
                }
                s.push_str(&format!(" {c:>w$}"));
            }
            if !note.is_empty() {
                s.push_str("  ");
                s.push_str(note);
            }
            writeln!(f, "{}", s.trim_end())
        };
        writeln!(f, "{}", self.title)?;
        writeln!(f)?;
        line(f, "time", &names, "")?;
        let total: usize = 8 + 2 + width.iter().map(|w| w + 1).sum::<usize>() + 2;
        writeln!(f, "{}", "-".repeat(total))?;
        for r in &self.rows {
            let t = r.time.as_ms();
            let time = format!("{}.{} s", t / 1000, (t % 1000) / 100);
            let cells: Vec<&str> = r.values.iter().map(String::as_str).collect();
            line(f, &time, &cells, &r.note)?;
        }
        for l in &self.footer {
            writeln!(f)?;
            writeln!(f, "{l}")?;
        }
        Ok(())
    }
}
