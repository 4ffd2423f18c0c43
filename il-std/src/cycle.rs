//! The cycle context handed to every function block call: current time and fault record.

use crate::FaultKind;
use crate::time::{DT, TIME};
use core::fmt;

/// How many faults [`Cycle`] keeps (the most recent ones); older ones are only counted.
pub const FAULT_RING_LEN: usize = 16;

/// One recorded runtime fault: what happened, where (POU and IL line) and when (cycle time).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Fault {
    /// What happened.
    pub kind: FaultKind,
    /// Name of the POU whose code faulted.
    pub pou: &'static str,
    /// 1-based IL source line of the faulting instruction.
    pub line: u32,
    /// [`Cycle::now`] when the fault was recorded.
    pub time: TIME,
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} in {} at IL line {} ({})",
            self.kind, self.pou, self.line, self.time
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Fault {}

/// The cycle context that generated code (and every [`FunctionBlock`](crate::FunctionBlock)
/// call) receives.
///
/// It holds the current time, which only the host sets or advances (nothing in this crate reads
/// a wall clock by itself, so simulated time gives the same result on every run), and a record
/// of runtime faults: a ring of the last [`FAULT_RING_LEN`] faults plus a total count.
///
/// ```
/// use il_std::{Cycle, FaultKind, TIME};
/// let mut ctx = Cycle::new();
/// ctx.advance(TIME::from_ms(10));
/// ctx.fault(FaultKind::DivisionByZero, "MAIN", 12);
/// let f = ctx.last_fault().unwrap();
/// assert_eq!((f.kind, f.pou, f.line, f.time), (FaultKind::DivisionByZero, "MAIN", 12, TIME::from_ms(10)));
/// assert_eq!(ctx.fault_count(), 1);
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Cycle {
    now: TIME,
    dt_offset: i64,
    faults: [Fault; FAULT_RING_LEN],
    /// Index of the next slot to write.
    next: usize,
    /// Faults currently stored (≤ FAULT_RING_LEN).
    stored: usize,
    total: u64,
    /// The process image (`%I`, `%Q`, `%M`): the host writes inputs before a
    /// scan and reads outputs after it; generated code reads and writes it
    /// for direct addresses and located (`AT`) variables.
    pub io: crate::ProcessImage,
}

impl Cycle {
    /// A context at time `T#0s` with no faults.
    pub fn new() -> Self {
        Self::default()
    }
    /// The current time (a monotonic TIME counter chosen by the host, wrapping).
    pub fn now(&self) -> TIME {
        self.now
    }
    /// Sets the current time.
    pub fn set_now(&mut self, t: TIME) {
        self.now = t;
    }
    /// Advances the current time by `dt` (wrapping at the `TIME` range; timers cope with it).
    pub fn advance(&mut self, dt: TIME) {
        self.now = self.now.wrapping_add(dt);
    }
    /// The current date and time: the last [`Cycle::set_now_dt`] plus the time advanced since
    /// (`DT#1970-01-01-00:00:00` + [`Cycle::now`] if never set).
    pub fn now_dt(&self) -> DT {
        DT(self.dt_offset.wrapping_add(self.now.0))
    }
    /// Sets the current date and time (without changing [`Cycle::now`]).
    pub fn set_now_dt(&mut self, dt: DT) {
        self.dt_offset = dt.0.wrapping_sub(self.now.0);
    }
    /// Records a fault of `kind` in POU `pou` at IL line `line`, stamped with [`Cycle::now`].
    pub fn fault(&mut self, kind: FaultKind, pou: &'static str, line: u32) {
        let f = Fault {
            kind,
            pou,
            line,
            time: self.now,
        };
        if let Some(slot) = self.faults.get_mut(self.next) {
            *slot = f;
        }
        self.next = (self.next + 1) % FAULT_RING_LEN;
        self.stored = (self.stored + 1).min(FAULT_RING_LEN);
        self.total = self.total.saturating_add(1);
    }
    /// How many faults were recorded since the last [`Cycle::clear_faults`] (including those
    /// no longer stored).
    pub fn fault_count(&self) -> u64 {
        self.total
    }
    /// The stored faults (at most [`FAULT_RING_LEN`], the most recent ones), oldest first.
    pub fn faults(&self) -> impl Iterator<Item = &Fault> + '_ {
        let start = (self.next + FAULT_RING_LEN - self.stored) % FAULT_RING_LEN;
        (0..self.stored).filter_map(move |i| self.faults.get((start + i) % FAULT_RING_LEN))
    }
    /// The most recent fault.
    pub fn last_fault(&self) -> Option<&Fault> {
        if self.stored == 0 {
            return None;
        }
        self.faults
            .get((self.next + FAULT_RING_LEN - 1) % FAULT_RING_LEN)
    }
    /// Forgets all faults and resets the count.
    pub fn clear_faults(&mut self) {
        self.faults = Default::default();
        self.next = 0;
        self.stored = 0;
        self.total = 0;
    }
}

