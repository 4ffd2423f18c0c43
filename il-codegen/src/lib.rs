//! IEC 61131-3 Instruction List → Rust.
//!
//! Stages: [`syntax`] (text → [`ast`]), [`sema`] (names, types of the current
//! result, flow → checked IR), [`emit`] (IR → Rust tokens). Every stage
//! collects [`diag::Diagnostic`]s. [`compile()`] runs them for the front ends:
//! the `il!` macro, the build-script [`Builder`] and the `ilc` command.
//! [`plcopen`] reads PLCopen TC6 XML projects; [`Input`] mixes them with IL.

#![warn(missing_docs)]

pub mod ast;
mod builder;
pub mod check;
pub mod compile;
pub mod diag;
pub mod emit;
pub mod expand;
pub mod input;
pub mod interp;
pub mod plcopen;
pub mod sema;
pub mod syntax;

pub use builder::{Builder, Error, output_paths, write_if_changed};
pub use check::{check_source, check_sources};
pub use compile::{Compiled, compile, compile_all_to_files, compile_to_file, format_file};
pub use input::{Input, check_inputs, compile_inputs};
