//! The process image as the world outside the scan sees it.
//!
//! The scan works on its own copy (`Cycle::io`); Modbus clients and the host
//! see the copy published after the last scan. A write from outside changes the
//! published image at once (so a client reads back what it wrote) and is queued
//! for the scan thread, which applies the queue just before the next scan. So a
//! scan never sees a write land half way through it, and a reader never sees
//! half a scan's outputs: the image is exchanged between scans only.

use std::sync::{Mutex, MutexGuard};

use il_std::ProcessImage;
use il_std::addr::Address;

/// A queued write: applied to the published image and, before the next scan,
/// to the scan's own.
type Write = Box<dyn Fn(&mut ProcessImage) + Send>;

/// Writes queued while scans do not run (a stalled scan) are refused past this,
/// so that a client cannot grow memory without bound.
const MAX_PENDING: usize = 10_000;

struct Inner {
    published: ProcessImage,
    pending: Vec<Write>,
    scans: u64,
}

/// The process image shared between the scan thread, the Modbus server and the
/// host ([`crate::Runtime::image`]).
pub struct SharedImage {
    inner: Mutex<Inner>,
}

/// A write was refused: too many writes are waiting for a scan.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Busy;

impl SharedImage {
    pub(crate) fn new(io: &ProcessImage) -> Self {
        SharedImage {
            inner: Mutex::new(Inner {
                published: io.clone(),
                pending: Vec::new(),
                scans: 0,
            }),
        }
    }

    fn lock(&self) -> MutexGuard<'_, Inner> {
        // A panic elsewhere while holding the lock leaves a consistent image
        // (every critical section is a copy or a queue push): keep going.
        self.inner.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Reads an address of the image published after the last scan:
    /// `rt.image().get(il_std::addr::qx(0, 0))`.
    pub fn get<A: Address>(&self, a: A) -> A::Value {
        a.get(&self.lock().published)
    }

    /// Writes an address (an input the host reads from its own hardware, say):
    /// the next scan sees it. `rt.image().set(il_std::addr::ix(0, 3), true)`.
    pub fn set<A>(&self, a: A, v: A::Value) -> Result<(), Busy>
    where
        A: Address + Send + 'static,
        A::Value: Send,
    {
        self.write(Box::new(move |io: &mut ProcessImage| a.set(io, v)))
    }

    /// Runs `f` on the published image (several reads of one scan's image).
    pub fn read<R>(&self, f: impl FnOnce(&ProcessImage) -> R) -> R {
        f(&self.lock().published)
    }

    /// How many scans have published their image.
    pub fn scans(&self) -> u64 {
        self.lock().scans
    }

    pub(crate) fn write(&self, w: Write) -> Result<(), Busy> {
        let mut g = self.lock();
        if g.pending.len() >= MAX_PENDING {
            return Err(Busy);
        }
        w(&mut g.published);
        g.pending.push(w);
        Ok(())
    }

    /// Before a scan: the writes queued since the last one, into the scan's image.
    pub(crate) fn take_into(&self, io: &mut ProcessImage) {
        let pending = std::mem::take(&mut self.lock().pending);
        for w in &pending {
            w(io);
        }
    }

    /// After a scan: its image becomes the published one, with the writes
    /// that arrived during the scan laid over it again (they are still queued
    /// for the next scan, and a client reading back must see them).
    pub(crate) fn publish(&self, io: &ProcessImage) {
        let mut g = self.lock();
        let Inner {
            published,
            pending,
            scans,
        } = &mut *g;
        published.clone_from(io);
        for w in pending.iter() {
            w(published);
        }
        *scans += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use il_std::addr::{mw, qx};

    #[test]
    fn a_write_during_a_scan_waits_for_the_next_and_stays_visible() {
        let mut io = ProcessImage::default();
        let img = SharedImage::new(&io);
        img.take_into(&mut io); // scan 1 starts
        img.set(qx(0, 1), true).unwrap(); // a client writes mid-scan
        io.set(mw(0), 7); // the scan writes
        img.publish(&io); // scan 1 ends
        assert!(!qx(0, 1).get(&io), "the running scan never saw it");
        assert!(img.get(qx(0, 1)), "the client reads back what it wrote");
        assert_eq!(img.get(mw(0)), 7);
        img.take_into(&mut io); // scan 2 sees it
        assert!(qx(0, 1).get(&io));
        assert_eq!(img.scans(), 1);
    }
}
