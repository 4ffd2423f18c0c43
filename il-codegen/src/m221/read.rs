//! The project as the XML holds it: the POUs of the master task with their
//! rungs and instruction lines, and the configuration of the timers,
//! counters and constant words. Nothing is written here.

use std::collections::HashMap;
use std::ops::Range;

use roxmltree::Node;

use super::codes::{BAD_CONFIG, BAD_PROJECT};
use crate::ast::Span;
use crate::diag::Diagnostic;
use crate::plcopen::text::content_range;
use crate::plcopen::validate::shown;

/// One `<InstructionLine>`: its text (entities decoded) and where its
/// content lies in the XML.
pub(super) struct Line {
    pub text: String,
    pub at: Range<usize>,
    /// Whether the XML content is the text byte for byte (no entity), so
    /// that an offset in the text is one in the XML.
    pub linear: bool,
}

impl Line {
    /// The XML range of bytes `r` of the text (the whole line when the
    /// content has entities).
    pub fn xml(&self, r: Range<usize>) -> Range<usize> {
        if self.linear {
            self.at.start + r.start..self.at.start + r.end
        } else {
            self.at.clone()
        }
    }
}

/// A `<RungEntity>`.
pub(super) struct Rung {
    /// Its number in the POU, from 1, for messages.
    pub number: usize,
    pub at: Range<usize>,
    pub lines: Vec<Line>,
    /// `<Label>%L1</Label>`: the rung is the target of `JMP %L1`.
    pub label: Option<Line>,
}

/// A `<ProgramOrganizationUnits>` of `<Pous>`, or a listing's main
/// program or subroutine.
pub(super) struct Pou {
    pub name: String,
    /// The subroutine's number (`SR3`), for a subroutine.
    pub sr: Option<u32>,
    pub at: Range<usize>,
    pub rungs: Vec<Rung>,
}

/// Timer types of `%TMn`.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum TimerKind {
    Ton,
    Tof,
    Tp,
}

/// The configuration of one `%TMn`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Timer {
    pub kind: TimerKind,
    /// The time base in milliseconds.
    pub base_ms: u64,
    pub preset: u64,
}

/// The defaults of an object the project does not configure (the editor
/// leaves out of the XML a value it has by default).
pub(super) const DEFAULT_TIMER: Timer = Timer {
    kind: TimerKind::Ton,
    base_ms: 60_000,
    preset: 9999,
};
pub(super) const DEFAULT_COUNTER_PRESET: u64 = 9999;

/// Everything read from the document.
#[derive(Default)]
pub(super) struct Project {
    pub pous: Vec<Pou>,
    pub timers: HashMap<u32, Timer>,
    pub counters: HashMap<u32, u64>,
    /// `%KWn` values.
    pub constants: HashMap<u32, i64>,
    /// Objects with a configuration the import does not read (`%DR0`).
    pub configured: std::collections::HashSet<String>,
    /// Registers `%Rn` configured as LIFO (the others are FIFO).
    pub lifo: std::collections::HashSet<u32>,
    /// Whether two memory objects share a word (`%MF1` and `%MW2`): then
    /// every `%MDn`/`%MFn` is a view of the words `%MWn`, `%MWn+1`.
    pub shared_words: bool,
    /// `<Subroutines>` that hold something, for one error.
    pub subroutines: Option<Range<usize>>,
    /// A text listing (`--dialect m221`): its timers, counters and constant
    /// words must be configured (`(*@ %TM0 ... *)`), there is no editor's
    /// default to fall back on.
    pub listing: bool,
}

pub(super) use crate::plcopen::nodes::{is, kid, kids};

fn text_of<'a>(n: Node<'a, '_>) -> &'a str {
    n.text().unwrap_or("").trim()
}

pub(super) fn span(r: &Range<usize>) -> Span {
    Span::new(r.start, r.end)
}

