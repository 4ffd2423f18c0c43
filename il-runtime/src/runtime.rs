//! Starting, watching and stopping a runtime.

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use il_std::Cycle;

use crate::error::Error;
use crate::modbus::{Server, ServerOptions};
use crate::retain::{self, RetainError};
use crate::sched::{self, Plan, Shared};
use crate::signals::Listener;
use crate::{Plc, Realtime, SharedImage, TaskStats};

/// How to run a configuration. `Options::default()` runs the tasks only.
#[derive(Clone, Debug)]
pub struct Options {
    /// Serve Modbus TCP here (port 0: any free port; see [`Runtime::modbus_addr`]).
    pub modbus: Option<SocketAddr>,
    /// How the Modbus server treats its clients.
    pub modbus_options: ServerOptions,
    /// Keep RETAIN variables in this file.
    pub retain: Option<PathBuf>,
    /// Save RETAIN variables this often (and on stop). A SIGKILL loses at
    /// most this much.
    pub retain_period: Duration,
    /// Stop the runtime with [`Error::Watchdog`] when one task's scan takes
    /// longer than this (even a scan that never returns).
    pub watchdog: Option<Duration>,
    /// Ask for `SCHED_FIFO` at this priority (1–99) for the scheduler thread;
    /// see [`Realtime`] for what was granted.
    pub realtime: Option<i32>,
    /// How often tasks that are not released by their INTERVAL alone (SINGLE,
    /// no INTERVAL, an INTERVAL read from a global) and programs without a
    /// task are given a chance to run.
    pub tick: Duration,
    /// Stop cleanly on SIGINT and SIGTERM.
    pub signals: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            modbus: None,
            modbus_options: ServerOptions::default(),
            retain: None,
            retain_period: Duration::from_secs(1),
            watchdog: None,
            realtime: None,
            tick: Duration::from_millis(10),
            signals: false,
        }
    }
}

/// What a retain file gave at start.
#[derive(Debug)]
pub enum RetainLoad {
    /// No retain file configured.
    NotConfigured,
    /// No file yet: initial values (a cold start).
    Missing,
    /// The saved state was restored (a warm start).
    Restored,
    /// The file could not be used (the reason); the runtime started from
    /// initial values and will overwrite it at the first save.
    Rejected(RetainError),
}

/// What a stopped runtime did.
#[derive(Debug)]
pub struct Report {
    /// Calls of the configuration (each runs the tasks released then).
    pub scans: u64,
    /// Per task.
    pub tasks: Vec<TaskStats>,
    /// Retain files written.
    pub retain_saves: u64,
    /// The last failed retain save, if any.
    pub retain_error: Option<String>,
}

impl Report {
    /// The statistics of the task named `name`.
    pub fn task(&self, name: &str) -> Option<&TaskStats> {
        self.tasks.iter().find(|t| t.name == name)
    }
}

#[derive(Default)]
struct Saves {
    count: AtomicU64,
    error: Mutex<Option<String>>,
}

/// A running configuration.
pub struct Runtime {
    shared: Arc<Shared>,
    done: Receiver<Result<(), Error>>,
    outcome: Option<Result<(), Error>>,
    sched: Option<JoinHandle<()>>,
    saver: Option<JoinHandle<()>>,
    saves: Arc<Saves>,
    watchdog: Option<JoinHandle<()>>,
    server: Option<Server>,
    load: RetainLoad,
}

