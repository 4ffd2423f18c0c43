//! Why the runtime stops: its one error type, for the scheduler that
//! detects the cause and the runtime that reports it.

use std::fmt;
use std::time::Duration;

/// Why the runtime could not start or had to stop.
#[derive(Debug)]
pub enum Error {
    /// A scan ran longer than [`crate::Options::watchdog`] allows (`took` so far,
    /// when the scan had not returned).
    Watchdog {
        /// The task whose program was running.
        task: &'static str,
        /// The watchdog setting.
        limit: Duration,
        /// How long the scan had run.
        took: Duration,
    },
    /// A scan panicked (in a host FUNCTION: generated code does not panic).
    Panic {
        /// The task whose program was running.
        task: &'static str,
        /// The panic's message.
        message: String,
    },
    /// The Modbus port could not be opened.
    Modbus(std::io::Error),
    /// A thread could not be started, or a signal handler installed.
    System(std::io::Error),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Watchdog { task, limit, took } => write!(
                f,
                "watchdog: a scan of task {task} ran {took:?}, longer than the {limit:?} allowed; the runtime stopped"
            ),
            Error::Panic { task, message } => {
                write!(
                    f,
                    "a scan of task {task} panicked: {message}; the runtime stopped"
                )
            }
            Error::Modbus(e) => write!(f, "modbus server: {e}"),
            Error::System(e) => write!(f, "runtime: {e}"),
        }
    }
}

impl std::error::Error for Error {}
