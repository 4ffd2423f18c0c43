//! The firmware's flash and RAM: flash and static RAM from the symbols of
//! cortex-m-rt's `link.x`, so that the run prints them without an ELF tool,
//! and the stack's high-water mark, from a pattern painted over the free
//! RAM at start.

use cortex_m_semihosting::hprintln;

// Only their addresses are taken, never their values.
unsafe extern "C" {
    static __sidata: u8;
    static __sdata: u8;
    static __edata: u8;
    static __sbss: u8;
    static __ebss: u8;
    static _stack_start: u8;
}

/// What free stack holds until something writes it.
const PAINT: u32 = 0x5A5A_A5A5;

/// The free RAM between the statics and the stack pointer, word by word.
fn free_words() -> impl Iterator<Item = *mut u32> {
    let bottom = (&raw const __ebss).addr();
    // Keep clear of this function's caller's frame.
    let top = cortex_m::register::msp::read() as usize - 64;
    (bottom..top)
        .step_by(4)
        .map(core::ptr::with_exposed_provenance_mut)
}

/// Paints the free RAM below the stack, before the scans (and before any
/// interrupt is enabled).
pub fn paint_stack() {
    for w in free_words() {
        // SAFETY: RAM between the end of .bss (4-aligned, link.x asserts it)
        // and below the stack pointer, which nothing uses yet.
        unsafe { w.write_volatile(PAINT) };
    }
}

/// Bytes of stack used so far: from the stack's top down to the deepest
/// word that is no longer the paint.
fn stack_used() -> usize {
    let top = (&raw const _stack_start).addr();
    let deepest = free_words()
        // SAFETY: reads of RAM that paint_stack wrote, as words.
        .find(|w| unsafe { w.read_volatile() } != PAINT)
        .map_or(top, |w| w.addr());
    top - deepest
}

/// Whether the stack stayed clear of the statics, with 256 bytes to spare
/// (cortex-m-rt puts nothing between them: an overflow would overwrite
/// .bss silently).
pub fn stack_fits() -> bool {
    let room = (&raw const _stack_start).addr() - (&raw const __ebss).addr();
    stack_used() + 256 <= room
}

/// Prints flash used (code, constants, the initial values of .data) and
/// static RAM (.data + .bss); the stack takes the rest of RAM, downwards.
pub fn report() {
    let at = |p: *const u8| p as usize;
    let data = at(&raw const __edata) - at(&raw const __sdata);
    let bss = at(&raw const __ebss) - at(&raw const __sbss);
    // Flash starts at 0 on the LM3S6965; .data's initial values end it.
    let flash = at(&raw const __sidata) + data;
    let stack = at(&raw const _stack_start) - at(&raw const __ebss);
    hprintln!(
        "# size: flash {} bytes, static RAM {} bytes (.data {} + .bss {}), stack {} bytes at most of the {} left",
        flash,
        data + bss,
        data,
        bss,
        stack_used(),
        stack
    );
}
