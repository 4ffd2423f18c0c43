//! "Flow control" offline: the current result after every IL line a scan
//! runs (what CODESYS shows next to each line online), recorded through the
//! interpreter's hook. `ilc run --flow` prints it for the last scan;
//! `ilc debug` keeps it for the scan it is in.

use std::io::Write;

use il_interp::{Cr, Here, Hook};

/// The CR a statement left, as shown next to its line: `1 : INT`, or
/// `undefined (after CAL on line 18)`.
pub fn cr_text(at: &Here<'_>) -> String {
    match at.cr(0) {
        Some(Cr::Value(v, t)) => format!("{} : {t}", v.display()),
        Some(Cr::Undefined(why)) => format!("undefined ({why})"),
        None => String::new(),
    }
}

/// The lines of the file the user wrote for the interpreter's IL lines:
/// the same for an IL file; for a PLCopen XML project, the XML line each
/// IL line came from; for a snippet, the line before the added header.
/// It keeps the IL text of an input that is not IL (the text shown by `--flow`).
#[derive(Clone, Debug, Default)]
pub struct SourceLines(Option<Vec<u32>>, Option<String>);

impl SourceLines {
    /// The map of the (single) input of a checked program.
    pub fn of(checked: &il_codegen::pipeline::Checked) -> SourceLines {
        use il_codegen::pipeline::Input;
        match checked.inputs().first() {
            Some(Input::PlcOpen(i)) => SourceLines(
                Some(i.xml_lines().into_iter().map(|l| l as u32).collect()),
                Some(i.il.text.to_string()),
            ),
            Some(Input::Snippet(s)) => {
                let n = s.il.text.lines().count() + 1;
                SourceLines(
                    Some((1..=n).map(|k| s.line_of(k) as u32).collect()),
                    Some(s.il.text.to_string()),
                )
            }
            _ => SourceLines(None, None),
        }
    }

    /// The user's line of IL line `line`.
    pub fn get(&self, line: u32) -> u32 {
        match &self.0 {
            None => line,
            Some(m) => m
                .get((line as usize).wrapping_sub(1))
                .copied()
                .unwrap_or(line),
        }
    }
}

/// The lines one scan ran, in order: POU, line, the CR after the line.
pub type Lines = std::collections::VecDeque<(String, u32, String)>;

/// Record the statement `at` just ran; the lines of a long loop are kept
/// up to `max` (the last ones).
pub fn record(lines: &mut Lines, at: &Here<'_>, max: usize) {
    {
        let cr = cr_text(at);
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

/// The recorder `ilc run --flow` attaches for the last scan.
#[derive(Default)]
pub struct Recorder(pub Lines);

/// Lines `ilc run --flow` keeps of one scan.
const MAX: usize = 100_000;

impl Hook for Recorder {
    fn before(&mut self, _: &mut Here<'_>) -> Result<(), String> {
        Ok(())
    }
    fn after(&mut self, at: &mut Here<'_>) -> Result<(), String> {
        record(&mut self.0, at, MAX);
        Ok(())
    }
}

/// Print the flow of scan `cycle`: one line per IL line run, with the
/// source text when it is at hand.
pub fn print(
    rec: &Recorder,
    (source, lines): (Option<&str>, &SourceLines),
    cycle: u64,
    time: &str,
    out: &mut dyn Write,
) -> std::io::Result<()> {
    writeln!(
        out,
        "\nflow of cycle {cycle} (time {time}): the CR after each line run"
    )?;
    // The IL text: the file's, or the IL an XML project or a snippet became
    // (then numbered by the interpreter's lines).
    let (text, il): (Vec<&str>, bool) = match (&lines.1, source) {
        (Some(il), _) => (il.lines().collect(), true),
        (None, s) => (s.map(|s| s.lines().collect()).unwrap_or_default(), false),
    };
    let at = |l: u32| if il { l } else { lines.get(l) };
    let pw = rec.0.iter().map(|l| l.0.len()).max().unwrap_or(0);
    let sw = rec
        .0
        .iter()
        .filter_map(|l| text.get((at(l.1) as usize).wrapping_sub(1)))
        .map(|s| strip_comment(s.trim()).chars().count())
        .max()
        .unwrap_or(0)
        .min(40);
    for (pou, il_line, cr) in &rec.0 {
        let line = lines.get(*il_line);
        let src = text
            .get((at(*il_line) as usize).wrapping_sub(1))
            .map(|s| s.trim())
            .unwrap_or("");
        let src = strip_comment(src);
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
