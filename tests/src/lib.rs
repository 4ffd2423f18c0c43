//! Integration tests live in tests/tests; this crate also compiles IL through build.rs.
