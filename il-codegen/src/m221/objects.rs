//! The M221's objects as IEC names: an operand (`%I0.3`, `%MW2`, `%TM0.Q`)
//! is parsed, given the IL name of the global that holds it (`I0_3`, `MW2`,
//! `TM0.Q`), and the global is noted for the CONFIGURATION with its
//! declaration.
//!
//! Inputs and outputs are the process image: `%Ii.j` and `%Qi.j` are the
//! bits `%IX`/`%QX` of byte `4i + j/8`, bit `j mod 8` (four bytes per
//! module, 32 channels); the analog channels `%IWi.j`/`%QWi.j` are the words
//! `%IW`/`%QW` number `64 + 8i + j` (bytes 128 to 255, 8 modules of 8
//! channels). Memory objects are globals of their own type, except in a
//! project where two of them share a word (`%MF1` and `%MW2`): there every
//! `%MDn`/`%MFn` is a view of `%MWn` and `%MWn+1` that `expr` reads and
//! writes.

use std::collections::BTreeMap;
use std::ops::Range;

use super::read::{self, Project, TimerKind};

/// The IEC type of a value an operand gives.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Ty {
    Bool,
    Int,
    Dint,
    Real,
    /// A DWORD, for temporaries only (the bits of a `%MD`/`%MF` view).
    Dword,
    /// An integer literal, of the type of the other operand.
    IntLit,
    /// A real literal.
    RealLit,
}

impl Ty {
    pub fn name(self) -> &'static str {
        match self {
            Ty::Bool => "BOOL",
            Ty::Int | Ty::IntLit => "INT",
            Ty::Dint => "DINT",
            Ty::Real | Ty::RealLit => "REAL",
            Ty::Dword => "DWORD",
        }
    }

    /// The type of `a op b`, literals taking the other side's type.
    pub fn join(a: Ty, b: Ty) -> Ty {
        match (a, b) {
            (Ty::IntLit, t) | (t, Ty::IntLit) => t,
            (Ty::RealLit, Ty::RealLit) => Ty::Real,
            (Ty::RealLit, t) | (t, Ty::RealLit) => t,
            (t, _) => t,
        }
    }
}

/// A function-block object a `BLK` names.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Block {
    Timer(u32),
    Counter(u32),
    Drum(u32),
    Register(u32),
    ShiftBit(u32),
    StepCounter(u32),
}

impl Block {
    pub fn name(self) -> String {
        match self {
            Block::Timer(n) => format!("TM{n}"),
            Block::Counter(n) => format!("C{n}"),
            Block::Drum(n) => format!("DR{n}"),
            Block::Register(n) => format!("R{n}"),
            Block::ShiftBit(n) => format!("SBR{n}"),
            Block::StepCounter(n) => format!("SC{n}"),
        }
    }
    /// The inputs (pins before `OUT_BLK`) and outputs of the block.
    pub fn pins(self) -> (&'static [&'static str], &'static [&'static str]) {
        match self {
            Block::Timer(_) => (&["IN"], &["Q"]),
            Block::Counter(_) => (&["R", "S", "CU", "CD"], &["E", "D", "F"]),
            Block::Drum(_) => (&["R", "U"], &["F"]),
            Block::Register(_) => (&["R", "I", "O"], &["E", "F"]),
            Block::ShiftBit(_) | Block::StepCounter(_) => (&["R", "CU", "CD"], &[]),
        }
    }
}

/// A global the program uses.
pub(super) struct Global {
    /// `BOOL`, `AT %IX0.3 : BOOL`, `TON := (PT := T#5s)` ...: what follows
    /// the name and `:`... written whole after the name.
    pub decl: String,
    /// The type as a VAR_EXTERNAL names it.
    pub ty: String,
    pub constant: bool,
    /// A system bit or word (one warning each).
    pub system: bool,
    /// Where it is first used, for the declaration's map.
    pub at: Range<usize>,
}

