//! The program's I/O: `%IX`/`%QX` bound to `embedded-hal` GPIO pins and `%IW`
//! to an ADC reading, as on a board; under QEMU the pins are wires of a
//! simulated [`Field`] that `scans.txt` drives. The guide's "On a
//! microcontroller" section shows this file.

use core::cell::Cell;
use core::convert::Infallible;
use embedded_hal::digital::{ErrorType, InputPin, OutputPin};
use il_std::Cycle;
use il_std::addr::{iw, ix, qx};

/// One analog channel: a conversion, in the ADC's counts. embedded-hal 1.0
/// has no ADC trait; a HAL's one-shot read fits as a closure.
pub trait Analog {
    fn read(&mut self) -> u16;
}

impl<F: FnMut() -> u16> Analog for F {
    fn read(&mut self) -> u16 {
        self()
    }
}

/// The inputs of `plc/pump.il`: which pin or channel is which address.
pub struct Inputs<S, T, L> {
    /// START button, `start_pb AT %IX0.0`.
    pub start: S,
    /// STOP button (normally closed), `stop_pb AT %IX0.1`.
    pub stop: T,
    /// Tank level, `level AT %IW1`.
    pub level: L,
}

impl<S: InputPin, T: InputPin, L: Analog> Inputs<S, T, L> {
    /// Reads every input into the process image, before a scan. A pin that
    /// cannot be read counts as FALSE (de-energised): for the normally
    /// closed STOP that is "pressed", the safe side.
    pub fn read(&mut self, ctx: &mut Cycle) {
        ctx.io.set(ix(0, 0), self.start.is_high().unwrap_or(false));
        ctx.io.set(ix(0, 1), self.stop.is_high().unwrap_or(false));
        ctx.io.set(iw(1), self.level.read());
    }
}

/// The outputs: the pump contactor and two lamps.
pub struct Outputs<P, F, D> {
    /// `pump AT %QX0.0`.
    pub pump: P,
    /// `full_lamp AT %QX0.1`.
    pub full: F,
    /// `done_lamp AT %QX0.2`.
    pub done: D,
}

impl<P: OutputPin, F: OutputPin, D: OutputPin> Outputs<P, F, D> {
    /// Drives every output from the process image, after a scan. A failed
    /// write is left for the next scan, which writes every output again.
    pub fn write(&mut self, ctx: &Cycle) {
        let _ = self.pump.set_state(ctx.io.get(qx(0, 0)).into());
        let _ = self.full.set_state(ctx.io.get(qx(0, 1)).into());
        let _ = self.done.set_state(ctx.io.get(qx(0, 2)).into());
    }
}

/// One change of `scans.txt`: what an input terminal of the field carries
/// from a scan on.
#[derive(Clone, Copy)]
pub enum Input {
    /// Digital terminal n (`%IX0.n` in the table, which is what it is wired to).
    Digital(usize, bool),
    /// Analog terminal n, in ADC counts (`%IWn` in the table).
    Analog(usize, u16),
}

/// The simulated plant under QEMU: what the input terminals carry, as
/// `scans.txt` sets them, and what the outputs drive. On a board this is the
/// real world, and the pins are the HAL's.
#[derive(Default)]
pub struct Field {
    digital: [Cell<bool>; 8],
    analog: [Cell<u16>; 4],
    outputs: [Cell<bool>; 8],
}

impl Field {
    /// Applies one change of the table (a terminal the field lacks is none).
    pub fn apply(&self, input: Input) {
        match input {
            Input::Digital(n, v) => self.digital.get(n).map(|c| c.set(v)),
            Input::Analog(n, v) => self.analog.get(n).map(|c| c.set(v)),
        };
    }
    /// Digital input terminal n, as a GPIO input pin.
    pub fn input(&self, n: usize) -> Pin<'_> {
        Pin(self.digital.get(n))
    }
    /// Output n, as a GPIO output pin.
    pub fn output(&self, n: usize) -> Pin<'_> {
        Pin(self.outputs.get(n))
    }
    /// What output n drives now.
    pub fn driven(&self, n: usize) -> bool {
        self.outputs.get(n).is_some_and(Cell::get)
    }
    /// Analog terminal n, as an ADC channel.
    pub fn adc(&self, n: usize) -> impl Analog + '_ {
        move || self.analog.get(n).map_or(0, Cell::get)
    }
}

/// A GPIO pin of the simulated field (a wire the field lacks reads low and
/// drives nothing).
pub struct Pin<'a>(Option<&'a Cell<bool>>);

impl ErrorType for Pin<'_> {
    type Error = Infallible;
}

impl InputPin for Pin<'_> {
    fn is_high(&mut self) -> Result<bool, Infallible> {
        Ok(self.0.is_some_and(Cell::get))
    }
    fn is_low(&mut self) -> Result<bool, Infallible> {
        self.is_high().map(|h| !h)
    }
}

impl OutputPin for Pin<'_> {
    fn set_high(&mut self) -> Result<(), Infallible> {
        self.0.inspect(|c| c.set(true));
        Ok(())
    }
    fn set_low(&mut self) -> Result<(), Infallible> {
        self.0.inspect(|c| c.set(false));
        Ok(())
    }
}
