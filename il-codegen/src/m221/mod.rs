//! Schneider Modicon M221 projects (Machine Expert Basic / SoMachine Basic,
//! `.smbp`, XML root `<ProjectDescriptor>`).
//!
//! Every rung of an M221 program, even one drawn in ladder, is stored with
//! its Instruction List (`<InstructionLines>`), and the timers, counters and
//! constants it uses are configured in the same file. The XML is parsed by
//! the PLCopen import's parser (same limits, same located errors for
//! malformed XML), which hands a `<ProjectDescriptor>` root to `translate`.
//! It writes one IEC IL text, mapped back into the XML
//! ([`crate::plcopen::SpanMap`]), so every diagnostic points at the
//! instruction line it comes from:
//! - each POU of the master task (`<Pous>`) as a PROGRAM, its rungs in
//!   order, each instruction line translated to IEC IL (`rung`, `blocks`,
//!   `brackets` for operation and comparison blocks, whose expressions
//!   `expr` parses and writes);
//! - the objects the program uses (`%I0.3`, `%M5`, `%MW2`, `%TM0` ...) as
//!   globals of one CONFIGURATION `M221` (`objects`, `write`), the timers
//!   and counters configured from `<Timers>` / `<Counters>` (`read`).
//!
//! - each subroutine (`<Subroutines>`) as a FUNCTION_BLOCK `SUB_SRn` with
//!   one global instance `SRn`, which `CAL SRn` calls;
//! - the system bits the controller sets (`%S0`, `%S13`, the clocks `%S4`
//!   .. `%S7`) from il-std's `M221_SYS`, run at the start of every scan.
//!
//! A text listing (`--dialect m221`, [`crate::Dialect::M221`]) is read by
//! `listing` into the same project (its configuration from `(*@ ... *)`
//! comments), so an instruction line has one translation whichever file
//! holds it.
//!
//! docs/semantics.md, "Modicon M221 dialect", says what each object and
//! instruction means and which choices are made where the manuals are
//! silent.

#[cfg(feature = "plcopen")]
mod blocks;
#[cfg(feature = "plcopen")]
mod brackets;
#[cfg(feature = "plcopen")]
mod expr;
#[cfg(feature = "plcopen")]
mod listing;
#[cfg(feature = "plcopen")]
mod objects;
#[cfg(feature = "plcopen")]
mod read;
#[cfg(feature = "plcopen")]
mod rung;
#[cfg(feature = "plcopen")]
mod write;

