//! The integration tests of `ilc`, one binary with a module per command or
//! topic (they run the built `ilc` as a user would). `../ui` holds the
//! golden outputs of the terminal UI.

mod cli;
mod corpus;
mod debug;
mod dialect;
mod docs;
mod encodings;
mod exp;
mod explain;
mod fmt;
mod logiclab;
mod lsp;
mod m221;
mod m221_listing;
mod plcopen;
mod run;
mod run_config;
mod ui;
mod waves;