/// The globals used so far, by IL name.
#[derive(Default)]
pub(super) struct Objects {
    pub globals: BTreeMap<String, Global>,
    /// The globals named since the caller last took them: the POU that
    /// names them declares them VAR_EXTERNAL.
    pub touched: Vec<String>,
    /// The system bits the controller sets that the program uses (`%S0`,
    /// `%S4` .. `%S7`, `%S13`): il-std's `M221_SYS` computes them.
    pub sys_bits: std::collections::BTreeSet<u32>,
}

/// The system bits `M221_SYS` computes.
pub(super) const SYS_BITS: [u32; 6] = [0, 4, 5, 6, 7, 13];

/// An operand: its IL text and type.
pub(super) struct Operand {
    pub il: String,
    pub ty: Ty,
}

fn num(s: &str) -> Option<u32> {
    if s.is_empty() || s.len() > 6 || !s.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

fn pair(s: &str) -> Option<(u32, u32)> {
    let (a, b) = s.split_once('.')?;
    Some((num(a)?, num(b)?))
}

/// An integer or real literal (`12`, `-3`, `16#FF`, `#FF`, `1.5`, `2.0E3`).
pub(super) fn literal(s: &str) -> Option<Operand> {
    let body = s.strip_prefix(['-', '+']).unwrap_or(s);
    let hex = body.strip_prefix("16#").or_else(|| body.strip_prefix('#'));
    if let Some(h) = hex {
        let v = i64::from_str_radix(h, 16).ok()?;
        let sign = if s.starts_with('-') { "-" } else { "" };
        return Some(Operand {
            il: format!("{sign}{v}"),
            ty: Ty::IntLit,
        });
    }
    if !body.starts_with(|c: char| c.is_ascii_digit()) {
        return None;
    }
    if body.bytes().all(|b| b.is_ascii_digit()) {
        let v: i64 = body.parse().ok()?;
        return Some(Operand {
            il: if s.starts_with('-') {
                format!("-{v}")
            } else {
                v.to_string()
            },
            ty: Ty::IntLit,
        });
    }
    let v: f64 = body.parse().ok()?;
    if !v.is_finite() {
        return None;
    }
    let mut t = format!("{v:?}");
    if s.starts_with('-') {
        t.insert(0, '-');
    }
    Some(Operand {
        il: t,
        ty: Ty::RealLit,
    })
}

/// Why an operand is not one: for the message.
pub(super) enum NotObject {
    /// Not an M221 object at all.
    Unknown,
    /// An object the import does not compile, and why.
    Unsupported(String),
    /// A timer, counter or constant word of a text listing without its
    /// configuration (`(*@ %TM0 ... *)`), and the comment that gives it.
    Unconfigured(String),
}

/// The error for an object of a text listing that has no configuration.
fn unconfigured(obj: &str, example: &str) -> NotObject {
    NotObject::Unconfigured(format!(
        "`{obj}` has no configuration in this listing: add a line `(*@ {obj} {example} *)`"
    ))
}

fn time_literal(ms: u64) -> String {
    format!("T#{ms}ms")
}

impl Objects {
    fn note(&mut self, name: &str, at: &Range<usize>, make: impl FnOnce() -> Global) {
        self.touched.push(name.to_string());
        if !self.globals.contains_key(name) {
            let mut g = make();
            g.at = at.clone();
            self.globals.insert(name.to_string(), g);
        }
    }

    fn plain(&mut self, name: &str, ty: &str, at: &Range<usize>, system: bool) {
        self.note(name, at, || Global {
            decl: ty.to_string(),
            ty: ty.to_string(),
            constant: false,
            system,
            at: 0..0,
        });
    }

    /// The block a `BLK` operand names, its instance declared.
    pub fn block(&mut self, p: &Project, s: &str, at: &Range<usize>) -> Result<Block, NotObject> {
        let up = s.to_ascii_uppercase();
        if let Some(n) = up.strip_prefix("%TM").and_then(num) {
            if p.listing && !p.timers.contains_key(&n) {
                return Err(unconfigured(&format!("%TM{n}"), "TON BASE=100ms PRESET=50"));
            }
            let t = p.timers.get(&n).copied().unwrap_or(read::DEFAULT_TIMER);
            let fb = match t.kind {
                TimerKind::Ton => "TON",
                TimerKind::Tof => "TOF",
                TimerKind::Tp => "TP",
            };
            let pt = time_literal(t.base_ms * t.preset);
            self.note(&format!("TM{n}"), at, || Global {
                decl: format!("{fb} := (PT := {pt})"),
                ty: fb.to_string(),
                constant: false,
                system: false,
                at: 0..0,
            });
            return Ok(Block::Timer(n));
        }
        if let Some(n) = up.strip_prefix("%C").and_then(num) {
            if p.listing && !p.counters.contains_key(&n) {
                return Err(unconfigured(&format!("%C{n}"), "PRESET=10"));
            }
            let pv = p
                .counters
                .get(&n)
                .copied()
                .unwrap_or(read::DEFAULT_COUNTER_PRESET);
            self.note(&format!("C{n}"), at, || Global {
                decl: format!("M221_C := (P := {pv})"),
                ty: "M221_C".to_string(),
                constant: false,
                system: false,
                at: 0..0,
            });
            return Ok(Block::Counter(n));
        }
        let vendor = |prefix: &str| up.strip_prefix(prefix).and_then(num);
        let (b, fb, init) = if let Some(n) = vendor("%DR") {
            if p.configured.contains(&format!("%DR{n}")) {
                return Err(NotObject::Unsupported(format!(
                    "the drum `%DR{n}` is configured (steps and control bits), which the import does not read yet"
                )));
            }
            // An unconfigured drum: 8 steps, no control bit assigned.
            (Block::Drum(n), "M221_DR", " := (STEPS := 8)")
        } else if let Some(n) = vendor("%SBR") {
            (Block::ShiftBit(n), "M221_SBR", "")
        } else if let Some(n) = vendor("%SC") {
            (Block::StepCounter(n), "M221_SC", "")
        } else if let Some(n) = vendor("%R") {
            let lifo = p.lifo.contains(&n);
            (
                Block::Register(n),
                if lifo { "M221_LIFO" } else { "M221_FIFO" },
                "",
            )
        } else {
            return Err(not_block(&up));
        };
        self.note(&b.name(), at, || Global {
            decl: format!("{fb}{init}"),
            ty: fb.to_string(),
            constant: false,
            system: false,
            at: 0..0,
        });
        Ok(b)
    }

    /// The global instance of subroutine `n` (`SRn`, a `SUB_SRn`), declared.
    pub fn subroutine(&mut self, n: u32, at: &Range<usize>) -> String {
        let name = format!("SR{n}");
        self.note(&name, at, || Global {
            decl: format!("SUB_SR{n}"),
            ty: format!("SUB_SR{n}"),
            constant: false,
            system: false,
            at: 0..0,
        });
        name
    }

    /// An operand of a bit or word instruction, or of an expression.
    pub fn operand(
        &mut self,
        p: &Project,
        s: &str,
        at: &Range<usize>,
    ) -> Result<Operand, NotObject> {
        if let Some(l) = literal(s) {
            return Ok(l);
        }
        let up = s.to_ascii_uppercase();
        let Some(rest) = up.strip_prefix('%') else {
            return Err(NotObject::Unknown);
        };
        let ok = |il: String, ty| Ok(Operand { il, ty });
        // Members of blocks: `%TM0.Q`, `%C1.V`, `%DR0.S`, `%R2.I`, `%SBR0.5`.
        if let Some((obj, member)) = rest.split_once('.')
            && ["TM", "C", "DR", "R", "SBR", "SC"].contains(&split_kind(obj).0)
            && !member.is_empty()
        {
            let b = self.block(p, &format!("%{obj}"), at)?;
            let name = b.name();
            let bit = num(member);
            return match (b, member) {
                (Block::Timer(_), "Q") => ok(format!("{name}.Q"), Ty::Bool),
                (Block::Counter(_), "D" | "E" | "F") => ok(format!("{name}.{member}"), Ty::Bool),
                (Block::Counter(_), "V" | "P") => ok(format!("{name}.{member}"), Ty::Int),
                (Block::Drum(_), "F") => ok(format!("{name}.F"), Ty::Bool),
                (Block::Drum(_), "S") => ok(format!("{name}.S"), Ty::Int),
                (Block::Register(_), "E" | "F") => ok(format!("{name}.{member}"), Ty::Bool),
                (Block::Register(_), "I") => ok(format!("{name}.IW"), Ty::Int),
                (Block::Register(_), "O") => ok(format!("{name}.OW"), Ty::Int),
                (Block::ShiftBit(_), _) if bit.is_some_and(|j| j < 16) => {
                    ok(format!("{name}.X.{member}"), Ty::Bool)
                }
                (Block::StepCounter(_), _) if bit.is_some_and(|j| j < 256) => {
                    let j = bit.unwrap_or(0);
                    ok(format!("{name}.X{}.{}", j / 16, j % 16), Ty::Bool)
                }
                (Block::Timer(_), "V" | "P") => Err(NotObject::Unsupported(format!(
                    "the timer's `%{obj}.{member}` is a word, for operation and comparison blocks (`[ %MW0 := %{obj}.{member} ]`)"
                ))),
                _ => Err(NotObject::Unknown),
            };
        }
        let (kind, tail) = split_kind(rest);
        match kind {
            "I" | "Q" => {
                let (m, c) = pair(tail).ok_or(NotObject::Unknown)?;
                if m >= 32 || c >= 32 {
                    return Err(NotObject::Unsupported(format!(
                        "`%{kind}{m}.{c}` lies outside the process image the import maps (modules 0 to 31, channels 0 to 31)"
                    )));
                }
                let name = format!("{kind}{m}_{c}");
                let addr = format!("%{kind}X{}.{}", 4 * m + c / 8, c % 8);
                self.note(&name, at, || Global {
                    decl: format!("AT {addr} : BOOL"),
                    ty: "BOOL".into(),
                    constant: false,
                    system: false,
                    at: 0..0,
                });
                ok(name, Ty::Bool)
            }
            "IW" | "QW" => {
                let (m, c) = pair(tail).ok_or(NotObject::Unknown)?;
                if m == 0 && ((100..108).contains(&c) || (200..208).contains(&c)) {
                    // A cartridge's channel (`%IW0.100`): a global the host
                    // binds, beside the image.
                    let name = format!("{kind}{m}_{c}");
                    self.plain(&name, "INT", at, false);
                    return ok(name, Ty::Int);
                }
                if m >= 8 || c >= 8 {
                    return Err(NotObject::Unsupported(format!(
                        "`%{kind}{m}.{c}` lies outside the process image the import maps (analog modules 0 to 7, channels 0 to 7)"
                    )));
                }
                let name = format!("{kind}{m}_{c}");
                let addr = format!("%{kind}{}", 64 + 8 * m + c);
                self.note(&name, at, || Global {
                    decl: format!("AT {addr} : INT"),
                    ty: "INT".into(),
                    constant: false,
                    system: false,
                    at: 0..0,
                });
                ok(name, Ty::Int)
            }
            "M" | "S" => {
                let n = num(tail).ok_or(NotObject::Unknown)?;
                let name = format!("{kind}{n}");
                let simulated = kind == "S" && SYS_BITS.contains(&n);
                if simulated {
                    self.sys_bits.insert(n);
                }
                self.plain(&name, "BOOL", at, kind == "S" && !simulated);
                ok(name, Ty::Bool)
            }
            "IWE" | "QWE" | "IWM" | "QWM" => {
                // EtherNet/IP and Modbus TCP exchange words: the host
                // reads and writes them.
                let n = num(tail).ok_or(NotObject::Unknown)?;
                let name = format!("{kind}{n}");
                self.plain(&name, "INT", at, true);
                ok(name, Ty::Int)
            }
            "SW" => {
                if let Some((w, b)) = tail.split_once(":X") {
                    let (Some(n), Some(k)) = (num(w), num(b)) else {
                        return Err(NotObject::Unknown);
                    };
                    if k > 15 {
                        return Err(NotObject::Unknown);
                    }
                    let word = self.operand(p, &format!("%SW{n}"), at)?;
                    return ok(format!("{}.{k}", word.il), Ty::Bool);
                }
                let n = num(tail).ok_or(NotObject::Unknown)?;
                let name = format!("SW{n}");
                self.plain(&name, "INT", at, true);
                ok(name, Ty::Int)
            }
            "MW" | "MD" | "MF" => {
                if let Some((w, b)) = tail.split_once(":X") {
                    // A bit of a word: `%MW4:X3` is bit 3 of `MW4`.
                    let (Some(n), Some(k)) = (num(w), num(b)) else {
                        return Err(NotObject::Unknown);
                    };
                    if kind != "MW" || k > 15 {
                        return Err(NotObject::Unknown);
                    }
                    let word = self.operand(p, &format!("%MW{n}"), at)?;
                    return ok(format!("{}.{k}", word.il), Ty::Bool);
                }
                let n = num(tail).ok_or(NotObject::Unknown)?;
                let (ty, t) = match kind {
                    "MW" => ("INT", Ty::Int),
                    "MD" => ("DINT", Ty::Dint),
                    _ => ("REAL", Ty::Real),
                };
                if kind != "MW" && p.shared_words {
                    // Views of two words: `expr` reads and writes them.
                    return Err(NotObject::Unsupported(format!(
                        "`%{kind}{n}` is a double word or float, for operation and comparison blocks"
                    )));
                }
                let name = format!("{kind}{n}");
                self.plain(&name, ty, at, false);
                ok(name, t)
            }
            "KW" => {
                let n = num(tail).ok_or(NotObject::Unknown)?;
                if p.listing && !p.constants.contains_key(&n) {
                    return Err(unconfigured(&format!("%KW{n}"), "VALUE=0"));
                }
                let name = format!("KW{n}");
                let v = p.constants.get(&n).copied().unwrap_or(0);
                self.note(&name, at, || Global {
                    decl: format!("INT := {v}"),
                    ty: "INT".into(),
                    constant: true,
                    system: false,
                    at: 0..0,
                });
                ok(name, Ty::Int)
            }
            _ => Err(not_block(&up)),
        }
    }
}

/// The letters of an object name and what follows (`MW` and `12`).
fn split_kind(rest: &str) -> (&str, &str) {
    let k = rest
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(rest.len());
    rest.split_at(k)
}

/// An object the import knows of but does not compile, or none.
fn not_block(up: &str) -> NotObject {
    let rest = up.trim_start_matches('%');
    let (kind, _) = split_kind(rest);
    let kind = if rest.starts_with("READ_VAR")
        || rest.starts_with("WRITE_VAR")
        || rest.starts_with("WRITE_READ_VAR")
        || rest.starts_with("SEND_RECV")
    {
        "MSG"
    } else {
        kind
    };
    let what = match kind {
        "DR" => "a drum",
        "R" => "a FIFO/LIFO register",
        "SBR" => "a shift bit register",
        "SC" => "a step counter",
        "FC" | "HSC" => "a fast or high-speed counter",
        "PLS" | "PWM" | "PTO" | "FREQGEN" => "a pulse or frequency generator",
        "SCH" => "a schedule block",
        "PID" => "a PID",
        "MSG" | "READ_VAR" | "WRITE_VAR" | "WRITE_READ_VAR" => "a communication block",
        "KD" | "KF" => "a constant double word or float (their configured values are not read)",
        "TMR" => "a timer of another series",
        _ => return NotObject::Unknown,
    };
    NotObject::Unsupported(format!(
        "`{up}` is {what}, which the import does not compile yet"
    ))
}
