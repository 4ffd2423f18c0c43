//! A bare M221 / TwidoSuite Instruction List listing (`--dialect m221`),
//! as the IDE shows and exports it: one instruction per line, read into the
//! same [`Project`] an `.smbp` gives, so each line has one translation.
//!
//! - A rung ends at a blank line, a line that holds only a comment, a label
//!   `%Ln:` (which starts the next rung), a subroutine head `SRn:`, or a
//!   load (`LD`, `LDN`, `LDR`, `LDF`, `LD [ ... ]`) outside `BLK` ...
//!   `END_BLK`, `(` ... `)` and `MPS` ... `MPP`: every rung starts with one.
//! - A line may start with its number (`12 LD %I0.1`, printed listings).
//! - `SRn:` starts subroutine n, up to the next `SRn:` or the end of the
//!   file; what comes before the first is the main program.
//! - `(*@ %TM0 TON BASE=100ms PRESET=50 *)` configures an object (timers,
//!   counters, constant words, registers), which a `.smbp` holds in its XML.

use std::ops::Range;

use super::codes::BAD_CONFIG;
use super::read::{self, Line, Pou, Project, Rung, Timer, TimerKind, span};
use crate::diag::Diagnostic;
use crate::plcopen::translate::Translation;

/// The IL text of a listing named `name`.
pub(crate) fn translate(name: &str, text: &str) -> Translation {
    let mut diags = Vec::new();
    let p = read(name, text, &mut diags);
    super::write::write(&p, 0..text.len(), diags)
}

/// The text with comments blanked (each byte a space, so offsets stay),
/// and the comments' contents with their ranges.
fn blank_comments(text: &str) -> (String, Vec<(Range<usize>, &str)>) {
    let mut out = String::with_capacity(text.len());
    let mut comments = Vec::new();
    let mut rest = 0;
    while let Some(k) = text[rest..].find("(*") {
        let open = rest + k;
        out.push_str(&text[rest..open]);
        let close = text[open + 2..]
            .find("*)")
            .map_or(text.len(), |c| open + 2 + c + 2);
        let inner_end = if close == text.len() && !text.ends_with("*)") {
            close
        } else {
            close - 2
        };
        comments.push((open..close, &text[open + 2..inner_end.max(open + 2)]));
        for c in text[open..close].chars() {
            if c == '\n' {
                out.push('\n');
            } else {
                out.extend(std::iter::repeat_n(' ', c.len_utf8()));
            }
        }
        rest = close;
    }
    out.push_str(&text[rest..]);
    (out, comments)
}

/// Whether the line's first word is a load that starts a rung.
fn is_load(first: &str) -> bool {
    matches!(
        first.to_ascii_uppercase().as_str(),
        "LD" | "LDN" | "LDR" | "LDF"
    )
}

/// `%L3:` → `%L3`, `SR2:` → `SR2`: a head word and what follows it.
fn head(t: &str) -> Option<(&str, usize)> {
    let colon = t.find(':')?;
    let word = t[..colon].trim_end();
    let is_label = super::rung::label_name(word).is_some();
    let is_sr = super::rung::sr_number(word).is_some() && !word.starts_with('%');
    (is_label || is_sr).then_some((word, colon + 1))
}

