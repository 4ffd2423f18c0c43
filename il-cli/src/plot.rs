//! `ilc run --plot`: a timing diagram as a PLC engineer draws one, one lane
//! per watched signal (BOOL high/low, numbers as stepped values, enumerations
//! and strings as a bus with the value written at each change), on a time axis
//! in ms or s, drawn with plotters' SVG backend.

use std::io::Write;
use std::path::Path;

use il_interp::il_std::TIME;
use il_interp::il_std::trace::{Value, Visitor};
use plotters::prelude::*;

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Bool,
    /// Integers and bit strings: ticks at whole numbers only, each change's
    /// value written where there is room.
    Integer,
    /// REAL and LREAL.
    Number,
    /// TIME and the like: drawn in the time axis' unit.
    Time,
    /// Enumerations (their value, named) and strings (named only).
    Bus,
}

struct Series {
    name: String,
    kind: Kind,
    /// Each change: time (ns), value, and the text to write for a bus.
    changes: Vec<(i64, f64, Option<String>)>,
}

/// The signals of a run, collected one sample per scan.
pub struct Lanes {
    step: TIME,
    series: Vec<Series>,
    last: i64,
    started: bool,
}

impl Lanes {
    pub fn new(step: TIME) -> Lanes {
        Lanes {
            step,
            series: Vec::new(),
            last: 0,
            started: false,
        }
    }

    /// Record what `offer` gives at time `now`.
    pub fn sample(&mut self, now: TIME, offer: impl FnOnce(&mut dyn Visitor)) {
        let mut c = Collect {
            lanes: self,
            path: Vec::new(),
            index: 0,
            now: now.0,
        };
        offer(&mut c);
        self.started = true;
        self.last = now.0;
    }
}

struct Collect<'a> {
    lanes: &'a mut Lanes,
    path: Vec<String>,
    index: usize,
    now: i64,
}

impl Collect<'_> {
    fn put(&mut self, name: String, value: Value<'_>) {
        let (kind, y, text) = match value {
            Value::Bool(b) => (Kind::Bool, b as u8 as f64, None),
            Value::Int { value, .. } => (Kind::Integer, value as f64, None),
            Value::UInt { value, .. } => (Kind::Integer, value as f64, None),
            Value::Real(r) => (Kind::Number, r, None),
            Value::Time(ns) => (Kind::Time, ns as f64, None),
            Value::Date(d) => (Kind::Integer, d as f64, None),
            Value::Enum { value, name } => (Kind::Bus, value as f64, Some(name.to_string())),
            Value::Str(b) => (
                Kind::Bus,
                0.0,
                Some(String::from_utf8_lossy(b).into_owned()),
            ),
            Value::WStr(u) => (Kind::Bus, 0.0, Some(String::from_utf16_lossy(u))),
        };
        let i = self.index;
        self.index += 1;
        if !self.lanes.started {
            let mut full = self.path.clone();
            full.push(name);
            self.lanes.series.push(Series {
                name: full.join("."),
                kind,
                changes: Vec::new(),
            });
        }
        if let Some(s) = self.lanes.series.get_mut(i) {
            let same = s
                .changes
                .last()
                .is_some_and(|(_, ly, lt)| *ly == y && *lt == text);
            if !same {
                s.changes.push((self.now, y, text));
            }
        }
    }
}

fn indexed(name: &str, index: &[i64]) -> String {
    let ix: Vec<String> = index.iter().map(i64::to_string).collect();
    format!("{name}[{}]", ix.join(","))
}

impl Visitor for Collect<'_> {
    fn enter(&mut self, name: &str) {
        self.path.push(name.to_string());
    }
    fn enter_elem(&mut self, name: &str, index: &[i64]) {
        self.path.push(indexed(name, index));
    }
    fn leave(&mut self) {
        self.path.pop();
    }
    fn var(&mut self, name: &str, _: &str, value: Value<'_>) {
        self.put(name.to_string(), value);
    }
    fn elem(&mut self, name: &str, index: &[i64], _: &str, value: Value<'_>) {
        self.put(indexed(name, index), value);
    }
}

