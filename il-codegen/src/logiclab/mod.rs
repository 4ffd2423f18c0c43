//! Axel LogicLab / Arduino PLC IDE projects (`.plcprj`, XML) and libraries
//! (`.plclib`).
//!
//! LogicLab 5 (and the Arduino PLC IDE built on it, for Opta and Portenta
//! Machine Control) saves a project as one XML file: `<plcProject>` holds
//! `<sources><main>` (the project's POUs, data types, global variable groups,
//! the target's tasks and the programs each runs) and `<libraries>`, whose
//! `<lib fullXml="true">` elements carry each linked library's contents in
//! the same structure (the vendor's `Standard.plclib`, Modbus, CANopen ...).
//! A `.plclib` file is one such library on its own (`<plcLibrary><lib>`).
//!
//! The XML is parsed by the PLCopen import's parser (same limits, same
//! located errors for malformed XML), which hands a `<plcProject>` or
//! `<plcLibrary>` root to `translate`. It writes one IL text, mapped back
//! byte for byte into the XML ([`crate::plcopen::SpanMap`]):
//! - the project's data types (structs, enums, typedefs, subranges) as
//!   `TYPE ... END_TYPE`;
//! - each POU whose `<sourceCode type="IL">` is Instruction List with its
//!   body copied as it is; a POU in another language (ST, LD, FBD, SFC, or
//!   the firmware's `EMBEDDED` functions) keeps its interface and is
//!   host-provided (`{extern}`), as the `.EXP` import does, with one warning
//!   (a library's get one warning for the library);
//! - a library's POUs, types and globals only when the project uses them
//!   (an unused `EMBEDDED` function would otherwise ask the crate for a body);
//! - the global variable groups as the VAR_GLOBALs of one generated
//!   CONFIGURATION `Project`; LogicLab POUs see them without VAR_EXTERNAL,
//!   so every IL PROGRAM and FUNCTION_BLOCK that names one gets it (a
//!   constant becomes a local `VAR CONSTANT` with its value); a VAR_EXTERNAL
//!   that names no global of the project names one of the target (`sysTimer`)
//!   and is declared in the CONFIGURATION, for the host to set;
//! - the resource's tasks and the programs they run (`<tasks>`): a cyclic
//!   task with its interval, a `single` task (LogicLab's `Init`, run once at
//!   start) as `SINGLE := TRUE`.
//!
//! A function block that has the name of an IEC standard block (the
//! vendor's `Standard.plclib` defines `TON`, `CTU`, `R_TRIG` ... in IL) is
//! compiled as `TON_LogicLab`, the type of the project's variables of type
//! `TON`, with a warning; a function of a standard name is left out
//! (il-std's is used).

#[cfg(feature = "plcopen")]
mod config;
#[cfg(feature = "plcopen")]
mod decls;
#[cfg(feature = "plcopen")]
mod lx;
#[cfg(feature = "plcopen")]
mod read;
#[cfg(feature = "plcopen")]
mod write;

