//! Idiomatic hand-written Rust with the same logic as `plc/*.il`: what a
//! Rust programmer would write for the same job, on the same data (fields of
//! the same types, il-std blocks for timers and counters), and the baseline
//! that generated code is measured against.

mod interlock;
mod mixed;
pub use interlock::Interlock;
pub use mixed::{Axis, Mixed};

use il_std::{CTU, Cycle, R_TRIG, TIME, TON};

/// `plc/arith_loop.il`.
#[derive(Clone, Debug, PartialEq)]
pub struct ArithLoop {
    pub n: i32,
    pub seed: i32,
    pub acc: i32,
    pub x: i32,
}

impl Default for ArithLoop {
    fn default() -> Self {
        ArithLoop {
            n: 1000,
            seed: 7,
            acc: 0,
            x: 0,
        }
    }
}

impl ArithLoop {
    pub fn call(&mut self) {
        let mut x = self.seed;
        let mut acc = 0i32;
        for i in 0..self.n.max(0) {
            x = x.wrapping_mul(1103).wrapping_add(i % 97);
            // i + 1 >= 1: never a division by zero.
            acc = acc.wrapping_add(x.wrapping_div(i + 1));
        }
        self.x = x;
        self.acc = acc;
    }
}

/// `plc/array_proc.il`.
#[derive(Clone, Debug, PartialEq)]
pub struct ArrayProc {
    pub samples: [i16; 256],
    pub gain: i16,
    pub filtered: [i16; 256],
    pub peak: i16,
}

impl Default for ArrayProc {
    fn default() -> Self {
        ArrayProc {
            samples: [0; 256],
            gain: 3,
            filtered: [0; 256],
            peak: 0,
        }
    }
}

impl ArrayProc {
    pub fn call(&mut self) {
        let mut acc = 0i16;
        let mut peak = 0i16;
        for (out, &s) in self.filtered.iter_mut().zip(&self.samples) {
            acc = s.wrapping_mul(self.gain).wrapping_add(acc.wrapping_mul(3)) / 4;
            *out = acc;
            peak = peak.max(acc);
        }
        self.peak = peak;
    }
}

/// One station of `plc/blocks.il`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Station {
    pub go: bool,
    pub reset: bool,
    pub done: bool,
    pub count: i16,
    t: TON,
    e: R_TRIG,
    c: CTU,
}

impl Station {
    pub fn call(&mut self, ctx: &mut Cycle) {
        self.t.IN = self.go;
        self.t.PT = TIME::from_ms(30);
        self.t.call(ctx);
        self.e.CLK = self.t.Q;
        self.e.call(ctx);
        self.c.CU = self.e.Q;
        self.c.R = self.reset;
        self.c.PV = 5;
        self.c.call(ctx);
        self.count = self.c.CV;
        self.done = self.c.Q;
    }
}

/// `plc/blocks.il`: 100 stations.
#[derive(Clone, Debug, PartialEq)]
pub struct Blocks {
    pub go: [bool; 100],
    pub reset: bool,
    pub done: [bool; 100],
    pub count: [i16; 100],
    pub stations: [Station; 100],
}

impl Default for Blocks {
    fn default() -> Self {
        Blocks {
            go: [false; 100],
            reset: false,
            done: [false; 100],
            count: [0; 100],
            stations: core::array::from_fn(|_| Station::default()),
        }
    }
}

impl Blocks {
    pub fn call(&mut self, ctx: &mut Cycle) {
        for (i, s) in self.stations.iter_mut().enumerate() {
            s.go = self.go[i];
            s.reset = self.reset;
            s.call(ctx);
            self.done[i] = s.done;
            self.count[i] = s.count;
        }
    }
}
