//! `ilc run --vcd FILE.vcd` also writes `FILE.gtkw`, a GTKWave save file,
//! so that `gtkwave FILE.gtkw` opens the dump readable: every watched
//! signal added in watch order, integers as signed decimal (the dump holds
//! two's complement vectors, which GTKWave shows in hex by default), an
//! enumeration through a translate filter file (`FILE.NAME.gtkw-enum`,
//! `value name` per line) so its lane shows `Filling`, not `1`, and the
//! view zoomed to the whole run.
//!
//! It is made from the dump as written (read back with il-trace), so the
//! names are exactly the dump's.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use il_trace::read::{Dump, Sample, Signal};

/// GTKWave's trace flags (its `TraceEntFlagBits`): right-justified values
/// (set on every trace it writes), decimal, signed, filter-translated.
const RJUSTIFY: u32 = 1 << 5;
const DEC: u32 = 1 << 2;
const BIN: u32 = 1 << 3;
const SIGNED: u32 = 1 << 10;
const FTRANSLATED: u32 = 1 << 13;

/// Pixels the run is fitted into: what a 1000-pixel-wide GTKWave window
/// leaves for the waves beside its tree and signal panes.
const WIDTH_PX: f64 = 550.0;

/// Each watched enumeration's values and their integers, by the variable's
/// path below the top scope (`tank.state`).
pub type EnumValues = BTreeMap<String, Vec<(i64, String)>>;

/// The files to write: the save file, then one translate file per
/// enumeration lane.
pub struct SaveFiles {
    /// `FILE.gtkw` and its text.
    pub save: (PathBuf, String),
    /// `FILE.<signal>.gtkw-enum` and its `value name` lines.
    pub filters: Vec<(PathBuf, String)>,
}

/// The enumeration lanes' value names: every value of the type, and the
/// `path = Name` comments (il-trace writes one at each change of an
/// enumeration) paired with the value the signal has at that time.
fn enum_names(dump: &Dump, enums: &EnumValues) -> BTreeMap<usize, BTreeMap<u64, String>> {
    let mut out: BTreeMap<usize, BTreeMap<u64, String>> = BTreeMap::new();
    for (i, s) in dump.signals.iter().enumerate() {
        let Some(values) = s.path.get(1..).and_then(|p| enums.get(&p.join("."))) else {
            continue;
        };
        if s.var_type == "integer" {
            let names = out.entry(i).or_default();
            for (v, n) in values {
                // The dump holds the value's 64 bits.
                names.insert(*v as u64, n.clone());
            }
        }
    }
    for (t, comment) in &dump.comments {
        for line in comment.lines() {
            let Some((path, name)) = line.trim().split_once(" = ") else {
                continue;
            };
            // The comment's path is below the top scope.
            let found = dump.signals.iter().position(|s| {
                s.var_type == "integer" && s.path.get(1..).is_some_and(|p| p.join(".") == path)
            });
            let Some(i) = found else { continue };
            if let Some(Sample::Bits(v)) = dump.signals[i].at(*t) {
                out.entry(i).or_default().insert(*v, name.to_string());
            }
        }
    }
    out
}

/// The name GTKWave gives a variable: its path joined by `.`, and a
/// vector's bit range.
///
/// A name with a `.` of its own (a direct address, `%QX0.2`) is an escaped
/// identifier to GTKWave, `Tank.\%QX0.2` (read back from its facility list
/// under Xvfb); such a trace gets its name unescaped as an alias.
fn trace_name(s: &Signal) -> (String, Option<String>) {
    let leaf = s.path.last().map_or("", String::as_str);
    let scopes = &s.path[..s.path.len().saturating_sub(1)];
    let escaped = leaf.contains('.');
    let mut name = scopes.join(".");
    if !name.is_empty() {
        name.push('.');
    }
    if escaped {
        name.push('\\');
    }
    name.push_str(leaf);
    if s.var_type == "wire" && s.width > 1 {
        let _ = write!(name, "[{}:0]", s.width - 1);
    }
    (name, escaped.then(|| leaf.to_string()))
}

/// The save file for `vcd` (already written), whose run ends at `end` (in
/// timescale units).
pub fn save_files(vcd: &Path, dump: &Dump, end: u64, enums: &EnumValues) -> SaveFiles {
    let save_path = vcd.with_extension("gtkw");
    let enums = enum_names(dump, enums);
    let stem = vcd
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let mut text = String::new();
    let _ = writeln!(
        text,
        "[*] written by ilc run: gtkwave {}",
        file_name(&save_path)
    );
    let _ = writeln!(text, "[dumpfile] \"{}\"", vcd.display());
    let _ = writeln!(text, "[savefile] \"{}\"", save_path.display());
    let _ = writeln!(text, "[timestart] 0");
    let _ = writeln!(text, "[size] 1000 600");
    // GTKWave shows 2^-zoom time units per 200 pixels (checked under Xvfb):
    // the zoom at which the run, and a little more, fills the pane.
    let zoom = -((200.0 * 1.05 * end.max(1) as f64) / WIDTH_PX).log2();
    let _ = writeln!(
        text,
        "*{zoom:.6} 0 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1"
    );
    if let Some(top) = dump.signals.first().and_then(|s| s.path.first()) {
        let _ = writeln!(text, "[treeopen] {top}.");
    }
    let mut filters = Vec::new();
    for (i, s) in dump.signals.iter().enumerate() {
        let flags = if let Some(names) = enums.get(&i) {
            let path = vcd.with_file_name(format!("{stem}.{}.gtkw-enum", s.path[1..].join(".")));
            let body: String = names.iter().map(|(v, n)| format!("{v} {n}\n")).collect();
            let _ = writeln!(text, "^1 {}", path.display());
            filters.push((path, body));
            RJUSTIFY | DEC | FTRANSLATED
        } else {
            match s.var_type.as_str() {
                "wire" if s.width == 1 => RJUSTIFY | BIN,
                "wire" | "integer" => RJUSTIFY | DEC | SIGNED,
                _ => RJUSTIFY,
            }
        };
        let _ = writeln!(text, "@{flags:x}");
        match trace_name(s) {
            (name, Some(alias)) => {
                let _ = writeln!(text, "+{{{alias}}} {name}");
            }
            (name, None) => {
                let _ = writeln!(text, "{name}");
            }
        }
    }
    SaveFiles {
        save: (save_path, text),
        filters,
    }
}

fn file_name(p: &Path) -> String {
    p.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}
