//! il-trace's integration tests: record blocks and parse the dump back.

mod recorder;
