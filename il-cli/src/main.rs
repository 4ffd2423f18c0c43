//! `ilc`: the command-line front end of the IL compiler.

mod check;
mod cli;
mod debug;
mod emit;
mod flow;
mod fmt;
mod gtkw;
mod input;
mod load;
mod lsp;
mod plot;
mod progress;
mod run;
mod run_target;
mod source_map;
mod wave;

use std::io::{self, IsTerminal};
use std::process::ExitCode;

fn main() -> ExitCode {
    // Usage errors exit with 2 (clap's own exit), --help and --version with 0.
    let matches = cli::command().get_matches();
    match matches.subcommand() {
        Some(("check", m)) => {
            let files = input::expand(m.get_many::<String>("files").into_iter().flatten().cloned());
            let format = match m.get_one::<String>("message-format").map(String::as_str) {
                Some("json") => check::Format::Json,
                _ => check::Format::Human,
            };
            let color = format == check::Format::Human
                && check::use_color(m.get_one::<String>("color").map_or("auto", String::as_str));
            let totals = check::run(
                &files,
                format,
                color,
                m.get_flag("verbose"),
                input::Front::of(m),
                io::stderr().is_terminal(),
                &mut io::stdout().lock(),
                &mut io::stderr().lock(),
            );
            if totals.errors + totals.unreadable > 0 {
                ExitCode::from(1)
            } else {
                ExitCode::SUCCESS
            }
        }
        Some(("emit", m)) => {
            let files = input::expand(m.get_many::<String>("files").into_iter().flatten().cloned());
            let dir = m.get_one::<String>("out-dir").map(std::path::PathBuf::from);
            let color =
                check::use_color(m.get_one::<String>("color").map_or("auto", String::as_str));
            let ok = emit::run(
                &files,
                dir.as_deref(),
                color,
                input::Front::of(m),
                io::stderr().is_terminal(),
                &mut io::stdout().lock(),
                &mut io::stderr().lock(),
            );
            if ok {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            }
        }
        Some(("fmt", m)) => {
            use il_codegen::format::{FormatOptions, KeywordCase};
            let files: Vec<String> = m
                .get_many::<String>("files")
                .into_iter()
                .flatten()
                .cloned()
                .collect();
            let keywords = match m.get_one::<String>("keywords").map(String::as_str) {
                Some("upper") => KeywordCase::Upper,
                Some("lower") => KeywordCase::Lower,
                Some("preserve") => KeywordCase::Preserve,
                _ => KeywordCase::AsTheFile,
            };
            let check = m.get_flag("check");
            let t = fmt::run(
                &files,
                check,
                FormatOptions { keywords },
                check::use_color("auto"),
                &mut io::stdout().lock(),
                &mut io::stderr().lock(),
            );
            if t.failed > 0 || (check && t.changed > 0) {
                ExitCode::from(1)
            } else {
                ExitCode::SUCCESS
            }
        }
        Some(("run", m)) => {
            let opts = run::Options {
                files: input::expand(m.get_many::<String>("files").into_iter().flatten().cloned()),
                program: m.get_one::<String>("program").cloned(),
                config: m.get_one::<String>("config").cloned(),
                cycles: m.get_one::<u64>("cycles").copied().unwrap_or(10),
                step: m
                    .get_one::<il_interp::il_std::TIME>("step")
                    .copied()
                    .unwrap_or(il_interp::il_std::TIME::from_ms(10)),
                sets: m
                    .get_many::<run::SetArg>("set")
                    .into_iter()
                    .flatten()
                    .cloned()
                    .collect(),
                watch: m
                    .get_many::<String>("watch")
                    .into_iter()
                    .flatten()
                    .flat_map(|s| run::split_watch(s))
                    .collect(),
                color: check::use_color(
                    m.get_one::<String>("color").map_or("auto", String::as_str),
                ),
                front: input::Front::of(m),
                vcd: m.get_one::<String>("vcd").map(std::path::PathBuf::from),
                plot: m.get_one::<String>("plot").map(std::path::PathBuf::from),
                flow: m.get_flag("flow"),
            };
            let code = run::run(&opts, &mut io::stdout().lock(), &mut io::stderr().lock());
            ExitCode::from(code)
        }
        Some(("lsp", m)) => ExitCode::from(lsp::run(
            m.get_one::<il_codegen::read::Encoding>("encoding")
                .copied()
                .unwrap_or_default(),
        )),
        Some(("debug", m)) => {
            // `ilc --encoding X debug`: the encoding of launches that name none.
            let encoding = m
                .try_get_one::<il_codegen::read::Encoding>("encoding")
                .ok()
                .flatten()
                .copied()
                .unwrap_or_default();
            ExitCode::from(debug::run(encoding))
        }
        Some(("explain", m)) => {
            let code = m.get_one::<String>("code").map_or("", String::as_str);
            match il_codegen::codes::lookup(code) {
                Some(info) => {
                    println!(
                        "{}: {}\n\n{}",
                        info.code,
                        info.title,
                        info.explanation.trim_end()
                    );
                    ExitCode::SUCCESS
                }
                None => {
                    eprintln!("error: no diagnostic code `{code}` (codes look like IL0003)");
                    ExitCode::from(1)
                }
            }
        }
        // subcommand_required: clap has already refused this.
        _ => ExitCode::from(2),
    }
}
