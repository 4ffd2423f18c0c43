//! What every command reads: its sources (a path, or `-` for standard
//! input) and how they are read and become a program (`--encoding`,
//! `--std`, `--dialect` and `--snippet`: the arguments and their values).

use std::io;
use std::path::Path;

use clap::{Arg, ArgAction, builder::PossibleValuesParser};
use il_codegen::SourceFile;

/// Read one source. `-` is standard input. The error names the path.
/// (`il_codegen::read`: the same rules as the build script and `il!`.)
pub fn read_source(path: &str, encoding: il_codegen::read::Encoding) -> Result<SourceFile, String> {
    let read = if path == "-" {
        il_codegen::read::read_stream(io::stdin().lock(), "<stdin>", encoding)
    } else {
        il_codegen::read::read_source(Path::new(path), path, encoding)
    };
    read.map_err(|e| e.to_string())
}

/// The paths given, with each folder replaced by its source files (`.exp`,
/// `.il`, `.xml`, `.plcprj`, any case), sorted: a CODESYS project exported one object
/// per file is given as its folder (`ilc check project/`).
pub fn expand(paths: impl Iterator<Item = String>) -> Vec<String> {
    let mut out = Vec::new();
    for p in paths {
        let Ok(entries) = std::fs::read_dir(&p) else {
            out.push(p);
            continue;
        };
        let mut inner: Vec<String> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|f| {
                f.is_file()
                    && f.extension().is_some_and(|e| {
                        ["exp", "il", "xml", "plcprj"]
                            .iter()
                            .any(|x| e.eq_ignore_ascii_case(x))
                    })
            })
            .map(|f| f.display().to_string())
            .collect();
        inner.sort();
        if inner.is_empty() {
            // Read as given: the error says it is a directory.
            out.push(p);
        }
        out.extend(inner);
    }
    out
}

/// `--std=iec2003`: refuse the 3rd-edition and vendor forms (pragmas,
/// implicit widening, partial access), each with an error naming it.
pub fn std_arg() -> Arg {
    Arg::new("std")
        .long("std")
        .value_name("STANDARD")
        .help("Edition of IEC 61131-3 to check against")
        .long_help(
            "Edition of IEC 61131-3 to check against: `iec2013` (the default) accepts the \
             3rd-edition and vendor forms real projects use (pragmas, implicit widening \
             conversions, partial bit access); `iec2003` refuses each of them with an error \
             that names it",
        )
        .value_parser(PossibleValuesParser::new(["iec2013", "iec2003"]))
        .default_value("iec2013")
}

/// `--dialect m221`: the text sources are Modicon M221 / TwidoSuite
/// Instruction List listings.
pub fn dialect_arg() -> Arg {
    Arg::new("dialect")
        .long("dialect")
        .value_name("DIALECT")
        .help("Instruction List of the text sources: `iec` (the default) or `m221`")
        .long_help(
            "Instruction List the text sources are written in: `iec` (the default), IEC \
             61131-3 IL; `m221`, a Modicon M221 (Machine Expert Basic, SoMachine Basic) or \
             Twido (TwidoSuite) listing as the IDE shows it: one instruction a line \
             (`LD %I0.1`, `BLK %TM0`, `[ %MW1 := %MW2 + 1 ]`), rungs apart by blank lines \
             or comments, `%L1:` labels, `SR1:` subroutines, and the timers, counters and \
             constant words configured in comments `(*@ %TM0 TON BASE=100ms PRESET=50 *)`. \
             XML sources (`.smbp` projects too) are read by their content either way",
        )
        .value_parser(PossibleValuesParser::new(["iec", "m221"]))
        .default_value("iec")
}

