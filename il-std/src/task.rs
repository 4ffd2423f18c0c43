//! Task scheduling for generated CONFIGURATIONs: when a TASK is released.

use crate::time::TIME;

/// The static description of a TASK, for hosts that list what a
/// configuration runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TaskInfo {
    /// The task's name as declared.
    pub name: &'static str,
    /// The RESOURCE that declares it (`""` for a configuration without RESOURCE).
    pub resource: &'static str,
    /// `INTERVAL` (`T#0s`: no periodic release).
    pub interval: TIME,
    /// The TIME global whose value is the interval, when `INTERVAL` names one
    /// (then `interval` is `T#0s`).
    pub interval_from: Option<&'static str>,
    /// `PRIORITY` (0 is the highest).
    pub priority: u32,
    /// What `SINGLE` reads, if anything: a BOOL global's name or a bit
    /// address (`"%IX0.0"`); `None` also for a literal `SINGLE := TRUE`.
    pub single: Option<&'static str>,
    /// The program instances it runs, in order.
    pub programs: &'static [&'static str],
}

/// The run-time state of one TASK (IEC 61131-3 2.7.2, non-preemptive).
///
/// * `INTERVAL` > 0: released at the first [`TaskState::due`] call, then every interval
///   after that release time. If the host calls late, the missed releases are
///   counted in [`TaskState::overruns`] and the task runs once.
/// * `SINGLE`: released once on each rising edge of the SINGLE input; while it
///   is TRUE the periodic releases are suspended.
/// * Neither (or `INTERVAL := T#0s`): released on every call.
///
/// ```
/// use il_std::{TaskState, TIME};
/// let mut t = TaskState::new();
/// let ms = TIME::from_ms;
/// assert!(t.due(ms(0), ms(10), None));   // first call: released
/// assert!(!t.due(ms(5), ms(10), None));
/// assert!(t.due(ms(10), ms(10), None));
/// assert!(t.due(ms(35), ms(10), None));  // releases at 20 and 30 were missed
/// assert_eq!(t.overruns(), 1);
/// assert!(t.due(ms(40), ms(10), None));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TaskState {
    next: Option<TIME>,
    single: bool,
    overruns: u64,
}

impl TaskState {
    /// A task that has never run.
    pub const fn new() -> Self {
        TaskState {
            next: None,
            single: false,
            overruns: 0,
        }
    }

    /// Whether the task is released at `now`; updates the next release time.
    pub fn due(&mut self, now: TIME, interval: TIME, single: Option<bool>) -> bool {
        let edge = match single {
            Some(s) => {
                let rising = s && !self.single;
                self.single = s;
                if rising {
                    return true;
                }
                s
            }
            None => false,
        };
        if interval.0 <= 0 {
            // No periodic release: a SINGLE task runs only on edges, others always.
            return single.is_none();
        }
        if edge {
            // SINGLE is TRUE: periodic releases wait.
            self.next = None;
            return false;
        }
        let Some(next) = self.next else {
            self.next = Some(now.wrapping_add(interval));
            return true;
        };
        // Wrapping difference: the TIME counter may wrap on long runs.
        let late = now.wrapping_sub(next).0;
        if late < 0 {
            return false;
        }
        let missed = late / interval.0;
        self.overruns = self.overruns.saturating_add(missed as u64);
        self.next = Some(TIME(
            next.0
                .wrapping_add((missed.wrapping_add(1)).wrapping_mul(interval.0)),
        ));
        true
    }

    /// Periodic releases that were missed because the host called too late.
    pub fn overruns(&self) -> u64 {
        self.overruns
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    const fn ms(n: i64) -> TIME {
        TIME::from_ms(n)
    }

    #[test]
    fn periodic_releases_keep_their_phase() {
        let mut t = TaskState::new();
        let runs: std::vec::Vec<i64> = (0..=100)
            .step_by(5)
            .filter(|&n| t.due(ms(n + 3), ms(20), None))
            .collect();
        // First release at 3 ms, then every 20 ms from there.
        assert_eq!(runs, [0, 20, 40, 60, 80, 100]);
        assert_eq!(t.overruns(), 0);
    }

    #[test]
    fn no_interval_runs_every_call() {
        let mut t = TaskState::new();
        assert!((0..5).all(|n| t.due(ms(n), ms(0), None)));
    }

    #[test]
    fn single_runs_once_per_rising_edge_and_suspends_the_period() {
        let mut t = TaskState::new();
        let s = [false, true, true, false, true];
        let got: std::vec::Vec<bool> = s
            .iter()
            .enumerate()
            .map(|(i, &x)| t.due(ms(i as i64), ms(0), Some(x)))
            .collect();
        assert_eq!(got, [false, true, false, false, true]);
        let mut p = TaskState::new();
        assert!(p.due(ms(0), ms(10), Some(false)));
        assert!(p.due(ms(1), ms(10), Some(true))); // edge
        assert!(!p.due(ms(20), ms(10), Some(true))); // suspended while TRUE
        assert!(p.due(ms(21), ms(10), Some(false))); // resumes: released now
        assert!(!p.due(ms(25), ms(10), Some(false)));
        assert!(p.due(ms(31), ms(10), Some(false)));
    }

    #[test]
    fn time_wrap_is_harmless() {
        let mut t = TaskState::new();
        let start = TIME(i64::MAX - 5_000_000);
        assert!(t.due(start, ms(10), None));
        assert!(!t.due(start.wrapping_add(ms(9)), ms(10), None));
        assert!(t.due(start.wrapping_add(ms(10)), ms(10), None));
    }
}
