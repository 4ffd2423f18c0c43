#![no_std]
//! IEC 61131-3 runtime.