/// `--snippet`: the file is a bare instruction list.
pub fn snippet_arg() -> Arg {
    Arg::new("snippet")
        .long("snippet")
        .action(ArgAction::SetTrue)
        .help("Each file is a bare instruction list, the body of a PROGRAM named after the file")
        .long_help(
            "Each file is a bare instruction list with no POU around it, like the standard's \
             Table 51 (`START: LD %IX1 / ANDN %MX5 / ST %QX2`): it is compiled as the body \
             of a PROGRAM named after the file. Only direct addresses and literals need no \
             declaration; an error lists every other name",
        )
}

/// `--encoding`: on every subcommand that reads files (`lsp` too).
pub fn encoding_arg() -> Arg {
    Arg::new("encoding")
        .long("encoding")
        .value_name("ENCODING")
        .global(true)
        .help("Encoding of the sources that are not UTF-8 (windows-1251, iso-8859-15 ...)")
        .long_help(
            "Encoding of the sources that are not UTF-8, a WHATWG label: `windows-1252` \
             (Western Europe), `windows-1251` (Cyrillic), `windows-1250` (Central Europe), \
             `iso-8859-15`, `koi8-r`, `shift_jis`, `gbk`, `utf-16le` ... PLC IDEs on Windows \
             (CODESYS V2.3 `.EXP` exports) write the machine's code page. A file that is valid \
             UTF-8, or has a byte order mark, is read as such all the same. Without it, a file \
             that is not UTF-8 is read as Windows-1252 with a warning (IL0039)",
        )
        .value_parser(|s: &str| il_codegen::read::Encoding::from_label(s))
}

/// How the sources are read and become a program: `--encoding`, `--std`
/// and `--snippet`.
#[derive(Clone, Copy, Debug, Default)]
pub struct Front {
    /// `--encoding`: how files that are not UTF-8 are read.
    pub encoding: il_codegen::read::Encoding,
    /// `--std`: the edition the program is checked against.
    pub standard: il_codegen::Standard,
    /// `--snippet`: each file is the body of a PROGRAM.
    pub snippet: bool,
    /// `--dialect`: the Instruction List of the text sources.
    pub dialect: il_codegen::Dialect,
}

impl Front {
    /// `--encoding`, `--std` and `--snippet` as given.
    pub fn of(m: &clap::ArgMatches) -> Front {
        Front {
            encoding: m
                .get_one::<il_codegen::read::Encoding>("encoding")
                .copied()
                .unwrap_or_default(),
            standard: m
                .get_one::<String>("std")
                .and_then(|s| il_codegen::Standard::from_name(s))
                .unwrap_or_default(),
            snippet: m.get_flag("snippet"),
            dialect: m
                .get_one::<String>("dialect")
                .and_then(|s| il_codegen::Dialect::from_name(s))
                .unwrap_or_default(),
        }
    }

    /// Read one source (`-`: standard input) in `--encoding`.
    pub fn read(self, path: &str) -> Result<il_codegen::SourceFile, String> {
        read_source(path, self.encoding)
    }

    /// A program of `files`, each read as these options say.
    pub fn program(self, files: Vec<il_codegen::SourceFile>) -> il_codegen::Program {
        files.into_iter().fold(
            il_codegen::Program::new().standard(self.standard),
            |p, f| {
                // XML is no instruction list: it is imported under
                // `--snippet` too.
                if self.snippet && !il_codegen::pipeline::is_xml(&f.name, &f.text) {
                    p.snippet(f)
                } else {
                    p.input(self.dialect.input(f))
                }
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn byte_order_mark_is_dropped() {
        let dir = std::env::temp_dir().join(format!("ilc-bom-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("bom.il");
        std::fs::write(&p, "\u{feff}PROGRAM p\nEND_PROGRAM\n").unwrap();
        let f = read_source(p.to_str().unwrap(), Default::default()).unwrap();
        assert!(f.text.starts_with("PROGRAM"));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn missing_file_names_the_path() {
        let e = read_source("/nonexistent/dir/x.il", Default::default()).unwrap_err();
        assert!(e.contains("`/nonexistent/dir/x.il`"), "{e}");
        assert!(e.contains("no such file"), "{e}");
    }
}