/// Host helper (feature `std`): drives a [`Cycle`]'s time from the real clock.
///
/// [`RealClock::update`] sets [`Cycle::now`] to the time at [`RealClock::start`] plus the
/// monotonic time elapsed since (from `std::time::Instant`), and [`Cycle::now_dt`] to the
/// system's UTC date and time.
#[cfg(feature = "std")]
#[derive(Clone, Copy, Debug)]
pub struct RealClock {
    origin: std::time::Instant,
    base: TIME,
}

#[cfg(feature = "std")]
impl RealClock {
    /// Starts a clock whose zero is `cycle`'s current time.
    pub fn start(cycle: &Cycle) -> Self {
        RealClock {
            origin: std::time::Instant::now(),
            base: cycle.now(),
        }
    }
    /// Sets `cycle`'s time to the real elapsed time since [`RealClock::start`].
    pub fn update(&self, cycle: &mut Cycle) {
        let el = self.origin.elapsed().as_nanos();
        let el = i64::try_from(el).unwrap_or(i64::MAX);
        cycle.set_now(self.base.wrapping_add(TIME(el)));
        if let Ok(d) = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH) {
            cycle.set_now_dt(DT(i64::try_from(d.as_nanos()).unwrap_or(i64::MAX)));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    #[cfg(feature = "std")]
    #[test]
    fn real_clock_moves_forward() {
        let mut c = Cycle::new();
        c.set_now(TIME::from_secs(5));
        let clock = RealClock::start(&c);
        std::thread::sleep(std::time::Duration::from_millis(2));
        clock.update(&mut c);
        assert!(c.now() >= TIME::from_ms(5002));
        assert!(c.now_dt().date() > crate::DATE::from_ymd(2020, 1, 1).unwrap());
        let e: &dyn std::error::Error = &Fault::default();
        assert!(!std::format!("{e}").is_empty());
    }

    #[test]
    fn time_and_dt() {
        let mut c = Cycle::new();
        assert_eq!(c.now(), TIME(0));
        c.set_now(TIME(i64::MAX));
        c.advance(TIME(2));
        assert_eq!(c.now(), TIME(i64::MIN + 1));
        c.set_now(TIME::from_secs(1));
        c.set_now_dt(DT(1_000_000_000_000));
        c.advance(TIME::from_secs(2));
        assert_eq!(c.now_dt(), DT(1_000_000_000_000 + 2_000_000_000));
    }

    #[test]
    fn fault_ring() {
        let mut c = Cycle::new();
        assert!(c.last_fault().is_none());
        assert_eq!(c.faults().count(), 0);
        for line in 1..=20u32 {
            c.advance(TIME(1));
            c.fault(FaultKind::DivisionByZero, "P", line);
        }
        assert_eq!(c.fault_count(), 20);
        let lines: Vec<u32> = c.faults().map(|f| f.line).collect();
        assert_eq!(lines, (5..=20).collect::<Vec<_>>());
        assert_eq!(
            c.last_fault().map(|f| (f.line, f.time)),
            Some((20, TIME(20)))
        );
        c.clear_faults();
        assert_eq!(c.fault_count(), 0);
        assert!(c.last_fault().is_none());
        c.fault(FaultKind::StringOverflow, "Q", 3);
        let v: Vec<_> = c.faults().map(|f| (f.kind, f.pou, f.line)).collect();
        assert_eq!(v, [(FaultKind::StringOverflow, "Q", 3)]);
        let s = std::format!("{}", c.last_fault().unwrap());
        assert_eq!(
            s,
            "string truncated to its capacity in Q at IL line 3 (T#20ns)"
        );
    }
}
