//! The scheduler thread: sleeps until the next release, runs the generated
//! `run_traced` (which decides, with its own `TaskState`s, which tasks are
//! released and runs them highest priority first), and times each task from
//! the trace callback, which the generated code calls before each program.

use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::mpsc::Sender;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use il_std::{Cycle, DT, TIME};

use crate::error::Error;
use crate::{Plc, SharedImage, TaskStats, retain};

/// Whether the scheduler thread runs under a real-time policy.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Realtime {
    /// Not asked for ([`crate::Options::realtime`] is `None`).
    Off,
    /// `SCHED_FIFO` at this priority; `memory_locked`: `mlockall` succeeded too,
    /// so no page fault stalls a scan.
    Fifo {
        /// The granted priority (1–99).
        priority: i32,
        /// `mlockall(MCL_CURRENT | MCL_FUTURE)` succeeded.
        memory_locked: bool,
    },
    /// Asked for and refused (no `CAP_SYS_NICE`, an `RLIMIT_RTPRIO` of 0, a
    /// container without the capability, not Linux): the thread runs under the
    /// normal policy, and the reason is here.
    Refused(String),
}

/// State the scheduler shares with the runtime's handle and watchdog.
pub(crate) struct Shared {
    pub stop: Arc<AtomicBool>,
    pub stats: Mutex<Vec<TaskStats>>,
    pub image: Arc<SharedImage>,
    /// ns since `origin` + 1 when the running scan started; 0 between scans.
    pub scan_started: AtomicU64,
    /// Index in `TASKS` of the task whose program runs now.
    pub scan_task: AtomicUsize,
    pub origin: Instant,
    pub realtime: Mutex<Realtime>,
    /// SIGINT/SIGTERM, when the runtime handles them.
    pub signals: Option<Arc<crate::signals::Listener>>,
}

impl Shared {
    /// Asked to stop (by the handle, the watchdog or a signal).
    pub fn stopping(&self) -> bool {
        self.stop.load(Ordering::SeqCst) || self.signals.as_ref().is_some_and(|s| s.signalled())
    }

    pub fn elapsed_ns(&self) -> u64 {
        u64::try_from(self.origin.elapsed().as_nanos()).unwrap_or(u64::MAX)
    }
}

/// What the scheduler needs besides the configuration.
pub(crate) struct Plan<R> {
    pub tick: Duration,
    pub watchdog: Option<Duration>,
    pub realtime: Option<i32>,
    pub retain_period: Duration,
    pub saver: Option<Sender<retain::Stored<R>>>,
    pub done: Sender<Result<(), Error>>,
    /// Told what the real-time request gave, before the first scan.
    pub ready: Sender<Realtime>,
}

/// The longest single sleep: the stop flag is looked at least this often.
const STOP_POLL: Duration = Duration::from_millis(50);

pub(crate) fn run<P: Plc>(mut plc: P, mut ctx: Cycle, plan: Plan<P::Retain>, sh: Arc<Shared>) {
    let rt = match plan.realtime {
        Some(p) => make_realtime(p),
        None => {
            precise_sleep();
            Realtime::Off
        }
    };
    *sh.realtime.lock().unwrap_or_else(|e| e.into_inner()) = rt.clone();
    let _ = plan.ready.send(rt);
    let tasks = P::tasks();
    let ns = |d: Duration| u64::try_from(d.as_nanos()).unwrap_or(u64::MAX);
    let intervals: Vec<u64> = tasks.iter().map(|t| t.interval.0.max(0) as u64).collect();
    // Tasks the generated code releases on something else than the clock
    // (SINGLE, an INTERVAL read from a global, no INTERVAL), and programs
    // without a task, are polled at the tick.
    let mut polled = tasks.is_empty()
        || tasks
            .iter()
            .any(|t| t.interval.0 <= 0 || t.single.is_some() || t.interval_from.is_some());
    let tick = ns(plan.tick).max(1);
    // Both the generated TaskStates and this loop count releases from the
    // first call: start + k·interval.
    let start = sh.elapsed_ns();
    let mut next: Vec<u64> = vec![start; tasks.len()];
    let mut next_tick = start;
    let mut last_save = start;
    let mut marks: Vec<(usize, u64)> = Vec::with_capacity(16);
    let mut first = true;
    let mut release: Vec<Option<u64>> = vec![None; tasks.len()];
    // Reused by `record`: no allocation in the loop once it runs.
    let mut ran: Vec<Option<(u64, u64)>> = vec![None; tasks.len()];
    let outcome = loop {
        let wake = intervals
            .iter()
            .zip(&next)
            .filter(|(iv, _)| **iv > 0)
            .map(|(_, n)| *n)
            .chain(polled.then_some(next_tick))
            .min()
            .unwrap_or(next_tick);
        if !sleep_until(&sh, wake) {
            break Ok(());
        }
        // The first call is at `start` exactly: the generated TaskStates take
        // their phase from the time of the first call, and so must `next`.
        let now = if std::mem::take(&mut first) {
            start
        } else {
            sh.elapsed_ns()
        };
        ctx.set_now(TIME(now as i64));
        if let Ok(d) = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH) {
            ctx.set_now_dt(DT(i64::try_from(d.as_nanos()).unwrap_or(i64::MAX)));
        }
        {
            let mut stats = sh.stats.lock().unwrap_or_else(|e| e.into_inner());
            for (i, iv) in intervals.iter().enumerate() {
                release[i] = None;
                if *iv > 0 && next[i] <= now {
                    let missed = (now - next[i]) / iv;
                    stats[i].missed += missed;
                    release[i] = Some(next[i] + missed * iv);
                    next[i] += (missed + 1) * iv;
                }
            }
        }
        if next_tick <= now {
            next_tick = (next_tick + tick).max(now + 1);
        }
        sh.image.take_into(&mut ctx.io);
        marks.clear();
        sh.scan_started.store(now + 1, Ordering::SeqCst);
        // Generated code does not panic, but a host FUNCTION ({extern}) may:
        // the runtime then stops with an error naming the task, not silently.
        let scan = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            plc.run_traced(&mut ctx, &mut |task, _program| {
                // "" (a program without a task) is kept as usize::MAX.
                let i = tasks
                    .iter()
                    .position(|t| t.name == task)
                    .unwrap_or(usize::MAX);
                sh.scan_task.store(i, Ordering::SeqCst);
                marks.push((i, sh.elapsed_ns()));
            })
        }));
        if let Err(p) = scan {
            let task = marks
                .last()
                .and_then(|m| tasks.get(m.0))
                .map_or("", |t| t.name);
            let message = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            sh.scan_started.store(0, Ordering::SeqCst);
            break Err(Error::Panic { task, message });
        }
        let end = sh.elapsed_ns();
        sh.scan_started.store(0, Ordering::SeqCst);
        sh.image.publish(&ctx.io);
        if let Some(e) = record(&sh, &marks, end, &release, &mut ran, plan.watchdog) {
            break Err(e);
        }
        polled |= marks.iter().any(|(i, _)| *i == usize::MAX);
        if let Some(s) = &plan.saver
            && end.saturating_sub(last_save) >= ns(plan.retain_period)
        {
            last_save = end;
            let _ = s.send(retain::capture(&plc, &ctx.io));
        }
    };
    // On stop (and after a watchdog trip, with the state the last scan left):
    // the last state goes to the retain file. Not after a panic: that scan
    // stopped half way, and the file keeps the last whole state.
    if let Some(s) = &plan.saver
        && !matches!(outcome, Err(Error::Panic { .. }))
    {
        let _ = s.send(retain::capture(&plc, &ctx.io));
    }
    drop(plan.saver);
    let _ = plan.done.send(outcome);
}