/// Read a listing into a project: its main program and subroutines, and
/// the configuration its comments give.
fn read(name: &str, text: &str, diags: &mut Vec<Diagnostic>) -> Project {
    let (clean, comments) = blank_comments(text);
    let mut p = Project {
        listing: true,
        ..Project::default()
    };
    for (at, inner) in &comments {
        if let Some(cfg) = inner.strip_prefix('@') {
            configure(&mut p, cfg, at.start + 3, diags);
        }
    }
    let stem = std::path::Path::new(name)
        .file_stem()
        .and_then(|s| s.to_str())
        .filter(|s| !s.is_empty() && *s != "<stdin>")
        .unwrap_or("Main");
    let mut pou = Pou {
        name: stem.to_string(),
        sr: None,
        at: 0..0,
        rungs: Vec::new(),
    };
    let mut rung: Option<Rung> = None;
    // Depths of `BLK`, `(` and `MPS` in the rung: a load inside them is
    // part of it.
    let mut depth = (0i32, 0i32, 0i32);
    let mut start = 0;
    for raw in clean.split_inclusive('\n') {
        let line_at = start;
        start += raw.len();
        let body = raw.trim_end_matches(['\n', '\r']);
        let lead = body.len() - body.trim_start().len();
        let mut t = body.trim();
        let mut at = line_at + lead;
        // A printed listing's line number.
        if let Some(k) = t.find(char::is_whitespace)
            && t[..k].bytes().all(|b| b.is_ascii_digit())
        {
            let rest = t[k..].trim_start();
            at += t.len() - rest.len();
            t = rest;
        }
        if t.is_empty() {
            end_rung(&mut pou, &mut rung);
            continue;
        }
        if let Some((word, after)) = head(t) {
            end_rung(&mut pou, &mut rung);
            depth = (0, 0, 0);
            if let Some(n) = super::rung::sr_number(word) {
                let done = std::mem::replace(
                    &mut pou,
                    Pou {
                        name: format!("SR{n}"),
                        sr: Some(n),
                        at: at..at + word.len(),
                        rungs: Vec::new(),
                    },
                );
                p.pous.push(done);
            } else {
                rung = Some(new_rung(
                    &pou,
                    at..at + t.len(),
                    Some(Line {
                        text: word.to_string(),
                        at: at..at + word.len(),
                        linear: true,
                    }),
                ));
            }
            let rest = t[after..].trim_start();
            if rest.is_empty() {
                continue;
            }
            at += t.len() - rest.len();
            t = rest;
        }
        let first = t.split_whitespace().next().unwrap_or("");
        let up = first.to_ascii_uppercase();
        if is_load(first)
            && depth == (0, 0, 0)
            && rung.as_ref().is_some_and(|r| !r.lines.is_empty())
        {
            end_rung(&mut pou, &mut rung);
        }
        match up.as_str() {
            "BLK" => depth.0 += 1,
            "END_BLK" => depth.0 -= 1,
            "MPS" => depth.2 += 1,
            "MPP" => depth.2 -= 1,
            ")" => depth.1 -= 1,
            _ if up.contains('(') && !up.starts_with('[') => depth.1 += 1,
            _ => {}
        }
        let r = rung.get_or_insert_with(|| new_rung(&pou, at..at + t.len(), None));
        r.lines.push(Line {
            text: t.to_string(),
            at: at..at + t.len(),
            linear: true,
        });
    }
    end_rung(&mut pou, &mut rung);
    p.pous.push(pou);
    p.shared_words = read::shared_words(&p);
    p
}

fn new_rung(pou: &Pou, at: Range<usize>, label: Option<Line>) -> Rung {
    Rung {
        number: pou.rungs.len() + 1,
        at,
        lines: Vec::new(),
        label,
    }
}

fn end_rung(pou: &mut Pou, rung: &mut Option<Rung>) {
    if let Some(r) = rung.take() {
        pou.rungs.push(r);
    }
}

