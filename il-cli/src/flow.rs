//! "Flow control" offline: the current result after every IL line a scan
//! runs (what CODESYS shows next to each line online), recorded through the
//! interpreter's hook. `ilc run --flow` prints it for the last scan;
//! `ilc debug` keeps it for the scan it is in.

use std::io::Write;

use il_interp::{Cr, Here, Hook, Undefined};

use crate::source_map::SourceMap;

/// The CR of frame `depth`, as shown next to its line: `1 : INT`, or
/// `undefined (after CAL on line 18)`, that line as `line` numbers the
/// IL lines of the frame's POU (the user's file, the client's base).
pub fn cr_text(at: &Here<'_>, depth: usize, line: &dyn Fn(&str, u32) -> u32) -> String {
    match at.cr(depth) {
        Some(Cr::Value(v, t)) => format!("{} : {t}", v.display()),
        Some(Cr::Undefined(Undefined::AfterCal(l))) => {
            let pou = at
                .frames()
                .get(depth)
                .map(|f| f.pou.clone())
                .unwrap_or_default();
            format!("undefined (after CAL on line {})", line(&pou, l))
        }
        Some(Cr::Undefined(why)) => format!("undefined ({why})"),
        None => String::new(),
    }
}

/// The lines one scan ran, in order: POU, line, the CR after the line.
pub type Lines = std::collections::VecDeque<(String, u32, String)>;

/// Record the statement `at` just ran; the lines of a long loop are kept
/// up to `max` (the last ones). `line` numbers a line a message names.
pub fn record(lines: &mut Lines, at: &Here<'_>, max: usize, line: &dyn Fn(&str, u32) -> u32) {
    {
        let cr = cr_text(at, 0, line);
        let line = at.line();
        match lines.back_mut() {
            // A line of several statements: the CR after its last one.
            Some(last) if last.0 == at.pou().name && last.1 == line => last.2 = cr,
            _ => {
                if lines.len() >= max {
                    lines.pop_front();
                }
                lines.push_back((at.pou().name.clone(), line, cr));
            }
        }
    }
}

/// The recorder `ilc run --flow` attaches for the last scan, with the
/// program's lines (a CAL's line in a message is the user's).
pub struct Recorder(pub Lines, pub SourceMap);

/// Lines `ilc run --flow` keeps of one scan.
const MAX: usize = 100_000;

impl Hook for Recorder {
    fn before(&mut self, _: &mut Here<'_>) -> Result<(), String> {
        Ok(())
    }
    fn after(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        let map = &self.1;
        record(&mut self.0, at, MAX, &|pou, l| map.line(pou, l));
        Ok(())
    }
}

/// Print the flow of scan `cycle`: one line per IL line run, numbered by
/// the user's file, with the source text when it is at hand (the IL text
/// an XML project, an export or a snippet became, numbered by its own lines).
pub fn print(
    rec: &Recorder,
    map: &SourceMap,
    cycle: u64,
    time: &str,
    out: &mut dyn Write,
) -> std::io::Result<()> {
    writeln!(
        out,
        "\nflow of cycle {cycle} (time {time}): the CR after each line run"
    )?;
    // Each input's text, read once: the file's, or the IL it became.
    let texts: Vec<Option<String>> = (0..map.files().len())
        .map(|k| match map.il_of(k) {
            Some(il) => Some(il.to_string()),
            None => std::fs::read_to_string(&map.files()[k].path).ok(),
        })
        .collect();
    let source = |pou: &str, l: u32| -> &str {
        let f = map.file_of(pou);
        let at = if map.il_of(f).is_some() {
            l
        } else {
            map.line(pou, l)
        };
        texts
            .get(f)
            .and_then(|t| t.as_deref())
            .and_then(|t| t.lines().nth((at as usize).wrapping_sub(1)))
            .map_or("", |s| strip_comment(s.trim()))
    };
    let pw = rec.0.iter().map(|l| l.0.len()).max().unwrap_or(0);
    let sw = rec
        .0
        .iter()
        .map(|l| source(&l.0, l.1).chars().count())
        .max()
        .unwrap_or(0)
        .min(40);
    for (pou, il_line, cr) in &rec.0 {
        let line = map.line(pou, *il_line);
        let src = source(pou, *il_line);
        writeln!(out, "{pou:<pw$} {line:>4}  {src:<sw$}  {cr}")?;
    }
    Ok(())
}

/// An IL line without its trailing `(* comment *)`.
fn strip_comment(s: &str) -> &str {
    match s.find("(*") {
        Some(i) if i > 0 => s[..i].trim_end(),
        _ => s,
    }
}
