//! il! macro.
