//! The reference interpreter's tests, one binary with a module per topic:
//! `plc` (the behaviour-test programs of `tests/plc`, asserting what
//! `tests/tests/*.rs` assert for the generated code), `smoke` (every POU of
//! `tests/plc` runs; features not covered by `plc`), `plcopen` (a PLCopen
//! project of the shared corpus), `user_types` (enumerations, structures,
//! arrays, subranges, host paths), `addresses` (located variables and direct
//! addresses in the process image), `corners` (the standard's corners of
//! `tests/plc/corners.il`).

mod addresses;
mod corners;
mod dialect;
mod exp;
mod hook;
mod plc;
mod plcopen;
mod smoke;
mod user_types;
