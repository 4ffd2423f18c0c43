//! IEC 61131-3 Instruction List → Rust.
//!
//! Stages: [`syntax`] (text → [`ast`]), [`sema`] (names, types of the current
//! result, flow → checked IR), [`emit`] (IR → Rust tokens). Every stage
//! collects [`diag::Diagnostic`]s. One pipeline runs them for every front end
//! (the `il!` macro, the build-script [`Builder`], the `ilc` command):
//! sources in ([`Program`]) → checked program ([`Checked`]) → emitted Rust
//! ([`Emitted`]). [`plcopen`] reads PLCopen TC6 XML projects; [`Input`] mixes
//! them with IL.

#![warn(missing_docs)]

pub mod ast;
mod builder;
pub mod codes;
pub mod diag;
pub mod emit;
pub mod expand;
pub mod interp;
pub mod pipeline;
pub mod plcopen;
pub mod read;
pub mod sema;
pub mod syntax;

pub use builder::{Builder, Error, write_if_changed};
pub use diag::{Diagnostic, SourceFile};
pub use pipeline::{Checked, Emitted, Input, Program};
