//! `plc/pump.il`, compiled to Rust by build.rs, on a Cortex-M3 (QEMU's
//! `lm3s6965evb`): SysTick releases one scan per `step` and gives the
//! program its time, the inputs come from `scans.txt`, and each scan prints
//! one trace line over semihosting, in the format run-qemu.sh compares with
//! `ilc run`'s. The exit status (semihosting) is a check of the run.
#![no_std]
#![no_main]

mod io;
mod size;
#[cfg(il_extra_trace)]
mod visit;

use core::sync::atomic::{AtomicU32, Ordering};
use cortex_m::peripheral::{SYST, syst::SystClkSource};
use cortex_m_rt::{entry, exception};
use cortex_m_semihosting::{debug, hprintln};
use il_std::{Cycle, TIME};

/// The generated program (and the size check's, with IL_EXTRA).
mod plc {
    include!(concat!(env!("OUT_DIR"), "/pump.rs"));
    include!(concat!(env!("OUT_DIR"), "/extra.rs"));
}

/// `scans.txt`: `CYCLES`, `STEP_MS` and the input table `SETS`.
mod scans {
    use crate::io::Input;
    include!(concat!(env!("OUT_DIR"), "/scans.rs"));
}

use plc::Pump;

/// SysTick counts per scan period: `step` at the LM3S6965's 12 MHz reset
/// clock. QEMU counts SysTick at a clock of its own, in virtual time; the
/// PLC's time is the number of periods times `step` either way.
const RELOAD: u32 = 12_000 * scans::STEP_MS;

/// Iterations of [`spin`] that calibrate SysTick counts to instructions.
const SPIN: u32 = 10_000;

/// SysTick periods since start: the PLC's clock.
static TICKS: AtomicU32 = AtomicU32::new(0);

#[exception]
fn SysTick() {
    TICKS.fetch_add(1, Ordering::Relaxed);
}

/// The watched variables, in the order of each trace line (run-qemu.sh
/// hands this header's names to `ilc run --watch`).
const HEADER: &str =
    "cycle time start_pb stop_pb level request delay.ET pump full_lamp fills.CV done_lamp";

#[entry]
fn main() -> ! {
    let ok = run();
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    // Only reached without a debugger or QEMU to end the program.
    loop {
        cortex_m::asm::wfi();
    }
}