/// The codes of the LogicLab import.
pub mod codes {
    crate::diag::codes::codes! {
    NOT_IL = "IL0420", "LogicLab POU not in IL: compiled as its interface",
        "A POU of a LogicLab / Arduino PLC IDE project whose `<sourceCode type=\"...\">` is not `IL` (ST, LD, LD2, FBD, SFC, CFC, or `EMBEDDED`: a function of the target's firmware) keeps its interface: its inputs, outputs and in-outs are compiled, so IL POUs can call it, and its body is not. In generated Rust it is host-provided, as an `{extern}` POU is: the crate supplies the body; the interpreter (`ilc run`) runs its interface only. One warning per POU of the project; the POUs of a library that the project uses get one warning for the library.\n\n    <functionBlock name=\"Ramp\">\n      <vars>...</vars>\n      <sourceCode type=\"ST\"><![CDATA[y := y + x;]]></sourceCode>\n    </functionBlock>";
    BAD_PROJECT = "IL0421", "not a LogicLab project the import can read",
        "The XML's root is LogicLab's (`<plcProject>`, `<plcLibrary>`) but it lacks what a project must have, or keeps it in a form the import does not read: no `<sources><main>`; a LogicLab 3 project (`.ppjs`), whose `<main>` is IEC text rather than XML elements (open it in LogicLab 5 or the Arduino PLC IDE and save it as `.plcprj`); a POU without `name`, a FUNCTION without `<returnValue>`, an enumeration without elements. The element is left out; the rest is still translated.\n\n    <plcProject>\n      <sources><main><![CDATA[PROGRAM Main ...]]></main></sources>   <!-- LogicLab 3 -->";
    BAD_VALUE = "IL0422", "value of a LogicLab project that cannot be written as IL",
        "An attribute or element text that becomes part of the IL text holds something it cannot: a name that is not an IEC identifier, a type that is not a type name (`type=\"@BYTE\"`), an array size or string length that is not a positive number, an initial value that is not one literal or name, a task interval that is not a duration. The element (a variable, a type, a POU, a task) is left out; nothing of the value reaches the IL text.\n\n    <var name=\"x; END_VAR\" type=\"INT\"/>\n    <var name=\"buf\" type=\"BYTE\" dim0=\"-1\"/>";
    STANDARD_NAME = "IL0423", "LogicLab POU with the name of a standard block or function",
        "LogicLab's `Standard.plclib` (and a project) may define a POU with the name of an IEC standard function block or function: `TON`, `TOF`, `TP`, `CTU`, `CTD`, `CTUD` and their typed forms, `R_TRIG`, `F_TRIG`, `SR`, `RS`. A POU may not take a standard name (IL0104), so a FUNCTION_BLOCK of such a name that the project uses is compiled under the name `TON_LogicLab`, and every variable of the project declared `TON` gets that type: the project runs the vendor's blocks, as on the target. LogicLab's timers take `PT` and give `ET` as UDINT milliseconds counted from the target's global `sysTimer`, which the host sets (IL0425). One warning per block of the project, one per library for the library's blocks. A FUNCTION or PROGRAM of a standard name is left out, and il-std's function is used.\n\n    <functionBlock name=\"TON\"> ... <sourceCode type=\"IL\"> ...";
    NOT_IEC_ADDRESS = "IL0424", "LogicLab address that is no IEC address",
        "LogicLab locates a variable with `<address type=\"M\" typeVar=\"W\" index=\"201\" subIndex=\"0\"/>`: a data block (`index`) and a position in it (`subIndex`). A bit address (`typeVar=\"X\"`) with a `subIndex` of 0 to 7 is bound as the IEC address `%QX1.5` (area, byte `index`, bit `subIndex`); a byte, word or double word address names a position in a data block, which IEC addresses do not: the variable is compiled without an address, with this warning, and the host binds it.\n\n    <var name=\"Setpoint\" type=\"INT\"><address type=\"M\" typeVar=\"W\" index=\"201\" subIndex=\"3\"/></var>";
    TARGET_GLOBAL = "IL0425", "VAR_EXTERNAL of a global of the target",
        "A POU declares a VAR_EXTERNAL that no global variable group of the project declares: it is a global of the target (LogicLab's `sysTimer`, `sysLEDOutputs` ...), which the target file defines and the project does not hold as XML. It is declared in the generated CONFIGURATION as a global of the VAR_EXTERNAL's type, without an address: the host sets it (for `sysTimer`, the milliseconds since start). One warning per name.\n\n    <externalVars><var name=\"sysTimer\" type=\"UDINT\"/></externalVars>";
    SKIPPED = "IL0426", "part of a LogicLab project not translated",
        "A part of the project is left out, with this warning: a library kept as text (`<lib fullXml=\"false\">`, LogicLab 3's `.pll`), macros, interfaces and methods, a variable block the import does not know, a task of a type other than `cyclic` or `single`, a task's program that is not in the project or was left out.\n\n    <lib name=\"Machine.pll\" fullXml=\"false\"><![CDATA[...]]></lib>";
    }
}
pub use codes::CODES;

/// Whether an XML root is LogicLab's: a project (`<plcProject>`) or a
/// library (`<plcLibrary>`), in no namespace.
#[cfg(feature = "plcopen")]
pub(crate) fn is_root(root: roxmltree::Node) -> bool {
    let tag = root.tag_name();
    tag.namespace().is_none() && matches!(tag.name(), "plcProject" | "plcLibrary")
}

#[cfg(feature = "plcopen")]
pub(crate) use write::translate;