/// Read the project whose root is `root` (a `<ProjectDescriptor>`).
pub(super) fn read(root: Node, xml: &str, diags: &mut Vec<Diagnostic>) -> Project {
    let mut p = Project::default();
    let pous = kid(root, "SoftwareConfiguration").filter(|sw| kid(*sw, "Pous").is_some());
    let Some(sw) = pous.filter(|_| is(&root, "ProjectDescriptor")) else {
        let tag = crate::plcopen::text::start_tag(xml, root.range());
        let what = if is(&root, "CryptedProject") {
            "a protected Machine Expert Basic project: its program is encrypted (save it without protection)"
        } else {
            "an M221 project without `<SoftwareConfiguration><Pous>`: no program to compile"
        };
        diags.push(
            Diagnostic::error(BAD_PROJECT, span(&tag), format!("this is {what}"))
                .with_label("nothing to compile"),
        );
        return p;
    };
    for (k, pou) in kids(sw, "Pous")
        .flat_map(|n| kids(n, "ProgramOrganizationUnits"))
        .enumerate()
    {
        p.pous.push(read_pou(xml, pou, k, None));
    }
    // Subroutines: the same elements as the POUs, numbered by their
    // `<SectionNumber>` or the digits of their name (`SR3`) *(inferred: no
    // public project with subroutines was found)*.
    if let Some(s) = kid(sw, "Subroutines").filter(|s| s.children().any(|c| c.is_element())) {
        let mut read_all = true;
        for (k, el) in s.children().filter(|c| c.is_element()).enumerate() {
            let number = kid(el, "SectionNumber")
                .and_then(|n| text_of(n).parse::<u32>().ok())
                .or_else(|| {
                    kid(el, "Name")
                        .and_then(|n| super::rung::sr_number(text_of(n).trim_start_matches('%')))
                })
                .filter(|n| *n < 256);
            match (is(&el, "ProgramOrganizationUnits"), number) {
                (true, Some(n)) if !p.pous.iter().any(|x| x.sr == Some(n)) => {
                    let mut sub = read_pou(xml, el, k, Some(n));
                    sub.name = format!("SR{n}");
                    p.pous.push(sub);
                }
                _ => read_all = false,
            }
        }
        if !read_all {
            p.pous.retain(|x| x.sr.is_none());
            p.subroutines = Some(s.range());
        }
    }
    p.shared_words = shared_words(&p);
    for t in kids(sw, "Timers").flat_map(|n| kids(n, "TimerTM")) {
        if let Some(i) = index(t) {
            p.timers.insert(i, timer(xml, t, diags));
        }
    }
    for c in kids(sw, "Counters").flat_map(|n| kids(n, "CounterCT")) {
        if let Some(i) = index(c) {
            let preset = kid(c, "Preset")
                .and_then(|n| number(xml, n, 0, 9999, diags))
                .unwrap_or(DEFAULT_COUNTER_PRESET);
            p.counters.insert(i, preset);
        }
    }
    for d in kids(sw, "Drums").flat_map(|n| n.children().filter(|c| c.is_element())) {
        if let Some(i) = index(d) {
            p.configured.insert(format!("%DR{i}"));
        }
    }
    // A register says LIFO in one of its elements (`<Type>Lifo</Type>`).
    for r in kids(sw, "Registers").flat_map(|n| n.children().filter(|c| c.is_element())) {
        let lifo = r.descendants().any(|e| {
            e.is_text()
                && e.text()
                    .is_some_and(|t| t.trim().eq_ignore_ascii_case("LIFO"))
        });
        if let (true, Some(i)) = (lifo, index(r)) {
            p.lifo.insert(i);
        }
    }
    for c in kids(sw, "ConstantWords").flat_map(|n| kids(n, "ConstantWord")) {
        if let (Some(i), Some(v)) = (index(c), kid(c, "Value"))
            && let Ok(v) = text_of(v).parse::<i64>()
        {
            p.constants.insert(i, v.clamp(-32768, 32767));
        }
    }
    p
}

/// A `<ProgramOrganizationUnits>` (the `k`th): its name and rungs.
fn read_pou(xml: &str, pou: Node, k: usize, sr: Option<u32>) -> Pou {
    let name = kid(pou, "Name").map_or(String::new(), |n| text_of(n).to_string());
    let name = if name.is_empty() {
        format!("POU {}", k + 1)
    } else {
        name
    };
    let rungs = kids(pou, "Rungs")
        .flat_map(|n| kids(n, "RungEntity"))
        .enumerate()
        .map(|(i, r)| Rung {
            number: i + 1,
            at: r.range(),
            lines: kids(r, "InstructionLines")
                .flat_map(|n| kids(n, "InstructionLineEntity"))
                .filter_map(|e| kid(e, "InstructionLine"))
                .map(|l| line(xml, l))
                .collect(),
            label: kid(r, "Label")
                .map(|l| line(xml, l))
                .filter(|l| !l.text.trim().is_empty()),
        })
        .collect();
    Pou {
        name,
        sr,
        at: pou.range(),
        rungs,
    }
}

