//! Compile-fail (UI) tests of the `il!` macro, and the `.stderr` with the
//! messages a PLC engineer sees.
//!
//! The IL mistakes are grouped by topic, one file per topic
//! (`ui/syntax.rs`, `ui/declarations.rs`, `ui/calls.rs`, ...): each mistake
//! is one `il!` in its own module, `mod unknown_label { il_macros::il!(...); }`,
//! under its comment, so the stub items `il!` emits next to its
//! `compile_error!`s cannot collide between cases; the file has one
//! `fn main() {}`. A file's `.stderr` holds the errors of all its modules, in
//! order. To add a mistake, add a module to the file of its topic.
//!
//! Cases whose point needs a file of their own stay alone: the `stub_*` and
//! `cross_pou_stub` cases (user Rust code, or a second POU, uses the stub),
//! `file_missing` (a `file = "..."` path) and `column_after_tab_and_umlaut`
//! (line/column arithmetic). In the messages, "line N of this file" is the
//! line in the grouped file; the IL line and column do not depend on it.
//!
//! `ui/pass/programs.rs` holds the accepted programs, one module each, with
//! the Rust code that uses them; its `main` runs them all. They prove that
//! accepted programs compile and run.
//!
//! Two `TestCases`: trybuild builds a set holding pass cases one file at a
//! time (a `cargo build` each, then runs it), but a compile-fail-only set in
//! one `cargo check --bins --keep-going`, all files at once. So the pass
//! cases run first, alone, and the compile-fail files in one batch.
//! Regenerate the expectations with
//! `TRYBUILD=overwrite cargo test -p il-tests --test all ui`.

#[test]
fn ui() {
    {
        let pass = trybuild::TestCases::new();
        pass.pass("ui/pass/*.rs");
        // dropped here: builds and runs the pass cases
    }
    let fail = trybuild::TestCases::new();
    fail.compile_fail("ui/*.rs");
}
