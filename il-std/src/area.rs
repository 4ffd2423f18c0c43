//! The process image's areas and their sizes: the runtime allocates them, the compiler
//! resolves addresses into them and refuses addresses beyond them (one vocabulary for both).

/// One of the three areas.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Area {
    /// `%I`: written by the host before a scan.
    Input,
    /// `%Q`: read by the host after a scan.
    Output,
    /// `%M`: flags kept between scans.
    Memory,
}

/// Size of the input area in bytes.
pub const INPUT_BYTES: usize = 256;
/// Size of the output area in bytes.
pub const OUTPUT_BYTES: usize = 256;
/// Size of the memory area in bytes.
pub const MEMORY_BYTES: usize = 1024;
