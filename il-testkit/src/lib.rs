//! Helpers the workspace's tests share (a dev-dependency only): golden-file
//! snapshots ([`golden`]), reading back the JSON that `ilc` and the
//! diagnostics renderer write ([`json`], with serde_json), and instruction
//! counts at n and 8n for scaling tests ([`instructions`]), and the
//! `Content-Length` framing of LSP and DAP messages ([`framed`]).

pub mod framed;
pub mod golden;
pub mod instructions;
pub mod json;
