//! il-codegen
