//! The sizes of the process image's areas: the runtime allocates them, the compiler refuses
//! addresses beyond them.

/// Size of the input area in bytes.
pub const INPUT_BYTES: usize = 256;
/// Size of the output area in bytes.
pub const OUTPUT_BYTES: usize = 256;
/// Size of the memory area in bytes.
pub const MEMORY_BYTES: usize = 1024;
