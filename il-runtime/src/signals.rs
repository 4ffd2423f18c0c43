//! SIGINT and SIGTERM: the first one stops the runtimes that handle signals
//! cleanly, a second one (or any when no runtime listens) ends the process as
//! it would without us.
//!
//! signal-hook cannot give a signal its default action back once a handler
//! is installed (unregistering leaves the signal ignored), so the handlers are
//! installed once per process and never removed, around one flag: set by a
//! signal, and also while no runtime listens, because signal-hook's
//! "conditional default" action ends the process on a signal that finds the
//! flag already set.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

struct Handlers {
    flag: Arc<AtomicBool>,
    /// Runtimes listening now.
    listening: Mutex<usize>,
}

static HANDLERS: OnceLock<Result<Handlers, String>> = OnceLock::new();

fn handlers() -> std::io::Result<&'static Handlers> {
    let h = HANDLERS.get_or_init(|| {
        let flag = Arc::new(AtomicBool::new(true));
        for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
            // In this order: a signal that finds the flag set ends the
            // process; otherwise it sets the flag.
            signal_hook::flag::register_conditional_default(sig, flag.clone())
                .and_then(|_| signal_hook::flag::register(sig, flag.clone()))
                .map_err(|e| e.to_string())?;
        }
        Ok(Handlers {
            flag,
            listening: Mutex::new(0),
        })
    });
    h.as_ref().map_err(|e| std::io::Error::other(e.clone()))
}

/// A runtime's subscription: [`Listener::signalled`] turns true on SIGINT or
/// SIGTERM. Dropping it gives the signals back their default action once no
/// runtime listens.
pub(crate) struct Listener(&'static Handlers);

impl Listener {
    pub fn new() -> std::io::Result<Listener> {
        let h = handlers()?;
        let mut n = h.listening.lock().unwrap_or_else(|e| e.into_inner());
        if *n == 0 {
            h.flag.store(false, Ordering::SeqCst);
        }
        *n += 1;
        Ok(Listener(h))
    }

    pub fn signalled(&self) -> bool {
        self.0.flag.load(Ordering::SeqCst)
    }
}

impl Drop for Listener {
    fn drop(&mut self) {
        let mut n = self.0.listening.lock().unwrap_or_else(|e| e.into_inner());
        *n = n.saturating_sub(1);
        if *n == 0 {
            self.0.flag.store(true, Ordering::SeqCst);
        }
    }
}