/// The traced scans, the cost of a scan and the size; true when the run
/// did what the scenario of `scans.txt` expects.
fn run() -> bool {
    size::paint_stack();
    let Some(cp) = cortex_m::Peripherals::take() else {
        return false;
    };
    let mut syst = cp.SYST;
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(RELOAD - 1);
    syst.clear_current();
    syst.enable_interrupt();
    syst.enable_counter();

    // The program and its context, in RAM of their own (not on the stack),
    // so that the ELF's .bss shows what the program needs. (Each is built
    // on the stack first and moved: at start-up the stack holds about two
    // copies of the largest, see BENCHMARKS.md.)
    let Some(prg) = cortex_m::singleton!(: Pump = Pump::default()) else {
        return false;
    };
    let Some(ctx) = cortex_m::singleton!(: Cycle = Cycle::new()) else {
        return false;
    };
    #[cfg(il_extra)]
    let Some(extra) = cortex_m::singleton!(: plc::Extra = plc::Extra::default()) else {
        return false;
    };

    // The board: pins and an ADC channel of the simulated field, bound to
    // the program's addresses (on real hardware, the HAL's pins).
    let field = io::Field::default();
    let mut inputs = io::Inputs {
        start: field.input(0),
        stop: field.input(1),
        level: field.adc(1),
    };
    let mut outputs = io::Outputs {
        pump: field.output(0),
        full: field.output(1),
        done: field.output(2),
    };

    hprintln!("{}", HEADER);
    #[cfg(il_extra_trace)]
    visit::header(&*extra);
    let (mut overruns, mut counts, mut max_counts) = (0u32, 0u32, 0u32);
    let first = wait_tick(TICKS.load(Ordering::Relaxed));
    let mut last = first;
    for k in 1..=scans::CYCLES {
        if k > 1 {
            let t = wait_tick(last);
            // A scan (with its printing) longer than a period misses ticks:
            // the PLC's time then jumps, as on a real controller.
            overruns += t - last - 1;
            last = t;
        }
        // The PLC's clock: SysTick periods since the first scan.
        let periods = i64::from(last.wrapping_sub(first));
        ctx.set_now(TIME::from_ms(periods * i64::from(scans::STEP_MS)));
        for (_, input) in scans::SETS.iter().filter(|(at, _)| *at == k) {
            field.apply(*input);
        }
        // The scan as a PLC runs it: inputs, program, outputs. Only the
        // program is timed.
        inputs.read(ctx);
        let start = SYST::get_current();
        prg.call(ctx);
        #[cfg(il_extra)]
        {
            extra.call(ctx);
            // Without its trace nothing reads its state: keep the optimiser
            // from dropping it.
            core::hint::black_box(&*extra);
        }
        // SysTick counts down; a scan is far shorter than a period, and it
        // starts just after a tick, so it does not wrap in between.
        let spent = start.wrapping_sub(SYST::get_current()) & 0x00ff_ffff;
        outputs.write(ctx);
        counts += spent;
        max_counts = max_counts.max(spent);
        trace(k, ctx, prg, &field);
        #[cfg(il_extra_trace)]
        visit::line(k, ctx.now(), &*extra);
    }

    // Under QEMU's -icount every instruction takes the same virtual time,
    // so SysTick counts measure instructions once a loop of known length
    // is timed. (QEMU does not model the DWT cycle counter of this board.)
    let t = SYST::get_current();
    spin(SPIN);
    let calib = u64::from(t.wrapping_sub(SYST::get_current()) & 0x00ff_ffff).max(1);
    let insns = |c: u64| c * u64::from(2 * SPIN) / calib;
    hprintln!(
        "# scan: {} instructions on average, {} at most (SysTick under QEMU -icount; {} counts per {} instructions)",
        insns(u64::from(counts)) / u64::from(scans::CYCLES),
        insns(u64::from(max_counts)),
        calib,
        2 * SPIN
    );
    size::report();

    // The scenario of scans.txt: three fills counted, DONE lit, the pump
    // stopped on the last full tank; no fault recorded, no scan missed, and
    // the stack never reached the statics.
    let ok = prg.fills.CV == 3
        && field.driven(2)
        && !field.driven(0)
        && ctx.fault_count() == 0
        && overruns == 0
        && size::stack_fits();
    if !ok {
        hprintln!(
            "# check failed: fills.CV {} (want 3), faults {}, overruns {}, stack fits {}",
            prg.fills.CV,
            ctx.fault_count(),
            overruns,
            size::stack_fits()
        );
    }
    ok
}

/// Sleeps until SysTick has ticked past `last`; the tick count then.
fn wait_tick(last: u32) -> u32 {
    loop {
        let t = TICKS.load(Ordering::Relaxed);
        if t != last {
            return t;
        }
        cortex_m::asm::wfi();
    }
}

/// `n` iterations of a two-instruction loop (`subs`, `bne`): 2n
/// instructions, whatever the optimiser does around it.
fn spin(n: u32) {
    // SAFETY: register arithmetic and a branch; no memory, no stack.
    unsafe {
        core::arch::asm!("1:", "subs {0}, #1", "bne 1b", inout(reg) n => _, options(nomem, nostack));
    }
}

/// One trace line: the scan, its time and the watched variables as `ilc
/// run` prints them (TRUE/FALSE, integers, T#...); the outputs as the pins
/// drive them, so that the trace checks the binding too.
fn trace(k: u32, ctx: &Cycle, p: &Pump, field: &io::Field) {
    hprintln!(
        "{} {} {} {} {} {} {} {} {} {} {}",
        k,
        ctx.now(),
        b(Pump::io_start_pb(ctx)),
        b(Pump::io_stop_pb(ctx)),
        Pump::io_level(ctx),
        b(p.request),
        p.delay.ET,
        b(field.driven(0)),
        b(field.driven(1)),
        p.fills.CV,
        b(field.driven(2)),
    );
}

/// A BOOL as IL writes it.
fn b(v: bool) -> &'static str {
    if v { "TRUE" } else { "FALSE" }
}

#[exception]
unsafe fn HardFault(frame: &cortex_m_rt::ExceptionFrame) -> ! {
    // A bad access (a stack that ran into the statics can cause one) ends
    // QEMU at once with the fault's address, not at run-qemu.sh's timeout.
    hprintln!("# hard fault at pc {:#010x}", frame.pc());
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    // The generated code does not panic; this catches the example's own
    // mistakes, and ends QEMU at once instead of at run-qemu.sh's timeout.
    hprintln!("# panic: {}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
}
