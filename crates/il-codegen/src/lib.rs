//! IEC 61131-3 Instruction List → Rust.
//!
//! Stages: [`syntax`] (text → [`ast`]), `sema` (names, types of the current
//! result, flow), `emit` (Rust tokens). Every stage collects [`diag::Diagnostic`]s.

pub mod ast;
pub mod check;
pub mod diag;
pub mod syntax;

pub use check::check_source;