impl Runtime {
    /// Loads the retain file, opens the Modbus port and starts the tasks.
    pub fn start<P: Plc>(mut plc: P, opts: Options) -> Result<Runtime, Error> {
        let mut ctx = Cycle::new();
        let load = match &opts.retain {
            None => RetainLoad::NotConfigured,
            Some(path) => match retain::load(path) {
                Ok(None) => RetainLoad::Missing,
                Ok(Some(p)) => match retain::apply(&mut plc, &mut ctx.io, &p) {
                    Ok(()) => RetainLoad::Restored,
                    Err(e) => RetainLoad::Rejected(e),
                },
                Err(e) => RetainLoad::Rejected(e),
            },
        };
        let stop = Arc::new(AtomicBool::new(false));
        let signals = if opts.signals {
            Some(Arc::new(Listener::new().map_err(Error::System)?))
        } else {
            None
        };
        let image = Arc::new(SharedImage::new(&ctx.io));
        let server = match opts.modbus {
            Some(a) => Some(
                Server::start(a, image.clone(), opts.modbus_options.clone())
                    .map_err(Error::Modbus)?,
            ),
            None => None,
        };
        let tasks = P::tasks()
            .iter()
            .map(|t| TaskStats::new(t.name, Duration::from_nanos(t.interval.0.max(0) as u64)))
            .collect();
        let shared = Arc::new(Shared {
            stop,
            stats: Mutex::new(tasks),
            image,
            scan_started: AtomicU64::new(0),
            scan_task: AtomicUsize::new(usize::MAX),
            origin: Instant::now(),
            realtime: Mutex::new(Realtime::Off),
            signals,
        });
        let saves = Arc::new(Saves::default());
        let (saver_tx, saver) = match &opts.retain {
            Some(path) => {
                let (tx, rx) = mpsc::channel();
                let (path, saves) = (path.clone(), saves.clone());
                let h = spawn("il-retain", move || {
                    save_loop::<P::Retain>(rx, path, &saves)
                })?;
                (Some(tx), Some(h))
            }
            None => (None, None),
        };
        let (done_tx, done) = mpsc::channel();
        let (ready_tx, ready) = mpsc::channel();
        let plan = Plan {
            tick: opts.tick,
            watchdog: opts.watchdog,
            realtime: opts.realtime,
            retain_period: opts.retain_period,
            saver: saver_tx,
            done: done_tx.clone(),
            ready: ready_tx,
        };
        let sh = shared.clone();
        let sched = spawn("il-scan", move || sched::run(plc, ctx, plan, sh))?;
        // So that `realtime()` tells the truth from the start.
        let _ = ready.recv_timeout(Duration::from_secs(1));
        let watchdog = match opts.watchdog {
            Some(w) => {
                let sh = shared.clone();
                let tasks = P::tasks();
                let h = spawn("il-watchdog", move || {
                    watch(&sh, w, done_tx, |i| tasks.get(i).map_or("", |t| t.name))
                });
                if h.is_err() {
                    // No Runtime will exist to stop the scan thread: stop it here.
                    shared.stop.store(true, Ordering::SeqCst);
                }
                Some(h?)
            }
            None => None,
        };
        Ok(Runtime {
            shared,
            done,
            outcome: None,
            sched: Some(sched),
            saver,
            saves,
            watchdog,
            server,
            load,
        })
    }

    /// The process image as Modbus clients see it; writes reach the next scan.
    pub fn image(&self) -> &Arc<SharedImage> {
        &self.shared.image
    }

    /// Where the Modbus server listens.
    pub fn modbus_addr(&self) -> Option<SocketAddr> {
        self.server.as_ref().map(Server::local_addr)
    }

