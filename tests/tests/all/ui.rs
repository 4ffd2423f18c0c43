//! Compile-fail (UI) tests of the `il!` macro: each `ui/*.rs` holds one IL
//! mistake, and its `.stderr` is the message a PLC engineer sees. The
//! `ui/pass/*.rs` cases prove that accepted programs compile, and that the
//! stub emitted next to an IL error keeps the user's Rust code type-checking.
//!
//! One `TestCases` run, so trybuild builds every case in a single batch.
//! Regenerate the expectations with
//! `TRYBUILD=overwrite cargo test -p il-tests --test all ui`.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.pass("ui/pass/*.rs");
    t.compile_fail("ui/*.rs");
}