const WIDTH: u32 = 960;
const LANE: u32 = 48;
const TITLE: u32 = 32;
const AXIS: u32 = 36;
const LABEL: u32 = 170;

/// A timing diagram of collected lanes.
pub struct Plot {
    title: String,
    lanes: Lanes,
}

/// The time unit of the axis for a run ending at `end_ns`: the IL's units.
fn time_unit(end_ns: i64) -> (&'static str, f64) {
    if end_ns < 1_000_000 {
        ("us", 1e3)
    } else if end_ns < 10_000_000_000 {
        ("ms", 1e6)
    } else {
        ("s", 1e9)
    }
}

impl Plot {
    pub fn new(title: &str, lanes: Lanes) -> Plot {
        Plot {
            title: title.to_string(),
            lanes,
        }
    }

    /// Draw the SVG text.
    pub fn svg(&self) -> Result<String, String> {
        let mut svg = String::new();
        let n = self.lanes.series.len() as u32;
        let height = TITLE + n.max(1) * LANE + AXIS;
        {
            let root = SVGBackend::with_string(&mut svg, (WIDTH, height)).into_drawing_area();
            self.draw(&root, n).map_err(|e| e.to_string())?;
            root.present().map_err(|e| e.to_string())?;
        }
        Ok(svg)
    }

    fn draw(
        &self,
        root: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
        n: u32,
    ) -> Result<(), Box<dyn std::error::Error>> {
        root.fill(&WHITE)?;
        let end_ns = (self.lanes.last + self.lanes.step.0.max(1)).max(1);
        let (unit, per) = time_unit(end_ns);
        let end = end_ns as f64 / per;
        let (title, mut rest) = root.split_vertically(TITLE);
        title.draw_text(
            &format!(
                "{}: {} scans, time in {unit}",
                self.title,
                self.scan_count()
            ),
            &("sans-serif", 16).into_font().color(&BLACK),
            (8, 8),
        )?;
        for (k, s) in self.lanes.series.iter().enumerate() {
            let last = k as u32 + 1 == n;
            let (lane, below) = if last {
                (rest.clone(), rest.clone())
            } else {
                rest.split_vertically(LANE)
            };
            rest = below;
            let (label, plot) = lane.split_horizontally(LABEL);
            let mid = (LANE / 2) as i32 - 7;
            label.draw_text(
                &s.name,
                &("monospace", 14).into_font().color(&BLACK),
                (8, mid),
            )?;
            self.lane(&plot, s, end, per, last, unit)?;
        }
        Ok(())
    }

    fn scan_count(&self) -> usize {
        let step = self.lanes.step.0.max(1);
        (self.lanes.last / step) as usize + 1
    }

