//! Hand-written twin of `plc/mixed.il`: the same REAL operations in the same
//! order (so the results are bit-equal), the loop as an iterator.

use il_std::{CTU, Cycle, R_TRIG, TIME, TON};

/// `FUNCTION Scale`.
fn scale(raw: i16, gain: f32) -> f32 {
    raw as f32 * gain
}

/// `FUNCTION_BLOCK Axis`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Axis {
    pub target: f32,
    pub enable: bool,
    pub pos: f32,
    pub moving: bool,
    pub slow: bool,
    t: TON,
}

impl Axis {
    pub fn call(&mut self, ctx: &mut Cycle) {
        if self.enable {
            self.pos = (self.target - self.pos) * 0.25 + self.pos;
            self.moving = self.target - self.pos > 0.5 || self.pos - self.target > 0.5;
        } else {
            self.moving = false;
        }
        self.t.IN = self.moving;
        self.t.PT = TIME::from_ms(50);
        self.t.call(ctx);
        self.slow = self.t.Q;
    }
}

/// `PROGRAM Mixed`.
#[derive(Clone, Debug, PartialEq)]
pub struct Mixed {
    pub raw: [i16; 32],
    pub run: bool,
    pub sum: f32,
    pub high: i16,
    pub alarms: i16,
    pub pos: f32,
    pub hist: [f32; 32],
    phase: i16,
    ax: Axis,
    edge: R_TRIG,
    cnt: CTU,
}

impl Default for Mixed {
    fn default() -> Self {
        Mixed {
            raw: [0; 32],
            run: true,
            sum: 0.0,
            high: 0,
            alarms: 0,
            pos: 0.0,
            hist: [0.0; 32],
            phase: 0,
            ax: Axis::default(),
            edge: R_TRIG::default(),
            cnt: CTU::default(),
        }
    }
}

impl Mixed {
    pub fn call(&mut self, ctx: &mut Cycle) {
        let (mut sum, mut high) = (0.0f32, 0i16);
        for (h, &r) in self.hist.iter_mut().zip(&self.raw) {
            let v = scale(r, 0.125);
            *h = v;
            sum += v; // IL: v + sum (IEEE addition commutes exactly)
            if v > 100.0 {
                high = high.wrapping_add(1);
            }
        }
        (self.sum, self.high) = (sum, high);
        self.phase = (self.phase + 1) % 40;
        let mut target = sum / 32.0;
        if self.phase >= 20 {
            target += 50.0;
        }
        self.ax.target = target;
        self.ax.enable = self.run;
        self.ax.call(ctx);
        self.pos = self.ax.pos;
        self.edge.CLK = self.ax.slow;
        self.edge.call(ctx);
        self.cnt.CU = self.edge.Q;
        self.cnt.R = false;
        self.cnt.PV = 1000;
        self.cnt.call(ctx);
        self.alarms = self.cnt.CV;
    }
}