/// Adds one call's scans to the statistics; the watchdog error if one was too long.
fn record(
    sh: &Shared,
    marks: &[(usize, u64)],
    end: u64,
    release: &[Option<u64>],
    ran: &mut [Option<(u64, u64)>],
    watchdog: Option<Duration>,
) -> Option<Error> {
    let mut stats = sh.stats.lock().unwrap_or_else(|e| e.into_inner());
    // Per task: the start of its first program and the time all its programs took.
    ran.fill(None);
    for (k, &(i, t)) in marks.iter().enumerate() {
        let stop = marks.get(k + 1).map_or(end, |m| m.1);
        if let Some(slot) = ran.get_mut(i) {
            let (s, d) = slot.get_or_insert((t, 0));
            *s = (*s).min(t);
            *d += stop.saturating_sub(t);
        }
    }
    let mut tripped = None;
    for (i, r) in ran.iter().enumerate() {
        if let Some((start, d)) = *r {
            let took = Duration::from_nanos(d);
            stats[i].record(start, took, release[i]);
            if let Some(w) = watchdog
                && took > w
                && tripped.is_none()
            {
                tripped = Some(Error::Watchdog {
                    task: stats[i].name,
                    limit: w,
                    took,
                });
            }
        }
    }
    tripped
}

/// Sleeps until `at` (ns since origin), waking to look at the stop flag;
/// `false` when stopped.
fn sleep_until(sh: &Shared, at: u64) -> bool {
    loop {
        if sh.stopping() {
            return false;
        }
        let now = sh.elapsed_ns();
        if now >= at {
            return true;
        }
        std::thread::sleep(Duration::from_nanos(at - now).min(STOP_POLL));
    }
}

/// `SCHED_FIFO` at `priority` for this thread, and memory locked.
#[cfg(target_os = "linux")]
fn make_realtime(priority: i32) -> Realtime {
    let param = libc::sched_param {
        sched_priority: priority,
    };
    // SAFETY: plain system calls on the calling thread with a valid parameter.
    let rc = unsafe { libc::pthread_setschedparam(libc::pthread_self(), libc::SCHED_FIFO, &param) };
    if rc != 0 {
        precise_sleep();
        return Realtime::Refused(format!(
            "SCHED_FIFO {priority}: {}",
            std::io::Error::from_raw_os_error(rc)
        ));
    }
    // SAFETY: as above; failure only leaves memory pageable.
    let locked = unsafe { libc::mlockall(libc::MCL_CURRENT | libc::MCL_FUTURE) } == 0;
    Realtime::Fifo {
        priority,
        memory_locked: locked,
    }
}

#[cfg(not(target_os = "linux"))]
fn make_realtime(priority: i32) -> Realtime {
    Realtime::Refused(format!("SCHED_FIFO {priority}: only on Linux"))
}

/// Under the normal policy Linux lets a sleep end up to 50 µs late ("timer
/// slack", to batch wake-ups); a PLC task wants its release on time.
fn precise_sleep() {
    #[cfg(target_os = "linux")]
    // SAFETY: prctl with an integer argument; failure changes nothing.
    unsafe {
        libc::prctl(libc::PR_SET_TIMERSLACK, 1 as libc::c_ulong);
    }
}
