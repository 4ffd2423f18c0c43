//! A cargo-like progress line for runs over many files, on a terminal only:
//! `Reading 120/500` while reading, `Checking 500 files` while the compiler
//! works, then one `Finished` line when the run took long enough to notice.

use std::io::Write;
use std::time::{Duration, Instant};

/// Below this many files, or when quicker than [`SLOW`], nothing is shown.
const MANY: usize = 20;
const SLOW: Duration = Duration::from_millis(500);
/// Redraw at most this often.
const TICK: Duration = Duration::from_millis(50);

pub struct Progress {
    on: bool,
    total: usize,
    start: Instant,
    last: Option<Instant>,
    drawn: bool,
}

impl Progress {
    /// `on`: stderr is a terminal (the line is redrawn with `\r`).
    pub fn new(on: bool, total: usize) -> Self {
        Progress {
            on: on && total >= MANY,
            total,
            start: Instant::now(),
            last: None,
            drawn: false,
        }
    }

    /// `done` files of the total have been read.
    pub fn reading(&mut self, done: usize, err: &mut dyn Write) {
        if !self.on || self.last.is_some_and(|t| t.elapsed() < TICK) {
            return;
        }
        self.last = Some(Instant::now());
        self.draw(err, &format!("{:>12} {done}/{}", "Reading", self.total));
    }

    /// The compiler runs over every file (one program).
    pub fn stage(&mut self, verb: &str, err: &mut dyn Write) {
        if self.on {
            self.draw(err, &format!("{verb:>12} {} files", self.total));
        }
    }

    /// Clear the line before diagnostics are printed.
    pub fn clear(&mut self, err: &mut dyn Write) {
        if self.drawn {
            let _ = write!(err, "\r\x1b[2K");
            let _ = err.flush();
            self.drawn = false;
        }
    }

    /// The closing line, for a run that was long enough to show progress.
    pub fn finish(&mut self, err: &mut dyn Write) {
        self.clear(err);
        let took = self.start.elapsed();
        if self.on && took >= SLOW {
            let _ = writeln!(
                err,
                "{:>12} {} files in {:.2} s",
                "Finished",
                self.total,
                took.as_secs_f64()
            );
        }
    }

    fn draw(&mut self, err: &mut dyn Write, text: &str) {
        let _ = write!(err, "\r\x1b[2K{text}");
        let _ = err.flush();
        self.drawn = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn silent_when_off_or_few_files() {
        for (on, n) in [(false, 500), (true, 3)] {
            let mut out = Vec::new();
            let mut p = Progress::new(on, n);
            p.reading(1, &mut out);
            p.stage("Checking", &mut out);
            p.finish(&mut out);
            assert!(out.is_empty());
        }
    }

    #[test]
    fn draws_then_clears_on_a_terminal() {
        let mut out = Vec::new();
        let mut p = Progress::new(true, 100);
        p.reading(1, &mut out);
        p.reading(2, &mut out); // within the tick: not redrawn
        p.stage("Checking", &mut out);
        p.start -= SLOW; // as if the run took long
        p.finish(&mut out);
        let s = String::from_utf8(out).unwrap();
        assert!(s.contains("Reading 1/100"), "{s:?}");
        assert!(!s.contains("Reading 2/100"), "{s:?}");
        assert!(s.contains("Checking 100 files"), "{s:?}");
        assert!(s.contains("Finished 100 files in"), "{s:?}");
        // The last drawn line is erased before the closing one.
        assert!(s.contains("\r\x1b[2K    Finished"), "{s:?}");
    }
}
