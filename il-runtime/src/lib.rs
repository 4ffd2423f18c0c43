//! # il-runtime — a soft-PLC host for generated CONFIGURATIONs
//!
//! Runs a CONFIGURATION compiled from IEC 61131-3 Instruction List (by `il!` or
//! `il_codegen::Builder`, with serde on) the way a PLC runtime does:
//!
//! * **tasks in real time**: one scheduler thread releases every TASK at its
//!   INTERVAL (phase kept, missed releases counted), SINGLE tasks on their
//!   rising edge, and keeps per-task scan statistics ([`TaskStats`]). It asks
//!   for `SCHED_FIFO` when [`Options::realtime`] is set and reports whether it
//!   got it ([`Realtime`]); a watchdog stops the runtime when a scan runs too
//!   long ([`Error::Watchdog`]); SIGINT/SIGTERM stop it cleanly.
//! * **Modbus TCP** ([`modbus`]) with OpenPLC's address table; the process image
//!   is exchanged between scans only ([`SharedImage`]).
//! * **RETAIN** ([`retain`]): the configuration's RETAIN snapshot and its located
//!   RETAIN variables, saved atomically at a period and on stop, loaded at start.
//!
//! Scheduling is non-preemptive (IEC 61131-3 2.7.2 allows it): the generated
//! `run` runs the tasks released at one instant highest priority first, so
//! PRIORITY orders tasks released together, and a long low-priority scan delays
//! a higher-priority release (shown as its latency). One thread is also what the
//! generated code allows: all tasks share the configuration's globals through
//! one `&mut`.
//!
//! ```no_run
//! il_macros::il!(file = "examples/softplc.il", serde);
//! il_runtime::plc!(Hmi); // `plc!(Name, retain = Name__Retain)` when it has a snapshot
//!
//! let opts = il_runtime::Options {
//!     modbus: Some("127.0.0.1:5020".parse().unwrap()),
//!     retain: Some("motor.retain".into()),
//!     ..Default::default()
//! };
//! let rt = il_runtime::Runtime::start(Hmi::default(), opts).unwrap();
//! let report = rt.wait().unwrap(); // until SIGINT/SIGTERM
//! println!("{} scans", report.scans);
//! ```
#![warn(missing_docs)]

pub mod client;
mod error;
mod image;
pub mod modbus;
pub mod retain;
mod runtime;
mod sched;
mod signals;
mod stats;

pub use error::Error;
pub use image::SharedImage;
pub use runtime::{Options, Report, RetainLoad, Runtime};
pub use sched::Realtime;
pub use stats::TaskStats;

use il_std::{Cycle, Located, TaskInfo};

/// A generated CONFIGURATION as the runtime drives it. Implement it with
/// [`plc!`], which forwards to the generated items.
pub trait Plc: Send + 'static {
    /// The RETAIN snapshot (`Name__Retain`), `()` for a configuration without one.
    type Retain: serde::Serialize + serde::de::DeserializeOwned + Send + 'static;
    /// The generated `TASKS`.
    fn tasks() -> &'static [TaskInfo];
    /// The generated `ADDRESSES` (located globals).
    fn addresses() -> &'static [Located];
    /// The generated `run_traced`: runs the tasks released at `ctx.now()`.
    fn run_traced(
        &mut self,
        ctx: &mut Cycle,
        trace: &mut dyn FnMut(&'static str, &'static str),
    ) -> usize;
    /// The generated `retain`.
    fn retain(&self) -> Self::Retain;
    /// The generated `restore`.
    fn restore(&mut self, s: &Self::Retain);
}

/// Implements [`Plc`] for a generated CONFIGURATION type:
/// `plc!(Plant, retain = Plant__Retain)`, or `plc!(Plant)` when it has no
/// RETAIN variables outside the process image.
#[macro_export]
macro_rules! plc {
    ($ty:ty, retain = $r:ty) => {
        impl $crate::Plc for $ty {
            type Retain = $r;
            fn tasks() -> &'static [::il_std::TaskInfo] {
                <$ty>::TASKS
            }
            fn addresses() -> &'static [::il_std::Located] {
                <$ty>::ADDRESSES
            }
            fn run_traced(
                &mut self,
                ctx: &mut ::il_std::Cycle,
                trace: &mut dyn FnMut(&'static str, &'static str),
            ) -> usize {
                <$ty>::run_traced(self, ctx, trace)
            }
            fn retain(&self) -> $r {
                <$ty>::retain(self)
            }
            fn restore(&mut self, s: &$r) {
                <$ty>::restore(self, s)
            }
        }
    };
    ($ty:ty) => {
        impl $crate::Plc for $ty {
            type Retain = ();
            fn tasks() -> &'static [::il_std::TaskInfo] {
                <$ty>::TASKS
            }
            fn addresses() -> &'static [::il_std::Located] {
                <$ty>::ADDRESSES
            }
            fn run_traced(
                &mut self,
                ctx: &mut ::il_std::Cycle,
                trace: &mut dyn FnMut(&'static str, &'static str),
            ) -> usize {
                <$ty>::run_traced(self, ctx, trace)
            }
            fn retain(&self) {}
            fn restore(&mut self, _: &()) {}
        }
    };
}