/// The codes of the M221 import.
pub mod codes {
    crate::diag::codes::codes! {
    BAD_LINE = "IL0430", "M221 instruction line the import cannot read",
        "An `<InstructionLine>` of a Modicon M221 project (`.smbp`) is not an instruction of the M221's Instruction List as the import reads it: an unknown instruction, a missing or extra operand, an operand that is no M221 object (`%I0.1`, `%M3`, `%MW10`, `%TM0` ...), a `)` without its `AND(`/`OR(`, an `OUT_BLK` outside `BLK ... END_BLK`. The rung is left out of the program, with this error; the other rungs are still translated, so every such line is reported at once.\n\n    <InstructionLine>LD %X0.0</InstructionLine>";
    UNSUPPORTED = "IL0431", "M221 object or instruction the import does not compile",
        "A rung uses an object or instruction of the M221 that the import does not compile yet (a fast counter `%FCn`, a PID, a communication block `%WRITE_VARn`, `CAL` of something other than a subroutine `SRn` ...), or one whose configuration it does not read (a configured drum `%DRn`, a project's `<Subroutines>` in another layout than its `<Pous>`). The message names the object, the rung and why. The rung is left out of the program.\n\n    <InstructionLine>BLK %FC0</InstructionLine>";
    BAD_CONFIG = "IL0433", "M221 object configuration the import cannot read",
        "An element of the project's configuration of an object (a `<TimerTM>`'s `<Preset>`, `<Base>` or `<Type>`, a `<CounterCT>`'s `<Preset>`, a `<ConstantWord>`'s `<Value>`) holds a value the import does not know: a preset that is not a number from 0 to 32767, a time base other than `OneMillisecond`, `TenMilliseconds`, `HundredMilliseconds`, `OneSecond`, `OneMinute`, a timer type other than `TON`, `TOF`, `TP`. The object takes its default (`TON`, one minute, preset 9999) with this error.\n\n    <TimerTM><Address>%TM0</Address><Base>Fortnight</Base></TimerTM>";
    BAD_PROJECT = "IL0435", "M221 project the import cannot read",
        "The XML's root is Machine Expert Basic's, but the file holds no program the import can read: a protected project (`<CryptedProject>`: its program is encrypted; save it without protection in Machine Expert Basic), or a `<ProjectDescriptor>` without `<SoftwareConfiguration><Pous>`. One error; nothing is compiled.\n\n    <CryptedProject><ProjectVersion>2.0.0.0</ProjectVersion><Crypted>...</Crypted></CryptedProject>";
    UNCONFIGURED = "IL0436", "M221 listing object without its configuration",
        "A text listing (`--dialect m221`) holds only the program: the timers' types, time bases and presets, the counters' presets and the constant words' values that a `.smbp` project configures are not in it. A listing gives each `%TMn`, `%Cn` and `%KWn` it uses in a configuration comment, one object per comment, anywhere in the file:\n\n    (*@ %TM0 TON BASE=100ms PRESET=50 *)   (* TON, TOF or TP; BASE 1ms, 10ms, 100ms, 1s or 1min; PRESET 0 to 32767 *)\n    (*@ %C0 PRESET=10 *)                   (* 0 to 9999 *)\n    (*@ %KW3 VALUE=-12 *)                  (* -32768 to 32767 *)\n    (*@ %R1 LIFO *)                        (* a register is a FIFO without it *)\n\nAn object used without one is this error at its first use in each rung (the rung is left out), whose message gives the comment to add. A configuration comment the import cannot read is IL0433.";
    SYSTEM_OBJECT = "IL0434", "M221 system or network object set by the host",
        "A rung uses a system bit `%Sn` or word `%SWn` whose behaviour the import does not simulate, or a word exchanged with a network master (EtherNet/IP `%IWEn`/`%QWEn`, Modbus TCP `%IWMn`/`%QWMn`). The import declares it as a global of the configuration (`S8`, `SW7`, `QWE0`) that starts at 0 and that the host (or `ilc run --set %S8=TRUE`) sets or reads. One warning per object. The bits the controller itself sets each scan are simulated and get no warning: `%S0` (cold start) and `%S13` (first cycle), 1 in the first scan only, and the clocks `%S4`, `%S5`, `%S6`, `%S7` (10 ms, 100 ms, 1 s, 1 min, each 0 in the first half of its period and 1 in the second), computed by il-std's `M221_SYS` at the start of every scan.\n\n    LD %S8     (* wiring test: not simulated *)";
    }
}
pub use codes::CODES;

/// Whether an XML root is an M221 project's: `<ProjectDescriptor>`, or a
/// protected project's `<CryptedProject>`, in no namespace.
#[cfg(feature = "plcopen")]
pub(crate) fn is_root(root: roxmltree::Node) -> bool {
    let tag = root.tag_name();
    tag.namespace().is_none() && matches!(tag.name(), "ProjectDescriptor" | "CryptedProject")
}

#[cfg(feature = "plcopen")]
pub(crate) use listing::translate as translate_listing;
#[cfg(feature = "plcopen")]
pub(crate) use write::translate;

/// The IL name the import gives an M221 object written as in the program
/// (`%I0.3` → `I0_3`, `%MW4:X3` → `MW4.3`, `%C0.V` → `C0.V`, `%SBR0.5` →
/// `SBR0.X.5`): what `ilc run --set/--watch` look up for a name that starts
/// with `%` in an M221 program. `None` for what is no M221 object (an IEC
/// address such as `%IX0.5` is then looked up as it is). The import's own
/// mapping (its `objects` module), so the two cannot differ.
pub fn il_name(object: &str) -> Option<String> {
    #[cfg(feature = "plcopen")]
    {
        if !object.starts_with('%') {
            return None;
        }
        let p = read::Project::default();
        let mut objs = objects::Objects::default();
        objs.operand(&p, object.trim(), &(0..0)).ok().map(|o| o.il)
    }
    #[cfg(not(feature = "plcopen"))]
    {
        let _ = object;
        None
    }
}

/// Whether an XML text is an M221 project: its root element, after the
/// prolog and comments, is `<ProjectDescriptor>` (for `ilc run`, which runs
/// such a project's configuration, as the controller runs its POUs).
pub fn is_project(xml: &str) -> bool {
    let mut rest = xml.trim_start_matches('\u{feff}');
    loop {
        rest = rest.trim_start();
        if let Some(r) = rest.strip_prefix("<?").or_else(|| rest.strip_prefix("<!")) {
            match r.find('>') {
                Some(k) => rest = &r[k + 1..],
                None => return false,
            }
        } else {
            return rest.strip_prefix("<ProjectDescriptor").is_some_and(|r| {
                r.starts_with(|c: char| c.is_whitespace() || c == '>' || c == '/')
            });
        }
    }
}
