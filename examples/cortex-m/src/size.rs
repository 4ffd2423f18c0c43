//! The firmware's flash and static RAM, from the symbols of cortex-m-rt's
//! `link.x`, so that the run prints them without an ELF tool.

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
        "# size: flash {} bytes, static RAM {} bytes (.data {} + .bss {}), {} bytes left for the stack",
        flash,
        data + bss,
        data,
        bss,
        stack
    );
}
