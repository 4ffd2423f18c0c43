//! Helpers the workspace's tests share (a dev-dependency only): golden-file
//! snapshots ([`golden`]) and a small JSON reader for checking the JSON that
//! `ilc` and the diagnostics renderer write ([`json`]).

pub mod golden;
pub mod json;
