//! The integration tests of il-codegen, one binary with a module per topic
//! (one link instead of one per file). Data they read sits beside this folder:
//! `../golden` (emitted code), `../diag` (rendered diagnostics).
//!
//! They compare rendered diagnostics and the files build.rs writes, so they
//! need the `build` feature; without it (as `il!` builds this crate) the
//! binary is empty and the lib's own tests run.
#![cfg(feature = "build")]

mod checked;
mod syntax_common;

mod corpus_configurations;
mod dialect;
mod encodings;
#[cfg(feature = "exp")]
mod exp;
mod format;
mod front_end_robustness;
mod golden_emit;
mod ir_operators;
mod ir_size;
#[cfg(feature = "plcopen")]
mod logiclab;
#[cfg(feature = "plcopen")]
mod m221_listing;
#[cfg(not(all(feature = "plcopen", feature = "exp")))]
mod not_built;
mod pipeline_snippet;
#[cfg(feature = "plcopen")]
mod plcopen_corpus;
#[cfg(feature = "plcopen")]
mod plcopen_hostile;
#[cfg(feature = "plcopen")]
mod plcopen_import;
#[cfg(feature = "plcopen")]
mod plcopen_limits;
#[cfg(feature = "plcopen")]
mod plcopen_xml;
mod render_golden;
mod resolutions;
mod scaling;
mod sema_calls;
mod sema_config_forms;
mod sema_config_paths;
mod sema_corners;
mod sema_declarations;
mod sema_fixes;
mod sema_hints;
mod sema_host_functions;
mod sema_hostile_names;
mod sema_literals;
mod sema_std_blocks;
mod sema_types;
mod session;
#[cfg(feature = "plcopen")]
mod sources_by_content;
mod syntax_comments;
mod syntax_corpus;
mod syntax_declarations;
mod syntax_errors;
mod syntax_grammar_up_to_date;
mod syntax_instructions;
mod syntax_literals;