    /// The statistics so far, per task in `TASKS` order (highest priority first).
    pub fn stats(&self) -> Vec<TaskStats> {
        self.shared
            .stats
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    /// What the retain file gave at start.
    pub fn retain_load(&self) -> &RetainLoad {
        &self.load
    }

    /// Whether the scheduler got `SCHED_FIFO`.
    pub fn realtime(&self) -> Realtime {
        self.shared
            .realtime
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    /// Asks the runtime to stop after the running scan.
    pub fn request_stop(&self) {
        self.shared.stop.store(true, Ordering::SeqCst);
    }

    /// Waits up to `d` for the runtime to stop (a signal, [`Runtime::request_stop`]
    /// or the watchdog); `true` once it has.
    pub fn wait_timeout(&mut self, d: Duration) -> bool {
        if self.outcome.is_some() {
            return true;
        }
        match self.done.recv_timeout(d) {
            Ok(r) => self.outcome = Some(r),
            Err(RecvTimeoutError::Timeout) => return false,
            // Every sender gone without a word: the scan thread panicked.
            Err(RecvTimeoutError::Disconnected) => {
                self.outcome = Some(Err(Error::System(std::io::Error::other(
                    "the scan thread ended unexpectedly",
                ))))
            }
        }
        self.request_stop();
        true
    }

    /// Runs until stopped, then cleans up: the Modbus server closes and the
    /// last state is in the retain file.
    pub fn wait(mut self) -> Result<Report, Error> {
        while !self.wait_timeout(Duration::from_secs(1)) {}
        self.finish()
    }

    /// Stops the runtime and reports.
    pub fn stop(self) -> Result<Report, Error> {
        self.request_stop();
        self.wait()
    }

    fn finish(mut self) -> Result<Report, Error> {
        if let Some(mut s) = self.server.take() {
            s.stop();
        }
        if let Some(w) = self.watchdog.take() {
            let _ = w.join();
        }
        // A scan that never returns (the watchdog's case) keeps its thread,
        // and with it the retain channel: wait a little, then leave both.
        let sched = self.sched.take();
        let deadline = Instant::now() + Duration::from_secs(2);
        let finished = match sched {
            Some(h) => {
                while !h.is_finished() && Instant::now() < deadline {
                    std::thread::sleep(Duration::from_millis(5));
                }
                h.is_finished() && h.join().is_ok()
            }
            None => true,
        };
        if finished && let Some(s) = self.saver.take() {
            let _ = s.join();
        }
        let report = Report {
            scans: self.shared.image.scans(),
            tasks: self.stats(),
            retain_saves: self.saves.count.load(Ordering::SeqCst),
            retain_error: self
                .saves
                .error
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .clone(),
        };
        match self.outcome.take() {
            Some(Err(e)) => Err(e),
            _ => Ok(report),
        }
    }
}

impl Drop for Runtime {
    fn drop(&mut self) {
        // Dropped without wait/stop: at least stop the threads.
        self.request_stop();
    }
}

fn spawn(name: &str, f: impl FnOnce() + Send + 'static) -> Result<JoinHandle<()>, Error> {
    std::thread::Builder::new()
        .name(name.into())
        .spawn(f)
        .map_err(Error::System)
}

/// Writes each state it is sent; when several wait, only the newest.
fn save_loop<R>(rx: Receiver<retain::Stored<R>>, path: PathBuf, saves: &Saves)
where
    R: serde::Serialize + serde::de::DeserializeOwned,
{
    while let Ok(mut state) = rx.recv() {
        while let Ok(newer) = rx.try_recv() {
            state = newer;
        }
        let saved = retain::payload(&state)
            .and_then(|p| retain::save(&path, &p).map_err(|e| e.to_string()));
        match saved {
            Ok(()) => {
                saves.count.fetch_add(1, Ordering::SeqCst);
            }
            Err(e) => {
                *saves.error.lock().unwrap_or_else(|e| e.into_inner()) =
                    Some(format!("{}: {e}", path.display()));
            }
        }
    }
}

/// The watchdog thread: trips when a scan has run longer than `limit`, even
/// one that never returns (the scan thread's own check sees only scans that end).
fn watch(
    sh: &Shared,
    limit: Duration,
    done: Sender<Result<(), Error>>,
    name: impl Fn(usize) -> &'static str,
) {
    let poll = (limit / 4).clamp(Duration::from_millis(1), Duration::from_millis(100));
    while !sh.stopping() {
        std::thread::sleep(poll);
        let started = sh.scan_started.load(Ordering::SeqCst);
        if started == 0 {
            continue;
        }
        let took = Duration::from_nanos(sh.elapsed_ns().saturating_sub(started - 1));
        if took > limit {
            let task = name(sh.scan_task.load(Ordering::SeqCst));
            let _ = done.send(Err(Error::Watchdog { task, limit, took }));
            sh.stop.store(true, Ordering::SeqCst);
            return;
        }
    }
}
