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

mod builder;
pub mod codes;
pub mod diag;
pub mod dialect;
pub mod plcopen;
pub mod read;

// The stages and the front-end glue: public for the other crates of this
// workspace (the macro crate, il-interp, the benchmarks, the tests),
// but not the documented API (as prost-build and cxx-build keep theirs):
// their items change with the compiler. Users drive the compiler through
// `Builder`, `Program` and `il!`.
#[doc(hidden)]
pub mod ast;
#[doc(hidden)]
pub mod emit;
#[doc(hidden)]
pub mod expand;
#[doc(hidden)]
pub mod pipeline;
#[doc(hidden)]
pub mod sema;
#[doc(hidden)]
pub mod syntax;

pub use builder::{Builder, Error, output_paths, write_if_changed};
pub use diag::{Diagnostic, SourceFile};
pub use dialect::Standard;
pub use emit::Options as EmitOptions;
pub use pipeline::{Checked, Emitted, Input, Program};