    fn lane(
        &self,
        area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
        s: &Series,
        end: f64,
        per: f64,
        axis: bool,
        unit: &str,
    ) -> Result<(), Box<dyn std::error::Error>> {
        // Durations in the unit of the time axis.
        let scale = if s.kind == Kind::Time { 1.0 / per } else { 1.0 };
        let (lo, hi) = match s.kind {
            Kind::Bool => (0.0, 1.0),
            _ => {
                let ys = s.changes.iter().map(|c| c.1 * scale);
                let lo = ys.clone().fold(f64::INFINITY, f64::min);
                let hi = ys.fold(f64::NEG_INFINITY, f64::max);
                if lo.is_finite() && hi > lo {
                    (lo, hi)
                } else if lo.is_finite() {
                    (lo - 1.0, lo + 1.0)
                } else {
                    (0.0, 1.0)
                }
            }
        };
        let pad = (hi - lo) * 0.15;
        let mut chart = ChartBuilder::on(area)
            .margin_right(24)
            .margin_top(4)
            .margin_bottom(4)
            .x_label_area_size(if axis { AXIS } else { 0 })
            .y_label_area_size(64)
            .build_cartesian_2d(0.0..end, (lo - pad)..(hi + pad))?;
        let mut mesh = chart.configure_mesh();
        mesh.disable_y_mesh()
            .x_labels(12)
            .max_light_lines(1)
            .bold_line_style(RGBColor(225, 225, 225))
            .axis_style(RGBColor(120, 120, 120))
            .label_style(("sans-serif", 12).into_font().color(&BLACK))
            .axis_desc_style(("sans-serif", 13).into_font().color(&BLACK))
            .x_label_formatter(&|x| format!("{x}"));
        if axis {
            mesh.x_desc(format!("time ({unit})"));
        }
        let suffix = if s.kind == Kind::Time { unit } else { "" };
        let integer = s.kind == Kind::Integer;
        let fmt_y = |y: &f64| {
            if y.fract() == 0.0 {
                format!("{y:.0}{suffix}")
            } else if integer {
                // An integer lane has no value between two whole numbers:
                // a tick there would be a value it cannot take.
                String::new()
            } else {
                format!("{y:.2}{suffix}")
            }
        };
        if matches!(s.kind, Kind::Number | Kind::Time | Kind::Integer) {
            mesh.y_labels(3).y_label_formatter(&fmt_y);
        } else {
            mesh.y_labels(0);
        }
        mesh.draw()?;
        let color = match s.kind {
            Kind::Bool => RGBColor(0, 110, 60),
            Kind::Number | Kind::Time | Kind::Integer => RGBColor(20, 70, 170),
            Kind::Bus => RGBColor(150, 70, 0),
        };
        // A value holds from its change until the next one.
        let mut pts = Vec::with_capacity(s.changes.len() * 2 + 1);
        for (i, (t, y, _)) in s.changes.iter().enumerate() {
            let x = *t as f64 / per;
            if i > 0 {
                pts.push((x, s.changes[i - 1].1 * scale));
            }
            pts.push((x, *y * scale));
        }
        if let Some((_, y, _)) = s.changes.last() {
            pts.push((end, *y * scale));
        }
        chart.draw_series(LineSeries::new(pts, color.stroke_width(2)))?;
        if integer {
            // Each change's value beside its step, when it does not run
            // into the previous one's text (a busy lane keeps its scale).
            let style = ("monospace", 11).into_font().color(&color);
            let px_per = f64::from(WIDTH - LABEL - 64 - 24) / end.max(f64::MIN_POSITIVE);
            let mut free_from = f64::NEG_INFINITY;
            let mut texts = Vec::new();
            for (t, y, _) in &s.changes {
                let x = *t as f64 / per;
                let text = format!("{y:.0}");
                if x * px_per >= free_from {
                    free_from = x * px_per + 7.0 * text.len() as f64 + 6.0;
                    texts
                        .push(EmptyElement::at((x, *y)) + Text::new(text, (3, -13), style.clone()));
                }
            }
            chart.draw_series(texts)?;
        }
        if s.kind == Kind::Bus {
            let style = ("monospace", 12).into_font().color(&color);
            // Each value's name just above its segment, from the change on.
            let texts = s.changes.iter().filter_map(|(t, y, text)| {
                text.as_ref().map(|txt| {
                    EmptyElement::at((*t as f64 / per, *y))
                        + Text::new(txt.clone(), (4, -15), style.clone())
                })
            });
            chart.draw_series(texts)?;
        }
        Ok(())
    }

    /// Write the SVG to `path` (complete, or not at all).
    pub fn write(&self, path: &Path) -> Result<(), String> {
        let svg = self.svg()?;
        let mut f = il_trace::AtomicFile::create(path).map_err(|e| e.to_string())?;
        f.write_all(svg.as_bytes()).map_err(|e| e.to_string())?;
        f.commit().map_err(|e| e.to_string())
    }
}