/// One configuration comment `(*@ %TM0 TON BASE=100ms PRESET=50 *)`;
/// `at` is where `cfg` starts in the file.
fn configure(p: &mut Project, cfg: &str, at: usize, diags: &mut Vec<Diagnostic>) {
    let words = super::rung::words(cfg);
    let whole = at..at + cfg.trim_end().len();
    let mut fail = |r: Range<usize>, what: String| {
        diags.push(
            Diagnostic::error(BAD_CONFIG, span(&(at + r.start..at + r.end)), what)
                .with_label("not a configuration the import reads")
                .with_help("write `(*@ %TM0 TON BASE=100ms PRESET=50 *)`, `(*@ %C0 PRESET=10 *)`, `(*@ %KW0 VALUE=5 *)` or `(*@ %R0 LIFO *)`"),
        );
    };
    let Some((obj, or)) = words.first().cloned() else {
        fail(0..2.min(cfg.len()), "an empty configuration comment".into());
        return;
    };
    let up = obj.to_ascii_uppercase();
    let number = |prefix: &str| -> Option<u32> {
        let n = up.strip_prefix(prefix)?;
        (!n.is_empty() && n.len() < 6 && n.bytes().all(|b| b.is_ascii_digit()))
            .then(|| n.parse().ok())
            .flatten()
    };
    let (kind, n) = if let Some(n) = number("%TM") {
        ("TM", n)
    } else if let Some(n) = number("%C") {
        ("C", n)
    } else if let Some(n) = number("%KW") {
        ("KW", n)
    } else if let Some(n) = number("%R") {
        ("R", n)
    } else {
        fail(
            or,
            format!("`{obj}` is no object a listing configures (`%TMn`, `%Cn`, `%KWn`, `%Rn`)"),
        );
        return;
    };
    let mut timer = Timer {
        kind: TimerKind::Ton,
        base_ms: 0,
        preset: u64::MAX,
    };
    let mut value: Option<i64> = None;
    for (w, r) in words.iter().skip(1).cloned() {
        let wu = w.to_ascii_uppercase();
        let (key, val) = wu.split_once('=').unwrap_or((wu.as_str(), ""));
        let ok = match (kind, key) {
            ("TM", "TON") => {
                timer.kind = TimerKind::Ton;
                true
            }
            ("TM", "TOF") => {
                timer.kind = TimerKind::Tof;
                true
            }
            ("TM", "TP") => {
                timer.kind = TimerKind::Tp;
                true
            }
            ("TM", "BASE") => {
                timer.base_ms = match val {
                    "1MS" => 1,
                    "10MS" => 10,
                    "100MS" => 100,
                    "1S" => 1000,
                    "1MIN" => 60_000,
                    _ => 0,
                };
                timer.base_ms != 0
            }
            ("TM", "PRESET") => {
                timer.preset = val.parse().ok().filter(|v| *v <= 32767).unwrap_or(u64::MAX);
                timer.preset != u64::MAX
            }
            ("C", "PRESET") => {
                value = val.parse().ok().filter(|v| (0..=9999).contains(v));
                value.is_some()
            }
            ("KW", "VALUE") => {
                value = val.parse().ok().filter(|v| (-32768..=32767).contains(v));
                value.is_some()
            }
            ("R", "LIFO") => {
                p.lifo.insert(n);
                true
            }
            ("R", "FIFO") => {
                p.lifo.remove(&n);
                true
            }
            _ => false,
        };
        if !ok {
            let what = match (kind, key) {
                ("TM", "BASE") => "a time base is 1ms, 10ms, 100ms, 1s or 1min",
                ("TM", "PRESET") => "a timer's preset is 0 to 32767",
                ("C", "PRESET") => "a counter's preset is 0 to 9999",
                ("KW", "VALUE") => "a constant word is -32768 to 32767",
                ("TM", _) => "a timer takes TON, TOF or TP, BASE= and PRESET=",
                ("C", _) => "a counter takes PRESET=",
                ("KW", _) => "a constant word takes VALUE=",
                _ => "a register takes LIFO or FIFO",
            };
            fail(r, format!("`{w}` in `{obj}`'s configuration: {what}"));
            return;
        }
    }
    match kind {
        "TM" if timer.base_ms == 0 || timer.preset == u64::MAX => fail(
            whole.start - at..whole.end - at,
            format!("`{obj}` needs its time base and preset: `BASE=100ms PRESET=50`"),
        ),
        "TM" => {
            p.timers.insert(n, timer);
        }
        "C" | "KW" => match value {
            Some(v) if kind == "C" => {
                p.counters.insert(n, v as u64);
            }
            Some(v) => {
                p.constants.insert(n, v);
            }
            None => fail(
                whole.start - at..whole.end - at,
                format!(
                    "`{obj}` needs its {}",
                    if kind == "C" {
                        "preset: `PRESET=10`"
                    } else {
                        "value: `VALUE=5`"
                    }
                ),
            ),
        },
        _ => {}
    }
}
