//! `il!`: IEC 61131-3 Instruction List (IL) inside Rust source, compiled
//! to Rust items where the macro stands.
//!
//! ```
//! il_macros::il!(r#"
//! FUNCTION_BLOCK Motor
//!   VAR_INPUT start, stop : BOOL; END_VAR
//!   VAR_OUTPUT run : BOOL; END_VAR
//!   LD start
//!   OR run
//!   ANDN stop
//!   ST run
//! END_FUNCTION_BLOCK
//! "#);
//!
//! let mut ctx = il_std::Cycle::new();
//! let mut m = Motor::default();
//! m.start = true;
//! m.call(&mut ctx);
//! assert!(m.run);
//! ```
//!
//! # Forms
//! - `il!(r#"...IL..."#)`: inline IL, in a raw string (IL's `T#1s` and
//!   `'text'` are not Rust tokens).
//! - `il!(file = "plc/motor.il")`: a file relative to the crate root
//!   (`CARGO_MANIFEST_DIR`); edits to it rebuild the crate. A `.xml` file is
//!   a PLCopen TC6 XML project.
//! - `il!(files = ["plc/types.il", "plc/tank.il"])`: several files as one
//!   program.
//!
//! # Options
//! - `, serde` after the input derives `serde::Serialize` and `Deserialize`
//!   on the generated types (the crate depends on `serde` and enables
//!   `il-std`'s `serde` feature).
//!
//! # One program per call
//! Each `il!` is a program of its own: its POUs see the TYPEs and
//! FUNCTION_BLOCKs of that call only. A PROGRAM that uses a TYPE or FB
//! declared in another file must be compiled with it: list both in one
//! `il!(files = [...])`, or compile them together with
//! `il_codegen::Builder` in build.rs. Two calls that declare the same TYPE
//! generate two Rust types of that name, so keep each in one call.
//!
//! # Errors
//! Each IL error becomes a `compile_error!` at the macro, whose message
//! gives the code, the IL line and column and the source line (a proc macro
//! cannot point inside a string literal). Warnings are not shown (proc
//! macros have no stable API for them): `ilc check` and build.rs show them.
//!
//! The crate using `il!` depends on `il-std`, the runtime the generated code
//! calls.

use proc_macro::TokenStream;

/// Compile IL to Rust items at the call site.
#[proc_macro]
pub fn il(input: TokenStream) -> TokenStream {
    il_codegen::expand::expand(input.into()).into()
}