fn line(xml: &str, l: Node) -> Line {
    let text = l.text().unwrap_or("").to_string();
    let at = content_range(xml, l.range());
    let linear = xml.get(at.clone()) == Some(text.as_str());
    Line { text, at, linear }
}

/// The object's number: `<Index>`, else the digits of `<Address>`.
fn index(n: Node) -> Option<u32> {
    if let Some(i) = kid(n, "Index").and_then(|i| text_of(i).parse().ok()) {
        return Some(i);
    }
    let a = kid(n, "Address").map(text_of)?;
    a.trim_start_matches(|c: char| !c.is_ascii_digit())
        .parse()
        .ok()
}

fn bad(xml: &str, n: Node, what: String) -> Diagnostic {
    let r = content_range(xml, n.range());
    Diagnostic::error(BAD_CONFIG, span(&r), what)
        .with_label("not a value the import knows")
        .with_note("the object takes its default (TON, one minute, preset 9999)")
}

fn number(xml: &str, n: Node, lo: u64, hi: u64, diags: &mut Vec<Diagnostic>) -> Option<u64> {
    match text_of(n).parse::<u64>() {
        Ok(v) if (lo..=hi).contains(&v) => Some(v),
        _ => {
            diags.push(bad(
                xml,
                n,
                format!(
                    "`<{}>` holds `{}`, not a number from {lo} to {hi}",
                    n.tag_name().name(),
                    shown(text_of(n))
                ),
            ));
            None
        }
    }
}

fn timer(xml: &str, t: Node, diags: &mut Vec<Diagnostic>) -> Timer {
    let mut out = DEFAULT_TIMER;
    if let Some(p) = kid(t, "Preset").and_then(|n| number(xml, n, 0, 32767, diags)) {
        out.preset = p;
    }
    if let Some(b) = kid(t, "Base") {
        // Editors spell it `HundredMilliseconds`, `OneHundredMilliSecond` ...
        let b_text = text_of(b).to_ascii_lowercase();
        match b_text.trim_end_matches('s').trim_start_matches("one") {
            "millisecond" => out.base_ms = 1,
            "tenmillisecond" => out.base_ms = 10,
            "hundredmillisecond" => out.base_ms = 100,
            "second" => out.base_ms = 1000,
            "minute" => out.base_ms = 60_000,
            _ => diags.push(bad(
                xml,
                b,
                format!("`<Base>` holds `{}`, not a time base", shown(text_of(b))),
            )),
        }
    }
    if let Some(k) = kid(t, "Type") {
        match text_of(k).to_ascii_uppercase().as_str() {
            "TON" => out.kind = TimerKind::Ton,
            "TOF" => out.kind = TimerKind::Tof,
            "TP" => out.kind = TimerKind::Tp,
            other => diags.push(bad(
                xml,
                k,
                format!("`<Type>` holds `{}`, not TON, TOF or TP", shown(other)),
            )),
        }
    }
    out
}

/// Whether the project names two memory objects that share a word: `%MWn`
/// is word n, `%MDn` and `%MFn` words n and n+1.
pub(super) fn shared_words(p: &Project) -> bool {
    let mut words: HashMap<u32, String> = HashMap::new();
    for l in p.pous.iter().flat_map(|x| &x.rungs).flat_map(|r| &r.lines) {
        let up = l.text.to_ascii_uppercase();
        for (i, _) in up.match_indices("%M") {
            let rest = &up[i + 2..];
            let (kind, count) = match rest.as_bytes().first() {
                Some(b'W') => ('W', 1),
                Some(b'D') => ('D', 2),
                Some(b'F') => ('F', 2),
                _ => continue,
            };
            let digits: String = rest[1..].chars().take_while(char::is_ascii_digit).collect();
            let Ok(n) = digits.parse::<u32>() else {
                continue;
            };
            let obj = format!("{kind}{n}");
            for w in n..n.saturating_add(count) {
                match words.get(&w) {
                    Some(o) if *o != obj => return true,
                    Some(_) => {}
                    None => {
                        words.insert(w, obj.clone());
                    }
                }
            }
        }
    }
    false
}
