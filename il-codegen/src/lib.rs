//! IEC 61131-3 Instruction List (IL) to Rust, at build time.
//!
//! Most users need one thing from this crate: [`Builder`], called from
//! `build.rs`. Each IL file (or PLCopen TC6 XML project) becomes a Rust file
//! in `OUT_DIR`, which the crate includes. All files of one `Builder` are
//! one program: a POU may use the TYPEs and FUNCTION_BLOCKs of every file.
//!
// The example needs the `build` feature (`il-macros` turns it off).
#![cfg_attr(feature = "build", doc = "```no_run")]
#![cfg_attr(not(feature = "build"), doc = "```ignore")]
//! // build.rs
//! fn main() -> Result<(), il_codegen::Error> {
//!     il_codegen::Builder::new()
//!         .file("plc/types.il")
//!         .file("plc/tank.il")
//!         .compile()?; // on an IL error, cargo shows it as rustc shows its own
//!     Ok(())
//! }
//! ```
//!
//! ```ignore
//! // src/lib.rs (or inside a `mod` of a binary)
//! include!(concat!(env!("OUT_DIR"), "/types.rs"));
//! include!(concat!(env!("OUT_DIR"), "/tank.rs"));
//! ```
//!
//! The crate depends on [`il-std`](https://docs.rs/il-std), the runtime the
//! generated code calls. A FUNCTION_BLOCK or PROGRAM `Tank` becomes `pub
//! struct Tank` with its variables as `pub` fields and `fn call(&mut self,
//! ctx: &mut il_std::Cycle)`; a FUNCTION becomes a `pub fn`. The user guide
//! (`docs/guide.md` in the repository) describes every item generated.
//!
//! For IL inside Rust source, use the `il!` macro of
//! [`il-macros`](https://docs.rs/il-macros); it runs this same compiler.
//!
//! Tools that need more than generated files (an editor, a checker) run the
//! pipeline themselves: [`Program`] of sources → [`Program::check`] →
//! [`Checked`], with every [`Diagnostic`] and, when there is no error, the
//! code ([`Checked::emit`], [`Checked::files`]). A tool that checks again
//! after every edit (an editor) checks through a [`Session`], which parses
//! and checks again only what an edit touched. [`codes`] lists every
//! diagnostic code with its explanation.
//!
//! # The modules, by who needs them
//!
//! | who | modules |
//! | --- | --- |
//! | a build script | [`Builder`] (re-exported at the root) |
//! | a tool (editor, checker, interpreter) | [`pipeline`] ([`Program`] → [`Checked`], [`Session`]), [`ir`] (the checked program: the contract between the checker and every consumer), [`diag`], [`codes`], [`format`](mod@format) (`ilc fmt`'s layout), [`read`] (reading a source file in its encoding), [`ast`] (the syntax tree, for outlines), [`dialect`], [`plcopen`] |
//! | the `il!` macro | [`expand`] (what `il-macros` calls: its input tokens to Rust tokens) |
//! | this crate's own tests | [`step_counter`] (the front end's work, counted for the scaling tests) |
//!
//! The user guide, `docs/guide.md` in the repository (the crate's
//! `README.md` links it), describes the language accepted, every item
//! generated, and the tools around them.

#![warn(missing_docs)]

#[cfg(feature = "build")]
mod builder;
pub mod codes;
pub mod diag;
pub mod dialect;
pub mod exp;
pub mod format;
pub mod ir;
pub mod logiclab;
pub mod m221;
pub mod plcopen;
pub mod read;
pub mod step_counter;

// The stages are private: their items change with the compiler. The
// documented contract between the checker and its consumers is `ir`;
// front ends drive the compiler through `Builder`, `Program` and `il!`.
pub mod ast;
mod emit;
pub mod expand;
pub mod pipeline;
mod sema;
mod syntax;

#[cfg(feature = "build")]
pub use builder::{Builder, Error, output_paths, write_if_changed};
pub use diag::{Diagnostic, SourceFile};
pub use dialect::{Dialect, Standard};
pub use emit::Options as EmitOptions;
pub use pipeline::{Checked, Emitted, Input, Program, Session};
