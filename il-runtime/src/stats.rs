//! Per-task scan statistics.

use std::fmt;
use std::time::Duration;

/// What one task did since the runtime started. Times are wall-clock
/// (monotonic) durations.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TaskStats {
    /// The task's name.
    pub name: &'static str,
    /// Its INTERVAL (zero: not periodic).
    pub interval: Duration,
    /// Scans run.
    pub scans: u64,
    /// Duration of the last scan (all of the task's programs).
    pub last: Duration,
    /// Shortest scan.
    pub min: Duration,
    /// Longest scan.
    pub max: Duration,
    /// Sum of all scans (mean = total / scans).
    pub total: Duration,
    /// Periodic tasks: how late the last scan started after its release time.
    pub latency: Duration,
    /// Periodic tasks: the largest such latency.
    pub max_latency: Duration,
    /// Periodic tasks: the largest deviation of the time between two
    /// consecutive scan starts from the interval (period jitter).
    pub jitter: Duration,
    /// Scans that took longer than the interval.
    pub overruns: u64,
    /// Periodic releases skipped because the previous scan (or the host) was late.
    pub missed: u64,
    /// Periodic tasks: release latencies by powers of two of microseconds:
    /// bucket 0 counts latencies under 1 µs, bucket k those in [2^(k-1), 2^k) µs,
    /// the last one everything longer (see [`TaskStats::latency_percentile`]).
    pub latency_histogram: [u64; BUCKETS],
    /// Start of the previous scan, for the jitter (ns since the runtime started).
    pub(crate) prev_start: Option<u64>,
}

/// Buckets of [`TaskStats::latency_histogram`]: up to 2^20 µs (about 1 s).
pub const BUCKETS: usize = 22;

fn bucket(d: Duration) -> usize {
    let us = d.as_micros();
    if us == 0 {
        0
    } else {
        (128 - us.leading_zeros() as usize).min(BUCKETS - 1)
    }
}

impl TaskStats {
    pub(crate) fn new(name: &'static str, interval: Duration) -> Self {
        TaskStats {
            name,
            interval,
            ..Default::default()
        }
    }

    /// Mean scan time.
    pub fn mean(&self) -> Duration {
        match u32::try_from(self.scans) {
            Ok(0) => Duration::ZERO,
            Ok(n) => self.total / n,
            Err(_) => Duration::from_nanos(
                (self.total.as_nanos() / u128::from(self.scans)).min(u64::MAX.into()) as u64,
            ),
        }
    }

    /// An upper bound of the `p`-th percentile (0–100) of the release latency:
    /// the top of the histogram bucket it falls in (`None` before any release).
    pub fn latency_percentile(&self, p: f64) -> Option<Duration> {
        let total: u64 = self.latency_histogram.iter().sum();
        let want = ((p / 100.0) * total as f64).ceil().max(1.0) as u64;
        let mut seen = 0;
        for (k, n) in self.latency_histogram.iter().enumerate() {
            seen += n;
            if total > 0 && seen >= want {
                return Some(if k + 1 == BUCKETS {
                    self.max_latency
                } else {
                    Duration::from_micros(1 << k)
                });
            }
        }
        None
    }

    /// Records one scan that started at `start` (ns since the runtime started)
    /// and took `took`; `release` is its release time for a periodic task.
    pub(crate) fn record(&mut self, start: u64, took: Duration, release: Option<u64>) {
        self.scans += 1;
        self.last = took;
        self.min = if self.scans == 1 {
            took
        } else {
            self.min.min(took)
        };
        self.max = self.max.max(took);
        self.total += took;
        if !self.interval.is_zero() && took > self.interval {
            self.overruns += 1;
        }
        if let Some(r) = release {
            self.latency = Duration::from_nanos(start.saturating_sub(r));
            self.max_latency = self.max_latency.max(self.latency);
            self.latency_histogram[bucket(self.latency)] += 1;
            if let Some(p) = self.prev_start {
                let period = start.saturating_sub(p) as i128;
                let dev = (period - self.interval.as_nanos() as i128).unsigned_abs();
                // A missed release makes the period a multiple of the interval:
                // that is counted in `missed`, not as jitter.
                if dev < self.interval.as_nanos() / 2 {
                    self.jitter = self.jitter.max(Duration::from_nanos(dev as u64));
                }
            }
            self.prev_start = Some(start);
        }
    }
}

fn us(d: Duration) -> f64 {
    d.as_secs_f64() * 1e6
}

impl fmt::Display for TaskStats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} scans, scan last/min/mean/max {:.1}/{:.1}/{:.1}/{:.1} µs",
            self.name,
            self.scans,
            us(self.last),
            us(self.min),
            us(self.mean()),
            us(self.max)
        )?;
        if !self.interval.is_zero() {
            write!(
                f,
                ", latency last/max {:.1}/{:.1} µs (99% under {:.0} µs), jitter {:.1} µs, overruns {}, missed {}",
                us(self.latency),
                us(self.max_latency),
                us(self.latency_percentile(99.0).unwrap_or_default()),
                us(self.jitter),
                self.overruns,
                self.missed
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figures_follow_the_scans() {
        let ms = Duration::from_millis;
        let mut s = TaskStats::new("t", ms(10));
        s.record(0, ms(1), Some(0));
        s.record(10_200_000, ms(3), Some(10_000_000));
        s.record(19_900_000, ms(12), Some(20_000_000 - 100_000));
        assert_eq!((s.scans, s.min, s.max, s.last), (3, ms(1), ms(12), ms(12)));
        assert_eq!(
            s.mean(),
            Duration::from_micros(5333) + Duration::from_nanos(333)
        );
        assert_eq!(s.max_latency, Duration::from_micros(200));
        assert_eq!(s.jitter, Duration::from_micros(300)); // 9.7 ms between starts
        assert_eq!(s.overruns, 1);
        // 0, 200 and 0 µs: buckets 0, 8 ([128, 256)) and 0.
        assert_eq!((s.latency_histogram[0], s.latency_histogram[8]), (2, 1));
        assert_eq!(s.latency_percentile(50.0), Some(Duration::from_micros(1)));
        assert_eq!(
            s.latency_percentile(100.0),
            Some(Duration::from_micros(256))
        );
        assert_eq!(TaskStats::new("u", ms(1)).latency_percentile(99.0), None);
    }
}
