//! The command line of `ilc` (clap builder API).

use clap::{Arg, ArgAction, Command, builder::PossibleValuesParser};

use crate::input::{dialect_arg, encoding_arg, snippet_arg, std_arg};

const ABOUT: &str = "Check IEC 61131-3 Instruction List (IL) sources and compile them to Rust";

const LONG_ABOUT: &str = "\
ilc checks IEC 61131-3 Instruction List (IL) sources and reports every problem
it finds, with the line and column and a suggestion where it has one.";

const EXAMPLES: &str = "\
Examples:
  ilc check motor.il                     Check one file; silent when it is fine
  ilc emit motor.il                      Print the Rust code generated from motor.il
  ilc emit -o src/plc *.il               Write one .rs file per IL file
  ilc check src/*.il                     Check several files (all are checked)
  ilc check plc.xml                      Check the IL POUs of a PLCopen XML project
                                         (any file whose text starts with `<`)
  ilc check --message-format json a.il   One JSON object per diagnostic on stdout
  ilc check --color always a.il | less -R
  cat a.il | ilc check -                 Read the source from standard input
  ilc run main.il --cycles 5 --watch q   Simulate 5 scans without compiling
  ilc check --snippet table51.il         A bare instruction list, no POU around it
  ilc --encoding windows-1251 check x.exp
                                         Read files that are not UTF-8 as Windows-1251
                                         (without it: Windows-1252, with a warning)
  ilc explain IL0003                     What a diagnostic code means
  ilc lsp                                Serve an editor (Language Server Protocol on stdio)
  ilc debug                              Serve a debugger (Debug Adapter Protocol on stdio)

Exit status:
  0  no errors (warnings may have been printed)
  1  at least one error, or a file could not be read
  2  the command line itself is wrong";

const CHECK_EXAMPLES: &str = "\
Examples:
  ilc check motor.il
  ilc check --message-format json motor.il conveyor.il
  ilc check --color never - < motor.il

JSON output: one object per line on stdout, with the fields file, line, column,
end_line, end_column (1-based; columns count characters), severity, code,
message, label, secondary, notes, help (string or null) and rendered (the
human-readable text). Nothing else is written to stdout.";

const EMIT_EXAMPLES: &str = "\
Examples:
  ilc emit motor.il                      Print the Rust code for motor.il
  ilc emit -o src/plc motor.il lib.il    Write src/plc/motor.rs and src/plc/lib.rs

The files are checked together (a FUNCTION_BLOCK of one can be used in another).
Nothing is written unless every file compiles; a file whose content did not
change is not rewritten. The generated code needs the il-std crate.";

const LSP_EXAMPLES: &str = "\
Examples:
  ilc lsp                     Started by the editor, which talks to it on stdin/stdout

The editor sends the IL (.il) and PLCopen (.xml) documents it opens, each read
as XML when its text starts with `<` and as IL otherwise, whatever its name;
the .il files of its workspace folders are read too, and all of them are checked as
one program, as `ilc check a.il b.il` does. Files read from disk that are not
UTF-8 are decoded in `--encoding`, or in the initialization option
`{\"encoding\": \"windows-1251\"}`. The server publishes the same
diagnostics as `ilc check`, and answers hover (the CR type before and after
an instruction, declarations, standard signatures), inlay hints (the CR type
at the end of each instruction line; off with the client setting
`inlayHints.crType: false`), go to definition, references, rename, document
and workspace symbols, completion and formatting (as `ilc fmt`). editors/vscode holds a VS Code client.";

const DEBUG_EXAMPLES: &str = "\
Examples:
  ilc debug                   Started by the editor, which talks to it on stdin/stdout

The editor's launch configuration names the program and how to run it:
  { \"type\": \"ilc\", \"request\": \"launch\", \"program\": \"motor.il\", \"pou\": \"Motor\",
    \"cycles\": 6, \"cycleTime\": \"10ms\", \"set\": [\"start=TRUE@3\"], \"stopOnEntry\": false }
Breakpoints go on IL lines (with conditions such as `count > 5`, hit counts and
log messages) and on POU names; every stop shows the current result (value and
type), the scan number and the simulated time first. docs/guide.md: Debugging.";

/// The whole command line.
pub fn command() -> Command {
    Command::new("ilc")
        .version(env!("CARGO_PKG_VERSION"))
        .about(ABOUT)
        .long_about(LONG_ABOUT)
        .after_long_help(EXAMPLES)
        .subcommand_required(true)
        .arg_required_else_help(true)
        .arg(encoding_arg())
        .subcommand(
            Command::new("check")
                .about("Parse and check IL files; print diagnostics")
                .after_long_help(CHECK_EXAMPLES)
                .arg(
                    Arg::new("files")
                        .value_name("FILE")
                        .help("IL source files to check (`-` reads standard input); a file whose text starts with `<` (or named `.xml`) is a PLCopen TC6 project")
                        .required(true)
                        .num_args(1..)
                        .action(ArgAction::Append),
                )
                .arg(
                    Arg::new("message-format")
                        .long("message-format")
                        .value_name("FORMAT")
                        .help("How diagnostics are written")
                        .long_help(
                            "How diagnostics are written: `human` renders them for people on \
                             stderr; `json` writes one JSON object per diagnostic per line on stdout",
                        )
                        .value_parser(PossibleValuesParser::new(["human", "json"]))
                        .default_value("human"),
                )
                .arg(
                    Arg::new("color")
                        .long("color")
                        .value_name("WHEN")
                        .help("Colour the human output")
                        .long_help(
                            "Colour the human output: `auto` colours only when stderr is a \
                             terminal and NO_COLOR is not set",
                        )
                        .value_parser(PossibleValuesParser::new(["auto", "always", "never"]))
                        .default_value("auto"),
                )
                .arg(
                    Arg::new("verbose")
                        .long("verbose")
                        .short('v')
                        .action(ArgAction::SetTrue)
                        .help("Also list what was not compiled: the objects of a CODESYS export (.EXP) that are no code, one note each"),
                )
                .arg(std_arg())
                .arg(dialect_arg())
                .arg(snippet_arg()),
        )
        .subcommand(
            Command::new("emit")
                .about("Compile IL files to Rust (to stdout, or files with -o)")
                .after_long_help(EMIT_EXAMPLES)
                .arg(
                    Arg::new("files")
                        .value_name("FILE")
                        .help("IL source files (or PLCopen XML projects, known by their text), compiled together as one program")
                        .required(true)
                        .num_args(1..)
                        .action(ArgAction::Append),
                )
                .arg(
                    Arg::new("out-dir")
                        .short('o')
                        .long("out-dir")
                        .value_name("DIR")
                        .help("Write DIR/<name>.rs for each FILE instead of printing"),
                )
                .arg(
                    Arg::new("color")
                        .long("color")
                        .value_name("WHEN")
                        .help("Colour the diagnostics")
                        .value_parser(PossibleValuesParser::new(["auto", "always", "never"]))
                        .default_value("auto"),
                )
                .arg(std_arg())
                .arg(dialect_arg())
                .arg(snippet_arg()),
        )
        .subcommand(
            Command::new("run")
                .about("Simulate scans of a PROGRAM or CONFIGURATION with the interpreter and print a table")
                .after_long_help(crate::run::EXAMPLES)
                .arg(
                    Arg::new("files")
                        .value_name("FILE")
                        .required(true)
                        .num_args(1..)
                        .help("IL source file, or a PLCopen XML project (known by its text), or the .EXP files (or folder) of a CODESYS project, read as one program"),
                )
                .arg(Arg::new("program").long("program").value_name("NAME").help(
                    "The PROGRAM (or FUNCTION_BLOCK) to run; default: the only PROGRAM; with several PROGRAMs or none (or in a CODESYS project with tasks, or an M221 project), the only CONFIGURATION",
                ))
                .arg(Arg::new("config").long("config").value_name("NAME").help(
                    "The CONFIGURATION to run: its tasks decide which programs each scan runs",
                ))
                .arg(
                    Arg::new("cycles")
                        .long("cycles")
                        .value_name("N")
                        .help("Number of scans")
                        .value_parser(clap::value_parser!(u64).range(1..=10_000_000))
                        .default_value("10"),
                )
                .arg(
                    Arg::new("step")
                        .long("step")
                        .value_name("DURATION")
                        .help("Simulated time between scans (10ms, T#1s)")
                        .value_parser(crate::run::parse_step)
                        .default_value("10ms"),
                )
                .arg(
                    Arg::new("set")
                        .long("set")
                        .value_name("VAR=VALUE[@CYCLE]")
                        .help("Write VALUE to VAR before scan CYCLE (default 1); repeatable")
                        .value_parser(crate::run::parse_set)
                        .action(ArgAction::Append),
                )
                .arg(
                    Arg::new("watch")
                        .long("watch")
                        .value_name("VAR,...")
                        .help("Variables to show (members as t1.Q, elements as m[1,2]); default: all")
                        .action(ArgAction::Append),
                )
                .arg(
                    Arg::new("vcd")
                        .long("vcd")
                        .value_name("FILE")
                        .help("Also write the watched variables as a VCD waveform (GTKWave, Surfer)"),
                )
                .arg(
                    Arg::new("plot")
                        .long("plot")
                        .value_name("FILE")
                        .help("Also draw a timing diagram of the watched variables as SVG"),
                )
                .arg(
                    Arg::new("flow")
                        .long("flow")
                        .action(ArgAction::SetTrue)
                        .help("Also print the current result after every IL line run in the last scan"),
                )
                .arg(
                    Arg::new("color")
                        .long("color")
                        .value_name("WHEN")
                        .help("Colour the diagnostics")
                        .value_parser(PossibleValuesParser::new(["auto", "always", "never"]))
                        .default_value("auto"),
                )
                .arg(std_arg())
                .arg(dialect_arg())
                .arg(snippet_arg()),
        )
        .subcommand(
            Command::new("lsp")
                .about("Run the language server for editors (LSP over stdio)")
                .after_long_help(LSP_EXAMPLES),
        )
        .subcommand(
            Command::new("fmt")
                .about("Lay out IL files as PLC IDEs show them (in place, or --check)")
                .long_about(
                    "Lay out IL files as PLC IDEs show them: the operator at column 4 after a \
                     label column, operands after the widest operator, declarations aligned by \
                     their `:`, trailing comments aligned, keywords in the case the file mostly \
                     uses. Only blanks and the case of keywords change; line breaks, comments \
                     and pragmas stay. A file with syntax errors is left as it is. Files are \
                     rewritten in place (`-` reads standard input and writes standard output).",
                )
                .arg(
                    Arg::new("files")
                        .value_name("FILE")
                        .help("IL files to format (`-`: standard input to standard output)")
                        .required(true)
                        .num_args(1..)
                        .action(ArgAction::Append),
                )
                .arg(
                    Arg::new("check")
                        .long("check")
                        .help("Change nothing; list the files that are not formatted and exit with 1 if any")
                        .action(ArgAction::SetTrue),
                )
                .arg(
                    Arg::new("keywords")
                        .long("keywords")
                        .value_name("CASE")
                        .help("The case of keywords")
                        .value_parser(PossibleValuesParser::new(["file", "upper", "lower", "preserve"]))
                        .default_value("file"),
                ),
        )
        .subcommand(
            Command::new("debug")
                .about("Run the debug adapter for editors (Debug Adapter Protocol over stdio)")
                .after_long_help(DEBUG_EXAMPLES),
        )
        .subcommand(
            Command::new("explain")
                .about("Explain a diagnostic code, e.g. IL0003")
                .arg(Arg::new("code").value_name("CODE").required(true)),
        )
}

#[cfg(test)]
mod tests {
    #[test]
    fn command_is_well_formed() {
        super::command().debug_assert();
    }
}
